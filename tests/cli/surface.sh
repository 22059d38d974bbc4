#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# CLI tests of `alphapocket surface`, one case per CTest test.
# Usage: surface.sh ALPHAPOCKET REPO_ROOT CASE
#
# Expected areas: 1a26A.pdb (2769 atoms without its ligand, ProtOr radii,
# probe 1.4) has a SASA of 16564.3 A^2; FreeSASA's Lee-Richards gives
# 16564.29 with 2000 slices per atom (tests/molecule/test_surface_area.cpp compares
# atom by atom). Two unit balls at distance 1: volume 9 pi / 4, area 6 pi.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" "$@"

# NUMBER rounded to DIGITS decimals, with awk (in every Debian base system).
rounded() {  # NUMBER DIGITS
  awk -v x="$1" -v d="$2" 'BEGIN { printf "%.*f", d, x }'
}

expect_rounded() {  # KEY DIGITS VALUE
  local got
  got=$(rounded "$(json_value "$1")" "$2")
  [[ "$got" == "$3" ]] || fail "\"$1\" rounds to '$got', expected '$3'"
}

# Two overlapping unit balls.
two_balls() {
  printf '0 0 0 1\n1 0 0 1\n' >"$tmp/two.xyz"
  echo "$tmp/two.xyz"
}

