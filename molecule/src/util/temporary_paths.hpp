// SPDX-License-Identifier: Apache-2.0
// The temporary files and directories of writes in progress, for a caller
// that may have to abandon them at any moment (apps/interrupt: a signal).
// abandon() removes every registered path and from then on blocks every
// writer, so that none is left behind and none is made after the sweep;
// the caller then ends the process. Writers that get one (TemporaryFile,
// StagedDirectory) hold() it around each change they make in a registered
// path. Thread-safe.
#pragma once
#include <mutex>
#include <string>
#include <vector>

namespace molecule {

class TemporaryPaths {
public:
  // Held while creating, filling or renaming a temporary path; after
  // abandon(), never returns.
  std::unique_lock<std::mutex> hold() { return std::unique_lock<std::mutex>(mutex_); }
  // Both under hold().
  void add(const std::string& path) { paths_.push_back(path); }
  void erase(const std::string& path);
  // Removes every registered path (files, and directories with what they
  // hold) and keeps the lock: for a process about to exit.
  void abandon();

private:
  std::mutex mutex_;
  std::vector<std::string> paths_;
};

}  // namespace molecule
