// SPDX-License-Identifier: Apache-2.0
// Library errors: one exception type with a category a caller can act on.
// Every throw names its category (there is no default), so the compiler
// checks that each one was chosen. Library code never prints or exits;
// callers decide what to do (the CLI's exit code per category: apps/main.cpp).
#pragma once
#include <stdexcept>
#include <string>
#include <string_view>

namespace alpha {

enum class ErrorKind {
  BadInput,       // the data cannot be used (unreadable file, coplanar points): skip this input
  LimitExceeded,  // too large for the library (32-bit ids, a size limit, memory): a smaller input may work
  Misuse,         // the caller broke an API contract (mismatched sizes, negative radius option): a bug upstream
  Internal,       // anything else (a bug here, a full disk)
};

// "bad_input", "limit_exceeded", "misuse", "internal".
std::string_view error_kind_name(ErrorKind kind);

class Error : public std::runtime_error {
public:
  Error(const std::string& message, ErrorKind kind) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const { return kind_; }

private:
  ErrorKind kind_;
};

[[noreturn]] void fail(const std::string& message, ErrorKind kind);

// The same error (same kind) about `file`: "<file>: <message>".
Error in_file(const std::string& file, const Error& e);

}  // namespace alpha
