#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds alphapocket and the ligand-site benchmark in BUILD_DIR (default
# build/; a new one is configured for Release) and runs it: DCC and DCA at
# top-1 and top-3 on the pockets-dev structures, sites per structure and
# runtime, next to fpocket's figures. Arguments go to ligand_sites (see the
# comment at the top of bench/ligand_sites.cpp), e.g.
#
#   bench/ligand_sites.sh                          # ../shared/data/pockets-dev
#   bench/ligand_sites.sh --details /data/other-set
#   bench/ligand_sites.sh -- --probe 1.6           # options for alphapocket pockets
#   BUILD_DIR=/tmp/b bench/ligand_sites.sh --json
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
if [[ ! -f "$build/CMakeCache.txt" ]]; then  # a new build directory: Release (the project's default)
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" --target ligand_sites alphapocket >/dev/null
exec "$build/bench/ligand_sites" "$@"
