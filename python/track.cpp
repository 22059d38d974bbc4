// SPDX-License-Identifier: Apache-2.0
// alphapocket._core.track_frames: molecule::track over frames that a Python
// iterator yields as (time, coordinates) pairs, pulled one at a time while
// the frames are analysed (the GIL taken only to pull one), so that memory
// holds only the frames in flight, as for the command line's files.
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "alpha/error.hpp"
#include "molecule/track.hpp"
#include "trajectory/track_outputs.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace alphapocket_python {
namespace {

// The next (time in ps or None, coordinates (N, 3) in A) of `frames`,
// nothing at its end.
std::optional<molecule::TimedCoordinates> next_frame(py::iterator& frames) {
  py::gil_scoped_acquire gil;
  if (frames == py::iterator::sentinel()) return std::nullopt;
  const py::tuple item = py::reinterpret_borrow<py::object>(*frames).cast<py::tuple>();
  ++frames;
  if (item.size() != 2) throw alpha::Error("a frame is not a (time, coordinates) pair", alpha::ErrorKind::Misuse);
  const Points xyz = item[1].cast<Points>();
  if (xyz.ndim() != 2 || xyz.shape(1) != 3)
    throw alpha::Error("a frame's coordinates: expected an array of shape (atoms, 3)", alpha::ErrorKind::Misuse);
  molecule::TimedCoordinates c;
  if (!item[0].is_none()) c.time = item[0].cast<double>();
  c.x.resize(xyz.shape(0));
  const auto r = xyz.unchecked<2>();
  for (py::ssize_t i = 0; i < xyz.shape(0); ++i) c.x[i] = {r(i, 0), r(i, 1), r(i, 2)};
  return c;
}

// `topology`: a structure file (PDB, mmCIF, GROMACS .gro) holding every
// atom of the frames, in their order.
std::shared_ptr<molecule::TrackResult> track_frames(const std::string& topology, const py::iterable& frames,
                                                    const py::dict& options) {
  molecule::TrackOptions o;
  o.analysis = analysis_options(options);
  o.jobs = o.analysis.cavities.threads;
  o.begin = options["begin"].cast<std::size_t>();
  if (!options["end"].is_none()) o.end = options["end"].cast<std::size_t>();
  o.stride = options["stride"].cast<std::size_t>();
  o.grid_spacing = options["grid_spacing"].cast<double>();
  o.min_lining_overlap = options["overlap"].cast<double>();
  py::iterator it = py::iter(frames);
  py::gil_scoped_release release;
  molecule::Structure structure = molecule::read_topology(topology, o.analysis.structure);
  const auto source = molecule::frames_from_function(std::move(structure), [&it] { return next_frame(it); });
  return std::make_shared<molecule::TrackResult>(molecule::track(*source, o));
}

// track()'s own defaults, by the CLI's names, from molecule::TrackOptions.
py::dict track_defaults() {
  const molecule::TrackOptions o;
  py::dict d;
  d["begin"] = o.begin;
  d["end"] = py::none();
  d["stride"] = o.stride;
  d["grid_spacing"] = o.grid_spacing;
  d["overlap"] = o.min_lining_overlap;
  return d;
}

// A grid's values as an (nx, ny, nz) array.
py::array_t<float> grid_array(const molecule::SpaceGrid& g, const std::vector<float>& values) {
  py::array_t<float> out({py::ssize_t(g.nx), py::ssize_t(g.ny), py::ssize_t(g.nz)});
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

}  // namespace

void add_track(py::module_& m) {
  py::class_<molecule::TrackResult, std::shared_ptr<molecule::TrackResult>>(m, "TrackResult")
      .def("files", [](const molecule::TrackResult& r) { return molecule::track_output_files(r); })
      .def("frequency", [](const molecule::TrackResult& r) { return grid_array(r.grid, r.frequency); })
      .def("density", [](const molecule::TrackResult& r) { return grid_array(r.grid, r.density); })
      .def_property_readonly("origin",
                             [](const molecule::TrackResult& r) {
                               return std::array<double, 3>{r.grid.origin.x, r.grid.origin.y, r.grid.origin.z};
                             })
      .def_property_readonly("spacing", [](const molecule::TrackResult& r) { return r.grid.spacing; });
  m.def("track_frames", &track_frames);
  m.def("track_defaults", &track_defaults);
}

}  // namespace alphapocket_python
