// SPDX-License-Identifier: Apache-2.0
#include "point_file.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

#include "alpha/error.hpp"
#include "alpha/input_file.hpp"

namespace alphapocket {
namespace {

// The coordinate range of alpha::Triangulation; a radius up to 1e15 keeps
// its weight r^2 within the triangulation's weight range (1e30).
constexpr double kMaxValue = 1e15;

[[noreturn]] void bad_input_at(const std::string& name, std::size_t line, const std::string& what) {
  throw alpha::Error(name + ":" + std::to_string(line) + ": " + what, alpha::ErrorKind::BadInput);
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// A token shown in a message: quoted, and shortened when very long.
std::string quoted(std::string_view token) {
  constexpr std::size_t kMax = 40;
  const bool cut = token.size() > kMax;
  std::string s(1, '\'');
  s.append(token.substr(0, kMax));
  s.append(cut ? "...'" : "'");
  return s;
}

double parse_number(std::string_view token, const std::string& name, std::size_t line) {
  std::string_view digits = token;
  // std::from_chars takes no leading '+'; accept one, but not "+-1" or "++1".
  if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+')
    digits.remove_prefix(1);
  double value = 0;
  const char* end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) bad_input_at(name, line, "number " + quoted(token) + " is out of range");
  if (ec != std::errc() || ptr != end) bad_input_at(name, line, quoted(token) + " is not a number");
  if (!std::isfinite(value)) bad_input_at(name, line, quoted(token) + " is not a finite number");
  if (std::fabs(value) > kMaxValue)
    bad_input_at(name, line, "number " + quoted(token) + " is out of range (|value| > 1e15)");
  return value;
}

}  // namespace

PointSet parse_points(std::string_view text, const std::string& name, bool weighted) {
  const std::size_t expected = weighted ? 4 : 3;
  PointSet set;
  std::size_t line_no = 0;
  std::vector<std::string_view> tokens;
  while (!text.empty()) {
    ++line_no;
    const std::size_t eol = text.find('\n');
    std::string_view line = text.substr(0, eol);
    text.remove_prefix(eol == std::string_view::npos ? text.size() : eol + 1);
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    if (line.find('\0') != std::string_view::npos)
      bad_input_at(name, line_no, "contains a NUL byte: not a text point file");
    tokens.clear();
    for (std::size_t i = 0; i < line.size();) {
      if (is_space(line[i])) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < line.size() && !is_space(line[j])) ++j;
      tokens.push_back(line.substr(i, j - i));
      i = j;
    }
    if (tokens.empty()) continue;
    if (tokens.size() != expected)
      bad_input_at(name, line_no,
                   "expected " + std::to_string(expected) + " numbers" + (weighted ? " (x y z r)" : "") + ", got " +
                       std::to_string(tokens.size()));
    double v[4];
    for (std::size_t k = 0; k < expected; ++k) v[k] = parse_number(tokens[k], name, line_no);
    set.points.push_back({v[0], v[1], v[2]});
    if (weighted) {
      if (v[3] < 0) bad_input_at(name, line_no, "radius " + quoted(tokens[3]) + " is negative");
      set.weights.push_back(v[3] * v[3]);
    }
  }
  if (set.points.empty())
    throw alpha::Error(name + ": no points (only comments and blank lines)", alpha::ErrorKind::BadInput);
  return set;
}

PointSet read_point_file(const std::string& path, bool weighted) {
  return parse_points(alpha::read_input_file(path), path, weighted);
}

}  // namespace alphapocket
