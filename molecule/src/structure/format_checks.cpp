// SPDX-License-Identifier: Apache-2.0
#include "structure/format_checks.hpp"

// Compiled as C++17 by clang (molecule/CMakeLists.txt): no std::span or
// starts_with here.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <unordered_set>

#include <gemmi/cif.hpp>
#include <gemmi/elem.hpp>
#include <gemmi/mmcif.hpp>

#include "alpha/error.hpp"
#include "util/case_insensitive.hpp"
#include "util/safe_text.hpp"

namespace molecule::format_checks {
namespace {

// The problem may quote the file's own bytes (a record, a token): any
// control or non-ASCII byte among them becomes '?', so the message stays
// one line and prints nothing but text.
[[noreturn]] void fail(const std::string& name, const std::string& what, alpha::ErrorKind kind) {
  throw alpha::Error(name + ": " + printable_ascii(what), kind);
}

std::string_view trimmed(std::string_view text) {
  const std::size_t begin = text.find_first_not_of(" \t");
  if (begin == std::string_view::npos) return {};
  return text.substr(begin, text.find_last_not_of(" \t") - begin + 1);
}

// mmCIF: the first thing after blanks and comments is a data_ block.
bool starts_with_data_block(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[i]))) {
      ++i;
    } else if (text[i] == '#') {
      i = text.find('\n', i);
      if (i == std::string_view::npos) return false;
    } else {
      break;
    }
  }
  std::string_view head = text.substr(i, 5);
  return head.size() == 5 && ends_with_ci(head, "data_");
}

// PDB: some line is an ATOM or HETATM record.
bool has_atom_records(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::string_view line = text.substr(i, 6);
    if (line.substr(0, 5) == "ATOM " || line == "HETATM") return true;
    const std::size_t eol = text.find('\n', i);
    if (eol == std::string_view::npos) break;
    i = eol + 1;
  }
  return false;
}

// A coordinate field of a PDB record: blanks, an optional sign, digits with
// at most one decimal point, blanks.
bool is_pdb_number(std::string_view field) {
  std::size_t i = field.find_first_not_of(' ');
  if (i == std::string_view::npos) return false;
  if (field[i] == '-' || field[i] == '+') ++i;
  bool digits = false;
  bool point = false;
  for (; i < field.size() && field[i] != ' '; ++i) {
    if (field[i] >= '0' && field[i] <= '9')
      digits = true;
    else if (field[i] == '.' && !point)
      point = true;
    else
      return false;
  }
  return digits && field.find_first_not_of(' ', i) == std::string_view::npos;
}

// What gemmi reads as a charge from columns 79-80 ("2+", "+2", "2", blank);
// it rejects other text without saying where.
bool is_pdb_charge(char c79, char c80) {
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  const auto sign = [](char c) { return c == '+' || c == '-' || c == ' '; };
  return !(digit(c79) && !sign(c80)) && !(digit(c80) && !sign(c79));
}

// Calls fn(line_number, line) for each line of text (numbered from 1, a
// trailing '\r' removed) until fn returns false.
template <class Fn> void for_each_line(std::string_view text, Fn fn) {
  std::size_t line_number = 0;
  for (std::size_t i = 0; i < text.size();) {
    std::size_t eol = text.find('\n', i);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view line = text.substr(i, eol - i);
    i = eol + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!fn(++line_number, line)) return;
  }
}

// END, which ends a PDB file's records (ENDMDL does not).
bool is_end_record(std::string_view line) {
  return line.size() >= 3 && equals_ci(line.substr(0, 3), "end") &&
         (line.size() == 3 || std::isspace(static_cast<unsigned char>(line[3])));
}

// Far beyond any structure (the largest assemblies span some 1e4 A), so a
// coordinate beyond it is a broken file.
constexpr double kMaxCoordinate = 1e6;

