// SPDX-License-Identifier: Apache-2.0
// Point files: plain text, one point per line.
//
//   # comment (also after the numbers on a line); blank lines are skipped
//   x y z        unweighted input
//   x y z r      weighted input: a ball of radius r >= 0, weight r^2
//
// Numbers are read strictly: whole tokens only, no NaN or infinity, and
// |value| <= 1e15 (the range the triangulation accepts). Every error names
// the file, and the line when there is one, e.g. "points.xyz:12: expected 3
// numbers, got 2".
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "alpha/geometry.hpp"

namespace alphapocket {

struct PointSet {
  std::vector<alpha::Vec3> points;
  std::vector<double> weights;  // r^2 per point; empty for unweighted input
};

// Reads a point file; throws alpha::Error (BadInput) naming the file on any error
// (missing, a directory, empty, no points, a malformed line).
PointSet read_point_file(const std::string& path, bool weighted);

// Parses the text of a point file; `name` is used in error messages.
PointSet parse_points(std::string_view text, const std::string& name, bool weighted);

}  // namespace alphapocket
