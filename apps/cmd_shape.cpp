// SPDX-License-Identifier: Apache-2.0
// alphapocket shape FILE --alpha-sq V [--weighted] -o OUT.{ply,obj,off,stl}
//
// Writes the boundary of the alpha shape at alpha_sq = V as a triangle
// mesh: its regular triangles, oriented outward, and the vertices they use,
// as a closed 2-manifold (points copied where the shape is pinched:
// molecule/mesh_export.hpp). Singular simplices (dangling triangles, edges,
// isolated vertices) are not part of a surface and are only counted in the
// log.
#include <memory>
#include <string>
#include <utility>

#include <spdlog/spdlog.h>

#include "alpha/alpha_complex.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "molecule/mesh_export.hpp"

namespace alphapocket {
namespace {

struct ShapeOptions {
  InputOptions input;
  double alpha_sq = 0;
  std::string output;
};

int run_shape(const ShapeOptions& opt) {
  molecule::check_mesh_file_name(opt.output);  // before the work
  const AlphaInput in = load_alpha_complex(opt.input);
  const alpha::AlphaComplex& ac = in.shape.complex();
  const alpha::Index level = ac.level(opt.alpha_sq);
  alpha::ShapeBoundary boundary = ac.boundary(level);

  molecule::TriangleMesh mesh;
  const auto points = in.shape.triangulation().points();
  mesh.points.assign(points.begin(), points.end());
  mesh.triangles = std::move(boundary.triangles);
  const molecule::MeshFileInfo info = molecule::write_mesh_file(opt.output, mesh);

  spdlog::info("alpha_sq {} ({} of {} critical values): wrote {} triangles, {} vertices to {} ({} {})",
               opt.alpha_sq, level, ac.spectrum_size(), info.faces, info.vertices, opt.output,
               info.binary ? "binary" : "ASCII", info.format);
  spdlog::info("not written (singular, not on a surface): {} triangles, {} edges, {} vertices",
               boundary.singular_triangles.size(), boundary.singular_edges.size(),
               boundary.singular_vertices.size());
  if (info.duplicated_vertices)
    spdlog::info("{} extra vertex copies (same coordinates) where the shape is pinched (tetrahedra meeting at an "
                 "edge or a vertex only): the file is a closed 2-manifold",
                 info.duplicated_vertices);
  if (info.faces == 0)
    spdlog::warn("the alpha shape has no boundary triangles at alpha_sq {}: {} holds an empty mesh", opt.alpha_sq,
                 opt.output);
  return 0;
}

}  // namespace

Subcommand add_shape_command(CLI::App& app) {
  auto opt = std::make_shared<ShapeOptions>();
  CLI::App* sub = app.add_subcommand(
      "shape", "Write the boundary of the alpha shape (its regular triangles, oriented outward) as a mesh file");
  sub->footer(std::string("Singular triangles, edges and vertices (not on a surface) are not written, only "
                          "counted in the log. ") +
              kAlphaSqHelp);
  add_input_options(*sub, opt->input);
  sub->add_option("--alpha-sq", opt->alpha_sq, "Squared radius of the shape (may be negative)")
      ->required()
      ->check(finite_number());
  sub->add_option("-o,--output", opt->output,
                  "Mesh file to write, in the format of its extension: .ply (binary), .stl (binary), .off or "
                  ".obj (ASCII). Written whole or not at all; an existing file is replaced")
      ->required();
  return {sub, [opt] { return run_shape(*opt); }};
}

}  // namespace alphapocket
