#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Reading hostile structure files: time and peak memory of
#   - one residue of 40,000 atoms in two alternate locations, whose atom
#     names have no partner in the other conformer (the worst case of the
#     altloc selection), against the same atoms without altlocs: the ratio
#     stays near 1 when the selection is linear;
#   - 1 MB of gzip that inflates to 1 GiB of blanks: refused at the 512 MiB
#     limit (--max-input-mb).
# Usage: bench/input_limits.sh ALPHAPOCKET   (about 20 s)
set -euo pipefail
exe=${1:?usage: input_limits.sh ALPHAPOCKET}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

python3 - "$tmp" <<'PY'
import string, sys
digits = string.digits + string.ascii_uppercase
def name(i, prefix):
    s = ''
    for _ in range(3):
        s = digits[i % 36] + s
        i //= 36
    return prefix + s
for path, altlocs in (("altloc.pdb", True), ("plain.pdb", False)):
    with open(f"{sys.argv[1]}/{path}", "w") as f:
        n = 0
        for i in range(20000):
            for alt, occ in (("A", 0.6), ("B", 0.4)):
                n += 1
                x = (i % 30) * 3.0 + (0.5 if alt == "B" else 0)
                y, z = ((i // 30) % 30) * 3.0, (i // 900) * 3.0
                f.write(f"HETATM{n % 100000:5d} {name(i, 'C' if alt == 'A' else 'N'):<4s}{alt if altlocs else ' '}"
                        f"LIG A   1    {x:8.3f}{y:8.3f}{z:8.3f}{occ:6.2f} 10.00           C\n")
PY
head -c $((1 << 30)) /dev/zero | tr '\0' ' ' | gzip -9 >"$tmp/bomb.pdb.gz"

# median of 3 of wall seconds and peak RSS (KB) of one read; the command
# fails after reading (no atoms left, or the limit), which is what is timed.
measure() {
  for _ in 1 2 3; do
    /usr/bin/time -f "%e %M" "$exe" -q surface "$1" --sa-only 2>&1 >/dev/null | tail -n 1
  done | sort -n | sed -n 2p
}
read -r alt_s alt_kb < <(measure "$tmp/altloc.pdb")
read -r plain_s plain_kb < <(measure "$tmp/plain.pdb")
read -r bomb_s bomb_kb < <(measure "$tmp/bomb.pdb.gz")
echo "40,000 atoms in one residue: altlocs ${alt_s} s, none ${plain_s} s," \
  "ratio $(awk -v a="$alt_s" -v b="$plain_s" 'BEGIN { printf "%.2f", a / b }')"
echo "gzip bomb ($(($(stat -c %s "$tmp/bomb.pdb.gz") >> 10)) KiB -> 1 GiB): refused in ${bomb_s} s," \
  "peak $((bomb_kb >> 10)) MiB: $("$exe" -q surface "$tmp/bomb.pdb.gz" 2>&1 | head -c 200)"
