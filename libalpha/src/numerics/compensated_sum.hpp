// SPDX-License-Identifier: Apache-2.0
// Neumaier's compensated sum: the error does not grow with the number of
// terms, and a fixed order of additions makes the result deterministic.
#pragma once
#include <cmath>

namespace alpha {

class Sum {
public:
  void add(double x) {
    const double t = s_ + x;
    c_ += std::fabs(s_) >= std::fabs(x) ? (s_ - t) + x : (x - t) + s_;
    s_ = t;
  }
  double value() const { return s_ + c_; }

private:
  double s_ = 0, c_ = 0;
};

}  // namespace alpha
