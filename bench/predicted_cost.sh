#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The predicted-model target (a predicted model costs no more than
# 1.5x a crystal chain of the same atom count): the CPU time of
# `alphapocket pockets` with its default outputs on each AlphaFold model of
# ../shared/data/formats against the K crystal chains of pockets-train
# nearest to it in atoms kept; each file REPS times, alternating, medians.
#
# Usage: bench/predicted_cost.sh [ALPHAPOCKET]
#   ALPHAPOCKET  default build/apps/alphapocket
# Environment: REPS (default 5), K (default 3), SHARED (default ../shared
# beside the repository).
# Needs GNU time (/usr/bin/time).
#
# Prints per model: its atoms and median CPU s, the chains' ids, atoms and
# median CPU s, and the ratio of the model's time to the median of the
# chains'. CPU = user + system of the process.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=$(realpath "${1:-$root/build/apps/alphapocket}")
shared=${SHARED:-$root/../shared}
reps=${REPS:-5}
k=${K:-3}

[[ -x /usr/bin/time ]] || { echo "/usr/bin/time not found (Debian: apt-get install time)" >&2; exit 1; }
[[ -x $exe ]] || { echo "$exe: not an executable (build alphapocket first)" >&2; exit 1; }

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

cpu() {  # FILE: user + system CPU seconds of `pockets` with its default outputs
  rm -rf "$scratch/out"
  /usr/bin/time -f '%U %S' -o "$scratch/time" "$exe" -q pockets "$1" -o "$scratch/out" >/dev/null 2>&1 || true
  awk '{ print $1 + $2 }' "$scratch/time"
}
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

# Atoms kept (as the analysis counts them): one batch run over both sets.
mkdir "$scratch/in"
ln -s "$shared"/data/pockets-train/*.pdb "$shared"/data/formats/AF-* "$scratch/in/"
"$exe" -q batch "$scratch/in" -o "$scratch/atoms" >/dev/null
# id,path,...,atoms (column 6)
awk -F, 'NR > 1 && $3 == "ok" { print $1, $2, $6 }' "$scratch/atoms/structures.csv" >"$scratch/all"

echo "load average $(cut -d' ' -f1-3 /proc/loadavg); REPS=$reps, K=$k nearest pockets-train chains"
printf '%-22s %6s %8s  %-40s %8s %7s\n' model atoms cpu_s chains chains_s ratio
grep '^AF-' "$scratch/all" | while read -r id path atoms; do
  grep -v '^AF-' "$scratch/all" | awk -v n="$atoms" '{ d = $3 - n; print (d < 0 ? -d : d), $0 }' | sort -g -k1,1 -k2,2 |
    awk -v k="$k" 'NR <= k' | cut -d' ' -f2- >"$scratch/near"  # reads to the end: no SIGPIPE for sort under pipefail
  : >"$scratch/model"
  while read -r cid cpath catoms; do : >"$scratch/$cid"; done <"$scratch/near"
  for ((r = 0; r < reps; ++r)); do
    cpu "$path" >>"$scratch/model"
    while read -r cid cpath catoms; do cpu "$cpath" >>"$scratch/$cid"; done <"$scratch/near"
  done
  m=$(median <"$scratch/model")
  names=""
  : >"$scratch/medians"
  while read -r cid cpath catoms; do
    names+="$cid($catoms) "
    median <"$scratch/$cid" >>"$scratch/medians"
  done <"$scratch/near"
  c=$(median <"$scratch/medians")
  awk -v id="$id" -v n="$atoms" -v m="$m" -v names="$names" -v c="$c" \
    'BEGIN { printf "%-22s %6d %8.3f  %-40s %8.3f %7.2f\n", id, n, m, names, c, (c > 0 ? m / c : 0) }'
done
