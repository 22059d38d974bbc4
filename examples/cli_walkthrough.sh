#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A tour of the alphapocket command line on a real protein, from the
# triangulation to the pockets. Every step prints what it runs.
#
#   examples/cli_walkthrough.sh [ALPHAPOCKET [WORKDIR]]
#
# ALPHAPOCKET defaults to build/apps/alphapocket, WORKDIR (where files are
# written) to a new temporary directory. Stops at the first failing step.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
exe=${1:-$here/../build/apps/alphapocket}
work=${2:-$(mktemp -d)}
pdb=$here/data/1a26A.pdb  # PDB 1A26 chain A, with its ligand CNA
mkdir -p "$work"
cd "$work"

step() {
  printf '\n$ alphapocket %s\n' "$*"
  "$exe" -q "$@"
}

echo "alphapocket $("$exe" --version | cut -d' ' -f2), working in $work"

# 1. The regular triangulation of the atoms (ProtOr radius + 1.4 A probe
#    each), checked exactly.
step delaunay "$pdb" --check

# 2. The alpha spectrum and the shape at one alpha_sq; 0 is the
#    solvent-accessible model, the one pockets are found on.
step spectrum "$pdb" --alpha-sq 0

# 3. Persistence: the 1-cycles (tunnels) and 2-cycles (voids) of the
#    filtration; those alive at alpha_sq 0 (born <= 0, dying > 0) are the
#    molecule's tunnels and voids.
printf '\n$ alphapocket persistence %s > persistence.txt\n' "$pdb"
"$exe" -q persistence "$pdb" >persistence.txt
echo "$(wc -l <persistence.txt) pairs; alive at alpha_sq 0:" \
  "$(awk '$1 == 1 && $2 <= 0 && $3 > 0' persistence.txt | wc -l) tunnels," \
  "$(awk '$1 == 2 && $2 <= 0 && $3 > 0' persistence.txt | wc -l) voids; the longest-lived void:"
awk '$1 == 2 && $2 <= 0 && $3 > 0 { print $3 - $2, $0 }' persistence.txt | sort -g | tail -n 1 | cut -d' ' -f2-

# 4. The solvent-accessible alpha shape as a mesh for MeshLab.
step shape "$pdb" --alpha-sq 0 -o sa_shape.ply

# 5. Solvent-accessible area and volume, exact for the union of balls, and
#    the solvent-excluded (molecular) surface: the union eroded by the probe.
step surface "$pdb"

# 6. Pockets, voids and tunnels, with every output file.
step pockets "$pdb" -o 1a26A_pockets
echo
echo "1a26A_pockets/ holds: $(cd 1a26A_pockets && ls | tr '\n' ' ')"
echo "open the meshes in MeshLab (1a26A_pockets/meshes/*.ply), or: pymol 1a26A_pockets/pockets.pml"
