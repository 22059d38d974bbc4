// SPDX-License-Identifier: Apache-2.0
#include "molecule/surface.hpp"

#include <chrono>
#include <cmath>
#include <string>
#include <utility>

#include "alpha/eroded_union.hpp"
#include "alpha/error.hpp"
#include "alpha/point_set_complex.hpp"
#include "alpha/triangulation.hpp"
#include "alpha/union_of_balls.hpp"
#include "molecule/atom_balls.hpp"

namespace molecule {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// erode >= 0: the MS surface too, the union eroded by that probe; per_atom: its per-atom split.
Surface measured(std::vector<alpha::Vec3> points, std::vector<double> weights, std::optional<double> erode,
                 bool per_atom = false) {
  if (points.size() != weights.size())
    alpha::fail("surface: " + std::to_string(weights.size()) + " weights for " + std::to_string(points.size()) +
                    " balls",
                alpha::ErrorKind::Misuse);
  if (points.empty()) alpha::fail("surface: no balls", alpha::ErrorKind::BadInput);
  Surface s;
  s.balls = points.size();
  auto start = std::chrono::steady_clock::now();
  // Any set of balls has a union, but a triangulation needs four points
  // not in one plane: far points make a small or flat molecule one.
  if (alpha::affine_dimension(points) < 3) alpha::add_far_points(points, weights);
  const alpha::PointSetComplex shape(std::move(points), std::move(weights));
  s.complex_seconds = seconds_since(start);
  start = std::chrono::steady_clock::now();
  const alpha::UnionOfBalls u(shape.complex());
  s.union_seconds = seconds_since(start);
  s.hidden = shape.triangulation().num_hidden();
  s.sa_area = u.area();
  s.sa_volume = u.volume();
  const auto areas = u.ball_areas();
  s.ball_areas.assign(areas.begin(), areas.begin() + s.balls);  // not the far points
  const auto volumes = u.ball_volumes();
  s.ball_volumes.assign(volumes.begin(), volumes.begin() + s.balls);
  if (erode) {
    start = std::chrono::steady_clock::now();
    const alpha::ErodedUnion eroded(u, *erode);
    std::vector<alpha::LayerShare> shares;
    const alpha::LayerShare layer = per_atom ? eroded.layer(shares) : eroded.layer();
    s.ms_volume = u.volume() - layer.volume;
    s.ms_area = layer.area;
    if (per_atom)
      for (std::size_t i = 0; i < s.balls; ++i) {
        s.ms_ball_volumes.push_back(volumes[i] - shares[i].volume);
        s.ms_ball_areas.push_back(shares[i].area);
      }
    s.excluded_seconds = seconds_since(start);
  }
  return s;
}

}  // namespace

Surface measure_surface(const std::vector<Atom>& atoms, const SurfaceOptions& options) {
  if (!(options.probe >= 0) || !std::isfinite(options.probe))
    alpha::fail("surface: the probe must be a number >= 0", alpha::ErrorKind::Misuse);
  AtomBalls balls = atom_balls(atoms, options.probe);
  return measured(std::move(balls.points), std::move(balls.weights),
                  options.excluded ? std::optional<double>(options.probe) : std::nullopt,
                  options.excluded && options.excluded_per_atom);
}

Surface measure_balls(std::vector<alpha::Vec3> centres, std::vector<double> weights) {
  return measured(std::move(centres), std::move(weights), std::nullopt);
}

namespace {

Surface measure_named(const std::string& name, const Structure& structure, const SurfaceOptions& options) {
  try {
    return measure_surface(structure.atoms, options);
  } catch (const alpha::Error& e) {
    throw alpha::in_file(name, e);
  }
}

}  // namespace

Surface surface_of_file(const std::string& path, const StructureOptions& selection, const SurfaceOptions& options) {
  return measure_named(path, read_structure(path, selection), options);
}

Surface surface_of_content(const std::string& name, std::string_view content, const StructureOptions& selection,
                           const SurfaceOptions& options) {
  return measure_named(name, parse_structure(content, name, selection), options);
}

}  // namespace molecule
