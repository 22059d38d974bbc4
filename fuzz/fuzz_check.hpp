// SPDX-License-Identifier: Apache-2.0
// What every fuzz target checks of an error message: the project's rule for
// bad input is one line naming the file. A violated property aborts, which
// libFuzzer reports as a crash with the input that caused it.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace fuzz {

[[noreturn]] inline void violated(const char* what, std::string_view detail = {}) {
  std::fprintf(stderr, "property violated: %s: %.*s\n", what, int(detail.size()), detail.data());
  std::abort();
}

inline void check(bool ok, const char* what, std::string_view detail = {}) {
  if (!ok) violated(what, detail);
}

// One line, starting with the file name.
inline void check_message(std::string_view message, std::string_view name) {
  check(message.substr(0, name.size()) == name, "the message does not start with the file name", message);
  check(message.find_first_of("\n\r") == std::string_view::npos, "the message is not one line", message);
}

}  // namespace fuzz
