#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Time of the tunnels (from the top 3 sites, --tunnels-from auto) and all
# pores (--pores) per structure, on top of the pocket search of the same
# run: the times alphapocket logs for its stages (wall clock), per
# structure, then medians. No tunnel program is packaged in Debian (CAVER,
# MOLE and HOLE are not), so the peer is the pocket search itself.
# Usage: bench/bench_tunnels.sh ALPHAPOCKET [DIR]   (DIR: ../shared/data/pockets-dev)
set -euo pipefail
exe=$1
dir=${2:-$(dirname "$0")/../../shared/data/pockets-dev}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '%-10s %6s %10s %10s %9s %7s %5s\n' structure atoms pockets_s tunnels_s ratio tunnels pores
for f in "$dir"/*.pdb; do
  id=$(basename "$f" .pdb)
  "$exe" pockets "$f" --pores --mesh ply -o "$tmp/o" >/dev/null 2>"$tmp/log"
  atoms=$(grep -oE '[0-9]+ atoms, [0-9]+ finite' "$tmp/log" | cut -d' ' -f1)
  complex=$(grep -oE 'alpha complex: [0-9.]+' "$tmp/log" | grep -oE '[0-9.]+$')
  cavities=$(grep -oE 'cavities: [0-9.]+' "$tmp/log" | grep -oE '[0-9.]+$')
  tunnels=$(grep -oE 'tunnels and pores: [0-9.]+' "$tmp/log" | grep -oE '[0-9.]+$')
  n_t=$(grep -c ',tunnel,' "$tmp/o/tunnels.csv" || true)
  n_p=$(grep -c ',pore,' "$tmp/o/tunnels.csv" || true)
  pockets=$(awk -v a="$complex" -v b="$cavities" 'BEGIN { printf "%.3f", a + b }')
  printf '%-10s %6s %10s %10s %9.3f %7s %5s\n' "$id" "$atoms" "$pockets" "$tunnels" \
    "$(awk -v t="$tunnels" -v p="$pockets" 'BEGIN { print t / p }')" "$n_t" "$n_p"
done | tee "$tmp/rows"
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
echo "median: pockets $(awk '{ print $3 }' "$tmp/rows" | median) s, tunnels and pores $(awk '{ print $4 }' "$tmp/rows" | median) s," \
     "ratio $(awk '{ print $5 }' "$tmp/rows" | median), max tunnels and pores $(awk '{ print $4 }' "$tmp/rows" | sort -g | tail -n 1) s"
