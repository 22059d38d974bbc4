# SPDX-License-Identifier: Apache-2.0
# Shared set-up and helpers of the CLI test scripts, sourced with the
# script's arguments: source lib.sh ALPHAPOCKET REPO_ROOT CASE.
# Needs only bash, grep and coreutils (no python, no jq): a fresh Debian 12
# machine has them.

exe=$1
root=$2
case_name=$3
data=$root/tests/data
pdb=$root/examples/data/1a26A.pdb

# A scratch directory, removed at the end (made writable first: a case may
# have locked a directory in it).
tmp=$(mktemp -d)
trap 'chmod -R u+rwx "$tmp"; rm -rf "$tmp"' EXIT

fail() {
  echo "FAIL [$case_name]: $*" >&2
  echo "--- stdout:" >&2
  cat "$tmp/out" >&2 || true
  echo "--- stderr:" >&2
  cat "$tmp/err" >&2 || true
  exit 1
}

# run ARGS...: runs alphapocket, keeps stdout, stderr and the exit code.
run() {
  set +e
  "$exe" "$@" >"$tmp/out" 2>"$tmp/err"
  rc=$?
  set -e
}

# The JSON value of KEY in stdout (compact, one object on one line): the
# first occurrence.
json_value() {
  grep -o "\"$1\":[^,}]*" "$tmp/out" | head -n 1 | cut -d: -f2
}

expect_json() {  # KEY VALUE
  local got
  got=$(json_value "$1")
  [[ "$got" == "$2" ]] || fail "\"$1\" is '$got', expected '$2'"
}

expect_success() {
  [[ $rc -eq 0 ]] || fail "exit code $rc, expected 0"
}

# A successful --json run: exit 0 and exactly one line on stdout holding
# one JSON object.
expect_json_object() {
  expect_success
  [[ $(wc -l <"$tmp/out") -eq 1 ]] || fail "stdout is not exactly one line"
  grep -qx '{.*}' "$tmp/out" || fail "stdout is not one JSON object"
}

# A failed run: non-zero exit, nothing on stdout, and exactly one line on
# stderr: "ERROR: " followed by the file name (and more).
expect_error() {  # FILE [MESSAGE-PATTERN]
  [[ $rc -ne 0 ]] || fail "exit code 0, expected an error"
  [[ ! -s "$tmp/out" ]] || fail "stdout is not empty"
  [[ $(wc -l <"$tmp/err") -eq 1 ]] || fail "stderr is not exactly one line"
  grep -qF "ERROR: $1" "$tmp/err" || fail "stderr does not start with 'ERROR: $1'"
  [[ $(head -c 7 "$tmp/err") == "ERROR: " ]] || fail "stderr does not start with 'ERROR: '"
  if [[ $# -ge 2 ]]; then
    grep -qE "$2" "$tmp/err" || fail "stderr does not match '$2'"
  fi
}

# py ARGS... <<'PY': runs the Python script on stdin (sys.argv[1:] = ARGS)
# with check(ok, detail...), which, unlike assert, python3 -O keeps.
py() {
  python3 -c "import sys
def check(ok, *detail):
    if not ok:
        sys.exit(f'check failed: {detail}')
$(cat)" "$@"
}

# run_unprivileged ARGS...: run as an unprivileged user (nobody), for whom
# permission bits hold (root writes into a mode-555 directory). alphapocket
# is copied into $tmp, which that user may read; ARGS name files in $tmp.
# Fails, never skips, when the permissions still do not hold.
run_unprivileged() {
  local as=() bin=$exe
  if [[ $(id -u) -eq 0 ]]; then
    as=(setpriv --reuid=65534 --regid=65534 --clear-groups)
    bin=$tmp/bin/alphapocket
    mkdir -p "$tmp/bin"
    cp "$exe" "$bin"
    chmod -R a+rX "$tmp"
  fi
  set +e
  "${as[@]}" "$bin" "$@" >"$tmp/out" 2>"$tmp/err"
  rc=$?
  set -e
}

# Whether an unprivileged run could write into DIR (then a test of a
# read-only place proves nothing).
writable_for_unprivileged() {  # DIR
  local as=()
  [[ $(id -u) -eq 0 ]] && as=(setpriv --reuid=65534 --regid=65534 --clear-groups)
  "${as[@]}" touch "$1/probe" 2>/dev/null
}
