#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# CLI tests of `alphapocket pockets`, one case per CTest test. Exit code 77
# means skipped. Usage: pockets.sh ALPHAPOCKET REPO_ROOT CASE
#
# The cases run on examples/data/1a26A.pdb; the contents of the files are
# checked in depth by tests/molecule/test_pocket_outputs.cpp, here: the command line,
# which files appear where, that they agree with each other, and errors.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" "$@"

# Files below directory DIR (hidden ones too), relative, sorted, one line.
tree_of() {
  (cd "$1" && find . -mindepth 1 | sed 's|^\./||' | LC_ALL=C sort | tr '\n' ' ' | sed 's/ $//')
}

# "N pockets, M voids, K tunnels" of the summary: prints N M K.
summary_counts() {
  grep -oE '^[0-9]+ pockets?, [0-9]+ voids?, [0-9]+ tunnels?' "$tmp/out" | grep -oE '[0-9]+' | tr '\n' ' ' |
    sed 's/ $//'
}

# The outputs of one run in DIR agree: one CSV row, one pml selection, one
# CEN pseudo-atom and, with meshes of format EXT (none if EXT is empty), one
# mesh per pocket (and per void).
expect_consistent() {  # DIR POCKETS VOIDS [EXT]
  local dir=$1 pockets=$2 voids=$3 ext=${4:-}
  for f in report.json pockets.csv pockets.pml pockets.cxc structure.cif pockets.pdb; do
    [[ -s "$dir/$f" ]] || fail "$dir/$f missing or empty"
  done
  [[ $(($(wc -l <"$dir/pockets.csv") - 1)) -eq $pockets ]] || fail "pockets.csv: not $pockets rows"
  [[ $(grep -c '^HETATM.\{6\} CEN STP P' "$dir/pockets.pdb") -eq $pockets ]] || fail "pockets.pdb: not $pockets pockets"
  [[ $(grep -c '^HETATM.\{6\} CEN STP V' "$dir/pockets.pdb") -eq $voids ]] || fail "pockets.pdb: not $voids voids"
  [[ $(grep -c '^pseudoatom pocket_[0-9]*_center' "$dir/pockets.pml") -eq $pockets ]] || fail "pockets.pml: centres"
  [[ $(grep -c '"rank": ' "$dir/report.json") -ge $((pockets + voids)) ]] || fail "report.json: ranks"
  [[ -z $(find "$dir" -name '.*.tmp') ]] || fail "temporary files left"
  if [[ -z $ext ]]; then
    [[ ! -e "$dir/meshes" ]] || fail "meshes/ written without being asked for"
    ! grep -q '"mesh":' "$dir/report.json" || fail "report.json names meshes that were not written"
    return
  fi
  for f in "meshes/surface.$ext" meshes/meshlab.mlp; do
    [[ -s "$dir/$f" ]] || fail "$dir/$f missing or empty"
  done
  [[ $(ls "$dir/meshes" | grep -c "^pocket_[0-9]*\.$ext$") -eq $pockets ]] || fail "meshes: not $pockets pockets"
  [[ $(ls "$dir/meshes" | grep -c "^void_[0-9]*\.$ext$") -eq $voids ]] || fail "meshes: not $voids voids"
}

