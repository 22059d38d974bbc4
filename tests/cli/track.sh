#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# CLI tests of `alphapocket track`: an NMR ensemble's models as frames and
# the output directory (PyMOL loads the grids and the script), GROMACS XTC
# and TRR written by GROMACS itself and the same frames as DCD written by
# MDAnalysis, a short real MD run, and bad input. The tracking rule is
# checked in tests/molecule/test_track.cpp. Usage: track.sh ALPHAPOCKET REPO_ROOT CASE
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" "$@"

nmr=$data/1l2y.pdb.gz
py=/usr/bin/python3

# The first model of 1l2y, and its models 1-6 as a multi-model file.
# (zcat ends on SIGPIPE when awk stops reading: not a failure.)
first_model() { { zcat "$nmr" || true; } | awk '/^ENDMDL/{exit} /^(ATOM|HETATM|TER)/{print} END{print "END"}' >"$tmp/m1.pdb"; }
six_models() { { zcat "$nmr" || true; } | awk '/^MODEL +7 /{exit} /^(MODEL|ATOM|HETATM|TER|ENDMDL)/{print} END{print "END"}' >"$tmp/m6.pdb"; }

# frames.csv without its time column.
untimed() { cut -d, -f1,3- "$1"; }

# mdanalysis_dcd TOPOLOGY TRAJECTORY OUT: every frame written as DCD by MDAnalysis.
mdanalysis_dcd() {
  $py - "$@" <<'EOF' 2>/dev/null || fail "MDAnalysis could not write $3"
import sys, warnings
warnings.simplefilter("ignore")
import MDAnalysis as mda
u = mda.Universe(sys.argv[1], sys.argv[2])
with mda.Writer(sys.argv[3], u.atoms.n_atoms) as w:
    for ts in u.trajectory:
        w.write(u.atoms)
EOF
}

need_gromacs() { command -v gmx >/dev/null || { echo "gmx not installed: skipped"; exit 77; }; }

case "$case_name" in
  nmr)
    run track "$nmr" --end 12 -o "$tmp/t"
    expect_success
    for f in frames.csv tracks.csv events.csv frequency.dx density.dx structure.cif track.pml volumes.svg; do
      [[ -s $tmp/t/$f ]] || fail "no $f"
    done
    grep -q '^12 frames of ' "$tmp/out" || fail "summary line"
    [[ $(tail -n +2 "$tmp/t/frames.csv" | cut -d, -f1 | sort -un | tail -n 1) -le 11 ]] || fail "a frame past 11 in frames.csv"
    head -n 1 "$tmp/t/tracks.csv" | grep -q '^track,kind,frames,frequency,transient,first_frame,last_frame' || fail "tracks.csv header"
    grep -q '^object 3 class array type double rank 0 items' "$tmp/t/frequency.dx" || fail "frequency.dx header"
    grep -q '<polyline' "$tmp/t/volumes.svg" || fail "no line in volumes.svg"
    # Every value of the frequency grid is a share of 12 frames.
    awk '/data follows/{on=1; next} /^attribute/{on=0} on{for(i=1;i<=NF;i++){v=$i*12; if (v<0 || v>12.0001 || (v-int(v+0.5))^2>1e-6) bad=1}} END{exit bad}' \
      "$tmp/t/frequency.dx" || fail "a frequency that is not k/12"
    ;;
  pymol)
    command -v pymol >/dev/null || { echo "pymol not installed: skipped"; exit 77; }
    six_models
    run track "$tmp/m6.pdb" -o "$tmp/t"
    expect_success
    # PyMOL reads the grid (its dimensions) and runs the script without an error.
    cat >"$tmp/check.py" <<EOF
