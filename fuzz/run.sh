#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs the libFuzzer targets of a fuzz build for a bounded time each.
#
#   fuzz/run.sh BUILD_DIR SECONDS [TARGET...]
#
# BUILD_DIR: configured with clang and -DALPHAPOCKET_FUZZ=ON (.ci/sanitizers
# does it). Each target first replays its regression inputs
# (fuzz/regressions/TARGET/: inputs that once found a bug), then fuzzes
# for SECONDS from a seed corpus (tests/data and the corpus kept in
# fuzz/corpus/TARGET/, which it first replays: the minimised inputs of
# the long runs, see fuzz/README.md) with the PDB/mmCIF dictionary. The random seed is fixed ($FUZZ_SEED, default 1) so that a
# CI run can be replayed; hunting runs set another one. The corpus grows in $FUZZ_CORPUS/TARGET (default: a
# temporary directory, removed at the end); a crash, leak, timeout or
# sanitizer report stops with exit 1, its input saved as
# $FUZZ_ARTIFACTS/TARGET-crash-... (default: the current directory).
set -euo pipefail

build=$1
seconds=$2
shift 2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(dirname "$here")
data=$root/tests/data
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(fuzz_structure fuzz_point_file fuzz_triangulation fuzz_pockets)
artifacts=${FUZZ_ARTIFACTS:-$PWD}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# The seed files of a target, and its libFuzzer options.
seeds() {
  case $1 in
    fuzz_structure) ls "$data"/*.pdb "$data"/*.cif "$data"/*.gz "$data"/*.ent "$data"/bad/* "$data"/catalog/* ;;
    # Small structures only: one input is one whole pocket search.
    fuzz_pockets) ls "$data"/bad/* "$data"/catalog/* ;;
    fuzz_point_file) ls "$data"/*.xyz ;;
    fuzz_triangulation) ;;
  esac
}
options() {
  case $1 in
    fuzz_structure) echo "-dict=$here/structure.dict -max_len=262144" ;;
    fuzz_pockets) echo "-dict=$here/structure.dict -max_len=16384" ;;
    fuzz_point_file) echo "-dict=$here/points.dict -max_len=4096" ;;
    fuzz_triangulation) echo "-max_len=1024" ;;
  esac
}

status=0
for target in "${targets[@]}"; do
  exe=$build/fuzz/$target
  [[ -x $exe ]] || { echo "fuzz/run.sh: $exe not built" >&2; exit 1; }
  regressions=$here/regressions/$target
  if [[ -d $regressions ]] && [[ -n $(ls -A "$regressions") ]]; then
    echo "== $target: replaying $(ls "$regressions" | wc -l) regression inputs"
    "$exe" $(options "$target") "$regressions"/* >"$scratch/$target.replay.log" 2>&1 ||
      { cat "$scratch/$target.replay.log"; status=1; continue; }
  fi
  kept=$here/corpus/$target
  if [[ -d $kept ]]; then
    echo "== $target: replaying the $(ls "$kept" | wc -l) inputs of its kept corpus"
    "$exe" $(options "$target") -runs=0 -timeout=30 -rss_limit_mb=2560 "$kept" >"$scratch/$target.corpus.log" 2>&1 ||
      { tail -n 60 "$scratch/$target.corpus.log"; status=1; continue; }
  fi
  corpus=${FUZZ_CORPUS:+$FUZZ_CORPUS/$target}
  corpus=${corpus:-$scratch/corpus/$target}
  mkdir -p "$corpus" "$scratch/seeds/$target"
  for f in $(seeds "$target"); do cp "$f" "$scratch/seeds/$target/"; done
  echo "== $target: fuzzing for $seconds s"
  if "$exe" $(options "$target") -seed="${FUZZ_SEED:-1}" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2560 \
      -print_final_stats=1 -artifact_prefix="$artifacts/$target-" \
      "$corpus" "$scratch/seeds/$target" $([[ -d $kept ]] && echo "$kept") >"$scratch/$target.log" 2>&1; then
    grep -E '^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)|^#[0-9]+.*DONE' "$scratch/$target.log" || true
  else
    tail -n 60 "$scratch/$target.log"
    echo "== $target: FAILED (input saved under $artifacts/$target-*)"
    status=1
  fi
done
exit $status
