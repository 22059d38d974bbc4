// SPDX-License-Identifier: Apache-2.0
// Progress of a batch run on stderr: on a terminal a live bar (done/total,
// structures/s, ETA, failures), redrawn at most 5 times a second; otherwise
// one plain line every 10 s. Disabled: nothing at all (-q). Safe to call
// from several threads. (Debian packages no C++ progress-bar library, so it
// is this small class.)
#pragma once
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace alphapocket {

class Progress {
public:
  Progress(std::size_t total, bool enabled);
  // One structure finished (failed: it did not succeed).
  void add(bool failed);
  // Logs a warning line without tearing the bar.
  void warn(const std::string& message);
  // Ends the bar's line (a terminal) and prints the final figures.
  void finish();

  std::size_t done() const { return done_; }
  std::size_t failed() const { return failed_; }

private:
  using Clock = std::chrono::steady_clock;
  std::mutex mutex_;
  std::size_t total_, done_ = 0, failed_ = 0;
  bool enabled_, terminal_;
  Clock::time_point start_ = Clock::now(), last_ = start_;
  bool drawn_ = false;

  std::string line() const;
  void draw(bool force);
};

}  // namespace alphapocket
