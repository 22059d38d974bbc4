#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The bad-input catalog: one runner for the table in
# catalog.cases, one CTest test "cli.catalog.ID.COMMAND" per row and
# command. Usage: catalog.sh ALPHAPOCKET REPO_ROOT ID.COMMAND
#
# Every run happens in an empty working directory with -o OUTDIR for the
# commands that write one (pockets, batch), -o OUTDIR.ply for shape (at
# --alpha-sq 1), the file it writes. What is asserted, by command:
#   all       the exit code; on an error, stdout empty and exactly one
#             "ERROR: " line on stderr, the last one, matching the row's
#             message (the other lines, if any, are [info]/[warning] logs);
#             on success the message, if any, matches a line of stderr or
#             stdout (the summary); the
#             working directory holds nothing but OUTDIR afterwards;
#   pockets   on an error, OUTDIR absent if it did not exist, and
#             byte-for-byte untouched if it held a previous run; on a
#             success, written whole (report.json) and no stale file of the
#             previous run left;
#   batch     a bad structure is not an error of the run: exit 4 (none
#             succeeded), its message in failures.tsv, the tables written.
# Rows whose id starts with '!' wait for a fix (CTest DISABLED).
set -euo pipefail

id_command=$3
id=${id_command%.*}
command=${id_command##*.}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

# The row: ID COMMANDS INPUT OUTDIR EXIT MESSAGE...
row=$(awk -v id="$id" -v c="$command" '
  /^[[:space:]]*(#|$)/ { next }
  { i = $1; sub(/^!/, "", i); n = split($2, cs, ","); for (k = 1; k <= n; k++)
      if (i == id && (cs[k] == c || cs[k] == "all")) { print; exit } }' "$here/catalog.cases")
[[ -n $row ]] || { echo "catalog.sh: no row '$id' for $command" >&2; exit 1; }
read -r _ _ input outdir_kind exit_code message <<<"$row"

# The OUTDIR kinds that need a filesystem of their own (read-only, full)
# run in a private mount namespace, so no mount outlives the test; where
# mounting is not allowed the case is skipped.
if [[ $outdir_kind == readonly_fs || $outdir_kind == full_fs ]] && [[ -z ${CATALOG_NS:-} ]]; then
  if unshare -m --propagation private true 2>/dev/null; then
    CATALOG_NS=1 exec unshare -m --propagation private bash "${BASH_SOURCE[0]}" "$@"
  fi
  echo "SKIP [$id_command]: cannot make a mount namespace (not root?)"
  exit 77
fi

source "$here/lib.sh" "$@"
# lib.sh's clean-up, after unmounting what this case mounted.
trap 'umount -q "$tmp/fs" 2>/dev/null || true; chmod -R u+rwx "$tmp"; rm -rf "$tmp"' EXIT

# Regex-escapes a path for the message patterns.
escape() { printf '%s' "$1" | sed 's/[][\.*^$+?(){}|/]/\\&/g'; }
# Every file below DIR with its checksum (hidden files too), or "absent".
snapshot() {
  if [[ -e $1 || -L $1 ]]; then
    (cd "$1" 2>/dev/null && find . -mindepth 1 | LC_ALL=C sort | while read -r f; do
      if [[ -f $f ]]; then echo "$f $(sha256sum <"$f" | cut -c1-16)"; else echo "$f"; fi
    done) || echo "not a directory"
  else
    echo absent
  fi
}

mkdir "$tmp/cwd"
case $input in
  @missing) in_path=$tmp/missing.pdb ;;
  @dir) in_path=$tmp/dir.pdb; mkdir "$in_path" ;;
  *) in_path=$data/$input ;;
esac

