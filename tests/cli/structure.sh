#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# CLI tests of structure files as input (any subcommand taking FILE): the
# atom selection options, atoms as weighted points (ProtOr radius + probe),
# and one-line errors for bad files. One case per CTest test.
# Usage: structure.sh ALPHAPOCKET REPO_ROOT CASE
#
# Atom counts were checked against the files' ATOM/HETATM records (see
# tests/molecule/test_structure.cpp): 1fbl.pdb has 3294 atoms, 2966 protein, 295
# waters, 33 hetero (HTA, 4 Ca, 2 Zn); 1d3z_models_1_2.pdb.gz two NMR
# models of 1231 atoms, 629 of them hydrogens; 1pfe.cif.gz a DNA strand
# (chain A, 161 atoms kept) and echinomycin (chain B, 52).
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" "$@"
bad=$data/bad

expect_points() {  # N: a successful delaunay --json run on N points
  expect_json_object
  expect_json points "$1"
}

# Four carbon atoms (radius 1.70) at the corners of a regular tetrahedron of
# edge 10 A, as a ligand: kept with --keep-hetero.
four_carbons() {
  local f=$tmp/four.pdb
  {
    echo "HETATM    1  C1  LIG A   1       0.000   0.000   0.000  1.00  0.00           C"
    echo "HETATM    2  C2  LIG A   1      10.000   0.000   0.000  1.00  0.00           C"
    echo "HETATM    3  C3  LIG A   1       5.000   8.660   0.000  1.00  0.00           C"
    echo "HETATM    4  C4  LIG A   1       5.000   2.887   8.165  1.00  0.00           C"
  } >"$f"
  echo "$f"
}

# The 80 atoms of catalog/peptide.pdb (chain A, residues 1-12) in models 1-4
# of one file: 1 and 3 empty, 2 whole, 4 residues 1-6 only.
models_file() {
  local f=$tmp/models.pdb atoms=$data/catalog/peptide.pdb
  {
    printf 'MODEL        1\nENDMDL\nMODEL        2\n'
    grep '^ATOM' "$atoms"
    printf 'ENDMDL\nMODEL        3\nENDMDL\nMODEL        4\n'
    awk '/^ATOM/ && substr($0, 23, 4) + 0 <= 6' "$atoms"
    printf 'ENDMDL\nEND\n'
  } >"$f"
  echo "$f"
}

# surface --json of FILE into $tmp/NAME.json.
surface_of() {  # FILE NAME
  run surface "$1" --json
  expect_json_object
  cp "$tmp/out" "$tmp/$2.json"
}

