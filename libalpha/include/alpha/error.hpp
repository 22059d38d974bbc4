// Library errors: one exception type, thrown through one function.
// Library code never prints or exits; callers decide what to do.
#pragma once
#include <stdexcept>
#include <string>

namespace alpha {

class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

[[noreturn]] void fail(const std::string& message);

}  // namespace alpha
