#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# CLI tests of `alphapocket delaunay`, one case per CTest test.
# Usage: delaunay.sh ALPHAPOCKET REPO_ROOT CASE
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" "$@"

# A successful --json run (one JSON object), with the counts of a
# triangulated ball: V - E + F - T = 1 (Euler characteristic) and
# 4T = 2F - H (each hull triangle bounds one cell).
expect_json_success() {
  expect_json_object
  local v e f t h
  v=$(json_value vertices) e=$(json_value edges) f=$(json_value triangles)
  t=$(json_value tetrahedra) h=$(json_value hull_triangles)
  [[ $((v - e + f - t)) -eq 1 ]] || fail "Euler characteristic V-E+F-T = $((v - e + f - t)), expected 1"
  [[ $((4 * t)) -eq $((2 * f - h)) ]] || fail "4T = $((4 * t)) but 2F-H = $((2 * f - h))"
}

case $case_name in
  cube_grid)
    run delaunay "$data/cube_grid.xyz" --check --json
    expect_json_success
    expect_json points 64
    expect_json vertices 64
    expect_json duplicates 0
    expect_json hidden 0
    expect_json edges 279
    expect_json triangles 378
    expect_json tetrahedra 162  # what libalpha gives (a 3x3x3-cube grid has no unique DT)
    expect_json hull_triangles 108  # 6 faces x 9 squares x 2 triangles
    expect_json valid true
    ;;
  cube_grid_summary)
    run delaunay "$data/cube_grid.xyz" --check
    expect_success
    grep -q '64 points, 64 vertices' "$tmp/out" || fail "no point count in the summary"
    grep -q '162 tetrahedra' "$tmp/out" || fail "no tetrahedron count in the summary"
    grep -q 'valid: yes' "$tmp/out" || fail "no validity in the summary"
    grep -q 'predicates:.*filtered' "$tmp/err" || fail "predicate counts not logged"
    grep -q 'bytes/point' "$tmp/err" || fail "memory not logged"
    ;;
  no_check)
    run delaunay "$data/cube_grid.xyz" --json
    expect_json_success
    grep -q '"valid"' "$tmp/out" && fail '"valid" present without --check'
    ;;
  quiet)
    run -q delaunay "$data/cube_grid.xyz" --json
    expect_json_success
    [[ ! -s "$tmp/err" ]] || fail "stderr not empty with --quiet"
    ;;
  weighted)
    run delaunay "$data/weighted.xyz" --weighted --check --json
    expect_json_success
    expect_json points 12
    expect_json vertices 10
    expect_json duplicates 1
    expect_json hidden 1
    expect_json valid true
    ;;
  weighted_file_unweighted)
    run delaunay "$data/weighted.xyz" --json
    expect_error "$data/weighted.xyz:6: expected 3 numbers, got 4"
    ;;
  pdb)
    # 2796 atoms, less the ligand CNA (27): the regular triangulation of the
    # atoms (ProtOr radius + probe 1.4 A).
    run delaunay "$pdb" --check --json
    expect_json_success
    expect_json points 2769
    expect_json valid true
    ;;
  pdb_weighted)
    # Structure files are always weighted: --weighted changes nothing.
    run delaunay "$pdb" --check --json
    cp "$tmp/out" "$tmp/plain"
    run delaunay "$pdb" --weighted --check --json
    expect_json_success
    expect_json points 2769
    expect_json valid true
    cmp -s "$tmp/out" "$tmp/plain" || fail "--weighted changed the result of a structure file"
    ;;
  missing_file)
    run delaunay "$tmp/missing.xyz" --json
    expect_error "$tmp/missing.xyz" 'no such file'
    ;;
  missing_structure)
    run delaunay "$tmp/missing.pdb" --json
    expect_error "$tmp/missing.pdb" 'no such file'
    ;;
  directory)
    mkdir "$tmp/dir.xyz"
    run delaunay "$tmp/dir.xyz" --json
    expect_error "$tmp/dir.xyz" 'directory'
    ;;
  empty_file)
    : >"$tmp/empty.xyz"
    run delaunay "$tmp/empty.xyz" --json
    expect_error "$tmp/empty.xyz" 'empty'
    ;;
  empty_structure)
    : >"$tmp/empty.pdb"
    run delaunay "$tmp/empty.pdb" --json
    expect_error "$tmp/empty.pdb" 'empty'
    ;;
  only_comments)
    printf '# nothing here\n\n   \n' >"$tmp/comments.xyz"
    run delaunay "$tmp/comments.xyz" --json
    expect_error "$tmp/comments.xyz" 'no points'
    ;;
  malformed_line)
    printf '0 0 0\n1 0 0\n\n# comment\n0 1\n0 0 1\n' >"$tmp/bad.xyz"
    run delaunay "$tmp/bad.xyz" --json
    expect_error "$tmp/bad.xyz:5: expected 3 numbers, got 2"
    ;;
  trailing_garbage)
    printf '0 0 0\n1 0 0x\n' >"$tmp/bad.xyz"
    run delaunay "$tmp/bad.xyz" --json
    expect_error "$tmp/bad.xyz:2: '0x' is not a number"
    ;;
  not_finite)
    printf '0 0 0\n1 nan 0\n' >"$tmp/bad.xyz"
    run delaunay "$tmp/bad.xyz" --json
    expect_error "$tmp/bad.xyz:2: 'nan' is not a finite number"
    ;;
  out_of_range)
    printf '0 0 0\n1 0 -2e15\n' >"$tmp/bad.xyz"
    run delaunay "$tmp/bad.xyz" --json
    expect_error "$tmp/bad.xyz:2: number '-2e15' is out of range"
    ;;
  negative_radius)
    printf '0 0 0 1\n1 0 0 -0.5\n' >"$tmp/bad.xyz"
    run delaunay "$tmp/bad.xyz" --weighted --json
    expect_error "$tmp/bad.xyz:2: radius '-0.5' is negative"
    ;;
  coplanar)
    printf '0 0 0\n1 0 0\n0 1 0\n1 1 0\n' >"$tmp/flat.xyz"
    run -q delaunay "$tmp/flat.xyz" --json  # the read is logged at info level
    expect_error "$tmp/flat.xyz" 'coplanar'
    ;;
  invalid_structure)
    printf 'data_broken\nloop_\n_atom_site.id\n' >"$tmp/broken.cif"
    run delaunay "$tmp/broken.cif" --json
    expect_error "$tmp/broken.cif"
    ;;
  usage_error)
    run delaunay
    expect_error "FILE is required"
    [[ $rc -eq 2 ]] || fail "exit code $rc, expected 2 for a wrong command line"
    ;;
  version)
    run --version
    expect_success
    # The version of project(VERSION) in CMakeLists.txt, the one place it is set.
    expected=$(sed -n 's/^project(alphapocket VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
    [[ -n $expected ]] || fail "no project(alphapocket VERSION x.y.z) in CMakeLists.txt"
    grep -qx "alphapocket $expected" "$tmp/out" || fail "--version is not 'alphapocket $expected'"
    run pockets "$data/1grm_single.pdb" -o "$tmp/pockets" --tunnels-from none -q
    expect_success
    grep -q "\"alphapocket\": *\"$expected\"" "$tmp/pockets/report.json" || fail "report.json's alphapocket is not $expected"
    ;;
  *)
    echo "unknown case: $case_name" >&2
    exit 2
    ;;
esac
echo "PASS [$case_name]"