// The line of value `index` (row by row) of the loop whose loop_ keyword is
// on line `loop_line`: the CIF tokens from there counted (the tags, then
// the values; quoted strings, ;-text fields and comments as CIF has them).
// gemmi's document keeps the line of a loop, not of its values.
std::size_t loop_value_line(std::string_view text, std::size_t loop_line, std::size_t tags, std::size_t index) {
  std::size_t i = 0;
  for (std::size_t line = 1; line < loop_line && i < text.size(); ++line) i = text.find('\n', i) + 1;
  std::size_t line = loop_line;
  const std::size_t wanted = 1 + tags + index;  // loop_ itself first
  const auto space = [&](std::size_t k) { return std::isspace(static_cast<unsigned char>(text[k])) != 0; };
  for (std::size_t token = 0; i < text.size();) {
    if (text[i] == '\n') {
      ++line;
      ++i;
    } else if (space(i)) {
      ++i;
    } else if (text[i] == '#') {
      i = std::min(text.find('\n', i), text.size());
    } else {
      const std::size_t start_line = line;
      if (text[i] == ';' && (i == 0 || text[i - 1] == '\n')) {  // a text field, to a line starting with ';'
        const std::size_t end = std::min(text.find("\n;", i), text.size());
        line += std::size_t(std::count(text.begin() + i, text.begin() + end, '\n')) + 1;
        i = end + 2;
      } else if (text[i] == '\'' || text[i] == '"') {  // to the same quote before a blank
        const char quote = text[i++];
        while (i < text.size() && text[i] != '\n' && !(text[i] == quote && (i + 1 == text.size() || space(i + 1)))) ++i;
        ++i;
      } else {
        while (i < text.size() && !space(i)) ++i;
      }
      if (token++ == wanted) return start_line;
    }
  }
  return loop_line;
}

// The _atom_site columns gemmi requires (mmcif.hpp, make_structure_from_block;
// label/auth_comp_id and label/auth_atom_id it checks itself): without one it
// reads no atoms at all, without saying why.
constexpr const char* kRequiredAtomSite[] = {"id",      "type_symbol", "label_alt_id", "label_asym_id",  "Cartn_x",
                                             "Cartn_y", "Cartn_z",     "occupancy",    "B_iso_or_equiv", "auth_seq_id"};

// Whether gemmi's string_to_int would overflow on v (undefined behaviour):
// the run of digits after blanks and a sign is beyond 2^31 - 1.
bool int_overflows(const std::string& v) {
  std::size_t i = 0;
  while (i < v.size() && (v[i] == ' ' || v[i] == '\t')) ++i;
  if (i < v.size() && (v[i] == '-' || v[i] == '+')) ++i;
  while (i < v.size() && v[i] == '0') ++i;
  std::size_t end = i;
  while (end < v.size() && v[end] >= '0' && v[end] <= '9') ++end;
  const std::string_view digits(v.data() + i, end - i);
  return digits.size() > 10 || (digits.size() == 10 && digits > "2147483647");
}

}  // namespace

