#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Results are a function of the set of atoms, not of the order of the
# records: the ATOM/HETATM records of a file permuted (within residues,
# residue order, reversed, a full shuffle; each within its TER-delimited
# section, as TER records say where a polymer ends) give byte-identical
# outputs of `pockets` (every file of OUTDIR) and `surface --json`.
# A file shuffled whole (TER records left in place) gives the same outputs
# too. Serial numbers travel with their records, so nothing needs to be masked:
# the outputs list atoms in the reader's canonical order (docs/cli.md, Structure
# files). Usage: order.sh ALPHAPOCKET REPO_ROOT CASE
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" "$@"

# permute MODE SEED < PDB > PDB: the records of each TER-delimited section
# permuted; other records first, then the sections, TER between them.
permute() {
  awk -v mode="$1" -v seed="$2" '
    function shuffle(a, n,   i, j, t) { for (i = n; i > 1; --i) { j = int(rand() * i) + 1; t = a[i]; a[i] = a[j]; a[j] = t } }
    function flush(   i, k, n, r, nr, key, seen, order, members, list, m) {
      if (mode == "reversed") { for (i = na; i >= 1; --i) print atoms[i] }
      else if (mode == "shuffle") { shuffle(atoms, na); for (i = 1; i <= na; ++i) print atoms[i] }
      else {
        nr = 0
        for (i = 1; i <= na; ++i) {
          key = substr(atoms[i], 18, 10)  # residue name, chain, number, insertion code
          if (!(key in seen)) { seen[key] = ++nr; order[nr] = key; members[key] = 0 }
          list[key, ++members[key]] = atoms[i]
        }
        if (mode == "residues") shuffle(order, nr)
        for (r = 1; r <= nr; ++r) {
          key = order[r]; n = members[key]
          for (k = 1; k <= n; ++k) m[k] = list[key, k]
          if (mode == "within") shuffle(m, n)
          for (k = 1; k <= n; ++k) print m[k]
        }
      }
      na = 0
    }
    BEGIN { srand(seed) }
    /^(ATOM|HETATM)/ { atoms[++na] = $0; next }
    /^TER/ { flush(); print "TER"; next }
    /^END/ { next }
    { print }
    END { flush(); print "END" }'
}

# scatter SEED < PDB > PDB: the ATOM/HETATM records shuffled across the
# whole file, every other record (TER too) left on its line: the records of
# a residue, a chain and the polymer are then apart, as a file written from
# a selection or a merge may have them.
scatter() {
  awk -v seed="$1" '
    BEGIN { srand(seed) }
    { line[NR] = $0; if (/^(ATOM|HETATM)/) atoms[++na] = NR }
    END {
      for (i = 1; i <= na; ++i) pick[i] = line[atoms[i]]
      for (i = na; i > 1; --i) { j = int(rand() * i) + 1; t = pick[i]; pick[i] = pick[j]; pick[j] = t }
      for (i = 1; i <= na; ++i) line[atoms[i]] = pick[i]
      for (i = 1; i <= NR; ++i) print line[i]
    }'
}

# Runs pockets and surface on $tmp/work/x.pdb (always that path: pockets.pml
# names it) and keeps their outputs under $tmp/NAME.
outputs() {  # NAME
  run pockets "$tmp/work/x.pdb" -o "$tmp/work/out" --outputs all
  expect_success
  mv "$tmp/work/out" "$tmp/$1"
  run surface "$tmp/work/x.pdb" --json
  expect_success
  mv "$tmp/out" "$tmp/$1/surface.json"
}

mkdir "$tmp/work"
case $case_name in
  within_residues | residue_order | reversed | shuffled)
    mode=${case_name%%_*}
    [[ $case_name == residue_order ]] && mode=residues
    [[ $case_name == shuffled ]] && mode=shuffle
    cp "$pdb" "$tmp/work/x.pdb"
    outputs original
    for seed in 1 2; do
      permute "$mode" "$seed" <"$pdb" >"$tmp/work/x.pdb"
      cmp -s "$pdb" "$tmp/work/x.pdb" && fail "permutation $mode $seed left the file as it was"
      [[ $(grep -c '^ATOM\|^HETATM' "$tmp/work/x.pdb") -eq $(grep -c '^ATOM\|^HETATM' "$pdb") ]] ||
        fail "permutation $mode $seed lost records"
      outputs "$mode$seed"
      diff -r "$tmp/original" "$tmp/$mode$seed" >"$tmp/diff" ||
        fail "outputs differ after permutation $mode $seed: $(head -c 600 "$tmp/diff")"
      [[ $mode == reversed ]] && break  # one reversal only
    done
    ;;
  # The whole file shuffled: residues are grouped by identity, not by
  # their records' order, and are polymer or not by their own kind (TER
  # records no longer say where a polymer ends). 1a26A: one chain and a
  # ligand; 1bna: two DNA chains and their waters.
  scattered | scattered_chains)
    input=$pdb
    [[ $case_name == scattered_chains ]] && input=$data/1bna.pdb
    cp "$input" "$tmp/work/x.pdb"
    outputs original
    for seed in 1 2; do
      scatter "$seed" <"$input" >"$tmp/work/x.pdb"
      [[ $(sort "$input" | md5sum) == $(sort "$tmp/work/x.pdb" | md5sum) ]] || fail "scatter $seed lost records"
      outputs "scattered$seed"
      diff -r "$tmp/original" "$tmp/scattered$seed" >"$tmp/diff" ||
        fail "outputs differ after scattering $seed: $(head -c 600 "$tmp/diff")"
    done
    ;;
  *)
    echo "unknown case: $case_name" >&2
    exit 2
    ;;
esac
echo "PASS [$case_name]"
