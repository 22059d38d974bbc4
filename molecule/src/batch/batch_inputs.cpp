// SPDX-License-Identifier: Apache-2.0
#include "batch/batch_inputs.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "alpha/error.hpp"
#include "molecule/structure.hpp"
#include "structure/structure_id.hpp"

namespace molecule {
namespace {

namespace fs = std::filesystem;

std::string trimmed(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return {};
  return s.substr(begin, s.find_last_not_of(" \t\r") + 1 - begin);
}

void add_directory(const fs::path& dir, std::vector<std::string>& out) {
  std::error_code ec;
  std::vector<std::string> found;
  fs::recursive_directory_iterator it(dir, fs::directory_options::follow_directory_symlink, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    std::error_code type;
    if (it->is_regular_file(type) && is_structure_file(it->path().filename().string()))
      found.push_back(it->path().lexically_normal().string());
  }
  if (ec) alpha::fail(dir.string() + ": cannot search the directory: " + ec.message(), alpha::ErrorKind::BadInput);
  std::sort(found.begin(), found.end());
  out.insert(out.end(), found.begin(), found.end());
}

}  // namespace

std::vector<std::string> read_path_list(std::istream& in, const std::string& name, bool dataset,
                                        const std::string& base_dir) {
  std::vector<std::string> out;
  std::string line;
  while (std::getline(in, line)) {
    line = trimmed(line.substr(0, line.find('#')));
    if (line.empty()) continue;
    if (dataset) {
      if (line.rfind("HEADER:", 0) == 0) continue;
      line = line.substr(0, line.find_first_of(" \t"));
    }
    fs::path p(line);
    if (p.is_relative() && !base_dir.empty()) p = fs::path(base_dir) / p;
    out.push_back(p.lexically_normal().string());
  }
  if (in.bad()) alpha::fail(name + ": cannot read the list", alpha::ErrorKind::BadInput);
  return out;
}

std::vector<std::string> read_path_list_file(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec))
    alpha::fail(path + ": is a directory, not a list of paths", alpha::ErrorKind::BadInput);
  std::ifstream in(path);
  if (!in) alpha::fail(path + ": cannot open the list", alpha::ErrorKind::BadInput);
  const bool dataset = fs::path(path).extension() == ".ds";
  const std::string base = dataset ? fs::path(path).parent_path().string() : std::string();
  return read_path_list(in, path, dataset, base);
}

std::vector<BatchInput> batch_inputs(const std::vector<std::string>& paths) {
  std::vector<std::string> files;
  for (const std::string& path : paths) {
    std::error_code ec;
    if (fs::is_directory(path, ec))
      add_directory(path, files);
    else if (is_structure_file(path))
      files.push_back(fs::path(path).lexically_normal().string());
    else
      alpha::fail(path + (fs::exists(path, ec) ? ": not a structure file (.pdb .ent .cif .mmcif, optionally .gz)"
                                               : ": no such file or directory"),
                  alpha::ErrorKind::BadInput);
  }
  std::vector<BatchInput> out;
  for (std::string& f : files) out.push_back({structure_id(f), std::move(f)});
  std::sort(out.begin(), out.end(),
            [](const BatchInput& a, const BatchInput& b) { return std::tie(a.id, a.path) < std::tie(b.id, b.path); });
  out.erase(std::unique(out.begin(), out.end(),
                        [](const BatchInput& a, const BatchInput& b) { return a.id == b.id && a.path == b.path; }),
            out.end());
  for (std::size_t i = 1; i < out.size(); ++i)
    if (out[i].id == out[i - 1].id)
      alpha::fail("two inputs with the structure id '" + out[i].id + "': " + out[i - 1].path + " and " + out[i].path,
                  alpha::ErrorKind::BadInput);
  return out;
}

}  // namespace molecule
