#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# How fast the screening index (index.html of `batch`/`merge`) is with
# 10,000 structures and 100,000 sites in headless chromium: the synthetic
# case of tests/browser/index_test.mjs run REPS times; the medians of the
# time to the first screen (from navigation start, as the page measures
# it; target: under 2 s), of sorting the sites by a column and of
# filtering them by a ligand.
#
# Usage: bench/index_page.sh [ALPHAPOCKET]
#   ALPHAPOCKET  default build/apps/alphapocket
# Environment: REPS (default 5).
# Needs chromium, node and `npm ci` in report_assets/ (puppeteer-core).
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
bench_setup "${1:-}"
reps=${REPS:-5}

for ((r = 1; r <= reps; r++)); do
  node "$root/tests/browser/index_test.mjs" "$exe" "$root" synthetic |
    sed -nE 's/.*first screen ([0-9]+) ms .*sort ([0-9]+) ms, filter ([0-9]+) ms.*/\1 \2 \3/p'
done >"$scratch/times"
[[ $(wc -l <"$scratch/times") -eq $reps ]] || { echo "index_page.sh: a run failed" >&2; exit 1; }
printf 'runs %d: first screen %s ms (target < 2000), sort %s ms, filter %s ms (medians)\n' "$reps" \
  "$(cut -d' ' -f1 "$scratch/times" | median)" "$(cut -d' ' -f2 "$scratch/times" | median)" \
  "$(cut -d' ' -f3 "$scratch/times" | median)"
