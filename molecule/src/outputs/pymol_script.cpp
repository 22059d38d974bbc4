// SPDX-License-Identifier: Apache-2.0
#include "outputs/pymol_script.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "outputs/pocket_colors.hpp"
#include "util/safe_text.hpp"

namespace molecule {
namespace {

// Atom-id runs per "select" line: keeps lines short for PyMOL's parser.
constexpr std::size_t kRunsPerLine = 40;

std::string rgb(Rgb c) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "[%d, %d, %d]", c.r, c.g, c.b);
  return buf;
}

std::string position(const alpha::Vec3& p) {
  return "pos=[" + script_number(p.x) + ", " + script_number(p.y) + ", " + script_number(p.z) + "]";
}

// "select NAME, OBJ and id 12-15+20 ..." lines, kRunsPerLine runs a line.
std::string select_lines(const std::string& name, const std::string& obj, const std::vector<std::size_t>& ids) {
  const auto runs = id_runs(ids);
  if (runs.empty()) return "select " + name + ", none\n";
  std::string s;
  for (std::size_t k = 0; k < runs.size(); k += kRunsPerLine) {
    std::string part;
    for (std::size_t j = k; j < std::min(runs.size(), k + kRunsPerLine); ++j) {
      if (!part.empty()) part += '+';
      part += std::to_string(runs[j].first);
      if (runs[j].second > runs[j].first) part += '-' + std::to_string(runs[j].second);
    }
    s += "select " + name + ", " + (k == 0 ? "" : name + " or ") + "(" + obj + " and id " + part + ")\n";
  }
  return s;
}

// Each section writes one part of the scene.

std::string header(const PocketRun& run, const ViewerScene& scene) {
  // No ';' in a comment: PyMOL's parser splits a line there first.
  std::string s = "# alphapocket " + printable_ascii(run.options.version, ";") + ": pockets of " +
                  printable_ascii(run.file, ";") + "\n";
  s += "# Open with `pymol pockets.pml` (from any directory) or `@pockets.pml` inside PyMOL: it loads\n";
  s += "# structure.cif beside it as " + scene.object + " (the atoms searched and the ligands).\n";
  s += "# Coloured by site rank (report.json sites). pocket_N selects the atoms lining pocket N,\n";
  s += "# pocket_N_space is its space (spheres at its sinks), pocket_N_center its centre (void_N likewise).\n";
  s += "# Sites after the " + std::to_string(kShownSites) + "th are loaded but disabled. tunnel_N selects the atoms of\n";
  s += "# tunnel N's bottleneck, tunnel_N_bottleneck is the largest probe passing it (cyan). For tunnels\n";
  s += "# and pores with a path (report.json tunnels of kind tunnel or pore), tunnel_N selects the lining\n";
  s += "# residues and tunnel_N_path is the centreline as spheres of the radius profile (shades of cyan).\n";
  s += "# pocket_N_cast is the cast of its space as the molecular surface bounds it (meshes/, when written\n";
  s += "# as PLY or OBJ: --mesh), in its colour, loaded disabled (enable the group casts to see them).\n";
  return s;
}

std::string structure(const ViewerScene& scene) {
  const std::string& obj = scene.object;
  std::string s;
  s += "/import os\n";
  s += "/cmd.load(os.path.join(os.path.dirname(os.path.abspath(globals().get(\"__script__\", \"pockets.pml\"))), "
       "\"structure.cif\"), \"" + obj + "\")\n";
  s += "hide everything\n";
  s += "bg_color white\n";
  s += select_lines("ligands", obj, scene.ligand_ids);
  s += "show cartoon, " + obj + "\n";
  s += "set cartoon_color, grey80, " + obj + "\n";
  s += "color grey80, " + obj + "\n";
  s += "show sticks, ligands\n";
  s += "color atomic, ligands\n";
  s += "color yellow, ligands and elem C\n";
  // A grey surface of its own colour (not the pockets' atoms'), light
  // enough to see the buried sites through it.
  s += "show surface, " + obj + " and not ligands\n";
  s += "set surface_color, grey70, " + obj + "\n";
  s += "set transparency, 0.75, " + obj + "\n";
  return s;
}