from pymol import cmd
cmd.load("$tmp/t/frequency.dx", "frequency")
print("extent", cmd.get_extent("frequency"))
cmd.cd("$tmp/t")
cmd.do("@track.pml")
print("objects", " ".join(cmd.get_names("all")))
EOF
    PATH=/usr/bin:$PATH pymol -cq "$tmp/check.py" >"$tmp/out" 2>"$tmp/err" || fail "pymol failed"
    grep -q 'extent \[\[' "$tmp/out" || fail "PyMOL did not load frequency.dx"
    for object in frame1 frequency frequency_05 density pocket_; do
      grep -q "^objects .*\b$object" "$tmp/out" || fail "track.pml did not make $object"
    done
    ! grep -qiE 'error|invalid|unknown' "$tmp/out" "$tmp/err" || fail "PyMOL reported an error"
    ;;
  gromacs_formats)
    # 1l2y's models 1-6 written as XTC and TRR by GROMACS and as DCD by
    # MDAnalysis (from the TRR): each read against the first model as
    # topology gives the frames of the multi-model file (XTC: to its 0.01 A
    # precision, the same tracks; TRR and DCD: the same coordinates).
    need_gromacs
    first_model
    six_models
    for fmt in xtc trr; do
      echo 0 | gmx -quiet trjconv -f "$tmp/m6.pdb" -s "$tmp/m1.pdb" -o "$tmp/m6.$fmt" >/dev/null 2>&1 ||
        fail "gmx trjconv could not write $fmt"
    done
    mdanalysis_dcd "$tmp/m1.pdb" "$tmp/m6.trr" "$tmp/m6.dcd"
    run track "$tmp/m6.pdb" -o "$tmp/models"
    expect_success
    for fmt in xtc trr dcd; do
      run track "$tmp/m1.pdb" "$tmp/m6.$fmt" -o "$tmp/$fmt"
      expect_success
      grep -q "^6 frames of " "$tmp/out" || fail "$fmt: not 6 frames"
    done
    [[ $(untimed "$tmp/trr/frames.csv") == $(untimed "$tmp/models/frames.csv") ]] || fail "TRR frames differ from the models"
    # DCD holds A in float32, TRR nm: the same pockets, each frame's, by rank.
    [[ $(cut -d, -f1,3,5 "$tmp/dcd/frames.csv") == $(cut -d, -f1,3,5 "$tmp/trr/frames.csv") ]] || fail "DCD frames differ from TRR's"
    [[ $(cut -d, -f1-3 "$tmp/xtc/tracks.csv" | wc -l) -ge 2 ]] || fail "no track from the XTC"
    # XTC keeps 0.01 A: the pockets of each frame within a few A^3.
    paste -d, <(cut -d, -f1,3,6 "$tmp/xtc/frames.csv") <(cut -d, -f1,3,6 "$tmp/models/frames.csv") | tail -n +2 |
      awk -F, '$2=="pocket" && $5=="pocket" && $1==$4 {n++; if ($3-$6 > 5 || $6-$3 > 5) far++} END {exit !(n > 0 && far <= n / 5)}' ||
      fail "XTC volumes far from the models'"
    ;;
  md_run)
    # A real MD run: 1l2y (its second model, which has a pocket) in vacuum, 200 steps of 1 fs with GROMACS, XTC and
    # TRR every 20 steps, and the TRR's frames written as DCD by MDAnalysis;
    # each tracked. Debian's mdrun is built to use rdtscp and refuses CPUs
    # whose CPUID does not announce it; where the instruction works all the
    # same (virtual machines that hide the bit), mdrun runs with the CPU
    # left undetected (gromacs_cpu_undetected.c); skipped where it does not.
    need_gromacs
    { zcat "$nmr" || true; } | awk '/^MODEL +2 /{on=1; next} on && /^ENDMDL/{exit} on && /^(ATOM|TER)/{print} END{print "END"}' >"$tmp/m2.pdb"
    cat >"$tmp/md.mdp" <<'EOF'
