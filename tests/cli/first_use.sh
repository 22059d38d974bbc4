#!/usr/bin/env bash
# CLI traps a new user meets (issue 18), one case per CTest test.
# Usage: first_use.sh ALPHAPOCKET REPO_ROOT CASE
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" "$@"

case "$case_name" in
  chains_before_file)
    # --chains takes one value: FILE after it is FILE.
    run pockets --chains A "$data/3stdA.pdb" -o "$tmp/o"
    expect_success
    grep -q '^[0-9]* pockets\?, ' "$tmp/out" || fail "no summary"
    run pockets --chains A --chains B "$data/3stdA.pdb" -o "$tmp/o2"
    expect_error "$data/3stdA.pdb" "no chain 'B'"
    ;;
  range_message)
    # A value out of range: a plain message, no 309-digit bound.
    run pockets --min-volume -3 "$data/3stdA.pdb" -o "$tmp/o"
    expect_error "--min-volume" "'-3' is below 0"
    [[ $rc -eq 2 ]] || fail "exit code $rc, expected 2"
    [[ $(wc -c <"$tmp/err") -lt 120 ]] || fail "the message is long"
    run pockets --probe 200 "$data/3stdA.pdb" -o "$tmp/o"
    expect_error "--probe" "'200' is not between 0 and 100"
    [[ ! -e "$tmp/o" ]] || fail "OUTDIR made for a wrong command line"
    ;;
  unknown_subcommand)
    run pocket "$data/3stdA.pdb"
    expect_error "unknown subcommand 'pocket'; did you mean 'pockets'?"
    [[ $rc -eq 2 ]] || fail "exit code $rc, expected 2"
    run frobnicate
    expect_error "unknown subcommand 'frobnicate'; subcommands: pockets, "
    ;;
  help_subcommand)
    run help pockets
    expect_success
    grep -q '^Usage: pockets \[OPTIONS\] FILE' "$tmp/out" || fail "not the help of pockets"
    grep -q 'Exit codes: 0 success; 1 ' "$tmp/out" || fail "no exit codes"
    grep -qE -- '--min-volume V=4 ' "$tmp/out" || fail "no plain default for --min-volume"
    ! grep -qE 'FLOAT:|NUMBER|in \[' "$tmp/out" || fail "raw type strings in the help"
    run help
    expect_success
    # pockets is the first subcommand listed.
    [[ $(grep -A1 '^Subcommands:' "$tmp/out" | tail -n 1 | awk '{print $1}') == pockets ]] ||
      fail "pockets is not listed first"
    run help nope
    expect_error "unknown subcommand 'nope'"
    ;;
  global_flags_after)
    # -q after the subcommand: no log lines; -v: every site logged.
    run pockets "$data/3stdA.pdb" -o "$tmp/o" -q
    expect_success
    [[ ! -s "$tmp/err" ]] || fail "-q after the subcommand did not quiet the log"
    run pockets "$data/3stdA.pdb" -o "$tmp/o" -v
    expect_success
    sites=$(grep -c '"rank"' "$tmp/o/report.json" || true)
    [[ $(grep -c '^\[debug\] site [0-9]*: ' "$tmp/err") -ge 1 ]] || fail "-v logs no site"
    run -vv pockets "$data/3stdA.pdb" -o "$tmp/o"
    grep -q '^\[trace\] site 1 lining residues: A:' "$tmp/err" || fail "-vv logs no residues"
    ;;
  ca_only)
    run pockets "$data/pdb1gdr.ent" -o "$tmp/o"
    expect_success
    grep -q "^\[warning\] $data/pdb1gdr.ent: only C-alpha atoms (a C-alpha trace): " "$tmp/err" ||
      fail "no warning on a C-alpha trace"
    run pockets "$data/3stdA.pdb" -o "$tmp/o2"
    ! grep -q 'only C-alpha\|only backbone\|only nucleic' "$tmp/err" || fail "a full-atom protein warned"
    ;;
  nucleic_only)
    run pockets "$data/1bna.pdb" -o "$tmp/o"
    expect_success
    grep -q "^\[warning\] $data/1bna.pdb: only nucleic acids: " "$tmp/err" || fail "no warning on DNA alone"
    ;;
  *)
    echo "unknown case $case_name" >&2
    exit 2
    ;;
esac
