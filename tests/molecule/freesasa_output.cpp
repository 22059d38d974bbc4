// SPDX-License-Identifier: Apache-2.0
#include "freesasa_output.hpp"

#include <catch2/catch.hpp>

#include <cstdio>

namespace {

std::string trim(std::string s) {
  s.erase(0, s.find_first_not_of(' '));
  s.erase(s.find_last_not_of(' ') + 1);
  return s;
}

}  // namespace

std::vector<FreesasaAtom> run_freesasa(const std::string& freesasa, const std::string& file,
                                       const std::string& flags) {
  const std::string cmd = freesasa + " " + flags + " --format=pdb '" + file + "' 2>/dev/null";
  FILE* pipe = ::popen(cmd.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::vector<FreesasaAtom> atoms;
  char buf[256];
  while (std::fgets(buf, sizeof buf, pipe)) {
    const std::string line = buf;
    if (line.rfind("ATOM  ", 0) != 0 && line.rfind("HETATM", 0) != 0) continue;
    REQUIRE(line.size() >= 66);
    atoms.push_back({trim(line.substr(21, 1)), trim(line.substr(17, 3)), std::stoi(line.substr(22, 4)),
                     trim(line.substr(12, 4)), std::stod(line.substr(54, 6)), std::stod(line.substr(60, 6))});
  }
  REQUIRE(::pclose(pipe) == 0);
  return atoms;
}
