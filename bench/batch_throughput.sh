#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Screening throughput: `alphapocket batch -j 2` against fpocket 4.0 run
# through GNU parallel -j 2, in the same run, on the same structures
# (default ../shared/data/pockets-train, 173 chains), then the scaling case
# of one large assembly (54 rotated copies of 1a26A against one copy).
#
# Usage: bench/batch_throughput.sh [ALPHAPOCKET] [DIR]
#   ALPHAPOCKET  default build/apps/alphapocket
#   DIR          a folder of .pdb files, default ../shared/data/pockets-train
# Environment: REPS (timed repetitions, default 3), SHARED (default
# ../shared beside the repository), CACHE (where fpocket is
# built, outside the repository; default ~/.cache/alphapocket-bench).
# Needs GNU parallel, GNU time (/usr/bin/time), make, g++, python3-gemmi, python3-scipy.
#
# Printed:
#   - wall-clock seconds of each repetition, both programs alternating, and
#     the medians; structures/s = structures / median seconds; the ratio.
#   - peak memory: the largest resident set of one process (GNU time's
#     "Maximum resident set size": for parallel, its largest fpocket child).
#     Ours also with -j 1, which is the memory of one worker.
#   - failures: ours from failures.tsv; fpocket returns 0 even when a file
#     fails, so its failures are the inputs without an _info.txt.
#   - scaling: `alphapocket batch -j 1` (the batch defaults: the pocket
#     search and the report, no meshes) on 1a26A and on the 54-copy
#     assembly: median seconds (user + system CPU, single-threaded; one copy
#     5 x REPS runs, 54 copies REPS runs) and peak memory, and the ratios
#     against the 54x of a linear cost.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=$(realpath "${1:-$root/build/apps/alphapocket}")
shared=${SHARED:-$root/../shared}
data=$(realpath "${2:-$shared/data/pockets-train}")
reps=${REPS:-3}
cache=${CACHE:-$HOME/.cache/alphapocket-bench}
peers=$shared/peers

command -v parallel >/dev/null || { echo "parallel not found" >&2; exit 1; }
[[ -x /usr/bin/time ]] || { echo "/usr/bin/time not found (Debian: apt-get install time)" >&2; exit 1; }
[[ -x $exe ]] || { echo "$exe: not an executable (build alphapocket first)" >&2; exit 1; }

