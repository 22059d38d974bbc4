// SPDX-License-Identifier: Apache-2.0
// Trajectory files: one frame of coordinates after another, every atom of
// the system in the file's order. CHARMM/NAMD DCD is read here (a few
// Fortran records); GROMACS XTC and TRR through libgromacs when the build
// has it. Errors throw alpha::Error (bad input) with one line naming the
// file and, past the header, the frame.
#pragma once
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "alpha/geometry.hpp"

namespace molecule {

struct CoordinateFrame {
  double time = 0;                  // ps
  std::vector<alpha::Vec3> x;       // A, in the file's atom order
};

class CoordinateReader {
public:
  virtual ~CoordinateReader() = default;
  virtual std::size_t atoms() const = 0;
  // Nothing at the end of the file.
  virtual std::optional<CoordinateFrame> next() = 0;
};

// Whether a file name is a trajectory this build reads (.dcd; .xtc, .trr with libgromacs).
bool is_trajectory_file(const std::string& path);

// By the file name's extension.
std::unique_ptr<CoordinateReader> open_trajectory(const std::string& path);

std::unique_ptr<CoordinateReader> open_dcd(const std::string& path);

}  // namespace molecule
