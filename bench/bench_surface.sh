#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Times `alphapocket surface` against FreeSASA's Lee-Richards on the PDB
# files shipped in the repository, in the same run, and compares their
# solvent-accessible surface areas (ProtOr radii, probe 1.4 A, hydrogens
# and waters left out by both).
#
# Usage: bench/bench_surface.sh [ALPHAPOCKET] [FILE.pdb ...]
#   ALPHAPOCKET  default build/apps/alphapocket
#   FILEs        default examples/data/*.pdb tests/data/*.pdb
# Environment: REPS (timed repetitions, default 5), FINE (slices per atom of
# FreeSASA's reference run, default 16000). Takes a few minutes.
#
# For each file:
#   - FreeSASA with FINE slices is the reference (Lee-Richards converges to
#     the exact area, slowly and not monotonically: about 1e-6 at 2000
#     slices, 5e-8 at 16000); "ours" is our relative difference from it.
#   - FreeSASA runs once per slice count 20 (its default), 50, 100, ..., 2000,
#     and its relative error against the reference is printed for each; n*
#     is the smallest count whose error is at most ours ("equal accuracy").
#     When none is, n* is 2000, marked ">2000": its time is then a lower
#     bound of FreeSASA's time at equal accuracy.
#   - median wall-clock times over REPS runs, both programs single-threaded
#     (freesasa -t 1), whole processes (reading the file included): ours, and
#     FreeSASA at 20 slices and at n*; ratios are FreeSASA time / our time.
# FreeSASA leaves out all HETATM records, alphapocket only hetero groups (a
# peptide or modified residue written as HETATM inside a polymer is kept),
# so a file with such records compares different atom sets: the script
# says so and skips it.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=${1:-$root/build/apps/alphapocket}
[[ $# -gt 0 ]] && shift
files=("$@")
if [[ ${#files[@]} -eq 0 ]]; then
  files=("$root"/examples/data/*.pdb "$root"/tests/data/*.pdb)
fi
reps=${REPS:-5}
fine=${FINE:-16000}
ladder=(20 50 100 200 500 1000 2000)

command -v freesasa >/dev/null || { echo "freesasa not found (Debian: apt-get install freesasa)" >&2; exit 1; }
[[ -x $exe ]] || { echo "$exe: not an executable (build alphapocket first)" >&2; exit 1; }

now() { date +%s.%N; }

# FreeSASA's total area with N slices per atom, full precision (JSON).
freesasa_area() {  # FILE N [THREADS]
  freesasa --lee-richards --resolution="$2" --probe-radius=1.4 -t "${3:-1}" --format=json "$1" 2>/dev/null |
    grep -o '"total":[0-9.e+-]*' | tail -n 1 | cut -d: -f2
}

freesasa_atoms() {  # FILE: the atoms FreeSASA keeps
  freesasa --resolution=1 --format=pdb "$1" 2>/dev/null | grep -c '^ATOM\|^HETATM'
}

# The median wall-clock seconds of REPS runs of a command.
median_time() {
  local k s e
  for ((k = 0; k < reps; ++k)); do
    s=$(now)
    "$@" >/dev/null 2>&1
    e=$(now)
    awk -v s="$s" -v e="$e" 'BEGIN { printf "%.6f\n", e - s }'
  done | sort -g | awk '{ t[NR] = $1 } END { print (NR % 2) ? t[(NR + 1) / 2] : (t[NR / 2] + t[NR / 2 + 1]) / 2 }'
}

rel() { awk -v a="$1" -v b="$2" 'BEGIN { d = (a - b) / b; printf "%.1e", d < 0 ? -d : d }'; }

printf '%-12s %6s %12s %9s | %8s %8s %7s | %5s %8s %7s | %7s %7s\n' \
  file atoms "area A^2" ours "t_ours" "t_fs20" "err20" "n*" "t_fs_n*" "err_n*" "x20" "x_n*"
for f in "${files[@]}"; do
  name=$(basename "$f")
  json=$("$exe" -q surface "$f" --json --sa-only 2>/dev/null)
  ours=$(grep -o '"sa_area":[^,]*' <<<"$json" | cut -d: -f2)
  atoms=$(grep -o '"atoms":[^,]*' <<<"$json" | cut -d: -f2)
  if [[ $atoms -ne $(freesasa_atoms "$f") ]]; then
    echo "$name: skipped, FreeSASA keeps $(freesasa_atoms "$f") atoms and alphapocket $atoms (HETATM polymer records)"
    continue
  fi
  reference=$(freesasa_area "$f" "$fine" 2)
  ours_err=$(rel "$ours" "$reference")
  nstar="" errors=""
  for n in "${ladder[@]}"; do
    e=$(rel "$(freesasa_area "$f" "$n")" "$reference")
    errors+=" $n:$e"
    [[ $n -eq 20 ]] && err20=$e
    if [[ -z $nstar ]] && awk -v e="$e" -v o="$ours_err" 'BEGIN { exit !(e <= o) }'; then
      nstar=$n errstar=$e
    fi
  done
  shown=$nstar
  [[ -z $nstar ]] && nstar=${ladder[-1]} errstar=$e shown=">${ladder[-1]}"
  t_ours=$(median_time "$exe" -q surface "$f" --json --sa-only)
  t_fs20=$(median_time freesasa --lee-richards --resolution=20 -t 1 "$f")
  t_fsn=$(median_time freesasa --lee-richards --resolution="$nstar" -t 1 "$f")
  printf '%-12s %6d %12.3f %9s | %8.4f %8.4f %7s | %5s %8.4f %7s | %7.1f %7.1f\n' \
    "$name" "$atoms" "$ours" "$ours_err" "$t_ours" "$t_fs20" "$err20" "$shown" "$t_fsn" "$errstar" \
    "$(awk -v a="$t_fs20" -v b="$t_ours" 'BEGIN { print a / b }')" \
    "$(awk -v a="$t_fsn" -v b="$t_ours" 'BEGIN { print a / b }')"
  echo "  FreeSASA error by slices per atom:$errors"
done
