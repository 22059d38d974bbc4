// SPDX-License-Identifier: Apache-2.0
#include "progress.hpp"

#include <cmath>
#include <cstdio>

#include <spdlog/spdlog.h>
#include <unistd.h>

namespace alphapocket {
namespace {

std::string duration_text(double seconds) {
  const long s = std::lround(seconds);
  char text[32];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, s / 60 % 60);
  else
    std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  return text;
}

}  // namespace

Progress::Progress(std::size_t total, bool enabled)
    : total_(total), enabled_(enabled), terminal_(::isatty(STDERR_FILENO) == 1) {}

std::string Progress::line() const {
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  const double rate = elapsed > 0 ? double(done_) / elapsed : 0;
  const std::string eta = rate > 0 ? duration_text(double(total_ - done_) / rate) : "?";
  char text[160];
  std::snprintf(text, sizeof text, "%zu/%zu structures, %.1f/s, ETA %s, %zu failed or skipped", done_, total_, rate,
                eta.c_str(), failed_);
  if (!terminal_) return text;
  constexpr int kWidth = 30;
  const int filled = total_ ? int(kWidth * done_ / total_) : kWidth;
  return "[" + std::string(filled, '#') + std::string(kWidth - filled, '.') + "] " + text;
}

void Progress::draw(bool force) {
  if (!enabled_) return;
  const auto now = Clock::now();
  const auto every = terminal_ ? std::chrono::milliseconds(200) : std::chrono::milliseconds(10000);
  if (!force && now - last_ < every) return;
  last_ = now;
  if (terminal_) {
    std::fprintf(stderr, "\r\033[K%s", line().c_str());
    drawn_ = true;
  } else {
    std::fprintf(stderr, "%s\n", line().c_str());
  }
  std::fflush(stderr);
}

void Progress::add(bool failed) {
  const std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  failed_ += failed;
  draw(false);
}

void Progress::warn(const std::string& message) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (drawn_) std::fprintf(stderr, "\r\033[K");
  spdlog::warn("{}", message);
  if (drawn_) draw(true);
}

void Progress::finish() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!enabled_) return;
  if (terminal_) {
    draw(true);
    std::fprintf(stderr, "\n");
  }
}

}  // namespace alphapocket
