#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# CLI tests of `alphapocket batch` and `alphapocket merge`, one case per
# CTest test. Usage: batch.sh ALPHAPOCKET REPO_ROOT CASE
#
# Small real chains (tests/data) and the broken files of tests/data/bad;
# the tables are compared byte for byte between runs that must agree (-j,
# input order, interrupted and resumed, merged chunks), and read back from
# the SQLite database with the sqlite3 program.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" "$@"

tables="structures.csv sites.csv tunnels.csv failures.tsv alphapocket.sqlite"

# Three good chains in $tmp/in (one of them inside a directory named like
# a structure file), three broken files, and a file that is no structure.
make_inputs() {
  mkdir -p "$tmp/in/nested/dir.pdb"
  cp "$data/1fkgA.pdb" "$data/1ytjA.pdb" "$tmp/in/"
  cp "$data/3stdA.pdb" "$tmp/in/nested/dir.pdb/"
  cp "$data/bad/corrupt.pdb.gz" "$data/bad/truncated.cif" "$data/bad/empty.pdb" "$tmp/in/"
  echo "not a structure" >"$tmp/in/notes.txt"
}

# The value of column NAME (by the header) in the row of structure ID of a CSV file.
csv_get() {  # FILE ID NAME
  awk -F, -v id="$2" -v name="$3" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; next }
    $1 == id { print $c; exit }' "$1"
}

# Rows of FILE (without the header).
rows() { echo $(($(wc -l <"$1") - 1)); }

same_tables() {  # DIR1 DIR2
  for t in $tables; do cmp -s "$1/$t" "$2/$t" || fail "$t differs between $1 and $2"; done
}