bool is_blank(std::string_view text) {
  return std::all_of(text.begin(), text.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
}

Format detect_format(std::string_view text, const std::string& name) {
  if (starts_with_data_block(text)) return Format::Mmcif;
  if (has_atom_records(text)) return Format::Pdb;
  if (text.substr(0, 4096).find('\0') != std::string_view::npos)
    fail(name, "binary data, not a PDB or mmCIF file", alpha::ErrorKind::BadInput);
  fail(name, "not a PDB or mmCIF file (no data_ block, no ATOM or HETATM records)", alpha::ErrorKind::BadInput);
}

void check_pdb_records(std::string_view text, const std::string& name, bool old_columns, UnknownElements& unknown) {
  const std::size_t last_line =
      (text.back() == '\n' || text.back() == '\r') ? text.size() : text.rfind('\n') + 1;  // npos + 1 = 0
  std::size_t shortest = 0;                                                               // of the atom records
  for_each_line(text, [&](std::size_t line_number, std::string_view line) {
    if (is_end_record(line)) return false;
    const auto bad_input = [&](const std::string& what) {
      fail(name, "line " + std::to_string(line_number) + ": " + what, alpha::ErrorKind::BadInput);
    };
    // gemmi reads the distance of a SSBOND or LINK record longer than 73
    // characters from columns 74-78, past the record's end when it is
    // shorter. Its record is the line up to a NUL, with the CR and LF.
    if ((equals_ci(line.substr(0, 4), "ssbo") || equals_ci(line.substr(0, 4), "link")) && !old_columns) {
      std::size_t length = line.find('\0');
      if (length == std::string_view::npos) {
        const std::size_t end = std::size_t(line.data() - text.data()) + line.size();
        length = std::min(text.size(), text.find('\n', end) + 1) - std::size_t(line.data() - text.data());
      }
      if (length > 73 && length < 78)
        bad_input(std::string(trimmed(line.substr(0, 6))) + " record ends inside its distance field (columns 74-78)");
    }
    const bool atom = equals_ci(line.substr(0, 4), "atom");
    if (!atom && !equals_ci(line.substr(0, 4), "heta")) return true;
    const std::string_view record = atom ? "ATOM" : "HETATM";
    if (line.data() == text.data() + last_line && line.size() < shortest)
      bad_input(std::string(record) + " record cut short by the end of the file (" + std::to_string(line.size()) +
                " columns and no line end, the others have " + std::to_string(shortest) + " or more): truncated file");
    shortest = shortest ? std::min(shortest, line.size()) : line.size();
    if (line.size() < 54)
      bad_input(std::string(record) + " record shorter than 54 columns ('" + std::string(line) + "')");
    if (!is_pdb_number(line.substr(30, 8)) || !is_pdb_number(line.substr(38, 8)) || !is_pdb_number(line.substr(46, 8)))
      bad_input("bad coordinates in " + std::string(record) + " record (columns 31-54: '" +
                std::string(line.substr(30, 24)) + "')");
    for (std::size_t column = 30; column < 54; column += 8)
      if (std::fabs(std::strtod(std::string(line.substr(column, 8)).c_str(), nullptr)) > kMaxCoordinate)
        bad_input("coordinate '" + std::string(line.substr(column, 8)) + "' (columns " + std::to_string(column + 1) +
                  "-" + std::to_string(column + 8) + ") is beyond 1e6 A");
    // Columns 77-78 as gemmi reads them: an element when either is a letter.
    if (!old_columns && line.size() > 76 &&
        (std::isalpha(static_cast<unsigned char>(line[76])) ||
         (line.size() > 77 && std::isalpha(static_cast<unsigned char>(line[77]))))) {
      const std::string symbol(trimmed(line.substr(76, 2)));
      if (gemmi::find_element(symbol.c_str()) == gemmi::El::X) unknown.emplace(symbol, line_number);
    }
    if (!old_columns && line.size() >= 79 && !is_pdb_charge(line[78], line.size() >= 80 ? line[79] : ' '))
      bad_input("bad charge in " + std::string(record) + " record (columns 79-80: '" + std::string(line.substr(78, 2)) +
                "')");
    return true;
  });
}

bool has_scattered_residues(std::string_view text, bool old_columns) {
  bool found = false;
  std::unordered_set<std::string> seen;  // the residues of the model so far
  std::string current;
  for_each_line(text, [&](std::size_t, std::string_view line) {
    if (is_end_record(line)) return false;
    if (equals_ci(line.substr(0, 6), "model ") || equals_ci(line.substr(0, 6), "endmdl")) {
      seen.clear();
      current.clear();
    }
    if (!equals_ci(line.substr(0, 4), "atom") && !equals_ci(line.substr(0, 4), "heta")) return true;
    std::string residue(line.substr(17, 10));
    if (!old_columns && line.size() > 72) residue += trimmed(line.substr(72, 4));
    if (residue == current) return true;
    found = !seen.insert(residue).second;
    current = std::move(residue);
    return !found;
  });
  return found;
}

std::optional<OldColumns> old_format_columns(std::string_view text) {
  std::optional<OldColumns> found;
  for_each_line(text, [&](std::size_t line_number, std::string_view line) {
    if (line.size() < 80 || !(equals_ci(line.substr(0, 4), "atom") || equals_ci(line.substr(0, 4), "heta")))
      return true;
    const std::string_view tail = line.substr(76, 4);
    const std::size_t first_digit = tail.find_first_not_of(' ');
    if (first_digit > 2) return true;
    if (std::all_of(tail.begin() + first_digit, tail.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      found = OldColumns{line_number, std::string(line.substr(72, 8))};
      return false;
    }
    return true;
  });
  return found;
}

std::optional<std::size_t> cif_without_data_block(std::string_view text) {
  std::optional<std::size_t> found;
  for_each_line(text, [&](std::size_t line_number, std::string_view line) {
    if ((!line.empty() && line[0] == '_') || equals_ci(line.substr(0, 5), "loop_")) found = line_number;
    return !found && !equals_ci(line.substr(0, 5), "data_");
  });
  return found;
}

void check_atom_site(gemmi::cif::Block& block, std::string_view text, const std::string& name,
                     UnknownElements& unknown) {
  std::vector<std::string> tags(std::begin(kRequiredAtomSite), std::end(kRequiredAtomSite));
  enum { kId = 0, kSymbol = 1, kAlt = 2, kX = 4, kAuthSeq = 9, kIcode, kLabelSeq, kCharge };
  for (const char* optional : {"?pdbx_PDB_ins_code", "?label_seq_id", "?pdbx_formal_charge"})
    tags.emplace_back(optional);
  gemmi::cif::Table table = block.find("_atom_site.", tags);
  if (!table.ok()) return;
  const gemmi::cif::Item* loop = table.loop_item;
  const auto line_of = [&](std::size_t row, std::size_t col) {
    const std::size_t position = std::size_t(table.positions[col]);
    return loop ? loop_value_line(text, std::size_t(loop->line_number), loop->loop.width(),
                                  row * loop->loop.width() + position)
                : std::size_t(block.items[position].line_number);
  };
  const auto bad_input = [&](std::size_t row, std::size_t col, const std::string& what) {
    const std::string& tag = tags[col];
    fail(name,
         "line " + std::to_string(line_of(row, col)) + ": _atom_site." + tag.substr(tag[0] == '?') + " is '" +
             table[int(row)][col] + "', " + what,
         alpha::ErrorKind::BadInput);
  };
  for (std::size_t row = 0; row < table.length(); ++row) {
    const gemmi::cif::Table::Row values = table[int(row)];
    for (const std::size_t c : {std::size_t(kId), std::size_t(kAuthSeq), std::size_t(kLabelSeq), std::size_t(kCharge)})
      if (values.has(c) && int_overflows(values[c])) bad_input(row, c, "an integer beyond 2147483647");
    for (const std::size_t c : {std::size_t(kAlt), std::size_t(kIcode)})
      if (values.has(c)) try {
          gemmi::cif::as_char(values[c], ' ');
        } catch (const std::exception&) {
          bad_input(row, c, "not a single character");
        }
    for (const std::size_t c : {std::size_t(kLabelSeq), std::size_t(kCharge)})
      if (values.has(c)) try {
          gemmi::cif::as_int(values[c], 0);
        } catch (const std::exception&) {
          bad_input(row, c, "not an integer");
        }
    try {
      gemmi::impl::make_seqid(values[kAuthSeq], values.has(kIcode) ? &values[kIcode] : nullptr);
    } catch (const std::exception&) {
      bad_input(row, kAuthSeq, "not a residue number (an integer, optionally followed by the insertion code)");
    }
    for (std::size_t c = kX; c < kX + 3; ++c) {
      const std::string& v = values[c];
      const double x = gemmi::cif::as_number(v);
      if (gemmi::cif::is_null(v))
        bad_input(row, c, v == "?" ? "unknown: not a coordinate" : "inapplicable: not a coordinate");
      if (std::isnan(x)) bad_input(row, c, "not a number");
      if (!(std::fabs(x) <= kMaxCoordinate)) bad_input(row, c, "beyond 1e6 A");
    }
    if (!gemmi::cif::is_null(values[kSymbol])) {
      const std::string element = gemmi::cif::as_string(values[kSymbol]);
      if (gemmi::find_element(element.c_str()) == gemmi::El::X && !unknown.count(element))
        unknown.emplace(element, line_of(row, kSymbol));
    }
  }
}

std::vector<std::string> missing_atom_site_columns(gemmi::cif::Block& block) {
  std::vector<std::string> missing;
  if (!block.find_mmcif_category("_atom_site.").ok()) return missing;
  for (const char* column : kRequiredAtomSite)
    if (!block.has_tag(std::string("_atom_site.") + column)) missing.push_back(std::string("_atom_site.") + column);
  return missing;
}

}  // namespace molecule::format_checks