case $case_name in
  default_selection)
    run delaunay "$data/1fbl.pdb" --json
    expect_points 2966
    grep -qF "1fbl.pdb: PDB, model 1: kept 2966 of 3294 atoms; dropped: 295 water, 33 hetero; 7 hetero groups" \
      "$tmp/err" || fail "no selection summary logged"
    grep -q "radius = ProtOr radius + probe 1.4 A" "$tmp/err" || fail "radii and probe not logged"
    ;;
  keep_all)
    run delaunay "$data/1fbl.pdb" --keep-waters --keep-hetero --json
    expect_points 3294
    ;;
  keep_waters)
    run delaunay "$data/1fbl.pdb" --keep-waters --json
    expect_points 3261
    ;;
  mmcif_gz)
    run delaunay "$data/1fbl.cif.gz" --keep-hetero --json
    expect_points 2999
    grep -qF "mmCIF (gzip), model 1: kept 2999 of 3294 atoms" "$tmp/err" || fail "format not logged"
    ;;
  hydrogens)
    run delaunay "$data/1d3z_models_1_2.pdb.gz" --json
    expect_points 602
    run delaunay "$data/1d3z_models_1_2.pdb.gz" --keep-hydrogens --json
    expect_points 1231
    ;;
  model)
    run delaunay "$data/1d3z_models_1_2.pdb.gz" --model 2 --json
    expect_points 602
    grep -qF "model 2 of 2: kept 602 of 1231 atoms" "$tmp/err" || fail "model not logged"
    ;;
  chains)
    run delaunay "$data/1pfe.cif.gz" --chains A --json
    expect_points 161
    run delaunay "$data/1pfe.cif.gz" --chains B --json
    expect_points 38
    run delaunay "$data/1pfe.cif.gz" --chains A,B --json
    expect_points 199
    run delaunay "$data/1pfe.cif.gz" --chains B --chains A --json
    expect_points 199
    ;;
  probe)
    # Each atom is the ball of radius 1.70 + probe: a component is born at
    # -(1.70 + probe)^2. 1.7 + 0.3 is exactly 2 in double precision.
    f=$(four_carbons)
    run persistence "$f" --keep-hetero --probe 0.3
    expect_success
    [[ $(grep -c '^0 -4 ' "$tmp/out") -eq 4 ]] || fail "components not born at -(1.7 + 0.3)^2 = -4"
    run persistence "$f" --keep-hetero --probe 0
    expect_success
    [[ $(grep -c '^0 -2.8899999999999997 ' "$tmp/out") -eq 4 ]] || fail "components not born at -1.7^2"
    run persistence "$f" --keep-hetero
    expect_success
    [[ $(grep -c '^0 -9.609999999999998 ' "$tmp/out") -eq 4 ]] || fail "components not born at -(1.7 + 1.4)^2"
    ;;
  weighted_is_implied)
    # --weighted changes nothing for a structure file.
    run -q persistence "$data/1UYD.pdb"
    cp "$tmp/out" "$tmp/plain"
    run -q persistence "$data/1UYD.pdb" --weighted
    expect_success
    cmp -s "$tmp/out" "$tmp/plain" || fail "--weighted changed the result of a structure file"
    ;;
  help)
    run delaunay --help
    expect_success
    for option in --probe --model --chains --keep-hydrogens --keep-waters --keep-hetero; do
      grep -q -- "$option" "$tmp/out" || fail "$option not in --help"
    done
    grep -q "ProtOr" "$tmp/out" || fail "radii not explained in --help"
    ;;
  empty_model)
    # The default model is the first with atoms; an empty one is an error.
    f=$(models_file)
    run delaunay "$f" --json
    expect_points 80
    grep -qF "model 2 of 4: kept 80 of 80 atoms" "$tmp/err" || fail "model 2 not taken by default"
    run delaunay "$f" --model 3 --json
    expect_error "$f: model 3 has no atoms (models with atoms: 2, 4)"
    ;;
  same_chain_in_models)
    # Chain A of model 4 is not chain A of model 2.
    f=$(models_file)
    run delaunay "$f" --model 4 --chains A --json
    expect_points "$(awk '/^ATOM/ && substr($0, 23, 4) + 0 <= 6' "$data/catalog/peptide.pdb" | wc -l)"
    run delaunay "$f" --model 2 --chains A --json
    expect_points 80
    ;;
  duplicate_serials)
    # Serial numbers only label atoms: every atom numbered 1 changes nothing.
    surface_of "$data/catalog/peptide.pdb" pdb
    sed -E 's/^(ATOM  ).{5}/\1    1/' "$data/catalog/peptide.pdb" >"$tmp/serials.pdb"
    [[ $(grep -c '^ATOM      1 ' "$tmp/serials.pdb") -eq 80 ]] || fail "serials not all 1"
    surface_of "$tmp/serials.pdb" serials_pdb
    cmp -s "$tmp/pdb.json" "$tmp/serials_pdb.json" || fail "PDB serials changed the surface"
    surface_of "$data/catalog/peptide.cif" cif
    awk '/^ATOM / { $2 = 1 } { print }' "$data/catalog/peptide.cif" >"$tmp/serials.cif"
    surface_of "$tmp/serials.cif" serials_cif
    cmp -s "$tmp/cif.json" "$tmp/serials_cif.json" || fail "mmCIF _atom_site.id changed the surface"
    ;;
  mmcif_split_residue)
    # Residues 7-12 of catalog/peptide.cif as chain B, then two waters of
    # chain A; split: two atoms of residue A 1 moved after the waters. gemmi
    # reads them as a third part of chain A whose first residue is a water,
    # so they were taken for a hetero group and dropped.
    awk '/^ATOM / && $14 >= 7 { $7 = "B"; $15 = "B" } { print }
         END { print "HETATM 97 O O . HOH C . 0.0 0.0 20.0 1.00 0.00 101 A 1"
               print "HETATM 98 O O . HOH C . 0.0 3.0 20.0 1.00 0.00 102 A 1" }' \
      "$data/catalog/peptide.cif" >"$tmp/whole.cif"
    awk '/^ATOM / && $14 == 1 && ($4 == "C" || $4 == "O") { moved = moved $0 "\n"; next } { print }
         END { printf "%s", moved }' "$tmp/whole.cif" >"$tmp/split.cif"
    [[ $(tail -n 1 "$tmp/split.cif" | awk '{print $4, $6, $14}') == "O GLY 1" ]] || fail "residue 1 not split"
    surface_of "$tmp/whole.cif" whole
    grep -qF "kept 80 of 82 atoms; dropped: 2 water" "$tmp/err" || fail "whole: not 80 atoms kept"
    surface_of "$tmp/split.cif" split
    grep -qF "kept 80 of 82 atoms; dropped: 2 water" "$tmp/err" || fail "split: not 80 atoms kept"
    cmp -s "$tmp/whole.json" "$tmp/split.json" || fail "the split residue changed the surface"
    ;;
  point_file_with_structure_option)
    run delaunay "$data/cube_grid.xyz" --probe 1 --keep-waters --json
    expect_error "$data/cube_grid.xyz: a point file, but --probe, --keep-waters are for structure files"
    ;;
  negative_probe)
    run delaunay "$data/1fbl.pdb" --probe -1
    expect_error "--probe"
    [[ $rc -eq 2 ]] || fail "exit code $rc, expected 2 for a wrong command line"
    ;;
  missing_chain)
    run delaunay "$data/1fbl.pdb" --chains B --json
    expect_error "$data/1fbl.pdb: no chain 'B' in model 1 (chains: A)"
    ;;
  missing_model)
    run delaunay "$data/1fbl.pdb" --model 2 --json
    expect_error "$data/1fbl.pdb: no model 2 (models: 1)"
    ;;
  only_ligands)
    # Without --keep-hetero nothing is left.
    run delaunay "$(four_carbons)" --json
    expect_error "$tmp/four.pdb: no atoms left after the selection (model 1 has 4 atoms; dropped: 4 hetero)"
    ;;
  three_atoms)
    run delaunay "$bad/three_atoms.pdb" --json
    expect_error "$bad/three_atoms.pdb: only 3 atoms after the selection, at least 4 are needed"
    ;;
  empty)
    run spectrum "$bad/empty.pdb" --json
    expect_error "$bad/empty.pdb: file is empty"
    ;;
  not_structure)
    run delaunay "$bad/not_structure.pdb" --json
    expect_error "$bad/not_structure.pdb: not a PDB or mmCIF file"
    ;;
  truncated_cif)
    run persistence "$bad/truncated.cif"
    expect_error "$bad/truncated.cif:3:1: Wrong number of values in the loop"
    ;;
  truncated_gz)
    run shape "$bad/truncated.pdb.gz" --alpha-sq 0 -o "$tmp/shape.ply"
    expect_error "$bad/truncated.pdb.gz: truncated gzip data"
    [[ ! -e "$tmp/shape.ply" ]] || fail "a mesh was written"
    ;;
  gzip_bomb)
    # 513 MiB of blanks in 0.5 MB of gzip (513 members of 1 MiB each):
    # refused at the 512 MiB limit, not inflated whole; a smaller
    # --max-input-mb stops it sooner.
    head -c $((1 << 20)) /dev/zero | tr '\0' ' ' | gzip -9 >"$tmp/one.gz"
    for _ in $(seq 513); do cat "$tmp/one.gz"; done >"$tmp/bomb.pdb.gz"
    run surface "$tmp/bomb.pdb.gz"
    expect_error "$tmp/bomb.pdb.gz: decompresses to more than 512 MiB" 'max-input-mb raises it'
    [[ $rc -eq 5 ]] || fail "exit code $rc, expected 5 (a limit exceeded)"
    run surface "$tmp/bomb.pdb.gz" --max-input-mb 8
    expect_error "$tmp/bomb.pdb.gz: decompresses to more than 8 MiB"
    [[ $rc -eq 5 ]] || fail "exit code $rc, expected 5 (a limit exceeded)"
    head -c $((9 << 20)) /dev/zero | tr '\0' ' ' >"$tmp/big.pdb"
    run surface "$tmp/big.pdb" --max-input-mb 8
    expect_error "$tmp/big.pdb: is 9 MiB, more than the limit for a structure file of 8 MiB"
    [[ $rc -eq 5 ]] || fail "exit code $rc, expected 5 (a limit exceeded)"
    ;;
  mmcif_messages)
    # gemmi's own messages had no line ('Not a single character: VAL',
    # 'coordinate nan' for ?, inf and abc alike, an unknown element as X).
    sed '927s/ \. GLU A 1 16 / VAL GLU A 1 16 /' "$data/1UYD.cif" >"$tmp/alt.cif"
    run surface "$tmp/alt.cif"
    expect_error "$tmp/alt.cif: line 927: _atom_site.label_alt_id is 'VAL', not a single character"
    for x in '?' inf abc 1e300; do
      sed "927s/ 6\.484 / $x /" "$data/1UYD.cif" >"$tmp/x.cif"
      run surface "$tmp/x.cif"
      expect_error "$tmp/x.cif: line 927: _atom_site.Cartn_x is '$x', "
    done
    tail -n +2 "$data/1UYD.cif" >"$tmp/nodata.cif"
    run surface "$tmp/nodata.cif"
    expect_error "$tmp/nodata.cif: line " 'mmCIF without a data_ block'
    sed '2572s/^HETATM 1646 C  C19 /HETATM 1646 QQ C19 /' "$data/1UYD.cif" >"$tmp/qq.cif"
    run surface "$tmp/qq.cif" --keep-hetero --sa-only
    expect_success
    grep -q "unknown element 'QQ' (on line 2572; first: atom C19 of PU8 A1224)" "$tmp/err" || fail "QQ not named"
    ;;
  corrupt_gz)
    run delaunay "$bad/corrupt.pdb.gz" --json
    expect_error "$bad/corrupt.pdb.gz: corrupt gzip data"
    ;;
  short_line)
    run delaunay "$bad/short_line.pdb" --json
    expect_error "$bad/short_line.pdb: line 2: ATOM record shorter than 54 columns ('ATOM      1  N   ALA A   1      11.104   6.134')"
    ;;
  old_format)
    # Columns 73-80 "1GRM 125": read without them, with a warning.
    run delaunay "$data/1grm_single.pdb" --keep-hetero --json
    expect_points 272
    grep -qF "1grm_single.pdb: columns 73-80 hold an old-format id code and line number (line 125: '1GRM 125')" \
      "$tmp/err" || fail "no warning about the old format"
    ;;
  directory)
    mkdir "$tmp/dir.pdb"
    run delaunay "$tmp/dir.pdb" --json
    expect_error "$tmp/dir.pdb: is a directory, not a file"
    ;;
  *)
    echo "unknown case: $case_name" >&2
    exit 2
    ;;
esac
echo "PASS [$case_name]"
