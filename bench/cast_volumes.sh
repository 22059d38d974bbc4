#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# How close each cast's enclosed volume (meshes/pocket_N, void_N) is to its
# cavity's reported ms_volume: `alphapocket pockets --mesh off` on every
# file, the casts' volumes by the divergence theorem, then the share within
# 2% overall, by kind and by ms_volume band, and the worst casts.
#
# Usage: bench/cast_volumes.sh [ALPHAPOCKET] [FILE ...]
#   ALPHAPOCKET  default build/apps/alphapocket
#   FILEs        default ../shared/data/pockets-dev/*.pdb
# Environment: OPTIONS (extra pockets options, e.g. "--mesh-resolution 0.25").
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exe=${1:-$root/build/apps/alphapocket}
[[ $# -gt 0 ]] && shift
files=("$@")
[[ ${#files[@]} -gt 0 ]] || files=("$root"/../shared/data/pockets-dev/*.pdb)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for f in "${files[@]}"; do
  # shellcheck disable=SC2086
  "$exe" -q pockets "$f" -o "$out/$(basename "${f%.*}")" --mesh off ${OPTIONS:-} >/dev/null
done
python3 - "$out" <<'PY'
import glob, json, os, sys
import numpy as np

def off_volume(path):  # COFF: points with colours, then "3 a b c" faces
    tok = open(path).read().split()
    nv, nf = int(tok[1]), int(tok[2])
    p = np.array(tok[4:4 + 6 * nv], float).reshape(nv, 6)[:, :3]
    f = np.array(tok[4 + 6 * nv:4 + 6 * nv + 4 * nf], int).reshape(nf, 4)[:, 1:]
    return np.einsum('ij,ij->i', p[f[:, 0]], np.cross(p[f[:, 1]], p[f[:, 2]])).sum() / 6

rows = []  # structure, kind, rank, ms_volume, cast volume
for d in sorted(glob.glob(os.path.join(sys.argv[1], '*', ''))):
    report = json.load(open(os.path.join(d, 'report.json')))
    for kind in ('pockets', 'voids'):
        for c in report[kind]:
            rows.append((os.path.basename(os.path.normpath(d)), kind, c['rank'], c['ms_volume'],
                         off_volume(os.path.join(d, c['mesh']))))

def line(name, sel):
    if not sel: return
    e = np.array([(v - m) / m for *_, m, v in sel])
    worst = e[np.argmax(abs(e))]
    print(f"{name}: {len(sel)} casts, {np.sum(abs(e) <= 0.02)} within 2% ({100 * np.mean(abs(e) <= 0.02):.1f}%), "
          f"median error {100 * np.median(e):+.2f}%, median |error| {100 * np.median(abs(e)):.2f}%, worst {100 * worst:+.2f}%")

line('voids', [r for r in rows if r[1] == 'voids'])
line('pockets', [r for r in rows if r[1] == 'pockets'])
for lo, hi in ((0, 10), (10, 30), (30, 60), (60, 150), (150, 400), (400, float('inf'))):
    line(f'  pockets of {lo}-{hi} A^3', [r for r in rows if r[1] == 'pockets' and lo <= r[3] < hi])
print('worst:')
for s, kind, rank, m, v in sorted(rows, key=lambda r: -abs(r[4] - r[3]) / r[3])[:8]:
    print(f'  {s} {kind[:-1]} {rank}: ms_volume {m:.1f}, cast {v:.1f} ({100 * (v - m) / m:+.2f}%)')
PY
