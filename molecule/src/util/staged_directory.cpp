// SPDX-License-Identifier: Apache-2.0
#include "util/staged_directory.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "alpha/error.hpp"

namespace molecule {

namespace fs = std::filesystem;

namespace {

// An flock'd descriptor of directory `dir`, or -1 when another process
// holds it (or it cannot be opened: errno says).
int lock_directory(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return -1;
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd);
    errno = err;
    return -1;
  }
  return fd;
}

bool exists_no_follow(const fs::path& p) {
  struct stat st {};
  return ::lstat(p.c_str(), &st) == 0;
}

}  // namespace

StagedDirectory::StagedDirectory(const fs::path& target, const std::string& name, TemporaryPaths* temporaries)
    : target_(target), name_(name), temporaries_(temporaries) {
  sibling_ = target_.parent_path() / ("." + target_.filename().string() + ".alphapocket-new");
  const auto lock = hold();
  if (exists_no_follow(sibling_)) {  // left by a killed run, or in use by a live one
    const int fd = lock_directory(sibling_);
    if (fd < 0 && errno == EWOULDBLOCK)
      alpha::fail(name_ + ": another alphapocket run is writing it (" + sibling_.string() + " is in use)",
                  alpha::ErrorKind::BadInput);
    if (fd >= 0) ::close(fd);
    std::error_code ec;
    fs::remove_all(sibling_, ec);
  }
  if (::mkdir(sibling_.c_str(), 0777) != 0)
    alpha::fail(name_ + ": cannot create " + sibling_.string() + ": " + std::strerror(errno),
                alpha::ErrorKind::BadInput);
  if (temporaries_) temporaries_->add(sibling_.string());
  lock_fd_ = lock_directory(sibling_);
  if (lock_fd_ < 0)
    alpha::fail(name_ + ": another alphapocket run is writing it (" + sibling_.string() + " is in use)",
                alpha::ErrorKind::BadInput);
}

StagedDirectory::~StagedDirectory() {
  if (!committed_) {
    const auto lock = hold();
    remove_sibling();
  }
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

std::unique_lock<std::mutex> StagedDirectory::hold() const {
  return temporaries_ ? temporaries_->hold() : std::unique_lock<std::mutex>();
}

void StagedDirectory::remove_sibling() {
  std::error_code ec;
  fs::remove_all(sibling_, ec);
  if (temporaries_) temporaries_->erase(sibling_.string());
}

namespace {

// `dir`/`file` with its directory made; `name` as StagedDirectory's.
fs::path made_path(const fs::path& dir, const std::string& file, const std::string& name) {
  const fs::path path = dir / file;
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  if (ec)
    alpha::fail(name + ": cannot create " + path.parent_path().string() + ": " + ec.message(),
                alpha::ErrorKind::BadInput);
  return path;
}

}  // namespace

void StagedDirectory::write(const std::string& file, std::string_view content) {
  const auto lock = hold();
  const fs::path path = made_path(sibling_, file, name_);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out)
    alpha::fail(name_ + ": cannot write " + path.string() + ": " + std::strerror(errno), alpha::ErrorKind::BadInput);
  out.write(content.data(), std::streamsize(content.size()));
  out.close();
  if (out.fail())
    alpha::fail(name_ + ": cannot write " + path.string() + ": " + std::strerror(errno), alpha::ErrorKind::BadInput);
}

void StagedDirectory::copy(const std::string& file, const fs::path& source) {
  const auto lock = hold();
  const fs::path path = made_path(sibling_, file, name_);
  std::error_code ec;
  fs::copy_file(source, path, ec);
  if (ec)
    alpha::fail(name_ + ": cannot copy " + source.string() + " to " + path.string() + ": " + ec.message(),
                alpha::ErrorKind::BadInput);
}

void StagedDirectory::commit() {
  const auto lock = hold();
  const auto fail_errno = [&](const std::string& what, alpha::ErrorKind kind) {
    alpha::fail(name_ + ": cannot " + what + ": " + std::strerror(errno), kind);
  };
  if (!exists_no_follow(target_)) {
    if (::rename(sibling_.c_str(), target_.c_str()) != 0) fail_errno("create it", alpha::ErrorKind::BadInput);
  } else {
    const int target_fd = lock_directory(target_);  // the earlier run, at sibling_ after the swap
    if (target_fd < 0 && errno == EWOULDBLOCK)
      alpha::fail(name_ + ": another alphapocket run is writing it", alpha::ErrorKind::BadInput);
    struct Close {
      int fd;
      ~Close() {
        if (fd >= 0) ::close(fd);
      }
    } close_target{target_fd};
    if (::renameat2(AT_FDCWD, sibling_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0) {
      if (errno != EINVAL && errno != ENOSYS && errno != EOPNOTSUPP)
        fail_errno("replace it", alpha::ErrorKind::BadInput);
      // No exchange on this file system: the earlier directory moves aside
      // first.
      const fs::path old = target_.parent_path() / ("." + target_.filename().string() + ".alphapocket-old");
      std::error_code ec;
      fs::remove_all(old, ec);
      if (temporaries_) temporaries_->add(old.string());
      if (::rename(target_.c_str(), old.c_str()) != 0) fail_errno("move it aside", alpha::ErrorKind::BadInput);
      if (::rename(sibling_.c_str(), target_.c_str()) != 0) {
        const int err = errno;
        ::rename(old.c_str(), target_.c_str());  // back in place
        errno = err;
        fail_errno("replace it", alpha::ErrorKind::BadInput);
      }
      fs::remove_all(old, ec);
      if (temporaries_) temporaries_->erase(old.string());
    }
  }
  committed_ = true;
  remove_sibling();  // the earlier directory, after an exchange
}

}  // namespace molecule
