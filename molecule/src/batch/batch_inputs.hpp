// SPDX-License-Identifier: Apache-2.0
// The structures of a batch run: what `alphapocket batch INPUT...` means
// by its inputs, and the id each structure is known by in the tables.
//
//   a structure file   itself (by name: .pdb .ent .cif .mmcif, optionally .gz;
//                      a path that does not exist but is named so is kept,
//                      and fails when read, as any unreadable file)
//   a directory        every structure file below it, recursively (regular
//                      files only: a directory named x.pdb is searched, not read)
//   a list             one path per line, '#' starts a comment; a P2Rank
//                      dataset (.ds): its "HEADER:" line is skipped and the
//                      first column is the path, relative to the .ds
//                      file's directory (other lists: to the current one)
//
// Structure id: structure/structure_id.hpp.
// Two inputs with the same id are an error naming both paths (the same
// path given twice is one input).
#pragma once
#include <istream>
#include <string>
#include <vector>

#include "structure/structure_id.hpp"

namespace molecule {

struct BatchInput {
  std::string id;
  std::string path;
};

// The entries of a list (stream `in`, named `name` in errors): paths as
// written, relative ones resolved against base_dir (empty: as written).
std::vector<std::string> read_path_list(std::istream& in, const std::string& name, bool dataset,
                                        const std::string& base_dir);
// A list file: a dataset when it ends in .ds.
std::vector<std::string> read_path_list_file(const std::string& path);

// The structures of these paths (files, directories, no lists), sorted by
// id; throws alpha::Error for a path that is neither a directory nor named
// as a structure file, or for a duplicate id.
std::vector<BatchInput> batch_inputs(const std::vector<std::string>& paths);

}  // namespace molecule