integrator = md
dt = 0.001
nsteps = 200
nstxout-compressed = 20
nstxout = 20
cutoff-scheme = Verlet
pbc = xyz
coulombtype = cut-off
rcoulomb = 1.0
rvdw = 1.0
tcoupl = v-rescale
tc-grps = System
tau-t = 0.1
ref-t = 300
gen-vel = yes
gen-seed = 7
ld-seed = 7
EOF
    (cd "$tmp" && gmx -quiet pdb2gmx -f m2.pdb -o conf.gro -p topol.top -ff amber99sb-ildn -water none -ignh &&
      gmx -quiet editconf -f conf.gro -o box.gro -c -d 1.2 -bt cubic &&
      gmx -quiet grompp -f md.mdp -c box.gro -p topol.top -o md.tpr -maxwarn 2) >"$tmp/gmx.log" 2>&1 ||
      fail "GROMACS set-up failed: $(tail -n 5 "$tmp/gmx.log")"
    mdrun() { (cd "$tmp" && gmx -quiet mdrun -s md.tpr -deffnm md -nt 1 -pin off) >>"$tmp/gmx.log" 2>&1; }
    if ! mdrun; then
      grep -q "compiled to use the rdtscp" "$tmp/gmx.log" || fail "gmx mdrun failed: $(tail -n 5 "$tmp/gmx.log")"
      printf '#include <x86intrin.h>\nint main(void) { unsigned c; return __rdtscp(&c) == 0; }\n' >"$tmp/rdtscp.c"
      gcc -O1 "$tmp/rdtscp.c" -o "$tmp/rdtscp" && "$tmp/rdtscp" 2>/dev/null ||
        { echo "this CPU has no rdtscp, which Debian's gmx mdrun needs: skipped"; exit 77; }
      gcc -shared -fPIC "$root/tests/cli/gromacs_cpu_undetected.c" -o "$tmp/undetected.so" -lgromacs ||
        fail "could not build the preload for mdrun"
      LD_PRELOAD=$tmp/undetected.so mdrun || fail "gmx mdrun failed: $(tail -n 5 "$tmp/gmx.log")"
    fi
    mdanalysis_dcd "$tmp/box.gro" "$tmp/md.trr" "$tmp/md.dcd"
    for fmt in xtc trr dcd; do
      run track "$tmp/box.gro" "$tmp/md.$fmt" -o "$tmp/$fmt"
      expect_success
      grep -q "^11 frames of " "$tmp/out" || fail "$fmt: not 11 frames (steps 0, 20, ..., 200)"
    done
    for fmt in xtc trr; do  # frame k at 0.02 k ps
      awk -F, 'NR > 1 && $2 != sprintf("%.3f", 0.02 * $1) {bad = 1} END {exit bad}' "$tmp/$fmt/frames.csv" ||
        fail "$fmt: a frame's time is not 0.02 ps times its number"
    done
    # Real dynamics: the longest-lived pocket's SA volume changes.
    awk -F, 'NR > 1 && $3 == "pocket" {n[$4]++; if (!seen[$4, $6]++) k[$4]++}
             END {for (t in n) if (n[t] > best) {best = n[t]; most = t} exit !(k[most] > 1)}' "$tmp/trr/frames.csv" ||
      fail "the longest-lived pocket has one volume in every frame"
    # DCD (A, float32) holds the TRR's coordinates (nm, float32) times 10,
    # rounded to float32 again: the same frames, so the same cavities and
    # tracks, every printed number within the last digit (but a tunnel's
    # length: its path may take another route for a change of 1e-6 A).
    [[ $(wc -l <"$tmp/dcd/frames.csv") -eq $(wc -l <"$tmp/trr/frames.csv") ]] || fail "DCD frames differ from TRR's"
    paste -d'|' <(untimed "$tmp/dcd/frames.csv") <(untimed "$tmp/trr/frames.csv") |
      awk -F'|' '{n = split($1, a, ","); split($2, b, ",");
                  for (i = 1; i <= n; i++) if (i != 10 && a[i] != b[i] && (a[i] !~ /^-?[0-9.]+$/ || (a[i] - b[i]) ^ 2 > 2.25e-6)) bad = 1}
                 END {exit bad}' || fail "DCD frames differ from TRR's"
    cut -d, -f1-7 "$tmp/dcd/tracks.csv" | cmp -s - <(cut -d, -f1-7 "$tmp/trr/tracks.csv") || fail "DCD tracks differ from TRR's"
    # XTC keeps 0.001 nm: the same number of frames with pockets.
    [[ $(grep -c ',pocket,' "$tmp/xtc/frames.csv") -gt 0 ]] || fail "no pocket in the XTC's frames"
    ;;
  bad_input)
    first_model
    # Atom counts differ: both named.
    { zcat "$nmr" || true; } | awk '/^ENDMDL/{exit} /^ATOM/ && ++n <= 300 {print} END{print "END"}' >"$tmp/short.pdb"
    $py - "$tmp/m1.pdb" <<'EOF' >/dev/null 2>&1 || { echo "no MDAnalysis: skipped"; exit 77; }
