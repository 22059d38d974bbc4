// SPDX-License-Identifier: Apache-2.0
// The models of a multi-model PDB file one at a time, so that reading an
// ensemble holds the file's text and the models in flight, not every model
// parsed: model k's text is the lines before the first MODEL record, blank
// lines in place of the models before it (messages keep the file's line
// numbers), its MODEL..ENDMDL lines and the lines after the last ENDMDL.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace molecule {

class PdbModels {
public:
  // `text` must outlive this. No models when it holds no MODEL record.
  explicit PdbModels(std::string_view text);

  std::size_t size() const { return blocks_.size(); }
  std::string text(std::size_t k) const;

private:
  struct Block {
    std::size_t begin, end, lines_before;  // byte range [begin, end) of MODEL..ENDMDL
  };
  std::string_view text_;
  std::vector<Block> blocks_;
};

}  // namespace molecule