std::string cavities(const ViewerScene& scene) {
  std::string s;
  for (const SceneCavity& c : scene.cavities) {
    s += "set_color ap_" + c.name + ", " + rgb(c.color) + "\n";
    s += select_lines(c.name, scene.object, c.lining_ids);
    s += "pseudoatom " + c.name + "_center, " + position(c.center) + ", vdw=0.4\n";
    for (const SinkSphere& sphere : c.space)
      s += "pseudoatom " + c.name + "_space, " + position(sphere.center) + ", vdw=" + script_number(sphere.radius) + "\n";
    s += "color ap_" + c.name + ", " + c.name + "_*\n";
  }
  // Worst site first: the best one's colour is the one left on shared residues.
  for (auto c = scene.cavities.rbegin(); c != scene.cavities.rend(); ++c) {
    if (c->shown) {
      s += "show sticks, byres " + c->name + "\n";
      s += "color ap_" + c->name + ", byres " + c->name + " and elem C\n";
    }
  }
  if (!scene.cavities.empty()) {
    s += "show spheres, *_space or *_center\n";
    // The other sites' spheres see-through, so none hides the best one.
    for (const SceneCavity& c : scene.cavities) {
      if (c.site_rank != 1) s += "set sphere_transparency, 0.6, " + c.name + "_space\n";
      if (!c.shown) s += "disable " + c.name + "_space\ndisable " + c.name + "_center\n";
    }
    s += "group spaces, *_space\n";
    s += "group centers, *_center\n";
  }
  return s;
}

// PyMOL 2.5 reads only ASCII PLY, and scales it by 100: the casts are read
// by Python of our own, from the binary PLY or the OBJ we write, as smooth
// CGO surfaces.
constexpr const char* kCastReader = R"py(python
import os, struct
from pymol import cgo, cmd
ap_dir = os.path.dirname(os.path.abspath(globals().get("__script__", "pockets.pml")))
def ap_cast(file, name, rgb):
    data = open(os.path.join(ap_dir, file), "rb").read()
    points, faces = [], []
    if file.endswith(".obj"):
        for w in (line.split() for line in data.decode("ascii").splitlines()):
            if w and w[0] == "v":
                points.append(tuple(map(float, w[1:4])))
            elif w and w[0] == "f":
                faces.append([int(x.split("/")[0]) - 1 for x in w[1:4]])
    else:  # binary little-endian PLY: vertices x y z first, faces a uchar count of int indices first
        end = data.index(b"end_header\n") + len(b"end_header\n")
        codes = {"float": "f", "double": "d", "uchar": "B", "char": "b", "int": "i", "uint": "I"}
        elements = []
        for w in (line.split() for line in data[:end].decode("ascii").splitlines()):
            if w[0] == "element":
                elements.append((int(w[2]), []))
            elif w[0] == "property":
                elements[-1][1].append(w[1:])
        at = end
        for count, props in elements:
            if props[0][0] == "list":
                rest = struct.calcsize("<" + "".join(codes[p[0]] for p in props[1:]))
                for k in range(count):
                    faces.append(struct.unpack_from("<%di" % data[at], data, at + 1))
                    at += 1 + 4 * data[at] + rest
            else:
                fmt = "<" + "".join(codes[p[0]] for p in props)
                size = struct.calcsize(fmt)
                points = [struct.unpack_from(fmt, data, at + k * size)[:3] for k in range(count)]
                at += count * size
    normals = [[0.0, 0.0, 0.0] for _ in points]
    for f in faces:
        a, b, c = (points[i] for i in f[:3])
        u, v = [b[j] - a[j] for j in range(3)], [c[j] - a[j] for j in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        for i in f[:3]:
            for j in range(3):
                normals[i][j] += n[j]
    obj = [cgo.BEGIN, cgo.TRIANGLES, cgo.COLOR] + list(rgb)
    for f in faces:
        for i in f[:3]:
            n = normals[i]
            length = (n[0] ** 2 + n[1] ** 2 + n[2] ** 2) ** 0.5 or 1.0
            obj += [cgo.NORMAL, n[0] / length, n[1] / length, n[2] / length, cgo.VERTEX] + list(points[i])
    obj.append(cgo.END)
    cmd.load_cgo(obj, name)
python end
)py";

