// SPDX-License-Identifier: Apache-2.0
// The compiled half of the Python package `alphapocket` (alphapocket/_core):
// thin bindings of molecule::analyse, molecule::measure_surface and
// alpha::AlphaComplex (molecule::track: track.cpp). The Python half (alphapocket/__init__.py) turns the
// report into objects and adapts gemmi structures. Every long call releases
// the GIL; alpha::Error becomes the exception of its kind (BadInputError,
// LimitExceededError, MisuseError, all alphapocket.Error) with the CLI's
// message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/error.hpp"
#include "alpha/point_set_complex.hpp"
#include "alphapocket/version.hpp"
#include "molecule/analysis.hpp"
#include "molecule/output_selection.hpp"
#include "molecule/radii.hpp"
#include "molecule/site_features.hpp"
#include "molecule/surface.hpp"
#include "bindings.hpp"

namespace py = pybind11;
using alphapocket_python::Points;

namespace {

std::vector<alpha::Vec3> points_of(const Points& a) {
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw alpha::Error("points: expected an array of shape (N, 3)", alpha::ErrorKind::Misuse);
  std::vector<alpha::Vec3> p(a.shape(0));
  const auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) p[i] = {r(i, 0), r(i, 1), r(i, 2)};
  return p;
}

std::vector<double> values_of(const Points& a, std::size_t n, const char* what) {
  if (a.ndim() != 1 || std::size_t(a.shape(0)) != n)
    throw alpha::Error(std::string(what) + ": expected " + std::to_string(n) + " values, one per point",
                       alpha::ErrorKind::Misuse);
  return {a.data(), a.data() + n};
}

py::array_t<double> array_of(const std::vector<double>& v) { return py::array_t<double>(v.size(), v.data()); }

// --max-input-mb: structure files above it (after gzip decompression) are
// refused (LimitExceededError).
std::size_t max_input_mib(const py::dict& o) {
  const long long mib = o["max_input_mb"].cast<long long>();
  if (mib < 1 || mib > (1 << 20))
    throw alpha::Error("max_input_mb: " + std::to_string(mib) + " is not in 1..1048576", alpha::ErrorKind::Misuse);
  return std::size_t(mib);
}


// analyze()'s defaults, by the CLI's names, read from the C++ option
// structs (and the CLI's default output list), so that the library, the
// CLI and Python cannot disagree.
py::dict analysis_defaults() {
  const molecule::AnalysisOptions a;
  py::dict d;
  d["probe"] = a.cavities.probe;
  d["min_volume"] = a.cavities.min_volume;
  d["model"] = a.structure.model;
  d["chains"] = py::list(py::cast(a.structure.chains));
  d["keep_hydrogens"] = a.structure.keep_hydrogens;
  d["keep_waters"] = a.structure.keep_waters;
  d["keep_hetero"] = a.structure.keep_hetero;
  d["keep_cofactors"] = a.structure.keep_cofactors;
  d["min_plddt"] = a.structure.min_plddt;
  d["radii"] = a.radii_file;
  d["tunnels_from"] = a.tunnels_from;
  d["tunnel_probe"] = a.tunnels.probe;
  d["pores"] = a.tunnels.pores;
  d["mesh"] = a.mesh_format;
  d["outputs"] = molecule::output_list(a.outputs);
  d["ranking"] = a.ranking == molecule::SiteRanking::probability ? "probability" : "geometric";
  d["max_input_mb"] = a.structure.max_input_mib;
  d["threads"] = a.cavities.threads;
  return d;
}

// surface()'s own defaults, read from molecule::SurfaceOptions (its atom
// selection is analyze()'s).
py::dict surface_defaults() {
  const molecule::SurfaceOptions o;
  py::dict d;
  d["probe"] = o.probe;
  d["excluded"] = o.excluded;
  return d;
}

using Analysis = std::shared_ptr<const molecule::Analysis>;

