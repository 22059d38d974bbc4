#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# CLI tests of the tunnels and pores of `alphapocket pockets` (--tunnels-from,
# --tunnel-probe, --pores, --radii) and their files: tunnels.csv,
# tunnel_profiles.csv, tunnels.pdb. The paths themselves are checked in
# tests/molecule/test_tunnel_paths.cpp. Usage: tunnels.sh ALPHAPOCKET REPO_ROOT CASE
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" "$@"

grm=$data/channels/1grm_single.pdb
rad=$data/channels/simple.rad

case "$case_name" in
  gramicidin_pore)
    # HOLE's example: one pore, its minimum radius near HOLE's 1.198 A.
    run pockets "$grm" --radii "$rad" --pores --keep-hetero -o "$tmp/g"
    expect_success
    grep -qE '^widest pore: bottleneck radius 1\.(19|20) A' "$tmp/out" || fail "no pore line of radius 1.19-1.20 A"
    [[ $(grep -c ',pore,' "$tmp/g/tunnels.csv") -eq 1 ]] || fail "not one pore in tunnels.csv"
    # HOLE: 1.198 A (its spheres touch the same van der Waals radii).
    bottleneck=$(awk -F, '$2 == "pore" { print $4 }' "$tmp/g/tunnels.csv")
    awk -v b="$bottleneck" 'BEGIN { exit !(b >= 1.178 && b <= 1.218) }' ||
      fail "pore bottleneck radius $bottleneck A, HOLE's is 1.198 A"
    head -n 1 "$tmp/g/tunnel_profiles.csv" | grep -qx 'tunnel,distance,x,y,z,radius' || fail "profile header"
    grep -qF "\"radii\": \"$rad\"" "$tmp/g/report.json" || fail "parameters.radii is not the file"
    grep -qF '"kind": "pore"' "$tmp/g/report.json" || fail "no pore in report.json"
    # tunnels.pdb: one TUN atom per profile point, B = the profile's radius.
    [[ $(grep -c '^HETATM.* TUN TUN P' "$tmp/g/tunnels.pdb") -eq $(($(wc -l <"$tmp/g/tunnel_profiles.csv") - 1)) ]] ||
      fail "tunnels.pdb and tunnel_profiles.csv differ in length"
    first_b=$(grep -m1 '^HETATM' "$tmp/g/tunnels.pdb" | cut -c61-66 | tr -d ' ')
    first_r=$(sed -n 2p "$tmp/g/tunnel_profiles.csv" | cut -d, -f6)
    [[ $(printf '%.2f' "$first_r") == "$first_b" ]] || fail "B $first_b is not the radius $first_r"
    ;;
  tunnels_from)
    # Every kind of start; a tunnel row names its start. (Site rank 1 of the
    # geometric ranking is pocket 1, which tunnels leave; the model's first
    # site is a small pocket off them.)
    for from in auto 1 A:49,A:105 26.5,10.3,42.0; do
      ranking=()
      [[ $from != 1 ]] || ranking=(--ranking geometric)
      run pockets "$pdb" --tunnels-from "$from" "${ranking[@]}" -o "$tmp/t"
      expect_success
      grep -q ',tunnel,' "$tmp/t/tunnels.csv" || fail "no tunnel from $from"
    done
    run pockets "$pdb" --tunnels-from none -o "$tmp/t"
    expect_success
    [[ -s $tmp/t/tunnels.csv ]] || fail "no tunnels.csv with --tunnels-from none"
    # Every cycle (1a26A's are all open to a 0.9 A probe) has the length of
    # the way through it, whatever the starts: report.json has its profile.
    [[ $(awk -F, '$2 == "cycle" && $8 > 0' "$tmp/t/tunnels.csv" | wc -l) -ge 1 &&
       $(awk -F, '$2 == "cycle" && $8 == ""' "$tmp/t/tunnels.csv" | wc -l) -eq 0 ]] || fail "a cycle without a way through"
    cycles=$(grep -c '^[0-9]*,cycle,' "$tmp/t/tunnels.csv")
    [[ $(grep -c '"kind": "cycle"' "$tmp/t/report.json") -eq $cycles ]] || fail "report.json and tunnels.csv differ in cycles"
    # ... its points in tunnel_profiles.csv (ranks 1..cycles) and in
    # tunnels.pdb (chain C), one atom per row.
    [[ $(awk -F, -v c="$cycles" 'NR > 1 && $1 <= c { print $1 }' "$tmp/t/tunnel_profiles.csv" | sort -u | wc -l) -eq $cycles ]] ||
      fail "not every cycle in tunnel_profiles.csv"
    [[ $(grep -c '^HETATM.* TUN TUN C' "$tmp/t/tunnels.pdb") -eq \
       $(awk -F, -v c="$cycles" 'NR > 1 && $1 <= c' "$tmp/t/tunnel_profiles.csv" | wc -l) ]] ||
      fail "tunnels.pdb's chain C and tunnel_profiles.csv's cycles differ"
    ! grep -q ',tunnel,' "$tmp/t/tunnels.csv" || fail "tunnels with --tunnels-from none"
    # A wider probe passes fewer ways: no wider bottleneck than it.
    run pockets "$pdb" --tunnel-probe 1.5 -o "$tmp/t"
    expect_success
    awk -F, 'NR > 1 && $2 == "tunnel" { n++; if ($4 < 1.5 - 5e-4) bad = bad " " $4 }
      END { if (!n) print "no tunnel row"; else if (bad != "") print "bottlenecks below the probe:" bad }' \
      "$tmp/t/tunnels.csv" >"$tmp/bad"
    [[ ! -s $tmp/bad ]] || fail "--tunnel-probe 1.5: $(cat "$tmp/bad")"
    ;;
  bad_options)
    # (-q: a start that is no site is known only once the sites are.)
    run -q pockets "$pdb" --tunnels-from 99 -o "$tmp/t"
    expect_error "$pdb" "there are [0-9]+ sites"
    [[ ! -e "$tmp/t" ]] || fail "OUTDIR left behind"
    run -q pockets "$pdb" --tunnels-from B:1 -o "$tmp/t"
    expect_error "$pdb" "no atom of residue B:1"
    run -q pockets "$pdb" --tunnels-from x -o "$tmp/t"
    expect_error "$pdb" "expected auto"
    printf 'ALA CB 1.8\nALA CA\n' >"$tmp/bad.rad"
    run -q pockets "$pdb" --radii "$tmp/bad.rad" -o "$tmp/t"
    expect_error "$tmp/bad.rad: line 2"
    run -q pockets "$pdb" --radii "$tmp/missing.rad" -o "$tmp/t"
    expect_error "$tmp/missing.rad"
    run -q pockets "$pdb" --tunnel-probe 0 -o "$tmp/t"
    [[ $rc -eq 2 ]] || fail "--tunnel-probe 0: exit $rc, expected 2"
    ;;
  *)
    echo "unknown case $case_name" >&2
    exit 2
    ;;
esac