case $case_name in
  json)
    run -q surface "$pdb" --json
    expect_json_object
    expect_json atoms 2769
    expect_json probe 1.4
    expect_json radii '"ProtOr"'
    expect_rounded sa_area 1 16564.3
    expect_rounded sa_volume 1 67402.5
    expect_rounded ms_area 1 15564.2
    expect_rounded ms_volume 1 44942.0
    grep -q per_atom "$tmp/out" && fail "per-atom areas without --per-atom"
    ;;
  summary)
    run surface "$pdb"
    expect_success
    grep -q '1a26A.pdb: 2769 atoms, ProtOr radii + probe 1.4 A' "$tmp/out" || fail "no header line"
    grep -q '^solvent-accessible area    16564.322 A^2$' "$tmp/out" || fail "no area line"
    grep -q '^solvent-accessible volume  67402.524 A^3$' "$tmp/out" || fail "no volume line"
    grep -q '^solvent-excluded area      15564.233 A^2$' "$tmp/out" || fail "no excluded area line"
    grep -q '^solvent-excluded volume    44942.045 A^3$' "$tmp/out" || fail "no excluded volume line"
    grep -q 'union of balls' "$tmp/err" || fail "timings not logged"
    ;;
  per_atom_json)
    # One entry per atom, in file order; they sum to the total.
    run -q surface "$pdb" --json --per-atom
    expect_json_object
    [[ $(grep -o '"serial":' "$tmp/out" | wc -l) -eq 2769 ]] || fail "expected 2769 per-atom entries"
    grep -q '"per_atom":\[{"serial":3,"name":"C","residue":"LYS","seq_num":1,"icode":"","chain":"A","area":0.110585' \
      "$tmp/out" || fail "first atom entry"
    sum=$(grep -o '"area":[^,}]*' "$tmp/out" | cut -d: -f2 | awk '{ s += $1 } END { printf "%.6f", s }')
    [[ $(rounded "$sum" 3) == $(rounded "$(json_value sa_area)" 3) ]] || fail "per-atom areas sum to $sum"
    # Buried atoms have area 0 exactly, never a negative rounding residue.
    grep -q '"area":-' "$tmp/out" && fail "a negative per-atom area"
    [[ $(grep -o '"area":0.0,' "$tmp/out" | wc -l) -gt 1000 ]] || fail "buried atoms should have area 0.0"
    # SA volumes and the molecular surface's area and volume per power cell
    # sum to their totals too.
    for key in volume:sa_volume ms_area:ms_area ms_volume:ms_volume; do
      sum=$(grep -o '"per_atom":.*' "$tmp/out" | grep -o "\"${key%%:*}\":[^,}]*" | cut -d: -f2 |
        awk '{ s += $1 } END { printf "%.6f", s }')
      [[ $(rounded "$sum" 3) == $(rounded "$(json_value "${key#*:}")" 3) ]] || fail "per-atom ${key%%:*} sum to $sum"
    done
    [[ $(grep -o '"ms_volume":' "$tmp/out" | wc -l) -eq 2770 ]] || fail "expected an ms_volume per atom"
    ;;
  per_atom_sa_only)
    # --sa-only: no molecular surface, per atom neither.
    run -q surface "$pdb" --json --per-atom --sa-only
    expect_json_object
    grep -q '"ms_area":[0-9]' "$tmp/out" && fail "per-atom ms_area with --sa-only"
    grep -q '"chain":"A","area":0.110585[0-9]*,"volume":[0-9.]*}' "$tmp/out" || fail "first atom entry"
    ;;
  per_atom_text)
    run -q surface "$pdb" --per-atom
    expect_success
    [[ $(grep -c '^[0-9]* [^ ]* [A-Z]* [0-9A-Z]* A [0-9.]* [0-9.]* [0-9.-]* [0-9.-]*$' "$tmp/out") -eq 2769 ]] ||
      fail "expected 2769 atom lines"
    grep -q '^serial name residue seq_num chain area volume ms_area ms_volume$' "$tmp/out" || fail "no table header"
    ;;
  probe)
    # The van der Waals surface (probe 0); with probe 0.001 FreeSASA (2000
    # slices) gives 36852.59 A^2 and this command 36852.69.
    run -q surface "$pdb" --probe 0 --json
    expect_json_object
    expect_json probe 0.0
    expect_rounded sa_area 1 36848.1
    expect_rounded sa_volume 1 32857.3
    expect_rounded ms_area 1 36848.1  # eroded by 0: the same union
    expect_rounded ms_volume 1 32857.3
    ;;
  sa_only)
    run -q surface "$pdb" --json --sa-only
    expect_json_object
    expect_json ms_volume null
    expect_json ms_area null
    expect_rounded sa_volume 1 67402.5
    ;;
  excluded_between)
    # The molecular body lies between the van der Waals union (probe 0)
    # and the SAS union, and grows with the probe (fewer crevices reached).
    run -q surface "$pdb" --probe 0 --json
    vdw=$(json_value sa_volume)
    run -q surface "$pdb" --probe 0.5 --json
    small=$(json_value ms_volume)
    run -q surface "$pdb" --json
    ms=$(json_value ms_volume) sa=$(json_value sa_volume)
    awk -v v="$vdw" -v s="$small" -v m="$ms" -v a="$sa" 'BEGIN { exit !(v < s && s < m && m < a) }' ||
      fail "expected vdW $vdw < MS(0.5) $small < MS(1.4) $ms < SAS $sa"
    ;;
  deterministic)
    run -q surface "$pdb" --json --per-atom
    cp "$tmp/out" "$tmp/first"
    run -q surface "$pdb" --json --per-atom
    cmp -s "$tmp/out" "$tmp/first" || fail "two runs differ"
    ;;
  weighted_file)
    run -q surface "$(two_balls)" --weighted --json --per-atom
    expect_json_object
    expect_json atoms 2
    expect_json probe null
    expect_json ms_volume null
    expect_json radii '"file"'
    expect_rounded sa_volume 10 "$(rounded 7.0685834705770345 10)"  # 9 pi / 4
    expect_rounded sa_area 10 "$(rounded 18.84955592153876 10)"     # 6 pi
    grep -q '"per_atom":\[{"index":0,"area":9.42477796076938' "$tmp/out" || fail "per-ball area: 3 pi"
    ;;
  one_atom)
    # A structure of one atom (or a flat one) has a surface: a CA (ProtOr
    # 1.88 A) grown by the probe, area 4 pi 3.28^2; eroded, the atom itself.
    printf 'ATOM      1  CA  GLY A   1       1.000   2.000   3.000  1.00  0.00           C\nEND\n' >"$tmp/one.pdb"
    run -q surface "$tmp/one.pdb" --json
    expect_json_object
    expect_json atoms 1
    expect_rounded sa_area 9 "$(rounded 135.19404161752163 9)"
    expect_rounded sa_volume 9 "$(rounded 147.81215216849027 9)"
    expect_rounded ms_area 9 "$(rounded 44.41458029939105 9)"  # 4 pi 1.88^2
    expect_rounded ms_volume 9 "$(rounded 27.833136987618392 9)"
    ;;
  flat_molecule)
    # Atoms in one plane (a ring of 6 carbons 1.4 A apart, as in benzene)
    # have a surface though no 3D triangulation: it differs from the same
    # ring with one atom lifted 0.001 A out of the plane by less than 0.01.
    ring() {  # Z of the first atom
      for k in 0 1 2 3 4 5; do
        awk -v k="$k" -v z="$1" 'BEGIN { a = k * atan2(0, -1) / 3; if (k > 0) z = 0;
          printf "HETATM%5d  C%d  BNZ A   1    %8.3f%8.3f%8.3f  1.00  0.00           C\n",
                 k + 1, k + 1, 1.4 * cos(a), 1.4 * sin(a), z }'
      done
    }
    ring 0 >"$tmp/flat.pdb"
    ring 0.001 >"$tmp/lifted.pdb"
    run -q surface "$tmp/lifted.pdb" --keep-hetero --json
    lifted_sa=$(json_value sa_area) lifted_ms=$(json_value ms_volume)
    run -q surface "$tmp/flat.pdb" --keep-hetero --json
    expect_json_object
    expect_json atoms 6
    sa=$(json_value sa_area) ms=$(json_value ms_volume)
    awk -v a="$sa" -v b="$lifted_sa" -v m="$ms" -v n="$lifted_ms" \
      'BEGIN { exit !(a > 100 && m > 10 && (a - b)^2 < 1e-4 && (m - n)^2 < 1e-4) }' ||
      fail "flat ring: SAS area $sa, molecular volume $ms; lifted: $lifted_sa, $lifted_ms"
    ;;
  unweighted_file)
    printf '0 0 0\n1 0 0\n0 1 0\n0 0 1\n' >"$tmp/points.xyz"
    run surface "$tmp/points.xyz"
    expect_error "$tmp/points.xyz" 'no balls without --weighted'
    ;;
  point_file_with_probe)
    run surface "$(two_balls)" --weighted --probe 1
    expect_error "$tmp/two.xyz" 'but --probe is for structure files'
    ;;
  missing_file)
    run surface "$tmp/none.xyz"  # a point file: said before that it holds no balls
    expect_error "$tmp/none.xyz" 'no such file'
    run surface "$tmp/none.pdb"
    expect_error "$tmp/none.pdb"
    ;;
  invalid_structure)
    printf 'ATOM  garbage\n' >"$tmp/bad.pdb"
    run surface "$tmp/bad.pdb"
    expect_error "$tmp/bad.pdb"
    ;;
  negative_probe)
    run surface "$pdb" --probe -1
    [[ $rc -eq 2 ]] || fail "exit code $rc, expected 2 (usage error)"
    [[ ! -s "$tmp/out" ]] || fail "stdout is not empty"
    grep -q '^ERROR: .*--probe' "$tmp/err" || fail "no usage error naming --probe"
    ;;
  help)
    run surface --help
    expect_success
    grep -q -- '--per-atom' "$tmp/out" || fail "--per-atom not in the help"
    grep -q -- '--probe' "$tmp/out" || fail "--probe not in the help"
    ;;
  *)
    echo "unknown case: $case_name" >&2
    exit 2
    ;;
esac
echo "PASS [$case_name]"
