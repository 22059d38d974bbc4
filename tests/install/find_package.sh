#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The installed package: `cmake --install` into a temporary prefix, no GMP,
# nlohmann, OpenMesh or gemmi in the installed headers, then the "Use
# from C++" example of docs/library.md built there with find_package(alphapocket) and run, the
# pkg-config file's version and flags, examples/'s programs built there
# and run, and the Python module imported from the prefix.
# Usage: find_package.sh BUILD_DIR REPO_ROOT
set -euo pipefail
build=$1
root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$tmp/prefix" --component Unspecified >/dev/null
[[ -f $tmp/prefix/lib/cmake/alphapocket/alphapocketConfig.cmake ]] || fail "no alphapocketConfig.cmake"
[[ -f $tmp/prefix/lib/cmake/alphapocket/alphapocketConfigVersion.cmake ]] || fail "no version file"
[[ -x $tmp/prefix/bin/alphapocket ]] || fail "no alphapocket binary"
if grep -rlE '#include *[<"](gmp|gmpxx|nlohmann/|OpenMesh/|gemmi/)' "$tmp/prefix/include"; then
  fail "installed headers include GMP, nlohmann, OpenMesh or gemmi"
fi
# Every installed header compiles on its own (none needs an uninstalled one).
for h in $(cd "$tmp/prefix/include" && find . -name '*.hpp' | sort); do
  echo "#include \"${h#./}\"" >>"$tmp/all.cpp"
done
g++ -std=c++20 -fsyntax-only -I"$tmp/prefix/include" "$tmp/all.cpp" || fail "installed headers do not compile alone"

# docs/library.md's example: its CMakeLists.txt and sites.cpp, built against the prefix.
mkdir "$tmp/sites"
awk '/^## Use from C\+\+/{s=1} /^## /&&!/C\+\+/{s=0} s' "$root/docs/library.md" >"$tmp/section.md"
awk '/^```cmake/{f=1;next} /^```/{f=0} f' "$tmp/section.md" >"$tmp/sites/CMakeLists.txt"
awk '/^```cpp/{f=1;next} /^```/{f=0} f' "$tmp/section.md" >"$tmp/sites/sites.cpp"
[[ -s $tmp/sites/CMakeLists.txt && -s $tmp/sites/sites.cpp ]] || fail "no cmake or cpp block in docs/library.md's Use from C++"
cmake -S "$tmp/sites" -B "$tmp/sites/build" -G Ninja -DCMAKE_PREFIX_PATH="$tmp/prefix" >/dev/null
cmake --build "$tmp/sites/build" >/dev/null
"$tmp/sites/build/sites" "$root/examples/data/1a26A.pdb" "$tmp/out" >"$tmp/stdout"
grep -qE '^(pocket|void) [0-9]+: probability [01]\.[0-9]+, score ' "$tmp/stdout" || fail "no site line: $(cat "$tmp/stdout")"
grep -q '^SA area .* A^2, MS volume .* A^3$' "$tmp/stdout" || fail "no surface line"
# The library's default outputs are the CLI's: no meshes unless asked.
"$build/apps/alphapocket" pockets "$root/examples/data/1a26A.pdb" --tunnels-from none -o "$tmp/cli" -q >/dev/null
cmp "$tmp/out/report.json" "$tmp/cli/report.json" || fail "report.json differs from the CLI's"
[[ ! -e $tmp/out/meshes ]] || fail "the library's default outputs include the meshes"
set +e
"$tmp/sites/build/sites" "$root/tests/data/bad/three_atoms.pdb" 2>"$tmp/err"
rc=$?
set -e
[[ $rc -eq 1 ]] || fail "bad input: exit $rc, expected 1"
grep -q "three_atoms.pdb: .*(bad_input)" "$tmp/err" || fail "bad input message: $(cat "$tmp/err")"

# examples/'s C++ programs, built against the prefix: they use only the
# installed headers. molecule_pockets finds the bound ligand in a site.
mkdir "$tmp/examples"
cat >"$tmp/examples/CMakeLists.txt" <<EOF
cmake_minimum_required(VERSION 3.22)
project(examples CXX)
set(CMAKE_CXX_STANDARD 20)
find_package(alphapocket REQUIRED)
foreach(example point_cloud_shape molecule_pockets)
  add_executable(\${example} $root/examples/\${example}.cpp)
  target_link_libraries(\${example} PRIVATE alphapocket::molecule)
endforeach()
EOF
cmake -S "$tmp/examples" -B "$tmp/examples/build" -G Ninja -DCMAKE_PREFIX_PATH="$tmp/prefix" >/dev/null
cmake --build "$tmp/examples/build" >/dev/null || fail "examples/ does not build against the installed package"
"$tmp/examples/build/molecule_pockets" "$root/examples/data/1a26A.pdb" "$tmp/example_out" >"$tmp/stdout"
grep -qE '^ligand CNA .*: in site [0-9]+ ' "$tmp/stdout" || fail "molecule_pockets: $(cat "$tmp/stdout")"
[[ -s $tmp/example_out/report.json ]] || fail "molecule_pockets wrote no report.json"
"$tmp/examples/build/point_cloud_shape" "$tmp/torus.ply" >/dev/null || fail "point_cloud_shape failed"

# pkg-config: version and a program linked with its flags.
export PKG_CONFIG_PATH=$tmp/prefix/lib/pkgconfig
version=$(pkg-config --modversion alphapocket)
grep -q "^project(alphapocket VERSION $version" "$root/CMakeLists.txt" || fail "pkg-config version $version"
printf '#include "alphapocket/version.hpp"\n#include "alpha/triangulation.hpp"\n#include <cstdio>\nint main() {\n  alpha::Triangulation t({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});\n  std::printf("%%s %%zu\\n", alphapocket::kVersion, t.num_finite_cells());\n}\n' >"$tmp/pc.cpp"
# shellcheck disable=SC2046
g++ "$tmp/pc.cpp" -o "$tmp/pc" $(pkg-config --cflags --libs --static alphapocket)
[[ $("$tmp/pc") == "$version 1" ]] || fail "pkg-config program printed '$("$tmp/pc")'"
# The Python module, when built: `cmake --install --component python` puts
# it under the prefix (lib/python3.X/dist-packages), importable from there.
if compgen -G "$build/python/alphapocket/_core*.so" >/dev/null; then
  cmake --install "$build" --prefix "$tmp/prefix" --component python >/dev/null
  init=$(find "$tmp/prefix" -path '*/dist-packages/alphapocket/__init__.py')
  [[ -n $init ]] || fail "the Python package was not installed under dist-packages"
  site=$(dirname "$(dirname "$init")")
  (cd "$tmp" && PYTHONPATH=$site /usr/bin/python3 -c "
import alphapocket, sys
if not alphapocket.__file__.startswith('$site'):
    sys.exit('imported from ' + alphapocket.__file__)
a = alphapocket.analyze('$root/examples/data/1a26A.pdb', tunnels_from='none')
if a.to_json() != open('$tmp/cli/report.json').read():
    sys.exit('to_json() differs from report.json')
") || fail "the installed Python module does not give report.json"
fi
echo PASS
