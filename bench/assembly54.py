#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# The scaling case of bench/: 54 copies of a chain (1a26A), each turned by
# a seeded random rotation, their centres on a 3x3x6 lattice 0.9 of the
# chain's span apart (the diameter holding 90% of its atoms); each copy's
# rotation is redrawn until no atom lies within 3 A of an earlier copy: the
# copies touch without clashing, and their interfaces are new pockets, as
# in an assembly.
#
# Usage: bench/assembly54.py CHAIN.pdb OUT.cif   (python3-gemmi, python3-scipy)
import string, sys
import gemmi, numpy as np
from scipy.spatial import cKDTree
src = gemmi.read_structure(sys.argv[1])
chain = src[0][0]
xyz = np.array([a.pos.tolist() for r in chain for a in r])
centre = xyz.mean(axis=0)
step = 2 * np.percentile(np.linalg.norm(xyz - centre, axis=1), 90)
rng = np.random.default_rng(54)

def rotation():  # uniform: a random unit quaternion
    q = rng.normal(size=4)
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])

out = gemmi.Structure()
out.add_model(gemmi.Model("1"))
placed = np.empty((0, 3))
for k, site in enumerate(np.ndindex(3, 3, 6)):
    tree = cKDTree(placed) if len(placed) else None
    for attempt in range(1000):
        p = (xyz - centre) @ rotation().T + step * np.array(site)
        if tree is None or np.isinf(tree.query(p, distance_upper_bound=3.0)[0]).all():
            break
    else:
        sys.exit("no rotation of copy %d clears the others" % k)
    placed = np.vstack([placed, p])
    copy = gemmi.Chain((string.ascii_uppercase + string.ascii_lowercase + string.digits)[k])
    for r in chain:
        copy.add_residue(r)
    for a, q in zip((a for r in copy for a in r), p):
        a.pos = gemmi.Position(*q)
    out[0].add_chain(copy)
out.setup_entities()
out.make_mmcif_document().write_file(sys.argv[2])
