#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# CLI tests of `alphapocket spectrum`, `persistence` and `shape`, one case
# per CTest test. Exit code 77 means skipped.
# Usage: alpha.sh ALPHAPOCKET REPO_ROOT CASE
#
# Most cases use tests/data/cube_grid.xyz, the 4x4x4 unit grid. Its alpha
# filtration is known by hand: at alpha_sq 0 the 64 points; at 0.25 the 144
# unit edges (a grid graph: 1 component, 144 - 64 + 1 = 81 independent
# cycles); at 0.5 every unit square (its two triangles of circumradius^2
# 1/2), so each of the 27 unit cubes encloses a void and the cycles die; at
# 0.75 all tetrahedra (circumradius^2 of a unit cube 3/4): the solid cube
# [0,3]^3, volume 27, bounded by 108 triangles on 56 points.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" "$@"
grid=$data/cube_grid.xyz

# The values of KEY in stdout, one per "at" entry, space-separated.
json_values() {
  grep -o "\"$1\":\(\[[^]]*\]\|[^,}]*\)" "$tmp/out" | cut -d: -f2 | tr '\n' ' ' | sed 's/ $//'
}

expect_json_values() {  # KEY "VALUE VALUE ..."
  local got
  got=$(json_values "$1")
  [[ "$got" == "$2" ]] || fail "\"$1\" values are '$got', expected '$2'"
}

# The number of lines of stdout that are exactly LINE.
count_lines() {
  grep -cxF "$1" "$tmp/out" || true
}

# Files in directory DIR (hidden ones too), one line.
files_in() {
  ls -A "$1" | tr '\n' ' ' | sed 's/ $//'
}

# The OFF file FILE is a closed, consistently oriented triangle surface with
# manifold edges: every directed edge of its faces occurs once, and so does
# its reverse. Prints 6 x the enclosed volume (divergence theorem), for
# integer coordinates only: positive when the faces are oriented outward.
off_closed_volume6() {
  local file=$1 header nv nf i x y z n a b c
  local -a px py pz
  {
    read -r header
    [[ $header == OFF ]] || fail "$file: not an OFF file"
    read -r nv nf _
    for ((i = 0; i < nv; ++i)); do
      read -r x y z
      [[ "$x $y $z" =~ ^-?[0-9]+\ -?[0-9]+\ -?[0-9]+$ ]] || fail "$file: vertex '$x $y $z' is not integer"
      px[i]=$x py[i]=$y pz[i]=$z
    done
    local volume6=0
    : >"$tmp/edges"
    for ((i = 0; i < nf; ++i)); do
      read -r n a b c
      [[ $n -eq 3 ]] || fail "$file: face $i is not a triangle"
      printf '%s %s\n%s %s\n%s %s\n' "$a" "$b" "$b" "$c" "$c" "$a" >>"$tmp/edges"
      # a . (b x c)
      volume6=$((volume6 + px[a] * (py[b] * pz[c] - pz[b] * py[c]) - py[a] * (px[b] * pz[c] - pz[b] * px[c]) +
                 pz[a] * (px[b] * py[c] - py[b] * px[c])))
    done
  } <"$file"
  sort "$tmp/edges" >"$tmp/forward"
  [[ -z $(uniq -d "$tmp/forward") ]] || fail "$file: a directed edge occurs twice"
  while read -r a b; do echo "$b $a"; done <"$tmp/forward" | sort >"$tmp/reverse"
  cmp -s "$tmp/forward" "$tmp/reverse" || fail "$file: not closed (an edge lacks its reverse)"
  echo "$volume6"
}

