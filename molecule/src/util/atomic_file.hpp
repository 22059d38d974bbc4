// SPDX-License-Identifier: Apache-2.0
// Output files that appear whole or not at all: the content goes to a
// hidden temporary file in the target's directory, which is renamed to the
// target only once complete (rename is atomic within one file system), and
// removed on any failure. An existing file of that name is replaced. A
// reader (or a crash) never sees half a file.
//
// Errors throw alpha::Error with one line naming the target file.
#pragma once
#include <string>
#include <string_view>

#include "util/temporary_paths.hpp"

namespace molecule {

// Throws alpha::Error when no file named path could be created: its
// directory is missing, not a directory, or not writable. Lets a caller fail
// before it does the work.
void check_can_create(const std::string& path);

// A new, empty file next to target (".<name>.<random>.tmp"); removed again
// when this object dies before commit() moved it into place. With
// `temporaries`, registered there while it exists.
class TemporaryFile {
public:
  explicit TemporaryFile(const std::string& target, TemporaryPaths* temporaries = nullptr);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const std::string& path() const { return path_; }

  // Renames the (closed, complete) file to the target.
  void commit();

private:
  std::string target_, path_;
  TemporaryPaths* temporaries_;

  std::unique_lock<std::mutex> hold() const;
};

// Writes content to path through a TemporaryFile.
void write_file_atomically(const std::string& path, std::string_view content);

}  // namespace molecule
