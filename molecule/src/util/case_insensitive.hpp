// SPDX-License-Identifier: Apache-2.0
// ASCII comparisons that ignore case, against a lower-case pattern
// (record names, file extensions, CIF reserved words).
#pragma once
#include <algorithm>
#include <cctype>
#include <string_view>

namespace molecule {

// Whether s equals `lower` (lower case) ignoring case.
inline bool equals_ci(std::string_view s, std::string_view lower) {
  return s.size() == lower.size() && std::equal(lower.begin(), lower.end(), s.begin(), [](char a, char b) {
           return a == std::tolower(static_cast<unsigned char>(b));
         });
}

inline bool starts_with_ci(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && equals_ci(s.substr(0, prefix.size()), prefix);
}

inline bool ends_with_ci(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && equals_ci(s.substr(s.size() - suffix.size()), suffix);
}

}  // namespace molecule
