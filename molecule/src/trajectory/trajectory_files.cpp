// SPDX-License-Identifier: Apache-2.0
// Which reader reads a trajectory file: by its extension.
#include "alpha/error.hpp"
#include "trajectory/coordinate_reader.hpp"

namespace molecule {

#ifdef ALPHAPOCKET_GROMACS
std::unique_ptr<CoordinateReader> open_gromacs(const std::string& path);  // gromacs_reader.cpp
#endif

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool is_gromacs(const std::string& path) { return ends_with(path, ".xtc") || ends_with(path, ".trr"); }

}  // namespace

bool is_trajectory_file(const std::string& path) {
#ifdef ALPHAPOCKET_GROMACS
  if (is_gromacs(path)) return true;
#endif
  return ends_with(path, ".dcd");
}

std::unique_ptr<CoordinateReader> open_trajectory(const std::string& path) {
  if (ends_with(path, ".dcd")) return open_dcd(path);
#ifdef ALPHAPOCKET_GROMACS
  if (is_gromacs(path)) return open_gromacs(path);
#else
  if (is_gromacs(path))
    throw alpha::Error(path + ": XTC and TRR need a build with libgromacs (Debian: libgromacs-dev)",
                       alpha::ErrorKind::Misuse);
#endif
  throw alpha::Error(path + ": not a trajectory file (.dcd, .xtc, .trr) nor a structure file", alpha::ErrorKind::BadInput);
}

}  // namespace molecule
