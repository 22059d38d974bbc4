// SPDX-License-Identifier: Apache-2.0
// A directory that appears whole or not at all, replacing an earlier one of
// the same name. Its files are written into a hidden sibling,
// ".NAME.alphapocket-new", which commit() swaps in with one atomic rename
// (renameat2 RENAME_EXCHANGE; on a file system without it, two renames,
// between which NAME is briefly absent); the earlier directory, now at the
// sibling's name, is then removed. So a process stopped at any moment, even
// by SIGKILL, leaves NAME as it was or complete, never a mix: at most the
// hidden sibling stays, and the next StagedDirectory of NAME removes it.
//
// Each holds an flock(2) on its sibling (and, while swapping, on NAME), so a
// second process staging the same NAME at the same time is an error, not
// a mixed directory. With a TemporaryPaths, the sibling is registered there
// and every change to it is made under its hold(), so that abandon()
// removes it and nothing is written after.
//
// Errors throw alpha::Error with one line naming NAME.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include "util/temporary_paths.hpp"

namespace molecule {

class StagedDirectory {
public:
  // `target`: absolute, lexically normal, with a file name; its parent must
  // exist. `name`: how messages call it (the path as the user gave it).
  StagedDirectory(const std::filesystem::path& target, const std::string& name, TemporaryPaths* temporaries);
  // Removes the sibling unless commit() swapped it in.
  ~StagedDirectory();
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  // A file of the new directory; `file` is relative and may name one
  // subdirectory ("meshes/pocket_1.ply"), created as needed.
  void write(const std::string& file, std::string_view content);
  // A file of the new directory with `source`'s content: a copy, never a
  // link (an edit of the output in place must not change the source, e.g.
  // the installed Mol*; the kernel copies, about 5 ms for Mol*'s 5 MB).
  void copy(const std::string& file, const std::filesystem::path& source);
  // Puts the new directory in place of the target and removes the
  // earlier one.
  void commit();

private:
  std::filesystem::path target_, sibling_;
  std::string name_;
  TemporaryPaths* temporaries_;
  int lock_fd_ = -1;  // the sibling, flock'd
  bool committed_ = false;

  std::unique_lock<std::mutex> hold() const;
  void remove_sibling();
};

}  // namespace molecule
