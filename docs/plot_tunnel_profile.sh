#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The radius profile of a pore (alphapocket's tunnel_profiles.csv) as a PNG,
# against HOLE's profile of the same channel when its output is given.
# Usage: plot_tunnel_profile.sh OUTDIR TUNNEL_RANK OUT.png [HOLE_OUT.txt]
# The horizontal axis is the coordinate along the line through the pore's
# two ends (report.json's start_point and mouth), from their midpoint, as
# HOLE's cenxyz.cvec is along its channel vector from its guessed centre;
# its direction is chosen so that the two curves run the same way (HOLE
# guesses its vector's sign). No shift is fitted.
set -euo pipefail
dir=$1 rank=$2 png=$3 hole=${4:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 - "$dir" "$rank" "$tmp" "$hole" <<'PY'
import json, sys
import numpy as np
d, rank, tmp, hole = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
t = next(x for x in json.load(open(d + "/report.json"))["tunnels"] if x["rank"] == rank)
a, b = np.array(t["start_point"]), np.array(t["mouth"])
axis = (b - a) / np.linalg.norm(b - a)
centre = (a + b) / 2
p = np.array(t["profile"])
s = (p[:, :3] - centre) @ axis
ours = np.column_stack([s, p[:, 3]])
if hole:
    rows, on = [], False
    for line in open(hole):
        if "cenxyz.cvec" in line and "radius" in line: on = True; continue
        f = line.split()
        if on and len(f) >= 3 and f[0].lstrip("-").replace(".", "", 1).isdigit():
            rows.append((float(f[0]), float(f[1])))
        elif on and rows and not f: break
    h = np.array(rows)
    # HOLE's vector sign is a guess: take the direction in which the two minima lie alike.
    if abs(h[np.argmin(h[:, 1]), 0] + ours[np.argmin(ours[:, 1]), 0]) < abs(h[np.argmin(h[:, 1]), 0] - ours[np.argmin(ours[:, 1]), 0]):
        h[:, 0] = -h[:, 0]
    np.savetxt(tmp + "/hole.dat", h)
np.savetxt(tmp + "/ours.dat", ours)
PY
{
  echo "set terminal pngcairo size 800,450 font 'DejaVu Sans,11'"
  echo "set output '$png'"
  echo "set xlabel 'coordinate along the pore (A)'; set ylabel 'radius (A)'"
  echo "set yrange [0:4]; set grid; set key top center"
  echo -n "plot '$tmp/ours.dat' with linespoints pt 7 ps 0.5 lw 2 title 'alphapocket --pores (power diagram, exact radii)'"
  [[ -n $hole ]] && echo -n ", '$tmp/hole.dat' with lines lw 2 dt 2 title 'HOLE 2.2 (hole\\_out.txt)'"
  echo
} | gnuplot
