// SPDX-License-Identifier: Apache-2.0
#include "util/atomic_file.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "alpha/error.hpp"

namespace molecule {
namespace {

namespace fs = std::filesystem;

// The directory that will hold path.
fs::path directory_of(const std::string& path) {
  const fs::path dir = fs::path(path).parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

[[noreturn]] void fail_to_create(const std::string& path, int err, alpha::ErrorKind kind) {
  alpha::fail(path + ": cannot create a file in " + directory_of(path).string() + ": " + std::strerror(err), kind);
}

}  // namespace

void check_can_create(const std::string& path) {
  const fs::path dir = directory_of(path);
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0) fail_to_create(path, errno, alpha::ErrorKind::BadInput);
  if (!S_ISDIR(st.st_mode)) fail_to_create(path, ENOTDIR, alpha::ErrorKind::BadInput);
  if (::access(dir.c_str(), W_OK | X_OK) != 0) fail_to_create(path, errno, alpha::ErrorKind::BadInput);
}

TemporaryFile::TemporaryFile(const std::string& target, TemporaryPaths* temporaries)
    : target_(target), temporaries_(temporaries) {
  const auto lock = hold();
  const fs::path p(target);
  const fs::path dir = directory_of(target);
  std::random_device rd;
  std::mt19937_64 rng((std::uint64_t(rd()) << 32) ^ rd() ^ std::uint64_t(::getpid()));
  for (int attempt = 0; attempt < 100; ++attempt) {
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, ".%012llx.tmp", (unsigned long long)(rng() & 0xffffffffffffULL));
    std::string name = ".";  // appended, not "." + ...: GCC 12 warns wrongly (-Wrestrict) on that
    name += p.filename().string();
    name += suffix;
    const fs::path candidate = dir / name;
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      path_ = candidate.string();
      if (temporaries_) temporaries_->add(path_);
      return;
    }
    if (errno != EEXIST) fail_to_create(target, errno, alpha::ErrorKind::BadInput);
  }
  alpha::fail(target + ": cannot create a temporary file in " + dir.string(), alpha::ErrorKind::BadInput);
}

TemporaryFile::~TemporaryFile() {
  if (path_.empty()) return;
  const auto lock = hold();
  ::unlink(path_.c_str());
  if (temporaries_) temporaries_->erase(path_);
}

std::unique_lock<std::mutex> TemporaryFile::hold() const {
  return temporaries_ ? temporaries_->hold() : std::unique_lock<std::mutex>();
}

// No fsync: rename already keeps readers and crashed runs from seeing half a
// file, and a flush per file would dominate batch runs writing dozens each.
void TemporaryFile::commit() {
  const auto lock = hold();
  if (::rename(path_.c_str(), target_.c_str()) != 0)
    alpha::fail(target_ + ": cannot create: " + std::strerror(errno), alpha::ErrorKind::BadInput);
  if (temporaries_) temporaries_->erase(path_);
  path_.clear();
}

namespace {

// The content in tmp, the temporary file of path (not yet renamed).
void fill(const TemporaryFile& tmp, const std::string& path, std::string_view content) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) alpha::fail(path + ": is a directory", alpha::ErrorKind::BadInput);
  std::ofstream out(tmp.path(), std::ios::binary | std::ios::trunc);
  if (!out)
    alpha::fail(path + ": cannot write " + tmp.path() + ": " + std::strerror(errno), alpha::ErrorKind::BadInput);
  out.write(content.data(), std::streamsize(content.size()));
  out.close();
  if (out.fail()) alpha::fail(path + ": write error: " + std::strerror(errno), alpha::ErrorKind::BadInput);
}

}  // namespace

void write_file_atomically(const std::string& path, std::string_view content) {
  TemporaryFile tmp(path);
  fill(tmp, path, content);
  tmp.commit();
}

}  // namespace molecule
