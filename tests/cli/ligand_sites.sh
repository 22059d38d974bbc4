#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Tests of the ligand-site benchmark's scoring (bench/ligand_sites.cpp), on
# a hand-made dataset whose hits are known: `ligand_sites --reports` reads
# given site centres and runs nothing. Usage: ligand_sites.sh LIGAND_SITES
# REPO_ROOT CASE.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" "$@"

# pdb_atom RECORD SERIAL NAME RESNAME RESSEQ X Y Z ELEMENT: one PDB line.
pdb_atom() {
  printf '%-6s%5d %-4s %3s A%4d    %8.3f%8.3f%8.3f  1.00  0.00          %2s\n' "$@"
}

# Dataset: a.pdb holds ligand L1 (LIG 101 and LIG 102, 1 A apart: merged)
# with atoms (0,0,0), (10,0,0), (11,0,0), centre (7,0,0); ligand L2 (LIG
# 103) at (50,0,0); a water, not listed. b.pdb holds one ligand, a carbon
# at (20,20,20) with a hydrogen 3.5 A away, which does not count.
make_dataset() {
  mkdir -p "$tmp/set" "$tmp/reports/a" "$tmp/reports/b"
  for f in a b; do
    {
      pdb_atom ATOM 1 N ALA 1 -30 -30 -30 N
      pdb_atom ATOM 2 CA ALA 1 -31 -30 -30 C
      pdb_atom ATOM 3 C ALA 1 -31 -31 -30 C
      pdb_atom ATOM 4 O ALA 1 -31 -31 -31 O
      if [[ $f == a ]]; then
        pdb_atom HETATM 5 C1 LIG 101 0 0 0 C
        pdb_atom HETATM 6 C2 LIG 101 10 0 0 C
        pdb_atom HETATM 7 C1 LIG 102 11 0 0 C
        pdb_atom HETATM 8 C1 LIG 103 50 0 0 C
        pdb_atom HETATM 9 O HOH 104 0 0 2 O
      else
        pdb_atom HETATM 5 C1 LIG 101 20 20 20 C
        pdb_atom HETATM 6 H1 LIG 101 20 20 23.5 H
      fi
      echo END
    } >"$tmp/set/$f.pdb"
  done
  printf 'HEADER: protein ligand_codes\n\na.pdb  LIG\nb.pdb  LIG\n' >"$tmp/set/test.ds"
  # Sites of a: 1 is 3.9 A from L1's atom (0,0,0) but 8 A from its
  # centre; 2 is 2 A from L1's centre; 3 is 3.9 A from L2; 4 is near
  # nothing. b's one site is 3.5 A from the hydrogen, 7 A from the carbon.
  echo '{"sites":[{"center":[0,0,3.9]},{"center":[7,0,2]},{"center":[50,3.9,0]},{"center":[80,0,0]}]}' \
    >"$tmp/reports/a/report.json"
  echo '{"sites":[{"center":[20,20,27]}]}' >"$tmp/reports/b/report.json"
}

# sdf_molecule NAME "X Y Z ELEMENT"...: one V2000 molfile and its "$$$$".
sdf_molecule() {
  local name=$1
  shift
  printf '%s\n  test\n\n%3d  0  0  0  0  0  0  0  0  0999 V2000\n' "$name" $#
  for atom in "$@"; do
    read -r x y z e <<<"$atom"
    printf '%10.4f%10.4f%10.4f %-3s 0  0  0  0  0  0  0  0  0  0  0  0\n' "$x" "$y" "$z" "$e"
  done
  printf 'M  END\n$$$$\n'
}