case "$case_name" in
  mixed)
    # Broken files among good ones: the run goes on, records each, exits 3.
    make_inputs
    run -q batch "$tmp/in" -o "$tmp/o" -j 2
    [[ $rc -eq 3 ]] || fail "exit code $rc, expected 3 (some failed)"
    for t in $tables records.jsonl; do [[ -s "$tmp/o/$t" ]] || fail "$t missing"; done
    [[ $(cut -d, -f1 "$tmp/o/structures.csv" | tr '\n' ' ') == "id 1fkgA 1ytjA 3stdA corrupt empty truncated " ]] ||
      fail "structures.csv ids: $(cut -d, -f1 "$tmp/o/structures.csv" | tr '\n' ' ')"
    [[ $(csv_get "$tmp/o/structures.csv" 3stdA path) == "$tmp/in/nested/dir.pdb/3stdA.pdb" ]] || fail "3stdA's path"
    for id in 1fkgA 1ytjA 3stdA; do
      [[ $(csv_get "$tmp/o/structures.csv" $id status) == ok ]] || fail "$id not ok"
      [[ $(ls "$tmp/o/$id") == report.json ]] || fail "$id/: $(ls "$tmp/o/$id") (default: the report only)"
      n=$(csv_get "$tmp/o/structures.csv" $id sites)
      [[ $(grep -c "^$id," "$tmp/o/sites.csv") -eq $n ]] || fail "$id: not $n rows in sites.csv"
    done
    for id in corrupt empty truncated; do
      [[ $(csv_get "$tmp/o/structures.csv" $id status) == failed ]] || fail "$id not failed"
      [[ ! -e "$tmp/o/$id" ]] || fail "$id/ written for a failure"
      grep -qP "^$id\t$tmp/in/$id\.[a-z.]+\tbad_input\t.*$id" "$tmp/o/failures.tsv" || fail "$id not in failures.tsv"
      grep -q "$id: bad_input: " "$tmp/err" || fail "$id's failure not logged"
    done
    [[ $(rows "$tmp/o/failures.tsv") -eq 3 ]] || fail "failures.tsv: not 3 rows"
    head -n 1 "$tmp/o/failures.tsv" | grep -qP '^id\tpath\tcategory\tmessage$' || fail "failures.tsv header"
    [[ -z $(find "$tmp/o" -name '.*.tmp') ]] || fail "temporary files left"
    ;;
  none_succeeded)
    mkdir "$tmp/in"
    cp "$data/bad/corrupt.pdb.gz" "$data/bad/three_atoms.pdb" "$tmp/in/"
    run -q batch "$tmp/in" -o "$tmp/o"
    [[ $rc -eq 4 ]] || fail "exit code $rc, expected 4 (none succeeded)"
    [[ $(rows "$tmp/o/failures.tsv") -eq 2 ]] || fail "failures.tsv: not 2 rows"
    [[ $(rows "$tmp/o/sites.csv") -eq 0 ]] || fail "sites.csv not empty"
    ;;
  duplicate_ids)
    # Two inputs with one id: an error naming both, before any work.
    mkdir -p "$tmp/a" "$tmp/b"
    cp "$data/1fkgA.pdb" "$tmp/a/"
    gzip -c "$data/1fkgA.pdb" >"$tmp/b/1fkgA.pdb.gz"
    run batch "$tmp/a" "$tmp/b" -o "$tmp/o"
    expect_error "two inputs with the structure id '1fkgA': $tmp/a/1fkgA.pdb and $tmp/b/1fkgA.pdb.gz"
    [[ ! -e "$tmp/o" ]] || fail "OUTDIR created"
    ;;
  bad_inputs)
    # Inputs that are no structures: errors before any work.
    echo x >"$tmp/notes.txt"
    run batch "$tmp/notes.txt" -o "$tmp/o"
    expect_error "$tmp/notes.txt: not a structure file"
    run batch "$tmp/missing" -o "$tmp/o"
    expect_error "$tmp/missing: no such file or directory"
    mkdir "$tmp/empty"
    run batch "$tmp/empty" -o "$tmp/o"
    expect_error "no structure files in the inputs"
    run batch "$data/1fkgA.pdb" -o "$tmp/o" --outputs report,movie
    expect_error "--outputs: unknown output 'movie'"
    [[ $rc -eq 2 ]] || fail "--outputs report,movie: exit code $rc, expected 2 (a wrong command line)"
    run batch "$data/1fkgA.pdb"
    [[ $rc -eq 2 ]] || fail "no -o: exit code $rc, expected 2"
    run batch -o "$tmp/o"
    expect_error "batch: no INPUT and no --list (see --help)"
    [[ $rc -eq 2 ]] || fail "no INPUT: exit code $rc, expected 2 (a wrong command line)"
    [[ ! -e "$tmp/o" ]] || fail "OUTDIR created"
    ;;
  lists)
    # --list (comments, blank lines), a P2Rank .ds dataset (paths relative
    # to its directory, ligand codes after them), and paths on stdin: the
    # same tables as the files given directly.
    make_inputs
    run -q batch "$tmp/in/1fkgA.pdb" "$tmp/in/1ytjA.pdb" "$tmp/in/nested/dir.pdb/3stdA.pdb" -o "$tmp/direct"
    expect_success
    printf '# my list\n\n%s\n  %s  \n' "$tmp/in/1fkgA.pdb" "$tmp/in/1ytjA.pdb" >"$tmp/list.txt"
    printf '# dataset\n\nHEADER: protein ligand_codes\n\nnested/dir.pdb/3stdA.pdb  MQ0\n' >"$tmp/in/set.ds"
    run -q batch --list "$tmp/list.txt" --list "$tmp/in/set.ds" -o "$tmp/listed"
    expect_success
    same_tables "$tmp/direct" "$tmp/listed"
    set +e
    printf '%s\n' "$tmp/in/1ytjA.pdb" "$tmp/in/nested/dir.pdb/3stdA.pdb" | "$exe" -q batch - "$tmp/in/1fkgA.pdb" \
      -o "$tmp/stdin" 2>"$tmp/err"
    rc=$?
    set -e
    expect_success
    same_tables "$tmp/direct" "$tmp/stdin"
    ;;
  max_atoms)
    # Over --max-atoms: skipped (not attempted), category limit_exceeded.
    run -q batch "$data/1fkgA.pdb" "$data/1ytjA.pdb" -o "$tmp/o" --max-atoms 800
    [[ $rc -eq 3 ]] || fail "exit code $rc, expected 3"
    [[ $(csv_get "$tmp/o/structures.csv" 1fkgA status) == skipped ]] || fail "1fkgA not skipped"
    [[ -z $(csv_get "$tmp/o/structures.csv" 1fkgA atoms) ]] || fail "a skipped structure has atoms"
    [[ $(csv_get "$tmp/o/structures.csv" 1ytjA status) == ok ]] || fail "1ytjA not ok"
    grep -qP '^1fkgA\t.*\tlimit_exceeded\t.*more than --max-atoms 800' "$tmp/o/failures.tsv" ||
      fail "1fkgA not in failures.tsv as limit_exceeded"
    [[ ! -e "$tmp/o/1fkgA" ]] || fail "outputs of a skipped structure"
    ;;
  deterministic)
    # -j 1 and -j 2, inputs in another order: byte-identical tables.
    make_inputs
    run -q batch "$tmp/in" -o "$tmp/j1" -j 1
    [[ $rc -eq 3 ]] || fail "exit code $rc"
    run -q batch "$tmp/in/nested" "$tmp/in/truncated.cif" "$tmp/in/empty.pdb" "$tmp/in/1ytjA.pdb" \
      "$tmp/in/corrupt.pdb.gz" "$tmp/in/1fkgA.pdb" -o "$tmp/j2" -j 2
    [[ $rc -eq 3 ]] || fail "exit code $rc"
    same_tables "$tmp/j1" "$tmp/j2"
    ;;
  sqlite)
    # The database holds the same rows as the text files: each CSV/TSV is
    # imported into a table of the same schema and compared both ways.
    make_inputs
    run -q batch "$tmp/in" -o "$tmp/o"
    [[ $rc -eq 3 ]] || fail "exit code $rc"
    db=$tmp/o/alphapocket.sqlite
    for t in structures sites tunnels failures; do
      file=$tmp/o/$t.csv
      mode=csv
      [[ $t == failures ]] && file=$tmp/o/$t.tsv && mode=tabs
      cols=$(sqlite3 "$db" "SELECT group_concat(name, ',') FROM pragma_table_info('$t')")
      nulls=$(sqlite3 "$db" "SELECT group_concat('UPDATE t SET ' || name || ' = NULL WHERE ' || name || \" = '';\", ' ')
        FROM pragma_table_info('$t')")
      n=$(sqlite3 "$db" "SELECT count(*) FROM $t")
      [[ $n -eq $(rows "$file") ]] || fail "$t: $n rows in the database, $(rows "$file") in $file"
      diff=$(sqlite3 :memory: "ATTACH '$db' AS d;" "CREATE TABLE t AS SELECT * FROM d.$t WHERE 0;" \
        ".mode $mode" ".import --skip 1 $file t" "$nulls" \
        "SELECT (SELECT count(*) FROM (SELECT * FROM t EXCEPT SELECT * FROM d.$t)) +
                (SELECT count(*) FROM (SELECT * FROM d.$t EXCEPT SELECT * FROM t));")
      [[ $diff -eq 0 ]] || fail "$t: $diff rows differ between the database and $file ($cols)"
    done
    [[ $(sqlite3 "$db" "SELECT count(*) FROM structures WHERE status = 'ok'") -eq 3 ]] || fail "3 ok in the database"
    [[ $(sqlite3 "$db" "SELECT count(*) FROM sites s JOIN structures t ON s.structure_id = t.id") -eq \
       $(sqlite3 "$db" "SELECT sum(sites) FROM structures") ]] || fail "sites do not join their structures"
    ;;
  outputs)
    # --outputs chooses the files of each structure; the same files as pockets writes.
    run -q batch "$data/1ytjA.pdb" -o "$tmp/o" --outputs report,csv,pml,pdb,meshes,tunnels --mesh obj
    expect_success
    for f in report.json pockets.csv pockets.pml pockets.pdb meshes/surface.obj meshes/surface.mtl meshes/meshlab.mlp; do
      [[ -s "$tmp/o/1ytjA/$f" ]] || fail "1ytjA/$f missing"
    done
    run -q pockets "$data/1ytjA.pdb" -o "$tmp/pockets" --outputs report,csv,pml,pdb,meshes,tunnels --mesh obj
    expect_success
    (cd "$tmp/pockets" && find . -type f | sort) >"$tmp/a"
    (cd "$tmp/o/1ytjA" && find . -type f | sort) >"$tmp/b"
    cmp -s "$tmp/a" "$tmp/b" || fail "batch's files differ from pockets' files"
    grep -v '"file"' "$tmp/pockets/report.json" >"$tmp/a"
    grep -v '"file"' "$tmp/o/1ytjA/report.json" >"$tmp/b"
    cmp -s "$tmp/a" "$tmp/b" || fail "batch's report differs from pockets'"
    # A re-run with fewer outputs removes the others.
    run -q batch "$data/1ytjA.pdb" -o "$tmp/o" --outputs csv
    expect_success
    [[ $(ls "$tmp/o/1ytjA" | tr '\n' ' ') == "pockets.csv sites.csv " ]] || fail "1ytjA/: $(ls "$tmp/o/1ytjA")"
    ;;
  sites_tables)
    # The run's sites.csv is its structures' sites.csv joined (each
    # structure's from its own csv output), ligands column included.
    mkdir "$tmp/in"
    cp "$pdb" "$data/3stdA.pdb" "$data/1fbl.pdb" "$tmp/in/"
    run -q batch "$tmp/in" -o "$tmp/o" --outputs csv -j 2
    expect_success
    { head -n 1 "$tmp/o/1a26A/sites.csv"
      for id in 1a26A 1fbl 3stdA; do tail -n +2 "$tmp/o/$id/sites.csv"; done; } >"$tmp/joined"
    cmp -s "$tmp/joined" "$tmp/o/sites.csv" || fail "sites.csv is not the structures' sites.csv joined"
    grep -q '^1a26A,[0-9]*,pocket,.*,A:CNA:200$' "$tmp/o/sites.csv" || fail "no site of 1a26A holds CNA"
    grep -q '^3stdA,1,void,.*,A:MQ0:503$' "$tmp/o/sites.csv" || fail "3stdA's void does not hold MQ0"
    [[ $(sqlite3 "$tmp/o/alphapocket.sqlite" "SELECT COUNT(*) FROM sites WHERE ligands LIKE '%A:CNA:200%'") -ge 1 ]] ||
      fail "sqlite: no site with CNA"
    # --print-inputs: the same structures and ids, without running them.
    run batch "$tmp/in" --print-inputs
    expect_success
    printf '1a26A\t%s\n1fbl\t%s\n3stdA\t%s\n' "$tmp/in/1a26A.pdb" "$tmp/in/1fbl.pdb" "$tmp/in/3stdA.pdb" >"$tmp/want"
    cmp -s "$tmp/want" "$tmp/out" || fail "--print-inputs: $(cat "$tmp/out")"
    run batch "$tmp/in" "$pdb" --print-inputs
    expect_error "two inputs with the structure id '1a26A'"
    ;;
  resume)
    # A re-run skips what is done (same content, parameters, version) and
    # redoes a structure whose file changed, or everything for new parameters.
    make_inputs
    run batch "$tmp/in" -o "$tmp/o" -j 2
    [[ $rc -eq 3 ]] || fail "exit code $rc"
    cp -r "$tmp/o" "$tmp/first"
    touch -d '2000-01-01' "$tmp/o"/*/report.json
    run batch "$tmp/in" -o "$tmp/o" -j 2
    [[ $rc -eq 3 ]] || fail "exit code $rc"
    grep -q '(6 done before)' "$tmp/err" || fail "not 6 done before"
    [[ -z $(find "$tmp/o" -name report.json -newer "$tmp/first/records.jsonl") ]] || fail "a report was rewritten"
    same_tables "$tmp/first" "$tmp/o"
    echo "REMARK   1 CHANGED" | cat - "$data/1ytjA.pdb" >"$tmp/in/1ytjA.pdb"
    run batch "$tmp/in" -o "$tmp/o" -j 2
    grep -q '(5 done before)' "$tmp/err" || fail "not 5 done before after a change"
    [[ -n $(find "$tmp/o/1ytjA" -name report.json -newer "$tmp/first/records.jsonl") ]] || fail "1ytjA not redone"
    # A structure that fails now: its earlier outputs go.
    echo "HETATM garbage" >"$tmp/in/1fkgA.pdb"
    run batch "$tmp/in" -o "$tmp/o" -j 2
    [[ $(csv_get "$tmp/o/structures.csv" 1fkgA status) == failed ]] || fail "1fkgA did not fail"
    [[ ! -e "$tmp/o/1fkgA" ]] || fail "1fkgA's outputs of the earlier run are left"
    cp "$data/1fkgA.pdb" "$tmp/in/"
    run batch "$tmp/in" -o "$tmp/o" -j 2 --probe 1.5
    grep -q '(0 done before)' "$tmp/err" || fail "new parameters, yet something done before"
    ! cmp -s "$tmp/first/sites.csv" "$tmp/o/sites.csv" || fail "sites.csv unchanged with another probe"
    ;;
  interrupt)
    # SIGINT to a real run: the structures in flight finish, the tables
    # hold what finished, exit 130; the re-run completes it, and its tables
    # are those of an uninterrupted run.
    mkdir "$tmp/in"
    cp "$pdb" "$data/1fbl.pdb" "$data/1UYD.pdb" "$data/1fkgA.pdb" "$data/1ytjA.pdb" "$data/3stdA.pdb" "$tmp/in/"
    cp "$data/bad/corrupt.pdb.gz" "$tmp/in/"
    run -q batch "$tmp/in" -o "$tmp/whole" -j 1
    [[ $rc -eq 3 ]] || fail "exit code $rc"
    "$exe" -q batch "$tmp/in" -o "$tmp/o" -j 1 2>"$tmp/err" &
    pid=$!
    for _ in $(seq 600); do [[ -s "$tmp/o/records.jsonl" ]] && break; sleep 0.05; done
    kill -INT $pid
    set +e
    wait $pid
    rc=$?
    set -e
    [[ $rc -eq 130 ]] || fail "exit code $rc after SIGINT, expected 130"
    done=$(grep -c . "$tmp/o/records.jsonl")
    [[ $done -ge 1 && $done -lt 7 ]] || fail "$done of 7 records after the interrupt"
    [[ $(rows "$tmp/o/structures.csv") -eq $done ]] || fail "structures.csv does not hold the $done finished"
    [[ -z $(find "$tmp/o" -name '.*.tmp') ]] || fail "temporary files left"
    run -q batch "$tmp/in" -o "$tmp/o" -j 2
    [[ $rc -eq 3 ]] || fail "exit code $rc on the re-run"
    same_tables "$tmp/whole" "$tmp/o"
    ;;
  outdir_refused)
    # -o '' (not "no -o") and a file system root are refused before any work.
    run batch "$pdb" -o ''
    [[ $rc -eq 2 ]] || fail "exit code $rc, expected 2"
    grep -q '^ERROR: .*an empty name is not an output directory' "$tmp/err" || fail "no message"
    run batch "$pdb" -o /
    expect_error "/: is the root of the file system"
    # A structure's directory holding other files: that structure fails,
    # its files are kept.
    mkdir -p "$tmp/o/1a26A"
    echo "mine" >"$tmp/o/1a26A/notes.txt"
    run -q batch "$pdb" -o "$tmp/o"
    [[ $rc -eq 4 ]] || fail "exit code $rc"
    grep -q "holds files that are not alphapocket outputs ('notes.txt')" "$tmp/o/failures.tsv" || fail "not in failures.tsv"
    [[ $(cat "$tmp/o/1a26A/notes.txt") == mine ]] || fail "notes.txt changed"
    ;;
  interrupt_twice)
    # A second signal abandons the structures in flight at once: exit 130,
    # no file half-written, and a re-run completes the tables.
    mkdir "$tmp/in"
    cp "$pdb" "$data/1fbl.pdb" "$data/1UYD.pdb" "$data/1fkgA.pdb" "$data/3stdA.pdb" "$tmp/in/"
    run -q batch "$tmp/in" -o "$tmp/whole" -j 2
    expect_success
    # Abandoning _exit()s with workers unjoined, by design: under
    # ThreadSanitizer (.ci/sanitizers) that is no leak to report.
    TSAN_OPTIONS=${TSAN_OPTIONS:-}:report_thread_leaks=0 "$exe" -q batch "$tmp/in" -o "$tmp/o" -j 2 2>"$tmp/err" &
    pid=$!
    for _ in $(seq 600); do [[ -s "$tmp/o/records.jsonl" ]] && break; sleep 0.05; done
    kill -INT $pid
    sleep 0.05
    kill -INT $pid 2>/dev/null || true
    set +e
    wait $pid
    rc=$?
    set -e
    [[ $rc -eq 130 ]] || fail "exit code $rc after two SIGINTs, expected 130"
    [[ ! -e "$tmp/o/structures.csv" ]] || fail "tables written: the second signal did not abandon the run"
    for f in "$tmp/o"/*/report.json; do grep -q '^}$' "$f" || fail "$f is incomplete"; done
    [[ -z $(find "$tmp/o" -name '.*') ]] || fail "temporaries left: $(find "$tmp/o" -name '.*')"
    run -q batch "$tmp/in" -o "$tmp/o" -j 2
    expect_success
    same_tables "$tmp/whole" "$tmp/o"
    ;;
  merge)
    # Two chunks merged: the tables of one run over both.
    make_inputs
    run -q batch "$tmp/in" -o "$tmp/whole"
    run -q batch "$tmp/in/1fkgA.pdb" "$tmp/in/corrupt.pdb.gz" -o "$tmp/chunk1"
    run -q batch "$tmp/in/nested" "$tmp/in/1ytjA.pdb" "$tmp/in/truncated.cif" "$tmp/in/empty.pdb" -o "$tmp/chunk2"
    run -q merge "$tmp/chunk2" "$tmp/chunk1" -o "$tmp/merged"
    expect_success
    same_tables "$tmp/whole" "$tmp/merged"
    run merge "$tmp/chunk1" "$tmp/whole" -o "$tmp/bad"
    expect_error "structure id '1fkgA' is in both $tmp/chunk1/records.jsonl and $tmp/whole/records.jsonl"
    run merge "$tmp/in" -o "$tmp/bad"
    expect_error "$tmp/in: not a batch output directory"
    ;;
  alphafold)
    # AlphaFold DB models: recognised (by name, or in mmCIF by
    # _ma_qa_metric_local), mean pLDDT per structure and per site;
    # --min-plddt leaves out the low-confidence residues.
    mkdir "$tmp/in"
    cp "$data/AF-X6R8D5-F1-model_v1.pdb.gz" "$data/1ytjA.pdb" "$tmp/in/"
    cp "$data/AF-P29373-F1-model_v4.cif.gz" "$tmp/in/model.cif.gz"
    run -q batch "$tmp/in" -o "$tmp/o"
    expect_success
    s=$tmp/o/structures.csv
    for id in AF-X6R8D5-F1-model_v1 model; do
      [[ $(csv_get "$s" $id predicted) == 1 ]] || fail "$id not predicted"
      p=$(csv_get "$s" $id mean_plddt)
      [[ $p =~ ^[0-9]+\.[0-9]+$ ]] || fail "$id: mean_plddt '$p'"
      [[ -z $(awk -F, -v id=$id '$1 == id && $20 == ""' "$tmp/o/sites.csv") ]] || fail "$id: a site without pLDDT"
    done
    [[ $(csv_get "$s" 1ytjA predicted) == 0 && -z $(csv_get "$s" 1ytjA mean_plddt) ]] || fail "1ytjA predicted"
    [[ -z $(awk -F, '$1 == "1ytjA" && $20 != ""' "$tmp/o/sites.csv") ]] || fail "1ytjA: a site with pLDDT"
    # The AF-X6R8D5 model's pLDDT spans 35-87: at 70 some residues go.
    run -q batch "$tmp/in" -o "$tmp/cut" --min-plddt 70
    expect_success
    all=$(csv_get "$s" AF-X6R8D5-F1-model_v1 atoms)
    kept=$(csv_get "$tmp/cut/structures.csv" AF-X6R8D5-F1-model_v1 atoms)
    [[ $kept -lt $all && $kept -gt 0 ]] || fail "--min-plddt 70 kept $kept of $all atoms"
    grep -q '"plddt": '$((all - kept)) "$tmp/cut/AF-X6R8D5-F1-model_v1/report.json" || fail "dropped count"
    grep -q 'not a predicted model (no pLDDT): --min-plddt ignored' "$tmp/cut/1ytjA/report.json" ||
      fail "no warning for an experimental structure"
    [[ $(csv_get "$tmp/cut/structures.csv" 1ytjA atoms) == $(csv_get "$s" 1ytjA atoms) ]] || fail "1ytjA changed"
    # pockets too: its report says the same.
    run -q pockets "$data/AF-X6R8D5-F1-model_v1.pdb.gz" -o "$tmp/p" --min-plddt 70 --json
    expect_json_object
    expect_json predicted true
    expect_json atoms_kept "$kept"
    ;;
  *)
    echo "unknown case $case_name" >&2
    exit 2
    ;;
esac