# fpocket 4.0 as ../shared/peers/README.md builds it, once per cache.
source "$root/bench/fpocket.sh"
fpocket=$(fpocket_binary "$cache" "$peers")

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# fpocket writes its results beside its input: it reads copies (ours reads
# DIR itself, and would find the copies' results).
mkdir "$scratch/in"
cp "$data"/*.pdb "$scratch/in/"
n=$(ls "$scratch/in" | wc -l)

# timed COMMAND...: runs it under GNU time; prints "WALL_S CPU_S MAX_RSS_KB"
# (CPU: user + system of the process and its children).
timed() {
  /usr/bin/time -f '%e %U %S %M' -o "$scratch/time" "$@" >/dev/null 2>"$scratch/stderr" || true
  awk '{ print $1, $2 + $3, $4 }' "$scratch/time"
}
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

ours() {  # JOBS: a fresh output directory (a re-run would resume)
  rm -rf "$scratch/ours"
  timed "$exe" -q batch "$data" -o "$scratch/ours" -j "$1"
}
theirs() {
  rm -rf "$scratch"/in/*_out
  timed parallel -j 2 "$fpocket" -f {} ::: "$scratch"/in/*.pdb
}

echo "$n structures from $data, $reps repetitions, $(nproc) cores"
printf '%-4s %9s %9s %9s %9s %12s %12s\n' rep ours_s ours_cpu fpocket_s fp_cpu ours_rss_MB fp_rss_MB
: >"$scratch/runs"
for ((k = 1; k <= reps; ++k)); do
  if ((k % 2)); then a=$(ours 2); b=$(theirs); else b=$(theirs); a=$(ours 2); fi
  echo "$a $b" >>"$scratch/runs"
  awk '{ printf "%-4d %9.2f %9.2f %9.2f %9.2f %12.1f %12.1f\n", '"$k"', $1, $2, $4, $5, $3 / 1024, $6 / 1024 }' \
    <<<"$a $b"
done
column_median() { cut -d' ' -f"$1" "$scratch/runs" | median; }
column_max() { cut -d' ' -f"$1" "$scratch/runs" | sort -g | tail -n 1; }
read -r t1 c1 m1 <<<"$(ours 1)"
ours_failed=$(tail -n +2 "$scratch/ours/failures.tsv" | wc -l)
fp_failed=0
for f in "$scratch"/in/*.pdb; do
  b=$(basename "$f" .pdb)
  [[ -s $scratch/in/${b}_out/${b}_info.txt ]] || fp_failed=$((fp_failed + 1))
done
awk -v n="$n" -v a="$(column_median 1)" -v ca="$(column_median 2)" -v b="$(column_median 4)" \
    -v cb="$(column_median 5)" -v ma="$(column_max 3)" -v mb="$(column_max 6)" -v t1="$t1" -v c1="$c1" -v m1="$m1" \
    -v fa="$ours_failed" -v fb="$fp_failed" 'BEGIN {
  printf "median wall: ours %.2f s = %.2f structures/s (%.2f per core), fpocket %.2f s = %.2f structures/s; throughput ours/fpocket %.2f\n",
         a, n / a, n / a / 2, b, n / b, b / a
  printf "median CPU: ours %.2f s = %.2f structures per CPU-second, fpocket %.2f s = %.2f; ratio %.2f\n",
         ca, n / ca, cb, n / cb, cb / ca
  printf "peak memory: ours -j 2 %.0f MB (one process), -j 1 %.0f MB (one worker; %.2f s wall, %.2f s CPU); fpocket %.0f MB per process\n",
         ma / 1024, m1 / 1024, t1, c1, mb / 1024
  printf "failures: ours %d, fpocket %d\n", fa, fb
}'

# The scaling case: 54 copies of 1a26A (bench/assembly54.py).
/usr/bin/python3 "$root/bench/assembly54.py" "$root/examples/data/1a26A.pdb" "$scratch/copies54.cif"
cpu_timed() {  # FILE: "CPU_SECONDS MAX_RSS_KB ATOMS" of alphapocket batch -j 1 (the batch defaults)
  rm -rf "$scratch/scale"
  /usr/bin/time -f '%U %S %M' -o "$scratch/time" "$exe" -q batch "$1" -o "$scratch/scale" -j 1 >/dev/null
  read -r u s m <"$scratch/time"
  echo "$(bc -l <<<"$u + $s") $m $(awk -F, 'NR == 2 { print $6 }' "$scratch/scale/structures.csv")"
}
# Each timed REPS times, alternating, medians; one copy five times as often
# (its 0.2 s are near GNU time's 0.01 s resolution).
: >"$scratch/one"
: >"$scratch/many"
for ((k = 1; k <= reps; ++k)); do
  for ((i = 0; i < 5; ++i)); do cpu_timed "$root/examples/data/1a26A.pdb" >>"$scratch/one"; done
  cpu_timed "$scratch/copies54.cif" >>"$scratch/many"
done
s1=$(cut -d' ' -f1 "$scratch/one" | median) r1=$(cut -d' ' -f2 "$scratch/one" | sort -g | tail -n 1)
s54=$(cut -d' ' -f1 "$scratch/many" | median) r54=$(cut -d' ' -f2 "$scratch/many" | sort -g | tail -n 1)
a1=$(cut -d' ' -f3 "$scratch/one" | head -n 1) a54=$(cut -d' ' -f3 "$scratch/many" | head -n 1)
awk -v s1="$s1" -v r1="$r1" -v a1="$a1" -v s54="$s54" -v r54="$r54" -v a54="$a54" 'BEGIN {
  printf "scaling: 1a26A %d atoms %.2f s %.0f MB; 54 copies %d atoms %.2f s %.0f MB: atoms x%.1f, time x%.1f (%.2f of linear), memory x%.1f\n",
         a1, s1, r1 / 1024, a54, s54, r54 / 1024, a54 / a1, s54 / s1, (s54 / s1) / (a54 / a1), r54 / r1
}'
