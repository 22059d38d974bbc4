#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The cavity stage on threads: `alphapocket -v pockets -j 1` against `-j 2`
# on the 54-copy 1a26A assembly (bench/assembly54.py, 149,526 atoms), runs
# alternating, REPS each (default 3). Prints the "cavities: S s" wall time
# that -v logs for each run, the medians and their ratio (-j 1 / -j 2:
# the speed-up), each run's whole-process CPU use (GNU time's %P: near
# 100 % for -j 2 means it got one core), the load average before and
# after, and whether the two settings' outputs are byte-identical (OUTDIR
# and stdout of the last runs).
#
# Usage: bench/pockets_threads.sh [ALPHAPOCKET]   (default build/apps/alphapocket)
# Needs python3-gemmi, python3-scipy, GNU time. The machine's load
# distorts wall times: quote the load with the figures.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
bench_setup "${1:-}"
/usr/bin/python3 "$root/bench/assembly54.py" "$root/examples/data/1a26A.pdb" "$scratch/copies54.cif"

cavities_seconds() {  # JOBS: runs the search, prints the logged cavity stage's seconds and the CPU use
  rm -rf "$scratch/j$1"
  mkdir "$scratch/j$1"
  (cd "$scratch/j$1" && /usr/bin/time -f %P -o ../cpu "$exe" -v pockets ../copies54.cif -o out -j "$1" >stdout 2>stderr)
  echo "$(sed -n 's/^\[info\] cavities: \([0-9.]*\) s,.*/\1/p' "$scratch/j$1/stderr") $(cat "$scratch/cpu")"
  rm "$scratch/j$1/stderr"
}

echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for ((r = 1; r <= reps; ++r)); do
  read -r a pa <<<"$(cavities_seconds 1)"
  read -r b pb <<<"$(cavities_seconds 2)"
  echo "run $r: cavities -j 1 $a s ($pa CPU), -j 2 $b s ($pb CPU)"
  echo "$a" >>"$scratch/j1.times"
  echo "$b" >>"$scratch/j2.times"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
m1=$(median <"$scratch/j1.times")
m2=$(median <"$scratch/j2.times")
awk -v a="$m1" -v b="$m2" 'BEGIN { printf "cavity stage, median of the runs: -j 1 %.2f s, -j 2 %.2f s: %.2fx\n", a, b, a / b }'
if diff -r "$scratch/j1" "$scratch/j2" >/dev/null; then
  echo "outputs: -j 1 and -j 2 byte-identical"
else
  echo "outputs: -j 1 and -j 2 DIFFER"
  exit 1
fi