bool pymol_reads(const std::string& cast) {
  const std::string ext = std::filesystem::path(cast).extension().string();
  return ext == ".ply" || ext == ".obj";
}

// Each cavity's cast, a surface in its colour, where the meshes are in a
// format the reader above reads; disabled (enable them to see the sites'
// volumes): opaque, they would hide each other and the sites' residues
// (and PyMOL 2.5's ray tracer drops a transparent CGO behind the
// transparent molecular surface).
std::string casts(const ViewerScene& scene) {
  std::string s;
  for (const SceneCavity& c : scene.cavities) {
    if (!pymol_reads(c.cast)) continue;
    if (s.empty()) s = kCastReader;
    char rgb[64];
    std::snprintf(rgb, sizeof rgb, "[%.4f, %.4f, %.4f]", c.color.r / 255.0, c.color.g / 255.0, c.color.b / 255.0);
    s += "/ap_cast(\"" + c.cast + "\", \"" + c.name + "_cast\", " + rgb + ")\n";
  }
  if (s.empty()) return s;
  s += "group casts, *_cast\n";
  for (const SceneCavity& c : scene.cavities)
    if (pymol_reads(c.cast)) s += "disable " + c.name + "_cast\n";
  return s;
}

std::string tunnels(const ViewerScene& scene) {
  std::string s;
  for (const SceneTunnel& t : scene.tunnels) {
    s += select_lines(t.name, scene.object, t.lining_ids);
    s += "pseudoatom " + t.name + "_bottleneck, " + position(t.bottleneck.center) +
         ", vdw=" + script_number(t.bottleneck.radius) + "\n";
  }
  if (!scene.tunnels.empty()) {
    s += "set_color ap_tunnel, " + rgb(kTunnelColor) + "\n";
    s += "color ap_tunnel, tunnel_*_bottleneck\n";
    s += "show spheres, tunnel_*_bottleneck\n";
    s += "set sphere_transparency, 0.5, tunnel_*_bottleneck\n";
  }
  for (const ScenePath& p : scene.paths) {
    s += "set_color ap_" + p.name + ", " + rgb(p.color) + "\n";
    s += select_lines(p.name, scene.object, p.lining_ids);
    for (const SinkSphere& sphere : p.spheres)
      s += "pseudoatom " + p.name + "_path, " + position(sphere.center) + ", vdw=" + script_number(sphere.radius) + "\n";
    s += "color ap_" + p.name + ", " + p.name + "_path\n";
  }
  if (!scene.paths.empty()) {
    s += "show spheres, tunnel_*_path\n";
    s += "set sphere_transparency, 0.3, tunnel_*_path\n";
  }
  if (!scene.tunnels.empty() || !scene.paths.empty()) s += "group tunnels, tunnel_*_bottleneck tunnel_*_path\n";
  return s;
}

// The best site in the middle of the view.
std::string view(const ViewerScene& scene) {
  std::string s = "deselect\n";
  if (scene.cavities.empty() || scene.cavities.front().site_rank != 1) return s + "orient " + scene.object + "\n";
  const std::string& top = scene.cavities.front().name;
  // orient fills the view with it: zoom out to show its surroundings.
  return s + "orient " + top + "_space or byres " + top + "\nzoom " + top + "_space or byres " + top + ", 8\n";
}

}  // namespace

std::string pymol_script(const PocketRun& run, const ViewerScene& scene) {
  return header(run, scene) + structure(scene) + cavities(scene) + casts(scene) + tunnels(scene) + view(scene);
}

}  // namespace molecule