case "$case_name" in
  default)
    # A bare run: OUTDIR is <name>_pockets in the current directory; the
    # viewer scripts load the copy of the structure beside them, not FILE.
    mkdir "$tmp/work"
    cp "$pdb" "$tmp/work/1a26A.pdb"
    cd "$tmp/work"
    run pockets 1a26A.pdb
    expect_success
    [[ -d 1a26A_pockets ]] || fail "1a26A_pockets/ not created"
    read -r pockets voids tunnels <<<"$(summary_counts)"
    [[ $pockets -ge 1 ]] || fail "no pockets in the summary"
    grep -q "^site  cavity .*lining residues$" "$tmp/out" || fail "no table in the summary"
    grep -qE '^ +1  pocket [0-9]+ +[01]\.[0-9]{3} .* A:[A-Z]{3}:[0-9]+' "$tmp/out" || fail "no residues for site 1"
    [[ $tunnels -ge 1 ]] || fail "1a26A has tunnels"
    grep -qE '^widest tunnel: bottleneck radius [0-9]+\.[0-9]{2} A between A:[A-Z]{3}:[0-9]+' "$tmp/out" ||
      fail "no line for the widest tunnel"
    [[ $(wc -l <"$tmp/out") -le 24 ]] || fail "the summary is longer than one screen"
    expect_consistent 1a26A_pockets "$pockets" "$voids"
    grep -q "; written to 1a26A_pockets/ (--mesh ply adds the surface and cavity meshes)$" "$tmp/out" ||
      fail "the summary does not say how to get the meshes"
    grep -qF '"structure.cif"), "1a26A")' 1a26A_pockets/pockets.pml || fail "pockets.pml does not load structure.cif"
    grep -qx 'open structure.cif' 1a26A_pockets/pockets.cxc || fail "pockets.cxc does not open structure.cif"
    ! grep -qF "$tmp" 1a26A_pockets/pockets.pml 1a26A_pockets/pockets.cxc || fail "a script names an absolute path"
    # 10 files, report.html with scene.mvsj and viewer/'s 4 (Mol* is
    # installed where the tests run: no_molstar is the case without it).
    [[ $(tree_of "$tmp/work" | wc -w) -eq $((2 + 10 + 2 + 5)) ]] || fail "unexpected files: $(tree_of .)"
    grep -q '<script src="viewer/molstar.js">' 1a26A_pockets/report.html || fail "report.html does not load viewer/molstar.js"
    ;;
  no_molstar)
    # Without Mol*, the default leaves report.html out with one warning
    # saying how to install it; asking for html is an error before anything
    # is written, in pockets and batch; batch's index.html needs no Mol*.
    mkdir "$tmp/empty"
    export ALPHAPOCKET_MOLSTAR=$tmp/empty
    run -q pockets "$pdb" -o "$tmp/o"
    expect_success
    [[ $(grep -c "report.html needs Mol\*.* not found in $tmp/empty: run \`npm ci --prefix report_assets\`" "$tmp/err") -eq 1 &&
       $(wc -l <"$tmp/err") -eq 1 ]] || fail "not one warning line"
    [[ -s "$tmp/o/report.json" && ! -e "$tmp/o/report.html" && ! -e "$tmp/o/scene.mvsj" && ! -e "$tmp/o/viewer" ]] ||
      fail "without Mol*: $(tree_of "$tmp/o")"
    for command in pockets batch; do
      run "$command" "$pdb" -o "$tmp/bad" --outputs report,html
      expect_error "report.html needs Mol*" "npm ci --prefix report_assets"
      [[ ! -e "$tmp/bad" ]] || fail "$command --outputs report,html without Mol* created OUTDIR"
    done
    run -q batch "$pdb" -o "$tmp/b"
    expect_success
    [[ -s "$tmp/b/index.html" && ! -e "$tmp/b/viewer" ]] || fail "batch without Mol*: $(tree_of "$tmp/b")"
    grep -qF '"pages":[]' "$tmp/b/index.html" || fail "index.html links to pages"
    ;;
  viewer_copies)
    # viewer/ holds copies of Mol*'s files, not links: editing an output in
    # place leaves the installed files as they were (pockets' viewer/ and
    # a batch run's one).
    mkdir "$tmp/molstar"
    printf '/* Mol* */\n' >"$tmp/molstar/molstar.js"
    printf '/* style */\n' >"$tmp/molstar/molstar.css"
    export ALPHAPOCKET_MOLSTAR=$tmp/molstar
    run -q pockets "$pdb" -o "$tmp/o" --outputs report,html
    expect_success
    run -q batch "$pdb" -o "$tmp/b" --outputs report,html
    expect_success
    for viewer in "$tmp/o/viewer" "$tmp/b/viewer"; do
      for f in molstar.js molstar.css; do
        [[ -f "$viewer/$f" && ! -L "$viewer/$f" ]] || fail "$viewer/$f is not a file"
        cmp -s "$tmp/molstar/$f" "$viewer/$f" || fail "$viewer/$f differs from Mol*'s"
        [[ $(stat -c %h "$viewer/$f") -eq 1 ]] || fail "$viewer/$f is linked to another name"
        echo 'edited' >>"$viewer/$f"
      done
    done
    [[ $(cat "$tmp/molstar/molstar.js") == '/* Mol* */' && $(cat "$tmp/molstar/molstar.css") == '/* style */' ]] ||
      fail "editing viewer/ changed the installed Mol*"
    ;;
  json)
    # --json: the report on one line, the same as report.json.
    run pockets "$pdb" -o "$tmp/out dir" --json
    expect_json_object
    [[ "$(tr -d ' \n' <"$tmp/out")" == "$(tr -d ' \n' <"$tmp/out dir/report.json")" ]] ||
      fail "stdout differs from report.json"
    pockets=$(grep -o '"pockets":[0-9]*' "$tmp/out" | head -n 1 | cut -d: -f2)
    voids=$(grep -o '"voids":[0-9]*' "$tmp/out" | head -n 1 | cut -d: -f2)
    expect_consistent "$tmp/out dir" "$pockets" "$voids"
    ;;
  mesh_formats)
    # --mesh obj writes the meshes; a second run with the default format
    # (--outputs all) into the same directory replaces them (no .obj left).
    run pockets "$pdb" -o "$tmp/o" --mesh obj
    expect_success
    read -r pockets voids tunnels <<<"$(summary_counts)"
    expect_consistent "$tmp/o" "$pockets" "$voids" obj
    [[ -z $(ls "$tmp/o/meshes" | grep -v '\.\(obj\|mtl\|mlp\)$') ]] || fail "other meshes than .obj"
    grep -q '^mtllib surface.mtl$' "$tmp/o/meshes/surface.obj" || fail "surface.obj names no .mtl"
    grep -q '^Kd ' "$tmp/o/meshes/surface.mtl" || fail "surface.mtl has no colours"
    grep -q "; written to $tmp/o/$" "$tmp/out" || fail "the summary offers meshes already written"
    run pockets "$pdb" -o "$tmp/o" --outputs all
    expect_success
    expect_consistent "$tmp/o" "$pockets" "$voids" ply
    [[ -z $(ls "$tmp/o/meshes" | grep -v '\.\(ply\|mlp\)$') ]] || fail "meshes of the first run left: $(ls "$tmp/o/meshes")"
    ;;
  threads)
    # -j N measures the cavities on N threads: every output and the summary
    # byte-identical to -j 1's (1fbl: many pockets, split regions); -j 0 is
    # a usage error.
    for input in "$pdb" "$root/tests/data/1fbl.pdb"; do
      for j in 1 2 3; do
        mkdir -p "$tmp/j$j"
        (cd "$tmp/j$j" && "$exe" -q pockets "$input" -o o -j "$j" --outputs all --mesh-resolution 1.5 >stdout) ||
          fail "-j $j failed on $input"
      done
      [[ $(ls "$tmp/j1/o/meshes" | wc -l) -gt 3 ]] || fail "$input: too few meshes to compare"
      for j in 2 3; do
        diff -r "$tmp/j1" "$tmp/j$j" >/dev/null || fail "$input: -j $j differs from -j 1: $(diff -rq "$tmp/j1" "$tmp/j$j")"
      done
      rm -rf "$tmp"/j[123]
    done
    run pockets "$pdb" -o "$tmp/bad" -j 0
    [[ $rc -eq 2 && ! -e "$tmp/bad" ]] || fail "-j 0: exit code $rc, expected 2 and no OUTDIR"
    ;;
  outputs)
    # --outputs chooses the files; the meshes' own options ask for meshes.
    run -q pockets "$pdb" -o "$tmp/o" --outputs report,tunnels
    expect_success
    [[ $(tree_of "$tmp/o") == "report.json tunnel_profiles.csv tunnels.csv tunnels.pdb" ]] ||
      fail "--outputs report,tunnels wrote: $(tree_of "$tmp/o")"
    run -q pockets "$pdb" -o "$tmp/o" --outputs report --mesh-resolution 1.5
    expect_success
    [[ $(tree_of "$tmp/o" | tr ' ' '\n' | grep -vc '^meshes') -eq 1 && -s "$tmp/o/meshes/surface.ply" ]] ||
      fail "--mesh-resolution did not add the meshes: $(tree_of "$tmp/o")"
    grep -q '"mesh": "meshes/surface.ply"' "$tmp/o/report.json" || fail "report.json does not name the surface mesh"
    for list in bogus "report,,csv" ""; do
      run pockets "$pdb" -o "$tmp/bad" --outputs "$list"
      [[ $rc -eq 2 && $(wc -l <"$tmp/err") -eq 1 ]] || fail "--outputs '$list': exit code $rc, expected 2 and one line"
      grep -q "^ERROR: --outputs: unknown output '" "$tmp/err" || fail "--outputs '$list': $(head -n 1 "$tmp/err")"
      [[ ! -e "$tmp/bad" ]] || fail "--outputs '$list' created OUTDIR"
    done
    ;;
  min_volume)
    # A huge --min-volume drops every pocket and void: the outputs are
    # empty but valid.
    run pockets "$pdb" -o "$tmp/o" --min-volume 1e9
    expect_success
    [[ $(summary_counts) == "0 0 "* ]] || fail "pockets or voids left: $(summary_counts)"
    expect_consistent "$tmp/o" 0 0
    grep -q '"pockets": \[\]' "$tmp/o/report.json" || fail "report.json: pockets not empty"
    ;;
  probe)
    # A larger probe fills narrow clefts: the solvent-accessible volume of
    # the molecule grows, and the parameter is reported.
    run pockets "$pdb" -o "$tmp/a" --json
    expect_json_object
    v14=$(grep -o '"sa_volume":[0-9.]*' "$tmp/out" | head -n 1 | cut -d: -f2)
    run pockets "$pdb" -o "$tmp/b" --probe 2 --json
    expect_json_object
    expect_json probe 2.0
    v20=$(grep -o '"sa_volume":[0-9.]*' "$tmp/out" | head -n 1 | cut -d: -f2)
    [[ ${v20%.*} -gt ${v14%.*} ]] || fail "sa_volume $v20 at probe 2 not above $v14 at probe 1.4"
    ;;
  missing_file)
    run pockets "$tmp/nope.pdb" -o "$tmp/o"
    expect_error "$tmp/nope.pdb"
    [[ ! -e "$tmp/o" ]] || fail "the output directory was left behind"
    ;;
  not_structure)
    run pockets "$data/cube_grid.xyz" -o "$tmp/o"
    expect_error "$data/cube_grid.xyz: not a structure file"
    [[ ! -e "$tmp/o" ]] || fail "the output directory was created"
    ;;
  invalid_structure)
    printf 'HETATM garbage\nthis is not a structure\n' >"$tmp/bad.pdb"
    cd "$tmp"
    run pockets bad.pdb
    expect_error "bad.pdb"
    [[ $(tree_of "$tmp") == "bad.pdb err out" ]] || fail "files left: $(tree_of "$tmp")"
    ;;
  outdir_under_file)
    echo "a file" >"$tmp/file"
    run pockets "$pdb" -o "$tmp/file/o"
    expect_error "$tmp/file/o: cannot create the output directory"
    [[ $(cat "$tmp/file") == "a file" ]] || fail "the file was changed"
    ;;
  outdir_is_file)
    echo "a file" >"$tmp/file"
    run pockets "$pdb" -o "$tmp/file"
    expect_error "$tmp/file: cannot create the output directory"
    [[ $(cat "$tmp/file") == "a file" ]] || fail "the file was changed"
    ;;
  outdir_missing_parent)
    run pockets "$pdb" -o "$tmp/missing/o"
    expect_error "$tmp/missing/o: cannot create the output directory"
    [[ ! -e "$tmp/missing" ]] || fail "the parent was created"
    ;;
  outdir_read_only)
    # As an unprivileged user: root may write there.
    mkdir -p "$tmp/locked/o"
    cp "$pdb" "$tmp/in.pdb"
    chmod 555 "$tmp/locked/o"
    run_unprivileged pockets "$tmp/in.pdb" -o "$tmp/locked/o"
    ! writable_for_unprivileged "$tmp/locked/o" || fail "the read-only directory is writable"
    expect_error "$tmp/locked/o" 'Permission denied'
    [[ -z $(tree_of "$tmp/locked/o") ]] || fail "files left: $(tree_of "$tmp/locked/o")"
    ;;
  outdir_empty_name)
    # -o '' is a usage error (was: the default OUTDIR).
    cd "$tmp"
    run pockets "$pdb" -o ''
    [[ $rc -eq 2 ]] || fail "exit code $rc, expected 2"
    grep -q '^ERROR: .*an empty name is not an output directory' "$tmp/err" || fail "no message"
    [[ $(tree_of "$tmp") == "err out" ]] || fail "files left: $(tree_of "$tmp")"
    ;;
  outdir_root)
    run pockets "$pdb" -o /
    expect_error "/: is the root of the file system"
    run pockets "$pdb" -o /tmp/..
    expect_error "/tmp/..: is the root of the file system"
    ;;
  outdir_foreign_files)
    # The input's own folder, and a folder of another tool's results: refused
    # (the swap would remove their files), and left as they were.
    mkdir "$tmp/in" "$tmp/fpocket"
    cp "$pdb" "$tmp/in/x.pdb"
    run pockets "$tmp/in/x.pdb" -o "$tmp/in"
    expect_error "$tmp/in: holds files that are not alphapocket outputs ('x.pdb')"
    [[ $(tree_of "$tmp/in") == "x.pdb" ]] || fail "the input's folder changed: $(tree_of "$tmp/in")"
    echo "HETATM" >"$tmp/fpocket/x_out.pdb"
    mkdir "$tmp/fpocket/meshes"
    echo "old" >"$tmp/fpocket/meshes/pocket_1.ply"
    echo "notes" >"$tmp/fpocket/meshes/notes.txt"
    run pockets "$pdb" -o "$tmp/fpocket"
    expect_error "$tmp/fpocket: holds files that are not alphapocket outputs ('meshes/notes.txt', 'x_out.pdb')"
    [[ $(cat "$tmp/fpocket/meshes/pocket_1.ply") == old ]] || fail "a file was changed"
    [[ $(echo $(ls -A "$tmp")) == "err fpocket in out" ]] || fail "left beside it: $(ls -A "$tmp")"
    ;;
  outdir_current)
    mkdir "$tmp/here"
    cd "$tmp/here"
    run pockets "$pdb" -o .
    expect_error ".: is the current directory or holds it"
    [[ -z $(ls -A "$tmp/here") ]] || fail "files written: $(ls -A "$tmp/here")"
    ;;
  outdir_symlink)
    # A link to nothing is named as such; a link to a directory is followed.
    ln -s "$tmp/nowhere" "$tmp/dangling"
    run pockets "$pdb" -o "$tmp/dangling"
    expect_error "$tmp/dangling: is a symbolic link to $tmp/nowhere, which does not exist"
    [[ ! -e "$tmp/nowhere" ]] || fail "the link's target was created"
    mkdir "$tmp/real"
    ln -s "$tmp/real" "$tmp/link"
    run -q pockets "$pdb" -o "$tmp/link"
    expect_success
    [[ -L "$tmp/link" && -f "$tmp/real/report.json" ]] || fail "the link was not followed"
    ;;
  outdir_replaced)
    # A second run replaces the first one's directory whole: its meshes of
    # another format and the pockets it no longer finds are gone.
    run -q pockets "$pdb" -o "$tmp/o" --mesh ply
    expect_success
    run -q pockets "$pdb" -o "$tmp/o" --mesh obj --min-volume 30
    expect_success
    [[ -z $(find "$tmp/o" -name '*.ply') ]] || fail "meshes of the first run left"
    mv "$tmp/o" "$tmp/second"
    run -q pockets "$pdb" -o "$tmp/o" --mesh obj --min-volume 30
    diff -r "$tmp/o" "$tmp/second" >/dev/null || fail "the replaced directory differs from a fresh one"
    [[ $(echo $(ls -A "$tmp")) == "err o out second" ]] || fail "left beside it: $(ls -A "$tmp")"
    ;;
  usage_errors)
    for args in "--probe -1" "--probe nan" "--probe 1e10" "--model 0" "--min-volume -5" "--mesh vrml" "--weighted" ""; do
      # shellcheck disable=SC2086
      run pockets $args ${args:+"$pdb"} -o "$tmp/o"
      [[ $rc -eq 2 ]] || fail "'pockets $args': exit code $rc, expected 2"
      [[ $(wc -l <"$tmp/err") -eq 1 ]] || fail "'pockets $args': stderr is not one line"
      [[ ! -e "$tmp/o" ]] || fail "'pockets $args': the output directory was created"
    done
    ;;
  stdout_full)
    # --json to a full device: the lost report is an error, not a success.
    [[ -w /dev/full ]] || { echo "SKIP [$case_name]: no /dev/full"; exit 77; }
    set +e
    "$exe" pockets "$pdb" -o "$tmp/o" --json >/dev/full 2>"$tmp/err"
    rc=$?
    set -e
    [[ $rc -ne 0 ]] || fail "exit code 0 with stdout lost"
    grep -q "^ERROR: cannot write to standard output$" "$tmp/err" || fail "no error about stdout"
    ;;
  help)
    run pockets --help
    expect_success
    for option in -o,--output-dir --probe --min-volume --mesh --json --chains --keep-hetero; do
      grep -qe "$option" "$tmp/out" || fail "--help does not mention $option"
    done
    if grep -q -e "--weighted" "$tmp/out"; then fail "--help offers --weighted"; fi
    ;;
  *)
    echo "unknown case: $case_name" >&2
    exit 2
    ;;
esac
echo "PASS [$case_name]"