case $case_name in
  # ---- spectrum ----------------------------------------------------------
  spectrum_grid)
    run spectrum "$grid" --json
    expect_json_object
    expect_json points 64
    expect_json vertices 64
    expect_json spectrum_size 4  # 0, 0.25, 0.5, 0.75
    expect_json optimal_alpha_sq 0.25
    [[ $(grep -o '"alpha_sq"' "$tmp/out" | wc -l) -eq 1 ]] || fail "expected one \"at\" entry"
    expect_json_values alpha_sq 0.25  # the optimal one when no --alpha-sq is given
    expect_json_values betti '[1,81,0]'
    expect_json_values components 1
    grep -q '"vertices":{"exterior":0,"singular":0,"regular":64,"interior":0}' "$tmp/out" ||
      fail "vertex classification at 0.25"
    grep -q '"edges":{"exterior":135,"singular":144,"regular":0,"interior":0}' "$tmp/out" ||
      fail "edge classification at 0.25 (the 144 unit edges are singular)"
    ;;
  spectrum_levels)
    # A simplex whose value equals alpha_sq is present: the unit edges enter
    # at exactly 0.25, and not at the double just below it.
    run spectrum "$grid" --alpha-sq 0 --alpha-sq 0.24999999999999997 --alpha-sq 0.25 --alpha-sq 0.5 \
      --alpha-sq 0.75 --alpha-sq -1 --alpha-sq=100 --json
    expect_json_object
    expect_json_values alpha_sq '0.0 0.24999999999999997 0.25 0.5 0.75 -1.0 100.0'
    expect_json_values betti '[64,0,0] [64,0,0] [1,81,0] [1,0,27] [1,0,0] [0,0,0] [1,0,0]'
    expect_json_values components '64 64 1 1 1 0 1'
    volumes=($(json_values volume))
    [[ ${volumes[0]} == 0.0 && ${volumes[3]} == 0.0 ]] || fail "volume before 0.75 not 0"
    [[ ${volumes[4]} =~ ^(27\.0{10}[0-9]*|26\.9{10}[0-9]*)$ ]] || fail "volume at 0.75 is ${volumes[4]}, expected 27"
    areas=($(json_values area))
    [[ ${areas[3]} == 108.0 ]] || fail "area at 0.5 is ${areas[3]}, expected 108 (216 singular unit triangles)"
    [[ ${areas[4]} == 54.0 ]] || fail "area at 0.75 is ${areas[4]}, expected 54 (the cube's surface)"
    grep -q '"tetrahedra":{"exterior":0,"singular":0,"regular":0,"interior":162}' "$tmp/out" ||
      fail "tetrahedra at 0.75 not all interior"
    grep -q '"triangles":{"exterior":0,"singular":0,"regular":108,"interior":270}' "$tmp/out" ||
      fail "triangles at 0.75: 108 on the surface expected"
    ;;
  spectrum_summary)
    run spectrum "$grid" --alpha-sq 0.5
    expect_success
    grep -q '64 points, 64 vertices, 4 critical values of alpha_sq from 0 to 0.75' "$tmp/out" ||
      fail "no spectrum in the summary"
    grep -q '^optimal alpha_sq: 0.25' "$tmp/out" || fail "no optimal alpha in the summary"
    grep -q '^alpha_sq 0.5: betti 1 0 27, components 1' "$tmp/out" || fail "no Betti numbers in the summary"
    grep -q 'alpha complex: .* 4 critical values' "$tmp/err" || fail "alpha complex not logged"
    ;;
  spectrum_weighted)
    # tests/data/weighted.xyz: radius-2 balls on the corners of a cube of
    # side 2, a hidden point, a duplicate, two small balls outside.
    run spectrum "$data/weighted.xyz" --weighted --alpha-sq -0.625 --alpha-sq -0.6250000000000001 --json
    expect_json_object
    expect_json points 12
    expect_json vertices 10
    expect_json optimal_alpha_sq -0.625  # negative: the balls overlap before alpha reaches 0
    expect_json_values components '1 3'
    ;;
  spectrum_pdb)
    run -q spectrum "$pdb" --json  # the 2769 atoms left without the ligand
    expect_json_object
    expect_json points 2769
    expect_json vertices 2769
    expect_json_values components 1
    grep -q '"singular":0,"regular":2769,"interior":0}' "$tmp/out" ||
      fail "at the optimal alpha every vertex is on the shape"
    ;;
  spectrum_optimal_roundtrip)
    # The printed optimal alpha_sq, fed back, gives the shape it names: one
    # component (the nearest double may lie below the exact critical value).
    for flags in "" --weighted; do
      run -q spectrum "$pdb" $flags --json
      expect_success
      optimal=$(json_values optimal_alpha_sq)
      run -q spectrum "$pdb" $flags --alpha-sq "$optimal" --json
      expect_success
      expect_json_values components 1
    done
    ;;
  spectrum_not_finite)
    run spectrum "$grid" --alpha-sq nan --json
    expect_error "--alpha-sq: 'nan' is not a finite number"
    [[ $rc -eq 2 ]] || fail "exit code $rc, expected 2 for a wrong command line"
    ;;
  help)
    for command in spectrum shape; do
      run "$command" --help
      expect_success
      grep -q 'SQUARED radius' "$tmp/out" || fail "$command --help does not say alpha is a squared radius"
      grep -q "CGAL's convention" "$tmp/out" || fail "$command --help does not state the convention"
    done
    run persistence --help
    expect_success
    grep -q "dim birth_sq death_sq" "$tmp/out" || fail "persistence --help does not give the format"
    ;;
  spectrum_missing_file)
    run spectrum "$tmp/missing.xyz" --json
    expect_error "$tmp/missing.xyz" 'no such file'
    ;;
  spectrum_coplanar)
    printf '0 0 0\n1 0 0\n0 1 0\n1 1 0\n' >"$tmp/flat.xyz"
    run -q spectrum "$tmp/flat.xyz" --json
    expect_error "$tmp/flat.xyz" 'coplanar'
    ;;

  # ---- persistence -------------------------------------------------------
  persistence_grid)
    run persistence "$grid"
    expect_success
    [[ $(count_lines '0 0 0.25') -eq 63 ]] || fail "expected 63 components dying at 0.25"
    [[ $(count_lines '0 0 inf') -eq 1 ]] || fail "expected one component living forever"
    [[ $(count_lines '1 0.25 0.5') -eq 81 ]] || fail "expected 81 cycles born at 0.25, dying at 0.5"
    [[ $(count_lines '2 0.5 0.75') -eq 27 ]] || fail "expected 27 voids (one per unit cube) from 0.5 to 0.75"
    [[ $(wc -l <"$tmp/out") -eq 172 ]] || fail "expected 172 lines, no others"
    [[ -z $(sort "$tmp/out" | uniq | grep -vxF -e '0 0 0.25' -e '0 0 inf' -e '1 0.25 0.5' -e '2 0.5 0.75') ]] ||
      fail "unexpected lines"
    grep -q '172 persistence pairs' "$tmp/err" || fail "pair count not logged"
    ;;
  persistence_threads)
    # 2^15 points or more are triangulated, their complex built and the
    # diagram's 230,000 lines formatted on -j threads: the cells are
    # numbered otherwise, the diagram and the counts stay the same.
    awk 'BEGIN { srand(7); for (i = 0; i < 40000; i++) printf "%.9f %.9f %.9f\n", rand(), rand(), rand() }' >"$tmp/cloud.xyz"
    run persistence "$tmp/cloud.xyz"
    expect_success
    mv "$tmp/out" "$tmp/one"
    run persistence "$tmp/cloud.xyz" -j 2
    expect_success
    cmp -s "$tmp/one" "$tmp/out" || fail "persistence -j 2 differs from -j 1"
    [[ $(wc -l <"$tmp/out") -gt 100000 ]] || fail "expected the pairs of 40000 points"
    run delaunay "$tmp/cloud.xyz" --json --check
    expect_json_object
    mv "$tmp/out" "$tmp/one"
    run delaunay "$tmp/cloud.xyz" --json --check -j 3
    expect_json valid true
    cmp -s "$tmp/one" "$tmp/out" || fail "delaunay -j 3 differs from -j 1"
    run persistence "$tmp/cloud.xyz" -j 0
    [[ $rc -eq 2 ]] || fail "-j 0 should be a usage error (exit 2), got $rc"
    ;;
  persistence_weighted)
    run persistence "$data/weighted.xyz" --weighted
    expect_success
    [[ -s "$tmp/out" ]] || fail "no pairs"
    bad=$(grep -vE '^[012] -?[0-9][0-9.e+-]* (-?[0-9][0-9.e+-]*|inf)$' "$tmp/out" || true)
    [[ -z $bad ]] || fail "malformed lines: $bad"
    # zero-length pairs are left out (birth == death)
    [[ -z $(grep -E '^[012] (\S+) \1$' "$tmp/out" || true) ]] || fail "a zero-length pair is listed"
    [[ $(grep -c ' inf$' "$tmp/out") -eq 1 ]] || fail "expected one class that never dies"
    grep -qx '0 -4 inf' "$tmp/out" || fail "the first ball enters at -r^2 = -4 and lives forever"
    ;;
  persistence_missing_file)
    run persistence "$tmp/missing.pdb"
    expect_error "$tmp/missing.pdb" 'no such file'
    ;;

  # ---- shape -------------------------------------------------------------
  shape_closed)
    run shape "$grid" --alpha-sq 0.75 -o "$tmp/cube.off"
    expect_success
    [[ ! -s "$tmp/out" ]] || fail "stdout is not empty"
    [[ $(sed -n 2p "$tmp/cube.off") == '56 108 0' ]] || fail "expected 56 vertices and 108 triangles"
    volume6=$(off_closed_volume6 "$tmp/cube.off")
    [[ $volume6 -eq 162 ]] || fail "6 x volume is $volume6, expected 162 (27, oriented outward)"
    grep -q 'wrote 108 triangles, 56 vertices' "$tmp/err" || fail "counts not logged"
    grep -q 'not written .*: 0 triangles, 0 edges, 0 vertices' "$tmp/err" || fail "singular counts not logged"
    [[ $(files_in "$tmp") == "cube.off edges err forward out reverse" ]] || fail "files left: $(files_in "$tmp")"
    ;;
  shape_formats)
    mkdir "$tmp/meshes"
    for ext in ply stl obj PLY; do
      run -q shape "$grid" --alpha-sq=0.75 --output "$tmp/meshes/cube.$ext"
      expect_success
    done
    [[ $(head -c 36 "$tmp/meshes/cube.ply") == $'ply\nformat binary_little_endian 1.0' ]] ||
      fail "cube.ply is not a binary PLY"
    grep -qa '^element vertex 56$' "$tmp/meshes/cube.ply" || fail "cube.ply: not 56 vertices"
    grep -qa '^element face 108$' "$tmp/meshes/cube.ply" || fail "cube.ply: not 108 faces"
    cmp -s "$tmp/meshes/cube.ply" "$tmp/meshes/cube.PLY" || fail "cube.PLY differs from cube.ply"
    [[ $(stat -c %s "$tmp/meshes/cube.stl") -eq $((84 + 50 * 108)) ]] || fail "cube.stl is not a binary STL of 108 triangles"
    [[ $(grep -c '^v ' "$tmp/meshes/cube.obj") -eq 56 ]] || fail "cube.obj: not 56 vertices"
    [[ $(grep -c '^f ' "$tmp/meshes/cube.obj") -eq 108 ]] || fail "cube.obj: not 108 faces"
    [[ $(files_in "$tmp/meshes") == "cube.PLY cube.obj cube.ply cube.stl" ]] || fail "files: $(files_in "$tmp/meshes")"
    ;;
  shape_singular)
    # At 0.5 the unit squares are there but no tetrahedron: nothing bounds a
    # solid, so the mesh is empty and the singular triangles are only logged.
    run shape "$grid" --alpha-sq 0.5 -o "$tmp/empty.off"
    expect_success
    [[ $(sed -n 2p "$tmp/empty.off") == '0 0 0' ]] || fail "expected an empty mesh"
    grep -q 'not written .*: 216 triangles, 0 edges, 0 vertices' "$tmp/err" || fail "singular triangles not logged"
    grep -q 'warning.*no boundary triangles' "$tmp/err" || fail "no warning for an empty mesh"
    ;;
  shape_replaces)
    echo "an old file" >"$tmp/cube.off"
    run -q shape "$grid" --alpha-sq 0.75 -o "$tmp/cube.off"
    expect_success
    [[ $(head -n 1 "$tmp/cube.off") == OFF ]] || fail "the old file was not replaced"
    [[ $(files_in "$tmp") == "cube.off err out" ]] || fail "files left: $(files_in "$tmp")"
    ;;
  shape_pdb)
    run shape "$pdb" --weighted --alpha-sq 1 -o "$tmp/1a26.ply"
    expect_success
    faces=$(grep -ao '^element face [0-9]*' "$tmp/1a26.ply" | cut -d' ' -f3)
    [[ $faces -gt 0 ]] || fail "no faces"
    grep -q "wrote $faces triangles" "$tmp/err" || fail "face count not logged"
    ;;
  shape_missing_alpha)
    run shape "$grid" -o "$tmp/cube.ply"
    expect_error "--alpha-sq is required"
    [[ $rc -eq 2 ]] || fail "exit code $rc, expected 2 for a wrong command line"
    [[ ! -e "$tmp/cube.ply" ]] || fail "a file was written"
    ;;
  shape_missing_output)
    run shape "$grid" --alpha-sq 1
    expect_error "--output is required"
    [[ $rc -eq 2 ]] || fail "exit code $rc, expected 2 for a wrong command line"
    ;;
  shape_bad_extension)
    mkdir "$tmp/dir"
    run shape "$grid" --alpha-sq 1 -o "$tmp/dir/cube.vrml"
    expect_error "$tmp/dir/cube.vrml: unknown mesh format (expected .ply, .obj, .off or .stl)"
    [[ -z $(files_in "$tmp/dir") ]] || fail "files left: $(files_in "$tmp/dir")"
    ;;
  shape_output_dir_missing)
    run shape "$grid" --alpha-sq 1 -o "$tmp/missing/cube.ply"
    expect_error "$tmp/missing/cube.ply: cannot create a file in $tmp/missing" 'No such file or directory'
    [[ ! -e "$tmp/missing" ]] || fail "the directory was created"
    ;;
  shape_output_dir_not_directory)
    echo "a file" >"$tmp/file"
    run shape "$grid" --alpha-sq 1 -o "$tmp/file/cube.ply"
    expect_error "$tmp/file/cube.ply" 'Not a directory'
    ;;
  shape_output_dir_read_only)
    # As an unprivileged user: root may write there.
    mkdir "$tmp/locked"
    cp "$grid" "$tmp/cube.xyz"
    chmod 555 "$tmp/locked"
    run_unprivileged shape "$tmp/cube.xyz" --alpha-sq 1 -o "$tmp/locked/cube.ply"
    ! writable_for_unprivileged "$tmp/locked" || fail "the read-only directory is writable"
    expect_error "$tmp/locked/cube.ply" 'Permission denied'
    [[ -z $(files_in "$tmp/locked") ]] || fail "files left: $(files_in "$tmp/locked")"
    ;;
  shape_output_is_directory)
    mkdir "$tmp/dir.ply"
    run shape "$grid" --alpha-sq 1 -o "$tmp/dir.ply"
    expect_error "$tmp/dir.ply: is a directory"
    [[ -z $(files_in "$tmp/dir.ply") ]] || fail "files left"
    ;;
  *)
    echo "unknown case: $case_name" >&2
    exit 2
    ;;
esac
echo "PASS [$case_name]"
