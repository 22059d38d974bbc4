#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A structure's candidate binding sites as a CSV table (no pandas needed),
ranked by the ligandability model.

Usage: sites_csv.py STRUCTURE [OUT.csv]   (stdout without OUT.csv)
"""
import csv
import sys

import alphapocket


def main(path, out):
    analysis = alphapocket.analyze(path, tunnels_from="none")
    writer = csv.writer(out)
    writer.writerow(["rank", "kind", "probability", "score", "sa_volume", "ms_volume", "center_x", "center_y",
                     "center_z", "residues"])
    for site in analysis.sites:
        x, y, z = site.center  # a numpy array
        residues = site.cavity.lining_residues  # tuples (chain, name, number, insertion code)
        writer.writerow([site.rank, site.kind, site.probability, site.score, site.sa_volume, site.cavity.ms_volume,
                         x, y, z,
                         " ".join(f"{c}:{n}:{num}{ins}" for c, n, num, ins in residues)])


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__.strip())
    if len(sys.argv) == 3:
        with open(sys.argv[2], "w", newline="") as f:
            main(sys.argv[1], f)
    else:
        main(sys.argv[1], sys.stdout)