import sys, warnings
warnings.simplefilter("ignore")
import MDAnalysis as mda
u = mda.Universe(sys.argv[1])
with mda.Writer(sys.argv[1][:-4] + ".dcd", u.atoms.n_atoms) as w:
    w.write(u.atoms)
    w.write(u.atoms)
EOF
    run track "$tmp/short.pdb" "$tmp/m1.dcd" -o "$tmp/t"
    [[ $rc -ne 0 ]] || fail "atom counts differ, yet exit 0"
    grep -q "m1.dcd: 304 atoms, but the topology .*short.pdb has 300" "$tmp/err" || fail "message does not name both counts"
    [[ ! -e $tmp/t ]] || fail "an output directory was left"
    # A DCD cut in its second frame: the frame named.
    head -c -100 "$tmp/m1.dcd" >"$tmp/cut.dcd"
    run track "$tmp/m1.pdb" "$tmp/cut.dcd" -o "$tmp/t"
    [[ $rc -ne 0 ]] || fail "truncated DCD, yet exit 0"
    grep -q "cut.dcd: truncated in frame 1" "$tmp/err" || fail "truncation not reported: $(cat "$tmp/err")"
    # The same file with every word byte-swapped reads the same.
    $py - "$tmp/m1.dcd" "$tmp/swapped.dcd" <<'EOF'
import struct, sys
data = open(sys.argv[1], "rb").read()
out, i = bytearray(), 0
while i < len(data):  # records: length, body, length; swap every 4-byte word
    n = struct.unpack_from("<i", data, i)[0]
    body = data[i + 4:i + 4 + n]
    if n == 84:  # "CORD" stays text
        words = body[:4] + b"".join(body[k:k + 4][::-1] for k in range(4, n, 4))
    elif n % 8 == 0 and n == 48:  # the unit cell: doubles
        words = b"".join(body[k:k + 8][::-1] for k in range(0, n, 8))
    elif i > 0 and n % 80 == 4 and n > 4:  # the title: its count, then text
        words = body[:4][::-1] + body[4:]
    else:
        words = b"".join(body[k:k + 4][::-1] for k in range(0, n, 4))
    out += struct.pack(">i", n) + words + struct.pack(">i", n)
    i += 8 + n
open(sys.argv[2], "wb").write(out)
EOF
    run track "$tmp/m1.pdb" "$tmp/m1.dcd" -o "$tmp/native"
    expect_success
    run track "$tmp/m1.pdb" "$tmp/swapped.dcd" -o "$tmp/swapped"
    expect_success
    cmp -s "$tmp/native/frames.csv" "$tmp/swapped/frames.csv" || fail "the byte-swapped DCD reads differently"
    # Not a trajectory, not a structure.
    echo hello >"$tmp/x.txt"
    run track "$tmp/m1.pdb" "$tmp/x.txt" -o "$tmp/t"
    [[ $rc -ne 0 ]] && grep -q "x.txt: neither a structure file" "$tmp/err" || fail "x.txt accepted"
    # A directory of someone else's files is not replaced.
    mkdir "$tmp/mine" && echo keep >"$tmp/mine/notes.txt"
    run track "$tmp/m1.pdb" -o "$tmp/mine"
    [[ $rc -ne 0 ]] && [[ -e $tmp/mine/notes.txt ]] || fail "a foreign directory was replaced"
    ;;
  *)
    echo "unknown case $case_name" >&2
    exit 2
    ;;
esac
