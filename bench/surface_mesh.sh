#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Time to mesh the molecular surface, ours against CGAL's Skin_surface_3
# (bench_surface_mesh) and PyMOL's surface (bench/pymol_surface.py, headless
# Debian pymol) on the same files in one run, with each one's area and
# volume error against our analytic molecular (SES) area and volume.
#
# Usage: bench/surface_mesh.sh [BENCH_SURFACE_MESH] [FILE ...]
#   BENCH_SURFACE_MESH  default build/bench/bench_surface_mesh (ALPHAPOCKET_BENCH=ON, CGAL)
#   FILEs               default ../shared/data/pockets-dev/*.pdb
# Environment: REPS (runs of ours and CGAL per file, median; default 3);
# NO_CGAL=1 leaves CGAL out (its minutes per file), RESOLUTION=H meshes ours
# at H A instead of the default.
# Prints bench_surface_mesh's table, then PyMOL's seconds and errors per
# file, then the median time ratios CGAL / ours and PyMOL / ours (> 1: ours
# is faster). Times are CPU seconds; ours counts everything from the atoms
# to the mesh (triangulation included), PyMOL only its surface build.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=${1:-$root/build/bench/bench_surface_mesh}
[[ $# -gt 0 ]] && shift
files=("$@")
[[ ${#files[@]} -gt 0 ]] || files=("$root"/../shared/data/pockets-dev/*.pdb)
[[ -x $exe ]] || { echo "$exe: not an executable (cmake -DALPHAPOCKET_BENCH=ON, target bench_surface_mesh)" >&2; exit 1; }
command -v pymol >/dev/null || { echo "pymol not found (Debian: apt-get install pymol)" >&2; exit 1; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$exe" ${NO_CGAL:+--no-cgal} ${RESOLUTION:+--resolution "$RESOLUTION"} "${files[@]}" | tee "$tmp/ours"
# Debian's pymol runs `python3` from PATH: make it Debian's own.
PATH=/usr/bin:$PATH pymol -cq "$root/bench/pymol_surface.py" -- "${files[@]}" >"$tmp/pymol"

echo
# PyMOL's lines: name atoms seconds area volume.
awk 'NR == FNR { if ($1 != "file" && NF == 12) { ours[$1] = $5; area[$1] = $3; vol[$1] = $4; cgal[$1] = $12 } next }
  ($1 in ours) { names[++n] = $1; pymol[$1] = $3; parea[$1] = $4; pvol[$1] = $5 }
  function median(a, m,   i, j, t) {  # sorts a[1..m]
    for (i = 2; i <= m; ++i) for (j = i; j > 1 && a[j - 1] > a[j]; --j) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
    return m % 2 ? a[(m + 1) / 2] : (a[m / 2] + a[m / 2 + 1]) / 2
  }
  END {
    printf "%-12s %8s %8s %8s %8s %9s\n", "file", "ours s", "PyMOL s", "area %", "vol %", "PyMOL/us"
    for (k = 1; k <= n; ++k) {
      f = names[k]
      r[k] = pymol[f] / ours[f]; c[k] = cgal[f]
      printf "%-12s %8.3f %8.3f %+8.2f %+8.2f %9.2f\n", f, ours[f], pymol[f], 100 * (parea[f] - area[f]) / area[f],
             100 * (pvol[f] - vol[f]) / vol[f], r[k]
    }
    printf "median over %d files: CGAL/ours %.2f, PyMOL/ours %.2f\n", n, median(c, n), median(r, n)
  }' "$tmp/ours" "$tmp/pymol"