Analysis analyse_path(const std::string& path, const py::dict& options) {
  molecule::AnalysisOptions o = alphapocket_python::analysis_options(options);
  py::gil_scoped_release release;
  return std::make_shared<const molecule::Analysis>(molecule::analyse(path, o));
}

// A structure file's text (e.g. gemmi's mmCIF of a gemmi.Structure), read
// as the file would be.
Analysis analyse_text(const std::string& name, const std::string& text, const py::dict& options) {
  molecule::AnalysisOptions o = alphapocket_python::analysis_options(options);
  py::gil_scoped_release release;
  return std::make_shared<const molecule::Analysis>(molecule::analyse_content(name, text, o));
}

// Atoms from arrays: radii given, or ProtOr radii from residue, atom names
// and elements.
molecule::Structure structure_of(const Points& xyz, const std::optional<Points>& radii, const py::dict& names) {
  const std::vector<alpha::Vec3> p = points_of(xyz);
  const auto column = [&](const char* key, const std::string& fallback) {
    std::vector<std::string> c(p.size(), fallback);
    if (names.contains(key) && !names[key].is_none()) c = names[key].cast<std::vector<std::string>>();
    if (c.size() != p.size())
      throw alpha::Error(std::string(key) + ": expected " + std::to_string(p.size()) + " values, one per atom",
                         alpha::ErrorKind::Misuse);
    return c;
  };
  const auto atom_names = column("atom_names", "X"), residue_names = column("residue_names", "UNK"),
             elements = column("elements", "X"), chains = column("chains", "A");
  std::vector<int> seq(p.size(), 1);
  if (names.contains("residue_numbers") && !names["residue_numbers"].is_none())
    seq = names["residue_numbers"].cast<std::vector<int>>();
  if (seq.size() != p.size()) throw alpha::Error("residue_numbers: expected one per atom", alpha::ErrorKind::Misuse);
  const std::vector<double> r = radii ? values_of(*radii, p.size(), "radii") : std::vector<double>();
  molecule::Structure s;
  for (std::size_t i = 0; i < p.size(); ++i) {
    molecule::Atom a;
    a.serial = int(i + 1);
    a.name = atom_names[i];
    a.residue_name = residue_names[i];
    a.element = elements[i];
    a.chain = chains[i];
    a.seq_num = seq[i];
    a.position = p[i];
    a.radius = radii ? r[i] : molecule::radius(a.residue_name, a.name, a.element);
    s.atoms.push_back(std::move(a));
  }
  s.report.format = "arrays";
  s.report.models = 1;
  s.report.model = 1;
  s.report.atoms_in_model = s.report.kept = s.atoms.size();
  return s;
}

Analysis analyse_arrays(const std::string& name, const Points& xyz, const std::optional<Points>& radii,
                        const py::dict& names, const py::dict& options) {
  molecule::AnalysisOptions o = alphapocket_python::analysis_options(options);
  molecule::Structure s = structure_of(xyz, radii, names);
  py::gil_scoped_release release;
  return std::make_shared<const molecule::Analysis>(molecule::analyse_structure(name, std::move(s), o));
}

// The atom selection of `alphapocket surface` (one atom is enough).
molecule::StructureOptions surface_selection(const py::dict& selection) {
  molecule::StructureOptions so;
  so.model = selection["model"].cast<int>();
  so.chains = selection["chains"].cast<std::vector<std::string>>();
  so.keep_hydrogens = selection["keep_hydrogens"].cast<bool>();
  so.keep_waters = selection["keep_waters"].cast<bool>();
  so.keep_hetero = selection["keep_hetero"].cast<bool>();
  so.keep_hetero_codes = selection["keep_hetero_codes"].cast<std::vector<std::string>>();
  so.keep_cofactors = selection["keep_cofactors"].cast<bool>();
  so.max_input_mib = max_input_mib(selection);
  so.min_atoms = 1;
  return so;
}

