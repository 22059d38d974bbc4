#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Dynamic update on the frames of a real MD run (a GROMACS XTC and its TPR,
# e.g. those of tests/cli/track.sh's md_run case: 1l2y in vacuum), written
# as .gro by gmx trjconv; then bench_dynamic_update --frames.
# Usage: bench/dynamic_update_md.sh BUILD_DIR MD.xtc MD.tpr [reps]. Needs gmx (Debian gromacs).
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: dynamic_update_md.sh BUILD_DIR MD.xtc MD.tpr [reps]" >&2; exit 1; }
command -v gmx >/dev/null || { echo "gmx not installed" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo 0 | gmx -quiet trjconv -f "$2" -s "$3" -o "$tmp/frames.gro" >"$tmp/gmx.log" 2>&1 ||
  { tail -n 5 "$tmp/gmx.log" >&2; exit 1; }
"$1/bench/bench_dynamic_update" --frames "$tmp/frames.gro" "${4:-50}"
