// SPDX-License-Identifier: Apache-2.0
#include "alpha/error.hpp"

namespace alpha {

std::string_view error_kind_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::BadInput: return "bad_input";
    case ErrorKind::LimitExceeded: return "limit_exceeded";
    case ErrorKind::Misuse: return "misuse";
    case ErrorKind::Internal: break;
  }
  return "internal";
}

void fail(const std::string& message, ErrorKind kind) { throw Error(message, kind); }

Error in_file(const std::string& file, const Error& e) { return Error(file + ": " + e.what(), e.kind()); }

}  // namespace alpha
