#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The README picture: alphapocket's molecular-surface mesh of a structure
# (meshes/surface.ply of `pockets`) with its sites painted on it, drawn by
# PyMOL 2.5 headless (Debian's pymol, ray-traced, no display needed) as a
# smooth surface with the mesh's own vertex colours, seen from the side of
# the best site, with the ligands as sticks.
# Usage: render_surface.sh ALPHAPOCKET STRUCTURE OUT.png [WIDTH HEIGHT [RESOLUTION]]
# (RESOLUTION: --mesh-resolution, default alphapocket's; ray tracing the
# default mesh of a 3,000-atom protein takes a minute or two.)
set -euo pipefail
exe=$1 structure=$2 png=$3 width=${4:-720} height=${5:-540} resolution=${6:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$exe" -q pockets "$structure" -o "$tmp/out" --mesh ply ${resolution:+--mesh-resolution "$resolution"} >/dev/null
cat >"$tmp/render.py" <<'PY'
import json, sys
import numpy as np
from pymol import cgo, cmd

out, structure, png, width, height = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5])

def read_ply(path):
    """Binary little-endian PLY as we write it: vertices x y z r g b site, faces of 3 with r g b."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = [line.split() for line in data[:end].decode("ascii").splitlines()]
    counts = [int(w[2]) for w in header if w[0] == "element"]
    vertex = np.dtype([("p", "<f4", 3), ("rgb", "u1", 3), ("site", "<i4")])
    face = np.dtype([("n", "u1"), ("v", "<i4", 3), ("rgb", "u1", 3)])
    v = np.frombuffer(data, vertex, counts[0], end)
    f = np.frombuffer(data, face, counts[1], end + counts[0] * vertex.itemsize)
    return v["p"].astype(float), v["rgb"] / 255.0, f["v"]

points, colors, faces = read_ply(out + "/meshes/surface.ply")
# Smooth shading: per-vertex normals, the sum of the faces' area normals.
a, b, c = (points[faces[:, k]] for k in range(3))
n = np.cross(b - a, c - a)
def vertex_sums(per_face):
    out = np.zeros_like(points)
    for k in range(3):
        np.add.at(out, faces[:, k], per_face)
    return out
def unit(v):
    return v / np.maximum(np.linalg.norm(v, axis=1), 1e-12)[:, None]
normals = unit(vertex_sums(n))
# Once more over the faces around (the lattice's facets otherwise show in highlights).
normals = unit(vertex_sums(normals[faces].sum(axis=1)))
corners = faces.reshape(-1)
block = np.empty((len(corners), 12))
block[:, 0] = cgo.COLOR
block[:, 1:4] = colors[corners]
block[:, 4] = cgo.NORMAL
block[:, 5:8] = normals[corners]
block[:, 8] = cgo.VERTEX
block[:, 9:12] = points[corners]
cmd.load_cgo([cgo.BEGIN, cgo.TRIANGLES] + block.reshape(-1).tolist() + [cgo.END], "surface")

cmd.load(structure, "molecule")
cmd.hide("everything", "molecule")
cmd.show("sticks", "molecule and hetatm and not solvent and not hydro")
cmd.color("yellow", "molecule and hetatm and elem C")

# Look at the best site from outside: the camera on the line from the
# molecule's centre through the site's centre.
report = json.load(open(out + "/report.json"))
best = report["sites"][0]
site = np.array(best["center"])
centre = points.mean(axis=0)
z = site - centre
z /= np.linalg.norm(z)
x = np.cross([0.0, 0.0, 1.0] if abs(z[2]) < 0.9 else [1.0, 0.0, 0.0], z)
x /= np.linalg.norm(x)
y = np.cross(z, x)
rotation = np.column_stack([x, y, z])  # model to camera, as PyMOL's view stores it (column-major)
radius = np.linalg.norm(points - centre, axis=1).max()
distance = 0.75 * radius / np.tan(np.radians(cmd.get_setting_float("field_of_view") / 2))  # the molecule fills the height
view = list(rotation.reshape(-1)) + [0.0, 0.0, -distance] + list(centre) + [distance - 1.5 * radius, distance + 1.5 * radius, 0.0]
cmd.set_view(view)
cmd.bg_color("white")
cmd.set("ray_opaque_background", 1)
cmd.set("ambient", 0.25)
cmd.set("specular", 0.1)
cmd.set("ray_shadows", 0)
cmd.set("antialias", 2)
cmd.ray(width, height)
cmd.png(png, dpi=150)
PY
env -i PATH=/usr/bin:/bin HOME="$tmp" /usr/bin/pymol -cq "$tmp/render.py" -- "$tmp/out" "$structure" "$png" "$width" "$height"