# OUTDIR by kind: new (absent), previous (a previous run's files), under_file
# (its parent is a file), readonly_fs (on a read-only filesystem), full_fs
# (on a filesystem with 16 KiB), dangling (a symlink to nowhere), empty
# (-o ''), root (-o /), input_dir (the input's own folder, which holds
# other files), stdout_full (no OUTDIR; stdout is /dev/full).
out=$tmp/outdir
case $outdir_kind in
  new | stdout_full | -) ;;
  previous)
    mkdir -p "$out/meshes"
    echo previous >"$out/report.json"
    echo previous >"$out/meshes/pocket_99.ply"
    ;;
  under_file) echo file >"$tmp/file"; out=$tmp/file/out ;;
  readonly_fs | full_fs)
    mkdir "$tmp/fs"
    options=size=16k
    [[ $outdir_kind == readonly_fs ]] && options=ro,size=16k
    mount -t tmpfs -o "$options" tmpfs "$tmp/fs" || { echo "SKIP [$id_command]: cannot mount a tmpfs"; exit 77; }
    out=$tmp/fs/out
    ;;
  dangling) ln -s "$tmp/nowhere" "$tmp/link"; out=$tmp/link ;;
  empty) out= ;;
  root) out=/ ;;
  input_dir)
    mkdir "$tmp/project"
    cp "$in_path" "$tmp/project/"
    echo "notes of another tool" >"$tmp/project/notes.txt"
    in_path=$tmp/project/$(basename "$in_path")
    out=$tmp/project
    ;;
  *) echo "catalog.sh: unknown OUTDIR kind '$outdir_kind'" >&2; exit 1 ;;
esac
[[ $command == shape && -n $out ]] && out=$out.ply
before=$(snapshot "$out")

args=("$command" "$in_path")
[[ $command == pockets || $command == batch ]] && args+=(-o "$out")
[[ $command == shape ]] && args+=(--alpha-sq 1 -o "$out")
cd "$tmp/cwd"
set +e
if [[ $outdir_kind == stdout_full ]]; then
  "$exe" "${args[@]}" >/dev/full 2>"$tmp/err"
  rc=$?
  : >"$tmp/out"
else
  "$exe" "${args[@]}" >"$tmp/out" 2>"$tmp/err"
  rc=$?
fi
set -e
cd "$tmp"

pattern=${message//\{IN\}/$(escape "$in_path")}
pattern=${pattern//\{OUT\}/$(escape "$out")}
[[ -z $(ls -A "$tmp/cwd") ]] || fail "files left in the working directory: $(ls -A "$tmp/cwd")"

if [[ $command == batch && $exit_code == 4 ]]; then
  [[ $rc -eq 4 ]] || fail "exit code $rc, expected 4 (none succeeded)"
  [[ -f $out/failures.tsv && -f $out/structures.csv ]] || fail "the tables were not written"
  [[ $(tail -n +2 "$out/failures.tsv" | wc -l) -eq 1 ]] || fail "failures.tsv: not one row"
  tail -n 1 "$out/failures.tsv" | cut -f4- | grep -qxE "$pattern" ||
    fail "failures.tsv message '$(tail -n 1 "$out/failures.tsv" | cut -f4-)' does not match '$pattern'"
  exit 0
fi

[[ $rc -eq $exit_code ]] || fail "exit code $rc, expected $exit_code"
if [[ $exit_code -ne 0 ]]; then
  [[ ! -s $tmp/out ]] || fail "stdout is not empty"
  [[ $(grep -c '^ERROR: ' "$tmp/err") -eq 1 ]] || fail "not exactly one ERROR line"
  tail -n 1 "$tmp/err" | grep -qxE "ERROR: $pattern" || fail "the last line does not match 'ERROR: $pattern'"
  ! grep -vE '^(ERROR: |\[info\] |\[warning\] )' "$tmp/err" | grep -q . || fail "stderr has lines that are not logs"
  if [[ $outdir_kind != - && $outdir_kind != stdout_full ]]; then
    [[ $(snapshot "$out") == "$before" ]] || fail "OUTDIR changed: $(snapshot "$out" | tr '\n' ' ')"
  fi
else
  [[ $message == - ]] || grep -qE "$pattern" "$tmp/err" "$tmp/out" || fail "no stderr or stdout line matches '$pattern'"
  case $command in
    pockets)
      [[ -s $out/report.json && $(head -c 8 "$out/report.json") != previous ]] || fail "report.json not written"
      [[ ! -e $out/meshes/pocket_99.ply ]] || fail "a stale mesh of the previous run is left"
      ;;
    batch) [[ -s $out/structures.csv ]] || fail "structures.csv not written" ;;
  esac
fi
