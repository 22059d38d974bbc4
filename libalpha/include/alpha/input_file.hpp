// SPDX-License-Identifier: Apache-2.0
// Whole-file input shared by every reader (point files, structures): one
// place decides what a missing, unreadable, directory or empty input is
// called, so every command reports it the same way.
#pragma once
#include <string>

namespace alpha {

// The bytes of the file at `path`. Throws alpha::Error with one line
// naming the file ("PATH: cannot open: no such file", "PATH: is a
// directory, not a file", "PATH: read error", "PATH: file is empty").
// Pipes and other special files are read like regular files.
std::string read_input_file(const std::string& path);

}  // namespace alpha