# PoseBusters' layout: e1 has one chain and one copy of its ligand, a carbon
# at (0,0,0); e2 has chains A and B and two copies, at (0,0,0) and at
# (30,0,0) with (33,0,0) (centre (31.5,0,0)), a hydrogen 1 A from the first
# copy, which does not count. e1's one site misses (5 A off); e2's site 1 is
# 3.9 A from the second copy's atom (33,0,0) but 5.4 A from its centre, its
# site 2 is 1 A from the first copy.
make_posebusters() {
  mkdir -p "$tmp/pb/e1" "$tmp/pb/e2" "$tmp/reports/e1" "$tmp/reports/e2"
  protein() {  # four atoms; the last two in chain $1
    pdb_atom ATOM 1 N ALA 1 -30 -30 -30 N
    pdb_atom ATOM 2 CA ALA 1 -31 -30 -30 C
    { pdb_atom ATOM 3 N ALA 2 -20 -30 -30 N; pdb_atom ATOM 4 CA ALA 2 -21 -30 -30 C; } | sed "s/^\(.\{21\}\)A/\1$1/"
  }
  protein A | gzip >"$tmp/pb/e1/protein.pdb.gz"
  protein B | gzip >"$tmp/pb/e2/protein.pdb.gz"
  sdf_molecule e1_LIG "0 0 0 C" >"$tmp/pb/e1/ligands.sdf"
  { sdf_molecule e2_LIG_A "0 0 0 C" "0 0 1 H"; sdf_molecule e2_LIG_B "30 0 0 C" "33 0 0 N"; } >"$tmp/pb/e2/ligands.sdf"
  echo '{"sites":[{"center":[0,5,0]}]}' >"$tmp/reports/e1/report.json"
  echo '{"sites":[{"center":[36.9,0,0]},{"center":[0,0,-1]}]}' >"$tmp/reports/e2/report.json"
}

case "$case_name" in
  scores)
    # L1: DCA rank 1, DCC rank 2; L2: both rank 3; b's ligand: none. Of 3
    # ligands: DCC 0, 2, 2 and DCA 1, 2, 2 at top-1, top-3, top-(n+2).
    make_dataset
    run --reports "$tmp/reports" --json "$tmp/set"
    expect_json_object
    expect_json structures 2
    expect_json ligands 3
    grep -qF '"dcc":[0.0,0.6666666666666666,0.6666666666666666]' "$tmp/out" || fail "dcc"
    grep -qF '"dca":[0.3333333333333333,0.6666666666666666,0.6666666666666666]' "$tmp/out" || fail "dca"
    expect_json sites_median 2.5
    expect_json seconds_median null
    ;;
  details)
    make_dataset
    run --reports "$tmp/reports" --details "$tmp/set"
    expect_success
    grep -qE '^a +4 sites +LIG\+LIG DCC 2 DCA 1 +LIG DCC 3 DCA 3$' "$tmp/err" || fail "details of a"
    grep -qE '^b +1 sites +LIG DCC - DCA -$' "$tmp/err" || fail "details of b"
    ;;
  missing_report)
    make_dataset
    rm "$tmp/reports/b/report.json"
    run --reports "$tmp/reports" "$tmp/set"
    [[ $rc -ne 0 ]] || fail "exit code 0 without a report"
    grep -qF "ERROR: $tmp/reports/b/report.json" "$tmp/err" || fail "the error does not name the missing report"
    ;;
  posebusters)
    # Targets are entries: e2 is found by DCA at rank 1 (any copy counts),
    # by DCC at rank 2; e1 is not found. The multi-chain entry apart.
    make_posebusters
    run --reports "$tmp/reports" --json "$tmp/pb"
    expect_json_object
    expect_json structures 2
    expect_json ligands 2
    grep -qF '"dcc":[0.0,0.5,0.5],"dca":[0.5,0.5,0.5]' "$tmp/out" || fail "dcc/dca"
    grep -qF '"single_chain":{"ligands":1,"dcc":[0.0,0.0,0.0],"dca":[0.0,0.0,0.0],"sites_median":1.0' "$tmp/out" ||
      fail "single-chain figures"
    grep -qF '"multi_chain":{"ligands":1,"dcc":[0.0,1.0,1.0],"dca":[1.0,1.0,1.0],"sites_median":2.0' "$tmp/out" ||
      fail "multi-chain figures"
    run --reports "$tmp/reports" --details "$tmp/pb"
    expect_success
    grep -qE '^e2 +2 sites +e2_LIG_A DCC 2 DCA 1$' "$tmp/err" || fail "details of e2"
    grep -qE '^ +multi-chain \(1\) +0\.000 +1\.000' "$tmp/out" || fail "multi-chain row"
    ;;
  *)
    echo "unknown case $case_name" >&2
    exit 2
    ;;
esac
