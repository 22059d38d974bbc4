// SPDX-License-Identifier: Apache-2.0
#include "trajectory/pdb_models.hpp"

namespace molecule {

PdbModels::PdbModels(std::string_view text) : text_(text) {
  std::size_t line = 0, open = std::string_view::npos, open_line = 0;
  for (std::size_t at = 0; at < text.size(); ++line) {
    std::size_t next = text.find('\n', at);
    next = next == std::string_view::npos ? text.size() : next + 1;
    const std::string_view record = text.substr(at, 6);
    if (record.starts_with("MODEL")) {
      if (open != std::string_view::npos) blocks_.push_back({open, at, open_line});  // no ENDMDL before it
      open = at, open_line = line;
    } else if (record.starts_with("ENDMDL") && open != std::string_view::npos) {
      blocks_.push_back({open, next, open_line});
      open = std::string_view::npos;
    }
    at = next;
  }
  if (open != std::string_view::npos) blocks_.push_back({open, text.size(), open_line});
}

std::string PdbModels::text(std::size_t k) const {
  const Block& b = blocks_[k];
  const Block& first = blocks_.front();
  std::string out(text_.substr(0, first.begin));
  out.append(b.lines_before - first.lines_before, '\n');
  out.append(text_.substr(b.begin, b.end - b.begin));
  out.append(text_.substr(blocks_.back().end));
  return out;
}

}  // namespace molecule
