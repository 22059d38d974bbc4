#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Line coverage of the structure reader (molecule's structure.cpp) by a set
# of inputs, with clang's source-based coverage: the reader compiled with
# -fprofile-instr-generate -fcoverage-mapping (nothing else instrumented),
# linked with fuzz_structure's harness, libFuzzer's driver and the libraries
# of an ordinary build, runs every input once (-runs=0, fuzz_structure's
# max_len); llvm-cov reports the file's lines, regions and branches.
#
#   fuzz/coverage.sh BUILD_DIR INPUT_DIR...
#
# BUILD_DIR: a configured and built tree (gcc or clang; molecule and alpha
# libraries). Needs clang, llvm-profdata and llvm-cov (Debian: clang, llvm).
set -euo pipefail

build=$(cd "$1" && pwd)
shift
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(dirname "$here")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

reader=$(find "$root/molecule/src" -name structure.cpp)
includes=(-I"$root/molecule/include" -I"$root/libalpha/include" -I"$build/generated")
while read -r dir; do includes+=(-I"$dir"); done < <(find "$root/molecule/src" -type d)
# C++17 as in the sanitizer builds (molecule/CMakeLists.txt: gemmi's cifdoc.hpp).
clang++ -std=c++17 -Wno-c++20-extensions -O1 -g -fprofile-instr-generate -fcoverage-mapping "${includes[@]}" \
  -c "$reader" -o "$work/reader.o"
clang++ -std=c++20 -O1 "${includes[@]}" -c "$here/fuzz_structure.cpp" -o "$work/harness.o"
libs=$(find "$build" -name 'libalphapocket_molecule.a' -o -name 'libalphapocket_alpha.a' | sort -r)
# shellcheck disable=SC2086
clang++ -fsanitize=fuzzer -fprofile-instr-generate "$work/harness.o" "$work/reader.o" $libs \
  -lgmpxx -lgmp -lOpenMeshCore -lz -lsqlite3 -lnettle -lspdlog -lfmt -o "$work/reader_coverage"
LLVM_PROFILE_FILE=$work/raw.profraw "$work/reader_coverage" -runs=0 -max_len=262144 "$@" >"$work/run.log" 2>&1 ||
  { tail -n 20 "$work/run.log"; exit 1; }
grep -E '^Done [0-9]+ runs' "$work/run.log"
llvm-profdata merge -o "$work/profile" "$work/raw.profraw"
llvm-cov report "$work/reader_coverage" -instr-profile="$work/profile" "$reader" | sed -n '1p;3p'