py::dict surface_dict(const molecule::Surface& s) {
  py::dict d;
  d["atoms"] = s.balls;
  d["sa_area"] = s.sa_area;
  d["sa_volume"] = s.sa_volume;
  d["ms_area"] = s.ms_area ? py::cast(*s.ms_area) : py::none();
  d["ms_volume"] = s.ms_volume ? py::cast(*s.ms_volume) : py::none();
  d["atom_areas"] = array_of(s.ball_areas);
  d["atom_volumes"] = array_of(s.ball_volumes);
  const bool per_atom = !s.ms_ball_areas.empty();
  d["ms_atom_areas"] = per_atom ? py::object(array_of(s.ms_ball_areas)) : py::object(py::none());
  d["ms_atom_volumes"] = per_atom ? py::object(array_of(s.ms_ball_volumes)) : py::object(py::none());
  return d;
}

// The triangulation and its complex (alpha::PointSetComplex). threads > 1 builds both on threads (2^15 points or
// more): the triangulation's cells are numbered otherwise, so shape_mesh
// lists the same faces in another order; everything else is the same.
class PyAlphaComplex {
public:
  PyAlphaComplex(const Points& points, const std::optional<Points>& weights, unsigned threads) {
    std::vector<alpha::Vec3> p = points_of(points);
    std::vector<double> w = weights ? values_of(*weights, p.size(), "weights") : std::vector<double>();
    if (threads < 1) throw py::value_error("threads must be at least 1");
    py::gil_scoped_release release;
    shape_ = std::make_unique<alpha::PointSetComplex>(std::move(p), std::move(w), threads);
  }

  // Every loop over the complex runs without the GIL (a spectrum of 10^5
  // values takes a second); only the copy into numpy holds it.
  py::array_t<double> spectrum() const {
    std::vector<double> v(complex().spectrum_size());
    {
      py::gil_scoped_release release;
      std::vector<alpha::Index> ranks(v.size());
      std::iota(ranks.begin(), ranks.end(), alpha::Index(0));
      complex().spectrum_values(ranks, v);
    }
    return array_of(v);
  }

  // Counts per dimension (rows: vertices, edges, triangles, tetrahedra) and
  // class (columns: exterior, singular, regular, interior).
  py::array_t<std::int64_t> classify(double alpha_sq) const {
    alpha::ClassCounts c;
    {
      py::gil_scoped_release release;
      c = complex().counts(complex().level(alpha_sq));
    }
    py::array_t<std::int64_t> out({4, 4});
    auto m = out.mutable_unchecked<2>();
    for (int d = 0; d < 4; ++d)
      for (int k = 0; k < 4; ++k) m(d, k) = std::int64_t(c[d][k]);
    return out;
  }

  std::array<std::size_t, 3> betti(double alpha_sq) const {
    const alpha::Index level = complex().level(alpha_sq);
    py::gil_scoped_release release;
    return complex().betti(level);
  }

  // Rows (dim, birth alpha_sq, death alpha_sq), death inf for classes that
  // never die.
  py::array_t<double> persistence() const {
    std::vector<double> rows;
    {
      py::gil_scoped_release release;
      const std::vector<alpha::PersistencePair>& pairs = complex().persistence();
      std::vector<alpha::Index> ranks;
      for (const alpha::PersistencePair& p : pairs) {
        ranks.push_back(p.birth);
        if (p.death != alpha::kNever) ranks.push_back(p.death);
      }
      std::vector<double> values(ranks.size());
      complex().spectrum_values(ranks, values);
      rows.reserve(3 * pairs.size());
      std::size_t next = 0;
      for (const alpha::PersistencePair& p : pairs) {
        rows.push_back(p.dim);
        rows.push_back(values[next++]);
        rows.push_back(p.death == alpha::kNever ? INFINITY : values[next++]);
      }
    }
    py::array_t<double> out({py::ssize_t(rows.size() / 3), py::ssize_t(3)});
    std::copy(rows.begin(), rows.end(), out.mutable_data());
    return out;
  }

