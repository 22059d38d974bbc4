#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# What writing report.html costs `alphapocket pockets`: the CPU time with
# the default outputs against the same without html (--outputs
# report,csv,pml,pdb,tunnels), alternating, in the same run, on chains of
# a folder; the median of the per-structure ratios (target: at most 1.10),
# and the page's own size (report.html without the shared viewer/ files).
#
# Usage: bench/report_page.sh [ALPHAPOCKET] [DIR]
#   ALPHAPOCKET  default build/apps/alphapocket
#   DIR          a folder of .pdb files, default ../shared/data/pockets-dev
# Environment: STEP (every STEP-th file, default 4), REPS (runs of each
# per structure, default 3; the median is kept).
# Needs GNU time (/usr/bin/time) and Mol* installed (`npm ci` in report_assets/).
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
bench_setup "${1:-}"
data=$(realpath "${2:-$root/../shared/data/pockets-dev}")
step=${STEP:-4}

cpu() {  # COMMAND...: user + system CPU seconds
  /usr/bin/time -f '%U %S' -o "$scratch/time" "$@" >/dev/null 2>&1
  awk '{ print $1 + $2 }' "$scratch/time"
}

printf '%-10s %6s %8s %8s %6s %9s\n' file atoms without with ratio page_kB
ratios=()
i=0
for pdb in "$data"/*.pdb; do
  (( i++ % step == 0 )) || continue
  without=() with=()
  for ((r = 0; r < reps; ++r)); do
    without+=("$(cpu "$exe" -q pockets "$pdb" -o "$scratch/a" --outputs report,csv,pml,pdb,tunnels)")
    with+=("$(cpu "$exe" -q pockets "$pdb" -o "$scratch/b" --outputs report,csv,pml,pdb,tunnels,html)")
  done
  a=$(printf '%s\n' "${without[@]}" | median)
  b=$(printf '%s\n' "${with[@]}" | median)
  atoms=$(grep -o '"atoms": [0-9]*' "$scratch/b/report.json" | head -1 | grep -o '[0-9]*$')
  kb=$(( $(stat -c %s "$scratch/b/report.html") / 1024 ))
  ratio=$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.3f", b / a }')
  ratios+=("$ratio")
  printf '%-10s %6s %8s %8s %6s %9s\n' "$(basename "$pdb" .pdb)" "$atoms" "$a" "$b" "$ratio" "$kb"
done
echo "median ratio (with html / without): $(printf '%s\n' "${ratios[@]}" | median)"
echo "viewer/ (shared, per output directory): $(du -sk "$scratch/b/viewer" | cut -f1) kB"
