// SPDX-License-Identifier: Apache-2.0
#include "alpha/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "alpha/error.hpp"

namespace alpha {

std::string read_input_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st))
    fail(path + ": cannot open: " +
             (ec && ec != std::errc::no_such_file_or_directory ? ec.message() : std::string("no such file")),
         ErrorKind::BadInput);
  if (fs::is_directory(st)) fail(path + ": is a directory, not a file", ErrorKind::BadInput);
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path + ": cannot open: " + std::strerror(errno), ErrorKind::BadInput);
  std::ostringstream buf;
  buf << in.rdbuf();
  if (in.bad()) fail(path + ": read error", ErrorKind::BadInput);
  std::string text = std::move(buf).str();
  // Checked after reading: a pipe's size is only known once read.
  if (text.empty()) fail(path + ": file is empty", ErrorKind::BadInput);
  return text;
}

}  // namespace alpha
