#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Byte-identical outputs: runs a reference build and a candidate build of
# alphapocket on the same inputs and compares everything they print or
# write (a speed-up must change no output). Inputs: the structures of
# tests/data and examples/data, ../shared/data/pockets-dev and formats/
# (`pockets` with every output, `--pores`, `--json`; `surface --per-atom`)
# and the point files of tests/data (`persistence`, `spectrum`,
# `delaunay`, `shape`); `track` over the CHK1 and 1l2y ensembles.
#
# Usage: bench/compare_outputs.sh REF_ALPHAPOCKET NEW_ALPHAPOCKET [FILE...]
#   FILE...  structures to use instead of the default set
# Prints one line per difference and a count; exit code 1 if any.
set -uo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
ref=$(realpath "$1")
new=$(realpath "$2")
shift 2
shared=${SHARED:-$root/../shared}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

if (($#)); then
  structures=()
  for f in "$@"; do structures+=("$(realpath "$f")"); done
else
  structures=("$root"/tests/data/*.pdb "$root"/tests/data/*.cif* "$root"/tests/data/*.pdb.gz "$root"/tests/data/*.ent
              "$root"/tests/data/channels/*.pdb "$root"/examples/data/*.pdb "$shared"/data/pockets-dev/*.pdb
              "$shared"/data/formats/*)
fi

differences=0
runs=0
# same NAME ARGS...: runs both builds, each in its own directory (OUT in ARGS
# names an output path, relative to it); compares exit codes, stdout and the files.
same() {
  local name=$1
  shift
  for side in ref new; do
    local exe=$ref
    [[ $side == new ]] && exe=$new
    rm -rf "${scratch:?}/$side"
    mkdir -p "$scratch/$side"
    (cd "$scratch/$side" && "$exe" "${@//OUT/out}" >stdout 2>/dev/null; echo "exit $?" >>stdout)
  done
  runs=$((runs + 1))
  if ! diff -r -q "$scratch/ref" "$scratch/new" >/dev/null; then
    echo "DIFFERENT: $name"
    differences=$((differences + 1))
  fi
}

for f in "${structures[@]}"; do
  [[ -f $f ]] || continue
  b=$(basename "$f")
  case $b in *.rad|*.txt|*.md|*.xyz) continue ;; esac
  same "pockets $b" pockets "$f" --outputs all -o OUT
  same "pockets --pores --json $b" pockets "$f" --pores --json -o OUT
  same "surface $b" surface "$f" --json --per-atom
done
for f in "$root"/tests/data/*.xyz; do
  b=$(basename "$f")
  same "persistence $b" persistence "$f"
  same "spectrum $b" spectrum "$f" --json
  same "delaunay $b" delaunay "$f" --json
  same "shape $b" shape "$f" --alpha-sq 1 -o OUT.off
done
if ((!$#)); then
  # track over ensembles: ten CHK1 structures (one thread) and an NMR file's models.
  chk1=("$shared"/data/ensembles/chk1_mdpocket/[0-9]*.pdb)
  [[ -f ${chk1[0]} ]] && same "track chk1_mdpocket" track "${chk1[@]}" -j 1 -o OUT
  [[ -f $shared/data/formats/1l2y.pdb ]] && same "track 1l2y" track "$shared/data/formats/1l2y.pdb" -o OUT
fi
echo "$runs runs, $differences different"
((differences == 0))
