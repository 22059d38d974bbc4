#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The per-structure cost target: the CPU time of `alphapocket pockets`
# with its default outputs against fpocket 4.0's on the same chain, one
# process each, alternating, in the same run; the median of the
# per-structure ratios.
#
# Usage: bench/pockets_cpu.sh [ALPHAPOCKET] [DIR]
#   ALPHAPOCKET  default build/apps/alphapocket
#   DIR          a folder of .pdb files, default ../shared/data/pockets-train
# Environment: STEP (every STEP-th file of DIR in name order, default 1:
# all), SHARED (default ../shared beside the repository), CACHE (where
# fpocket is built, see batch_throughput.sh).
# Needs GNU time (/usr/bin/time); make and g++ to build fpocket.
#
# Prints one line per structure (atoms, our CPU s, fpocket's, the ratio),
# then the median ratio and the medians of both CPU times. CPU = user +
# system of the process (steadier than wall-clock time on a shared machine).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=$(realpath "${1:-$root/build/apps/alphapocket}")
shared=${SHARED:-$root/../shared}
data=$(realpath "${2:-$shared/data/pockets-train}")
step=${STEP:-1}
cache=${CACHE:-$HOME/.cache/alphapocket-bench}

[[ -x /usr/bin/time ]] || { echo "/usr/bin/time not found (Debian: apt-get install time)" >&2; exit 1; }
[[ -x $exe ]] || { echo "$exe: not an executable (build alphapocket first)" >&2; exit 1; }

source "$root/bench/fpocket.sh"
fpocket=$(fpocket_binary "$cache" "$shared/peers")

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

cpu() {  # COMMAND...: user + system CPU seconds
  /usr/bin/time -f '%U %S' -o "$scratch/time" "$@" >/dev/null 2>&1 || true
  awk '{ print $1 + $2 }' "$scratch/time"
}
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

printf '%-10s %7s %9s %9s %7s\n' id atoms ours_cpu fp_cpu ratio
: >"$scratch/rows"
k=0
for f in "$data"/*.pdb; do
  if ((k++ % step)); then continue; fi
  id=$(basename "$f" .pdb)
  # fpocket writes beside its input: it reads a copy.
  cp "$f" "$scratch/$id.pdb"
  rm -rf "$scratch/ours"
  a=$(cpu "$exe" -q pockets "$f" -o "$scratch/ours")
  b=$(cpu "$fpocket" -f "$scratch/$id.pdb")
  rm -rf "$scratch/$id.pdb" "$scratch/${id}_out"
  atoms=$(grep -c '^ATOM\|^HETATM' "$f" || true)
  awk -v id="$id" -v n="$atoms" -v a="$a" -v b="$b" \
    'BEGIN { printf "%-10s %7d %9.2f %9.2f %7.3f\n", id, n, a, b, (b > 0 ? a / b : 0) }' | tee -a "$scratch/rows"
done
awk '{ print $5 }' "$scratch/rows" | median >"$scratch/r"
awk '{ print $3 }' "$scratch/rows" | median >"$scratch/a"
awk '{ print $4 }' "$scratch/rows" | median >"$scratch/b"
echo "$(wc -l <"$scratch/rows") structures from $data (STEP=$step); load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "median ratio ours/fpocket CPU: $(cat "$scratch/r"); median CPU s: ours $(cat "$scratch/a"), fpocket $(cat "$scratch/b")"
