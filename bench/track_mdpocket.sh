#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `alphapocket track` against mdpocket (fpocket 4.0) on the same frames:
# mdpocket's example, the ten superposed CHK1 structures. Both on one
# core, alternating, RUNS times in the same run; prints each run's CPU
# seconds per frame and the ratio (ours / mdpocket's), their medians,
# where our time goes (track's log, -v), and the overlap of the two
# frequency maps' 0.5 iso-surfaces (grid points at frequency >= 0.5 within
# 1 A of the other's).
#
# Usage: bench/track_mdpocket.sh [ALPHAPOCKET]
#   ALPHAPOCKET  default build/apps/alphapocket
# Environment: RUNS (default 5), SHARED (default ../shared beside the
# repository), CACHE (where fpocket is built, see fpocket.sh).
# Needs GNU time (/usr/bin/time), python3 with numpy; make and g++ to build mdpocket.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=$(realpath "${1:-$root/build/apps/alphapocket}")
shared=${SHARED:-$root/../shared}
runs=${RUNS:-5}
source "$root/bench/lib.sh"
source "$root/bench/fpocket.sh"
cache=${CACHE:-$HOME/.cache/alphapocket-bench}
mdpocket=$(dirname "$(fpocket_binary "$cache" "$shared/peers")")/mdpocket

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$shared"/data/ensembles/chk1_mdpocket/*.pdb "$shared/data/ensembles/chk1_mdpocket/input.txt" "$work/"
rm -f "$work"/mdpout_*.pdb
frames=$(wc -l <"$work/input.txt")
mapfile -t files < <(sed "s|^|$work/|" "$work/input.txt")

cpu() {  # COMMAND...: user + system seconds of the process
  /usr/bin/time -f '%U %S' -o "$work/time" "$@" >/dev/null 2>"$work/log" || { cat "$work/log" >&2; return 1; }
  awk '{print $1 + $2}' "$work/time"
}

echo "run  mdpocket_s/frame  ours_s/frame  ratio"
for ((r = 1; r <= runs; r++)); do
  theirs=$(cd "$work" && cpu "$mdpocket" --pdb_list input.txt -o "$work/mdp")
  ours=$(cpu "$exe" track "${files[@]}" -j 1 -o "$work/ours")
  echo "$r $theirs $ours $frames" | awk '{printf "%3d  %16.4f  %12.4f  %5.2f\n", $1, $2 / $4, $3 / $4, $3 / $2}' |
    tee -a "$work/runs"
done
awk '{print $4}' "$work/runs" | median | xargs printf 'median ratio (ours / mdpocket, CPU per frame): %s\n'
awk '{print $2}' "$work/runs" | median | xargs printf 'median mdpocket: %s s a frame\n'
awk '{print $3}' "$work/runs" | median | xargs printf 'median ours: %s s a frame\n'
"$exe" track "${files[@]}" -j 1 -o "$work/ours" -v 2>&1 >/dev/null | grep -o '[0-9]* frames, .* s a frame: .*rest' |
  sed 's/^/where our time goes: /'

/usr/bin/python3 - "$work/mdp_freq.dx" "$work/ours/frequency.dx" <<'EOF'
import sys
import numpy as np

def points(path, level=0.5):
    """Coordinates of the grid points at or above level."""
    counts = origin = None
    deltas, values, data = [], [], False
    for line in open(path):
        w = line.split()
        if not w:
            continue
        if w[0] == "object" and "gridpositions" in w:
            counts = [int(x) for x in w[-3:]]
        elif w[0] == "origin":
            origin = np.array([float(x) for x in w[1:4]])
        elif w[0] == "delta":
            deltas.append([float(x) for x in w[1:4]])
        elif w[0] == "object" and "data" in w and "follows" in w:
            data = True
        elif data and w[0][0] in "0123456789-.":
            values.extend(float(x) for x in w)
        elif data:
            data = False
    v = np.array(values).reshape(counts)
    ijk = np.argwhere(v >= level)
    return origin + ijk @ np.array(deltas)

from scipy.spatial import cKDTree
theirs, ours = points(sys.argv[1]), points(sys.argv[2])
near_ours = cKDTree(ours).query(theirs, distance_upper_bound=1.0)[0] <= 1.0
near_theirs = cKDTree(theirs).query(ours, distance_upper_bound=1.0)[0] <= 1.0
print(f"0.5 iso-surfaces: mdpocket {len(theirs)} grid points, ours {len(ours)}; "
      f"mdpocket's within 1 A of ours {near_ours.mean():.3f}, ours within 1 A of mdpocket's {near_theirs.mean():.3f}")
EOF