  // The shape's boundary at alpha_sq: (vertices (V, 3), faces (F, 3) outward).
  py::tuple shape_mesh(double alpha_sq) const {
    alpha::ShapeBoundary b;
    {
      py::gil_scoped_release release;
      b = complex().boundary(complex().level(alpha_sq));
    }
    const auto points = shape_->triangulation().points();
    py::array_t<double> v({py::ssize_t(points.size()), py::ssize_t(3)});
    auto mv = v.mutable_unchecked<2>();
    for (std::size_t i = 0; i < points.size(); ++i) mv(i, 0) = points[i].x, mv(i, 1) = points[i].y, mv(i, 2) = points[i].z;
    py::array_t<std::int64_t> f({py::ssize_t(b.triangles.size()), py::ssize_t(3)});
    auto mf = f.mutable_unchecked<2>();
    for (std::size_t i = 0; i < b.triangles.size(); ++i)
      for (int k = 0; k < 3; ++k) mf(i, k) = b.triangles[i][k];
    return py::make_tuple(v, f);
  }

  std::size_t num_points() const { return shape_->triangulation().num_points(); }

private:
  const alpha::AlphaComplex& complex() const { return shape_->complex(); }

  std::unique_ptr<const alpha::PointSetComplex> shape_;  // built without the GIL
};

}  // namespace

namespace alphapocket_python {

molecule::AnalysisOptions analysis_options(const py::dict& o) {
  molecule::AnalysisOptions a;
  a.cavities.probe = o["probe"].cast<double>();
  a.cavities.min_volume = o["min_volume"].cast<double>();
  const long long threads = o["threads"].cast<long long>();
  if (threads < 1 || threads > 4096)
    throw alpha::Error("threads: " + std::to_string(threads) + " is not in 1..4096", alpha::ErrorKind::Misuse);
  a.cavities.threads = unsigned(threads);
  a.structure.model = o["model"].cast<int>();
  a.structure.chains = o["chains"].cast<std::vector<std::string>>();
  a.structure.keep_hydrogens = o["keep_hydrogens"].cast<bool>();
  a.structure.keep_waters = o["keep_waters"].cast<bool>();
  a.structure.keep_hetero = o["keep_hetero"].cast<bool>();
  a.structure.keep_hetero_codes = o["keep_hetero_codes"].cast<std::vector<std::string>>();
  a.structure.keep_cofactors = o["keep_cofactors"].cast<bool>();
  a.structure.min_plddt = o["min_plddt"].cast<double>();
  a.structure.max_input_mib = max_input_mib(o);
  a.radii_file = o["radii"].cast<std::string>();
  a.tunnels_from = o["tunnels_from"].cast<std::string>();
  a.tunnels.probe = o["tunnel_probe"].cast<double>();
  a.tunnels.pores = o["pores"].cast<bool>();
  a.mesh_format = o["mesh"].cast<std::string>();
  try {
    a.outputs = molecule::parse_output_selection(o["outputs"].cast<std::string>());
  } catch (const alpha::Error& e) {
    throw alpha::Error(std::string("outputs: ") + e.what(), alpha::ErrorKind::Misuse);
  }
  try {
    a.ranking = molecule::parse_site_ranking(o["ranking"].cast<std::string>());
  } catch (const alpha::Error& e) {
    throw alpha::Error(std::string("ranking: ") + e.what(), alpha::ErrorKind::Misuse);
  }
  return a;
}

}  // namespace alphapocket_python

