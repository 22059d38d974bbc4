#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The persistence targets (bench/README.md) in one run with the peer: on N uniform
# random points (default 1e6, seed 2), CGAL's sequential Delaunay
# triangulation (bench/cgal_delaunay: the construction alone) against
# `alphapocket persistence -v` at -j 1 and at -j 2, each in a fresh process,
# runs alternating, REPS each (default 3). Prints each run, then the medians
# and their ratios to CGAL's:
# - stages: triangulation + alpha complex + persistence pairs, as logged
#   (target: 2 times CGAL's Delaunay);
# - whole: the process's wall time, reading and printing the diagram
#   included (target: 2.5 times);
# - CPU: user + system seconds of the whole process; peak RSS per point;
# and whether -j 1 and -j 2 printed the same diagram.
#
# Usage: bench/persistence_process.sh [ALPHAPOCKET [CGAL_DELAUNAY]]
#   (defaults build/apps/alphapocket and build/bench/cgal_delaunay, which
#   needs libcgal-dev). Needs python3 and GNU time. The machine's load
#   distorts wall times.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
bench_setup "${1:-}"
peer=$(realpath "${2:-$root/build/bench/cgal_delaunay}")
[[ -x $peer ]] || { echo "$peer: not an executable (build cgal_delaunay first)" >&2; exit 1; }
n=${N:-1000000}
write_random_points "$scratch/points.xyz" "$n" 2

ours() {  # JOBS: prints the stages' seconds, wall and CPU seconds, peak RSS (kB)
  /usr/bin/time -f "%e %U %S %M" -o "$scratch/time" "$exe" persistence -v "$scratch/points.xyz" -j "$1" \
    >"$scratch/j$1.txt" 2>"$scratch/log"
  local stages
  stages=$(sed -n 's/.*\(Delaunay triangulation\|alpha complex\|persistence pairs\): \([0-9.]*\) s.*/\2/p' \
    "$scratch/log" | awk '{ s += $1; k++ } END { if (k == 3) print s }')
  [[ -n $stages ]] || { echo "persistence -j $1: no stage timings in its log" >&2; exit 1; }
  read -r wall user sys kb <"$scratch/time"
  echo "$stages $wall $(echo "$user + $sys" | bc -l) $kb"
}

echo "$n points; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-4s %8s   %8s %8s %8s %8s   %8s %8s %8s %8s\n' run "CGAL s" "j1 stg" "j1 wall" "j1 CPU" "j1 MB" \
  "j2 stg" "j2 wall" "j2 CPU" "j2 MB"
cgal=() stg1=() wall1=() cpu1=() kb1=() stg2=() wall2=() cpu2=() kb2=()
for ((r = 0; r < reps; r++)); do
  read -r s _ < <("$peer" "$scratch/points.xyz")
  cgal+=("$s")
  read -r a b c d < <(ours 1)
  stg1+=("$a") wall1+=("$b") cpu1+=("$c") kb1+=("$d")
  read -r e f g h < <(ours 2)
  stg2+=("$e") wall2+=("$f") cpu2+=("$g") kb2+=("$h")
  printf '%-4d %8.3f   %8.3f %8.3f %8.3f %8.0f   %8.3f %8.3f %8.3f %8.0f\n' "$r" "$s" "$a" "$b" "$c" "$((d / 1024))" \
    "$e" "$f" "$g" "$((h / 1024))"
done
med() { printf '%s\n' "$@" | median; }
c=$(med "${cgal[@]}")
echo "medians (ratio to CGAL's Delaunay, ${c} s):"
for row in "stages:stg" "whole:wall" "CPU:cpu"; do
  name=${row%%:*} var=${row#*:}
  one="${var}1[@]" two="${var}2[@]"
  m1=$(med "${!one}") m2=$(med "${!two}")
  printf '  %-7s -j 1 %8.3f s %6.2fx   -j 2 %8.3f s %6.2fx\n' "$name" "$m1" "$(echo "$m1 / $c" | bc -l)" \
    "$m2" "$(echo "$m2 / $c" | bc -l)"
done
printf '  peak RSS -j 1 %6.0f B/point, -j 2 %6.0f B/point\n' "$(echo "$(med "${kb1[@]}") * 1024 / $n" | bc -l)" \
  "$(echo "$(med "${kb2[@]}") * 1024 / $n" | bc -l)"
cmp -s "$scratch/j1.txt" "$scratch/j2.txt" && echo "-j 1 and -j 2: the same diagram" || echo "-j 1 and -j 2: DIAGRAMS DIFFER"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
