#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The triangulation on threads: `alphapocket delaunay -j 1`
# against `-j 2` on 1e6 uniform random points and on 1e6 weighted ones
# (the distributions of bench_triangulation), each in a fresh process, runs
# alternating, REPS each (default 3). Prints the "triangulation: S s" wall
# time that delaunay logs (the construction alone, not the reading), the
# medians and their ratio (-j 1 / -j 2: the speed-up), each run's CPU use
# (GNU time's %P of the whole process), the load average before and after,
# and whether the two settings print the same JSON.
#
# A separate process per run, not a loop in bench_triangulation: there, the
# heap that CGAL's runs left behind changes what the builds pay for fresh
# pages, on which the two settings differ.
#
# Usage: bench/triangulation_threads.sh [ALPHAPOCKET]   (default build/apps/alphapocket)
# Needs python3 and GNU time. The machine's load distorts wall times.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
bench_setup "${1:-}"
write_random_points "$scratch/random.xyz" 1000000 2
python3 - "$scratch" <<'PY'
import random, sys
d = sys.argv[1]
r = random.Random(5)
side = 100.0  # unit density; weights (squared radii) in [0, 1)
with open(d + "/weighted.xyz", "w") as f:
    for _ in range(1000000):
        f.write("%.17g %.17g %.17g %.17g\n" % (r.random() * side, r.random() * side, r.random() * side, r.random() ** 0.5))
PY

build_seconds() {  # SET JOBS [FLAGS]: prints the logged construction seconds and the CPU use
  /usr/bin/time -f %P -o "$scratch/cpu" "$exe" delaunay "$scratch/$1.xyz" -j "$2" "${@:3}" --json \
    >"$scratch/$1.j$2.json" 2>"$scratch/err"
  echo "$(sed -n 's/.*triangulation: \([0-9.]*\) s .*/\1/p' "$scratch/err") $(cat "$scratch/cpu")"
}

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-9s %9s %9s %9s  %s\n' set "-j 1 s" "-j 2 s" speed-up "runs (s, CPU use)"
for set in random weighted; do
  flags=()
  [[ $set == weighted ]] && flags=(--weighted)
  one=() two=() runs=""
  for ((r = 0; r < reps; r++)); do
    read -r s cpu < <(build_seconds "$set" 1 "${flags[@]}")
    one+=("$s") runs+=" j1 $s $cpu"
    read -r s cpu < <(build_seconds "$set" 2 "${flags[@]}")
    two+=("$s") runs+=" j2 $s $cpu"
  done
  m1=$(printf '%s\n' "${one[@]}" | median) m2=$(printf '%s\n' "${two[@]}" | median)
  same=$(cmp -s "$scratch/$set.j1.json" "$scratch/$set.j2.json" && echo "same JSON" || echo "JSON DIFFERS")
  printf '%-9s %9.3f %9.3f %9.2f %s; %s\n' "$set" "$m1" "$m2" "$(echo "$m1 / $m2" | bc -l)" "$runs" "$same"
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