PYBIND11_MODULE(_core, m) {
  m.doc() = "alphapocket's compiled core; use the package alphapocket";
  m.attr("__version__") = alphapocket::kVersion;

  // Exceptions, one per alpha::ErrorKind, under alphapocket.Error.
  static py::exception<alpha::Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<alpha::Error> bad_input(m, "BadInputError", error.ptr());
  static py::exception<alpha::Error> limit(m, "LimitExceededError", error.ptr());
  static py::exception<alpha::Error> misuse(m, "MisuseError", error.ptr());
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const alpha::Error& e) {
      switch (e.kind()) {
        case alpha::ErrorKind::BadInput: bad_input(e.what()); return;
        case alpha::ErrorKind::LimitExceeded: limit(e.what()); return;
        case alpha::ErrorKind::Misuse: misuse(e.what()); return;
        case alpha::ErrorKind::Internal: break;
      }
      error(e.what());
    } catch (const std::bad_alloc&) {
      limit("out of memory");
    }
  });

  py::class_<molecule::Analysis, std::shared_ptr<molecule::Analysis>>(m, "Analysis")
      .def("report_json", [](const molecule::Analysis& a) { return molecule::report_text(a); })
      .def("write",
           [](const molecule::Analysis& a, const std::string& outdir) {
             py::gil_scoped_release release;
             return molecule::write_outputs(a, outdir);
           })
      .def("features_csv",
           [](const molecule::Analysis& a) {
             py::gil_scoped_release release;
             return molecule::site_features_csv(a.structure, a.search.cavities);
           })
      .def_property_readonly("file", [](const molecule::Analysis& a) { return a.file; });

  alphapocket_python::add_track(m);
  m.def("analysis_defaults", &analysis_defaults);
  m.def("surface_defaults", &surface_defaults);
  m.def("analyse_path", [](const std::string& path, const py::dict& options) {
    return std::const_pointer_cast<molecule::Analysis>(analyse_path(path, options));
  });
  m.def("analyse_text", [](const std::string& name, const std::string& text, const py::dict& options) {
    return std::const_pointer_cast<molecule::Analysis>(analyse_text(name, text, options));
  });
  m.def("analyse_arrays", [](const std::string& name, const Points& xyz, const std::optional<Points>& radii,
                             const py::dict& names, const py::dict& options) {
    return std::const_pointer_cast<molecule::Analysis>(analyse_arrays(name, xyz, radii, names, options));
  });

  m.def("surface_path", [](const std::string& path, double probe, bool excluded, bool per_atom,
                           const py::dict& selection) {
    const molecule::StructureOptions so = surface_selection(selection);
    molecule::Surface s;
    {
      py::gil_scoped_release release;
      s = molecule::surface_of_file(path, so, {probe, excluded, per_atom});
    }
    return surface_dict(s);
  });
  m.def("surface_text", [](const std::string& name, const std::string& text, double probe, bool excluded,
                           bool per_atom, const py::dict& selection) {
    const molecule::StructureOptions so = surface_selection(selection);
    molecule::Surface s;
    {
      py::gil_scoped_release release;
      s = molecule::surface_of_content(name, text, so, {probe, excluded, per_atom});
    }
    return surface_dict(s);
  });
  m.def("surface_arrays", [](const Points& xyz, const std::optional<Points>& radii, const py::dict& names,
                             double probe, bool excluded, bool per_atom) {
    const molecule::Structure st = structure_of(xyz, radii, names);
    molecule::Surface s;
    {
      py::gil_scoped_release release;
      s = molecule::measure_surface(st.atoms, {probe, excluded, per_atom});
    }
    return surface_dict(s);
  });

  py::class_<PyAlphaComplex>(m, "AlphaComplex")
      .def(py::init<const Points&, const std::optional<Points>&, unsigned>(), py::arg("points"),
           py::arg("weights") = py::none(), py::arg("threads") = 1)
      .def_property_readonly("spectrum", &PyAlphaComplex::spectrum)
      .def("classify", &PyAlphaComplex::classify, py::arg("alpha_sq"))
      .def("betti", &PyAlphaComplex::betti, py::arg("alpha_sq"))
      .def("persistence", &PyAlphaComplex::persistence)
      .def("shape_mesh", &PyAlphaComplex::shape_mesh, py::arg("alpha_sq"))
      .def("__len__", &PyAlphaComplex::num_points);
}
