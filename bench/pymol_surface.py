# SPDX-License-Identifier: Apache-2.0
# PyMOL's molecular surface of each file, headless: run as
#   pymol -cq bench/pymol_surface.py -- FILE...
# (Debian's pymol, with Debian's python3 first in PATH). Prints one line per
# file: name, atoms, CPU seconds to build the surface, its area and the
# volume it encloses (divergence theorem over its triangles).
#
# PyMOL builds a representation only when something draws or exports it, so
# the surface is exported twice as OBJ: the first export builds and writes
# it, the second only writes it; the build time is the difference. The
# atoms are those alphapocket keeps (no hydrogens, waters or hetero groups);
# the surface is PyMOL's default (solvent-excluded, probe 1.4 A, its own
# van der Waals radii, surface_quality 0).
import os
import sys
import tempfile
import time

from pymol import cmd


def obj_measures(path):
    points, area, volume = [], 0.0, 0.0
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                points.append(tuple(float(x) for x in line.split()[1:4]))
            elif line.startswith("f "):
                a, b, c = (points[int(w.split("/")[0]) - 1] for w in line.split()[1:4])
                ab = [b[i] - a[i] for i in range(3)]
                ac = [c[i] - a[i] for i in range(3)]
                n = (ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0])
                area += (n[0] ** 2 + n[1] ** 2 + n[2] ** 2) ** 0.5 / 2
                bc = (b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2], b[0] * c[1] - b[1] * c[0])
                volume += (a[0] * bc[0] + a[1] * bc[1] + a[2] * bc[2]) / 6
    return area, volume


def main(files):
    with tempfile.TemporaryDirectory() as tmp:
        obj = os.path.join(tmp, "surface.obj")
        for path in files:
            cmd.reinitialize()
            cmd.load(path, "m")
            cmd.remove("hydro or solvent or hetatm")
            atoms = cmd.count_atoms("m")
            cmd.show_as("surface", "m")
            start = time.process_time()
            cmd.save(obj)
            built = time.process_time()
            cmd.save(obj)
            written = time.process_time()
            area, volume = obj_measures(obj)
            seconds = (built - start) - (written - built)
            print(f"{os.path.basename(path)} {atoms} {seconds:.4f} {area:.2f} {volume:.2f}", flush=True)


main(sys.argv[1:])
