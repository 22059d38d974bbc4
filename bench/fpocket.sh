# SPDX-License-Identifier: Apache-2.0
# fpocket 4.0, the benchmarks' peer (sourced by batch_throughput.sh and
# pockets_cpu.sh): built once per cache from ../shared/peers as its
# README says, outside the repository.

# fpocket_binary CACHE PEERS: prints the path of fpocket, building it first
# when CACHE has none (needs make and g++).
fpocket_binary() {
  local cache=$1 peers=$2
  local exe=$cache/fpocket-4.0/bin/fpocket
  if [[ ! -x $exe ]]; then
    for tool in make g++; do
      command -v $tool >/dev/null || { echo "$tool not found (needed to build fpocket)" >&2; return 1; }
    done
    echo "building fpocket 4.0 into $cache ..." >&2
    mkdir -p "$cache"
    rm -rf "$cache/fpocket-4.0"
    tar xzf "$peers/fpocket-4.0-src.tar.gz" -C "$cache"
    (cd "$cache/fpocket-4.0" && sed -i 's/ -pg//g' makefile &&
       make CXX=g++ QCFLAGS="-O2 -ansi -Isrc/qhull/src" >build.log 2>&1) ||
      { echo "fpocket build failed: $cache/fpocket-4.0/build.log" >&2; return 1; }
  fi
  echo "$exe"
}
