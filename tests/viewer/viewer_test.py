#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The viewer scripts of `alphapocket pockets` in the real viewer: PyMOL
2.5 headless (`pymol -cq`, Debian's pymol), ChimeraX's script through
check_cxc.py (ChimeraX is not in Debian). One case per CTest test:

    viewer_test.py ALPHAPOCKET REPO_ROOT CASE

  pymol_1a26A  OUTDIR moved elsewhere and opened from a third directory:
               no error or warning, the named objects hold what report.json
               says, the ligand is there, sites after the 12th are
               disabled, and a rendered PNG shows the colour of the top
               site (report.json's first) in the middle of the view
               (which disabling the top site's objects takes away); each
               cavity's cast is loaded, disabled (pocket_N_cast), and the
               top site's cast, enabled without the other sites' spaces,
               shows its colour there too. 1a26A runs without meshes
               (the default): no casts, the rest the same.
  pymol_3stdA  the same with meshes (--mesh ply) where the best site is a
               buried void.
  pymol_1fkgA  the same where the second site's sphere lies between the
               best site and the viewer (it must not hide it).
  pymol_pore   gramicidin A's pore: its spheres and lining residues.
  (pymol_1a26A and pymol_3stdA check the tunnels' spheres likewise.)
  injection    a file name and chain/residue/atom names made of newlines,
               quotes, ';', '#', backslashes and non-ASCII: PyMOL runs none
               of it (a `system touch PWNED` in the name stays text), the
               ChimeraX script is only our commands, pockets.pdb, CSV,
               JSON and structure.cif stay well-formed.
  cxc_grammar_1a26A
               pockets.cxc read by ChimeraX's documented grammar
               (check_cxc.py), not by ChimeraX: accepted, and broken
               commands refused.
"""
import csv
import io
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

import gemmi
from PIL import Image

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_cxc  # noqa: E402

EXE, ROOT, CASE = sys.argv[1:4]
# Debian's pymol runs `python3` from PATH: make it Debian's own.
ENV = dict(os.environ, PATH="/usr/bin:/bin:" + os.environ.get("PATH", ""))
PYMOL = shutil.which("pymol", path=ENV["PATH"])


def fail(message):
    print(f"FAIL [{CASE}]: {message}", file=sys.stderr)
    sys.exit(1)


def pockets(structure, outdir, *args):
    run = subprocess.run([EXE, "-q", "pockets", structure, "-o", outdir, *args], capture_output=True)
    if run.returncode != 0:
        fail(f"alphapocket pockets failed: {run.stderr!r}")
    return run


def pymol(cwd, pml, extra):
    """Runs `pymol -cq PML EXTRA.py` in cwd; fails on any error or warning
    PyMOL prints. Returns what EXTRA.py printed as JSON on its last line."""
    if PYMOL is None:
        fail("pymol is not installed (Debian: pymol, in deps/test.txt)")
    script = os.path.join(cwd, "check_view.py")
    with open(script, "w") as f:
        f.write(extra)
    run = subprocess.run([PYMOL, "-cq", pml, script], cwd=cwd, env=ENV, capture_output=True, text=True,
                         errors="replace", timeout=600)
    output = run.stdout + run.stderr
    # PyMOL echoes the script's commands ("PyMOL>..."); everything else it
    # prints must be free of complaints.
    said = [line for line in output.splitlines() if not line.startswith("PyMOL>")]
    bad = [line for line in said if re.search(r"error|warning|traceback|unknown|invalid|not found|exception",
                                              line, re.I)]
    if run.returncode != 0 or bad:
        fail(f"PyMOL complained (exit {run.returncode}): {bad[:5]}\n{output[-3000:]}")
    results = [line for line in said if line.startswith("RESULT ")]
    if not results:
        fail(f"the check script printed nothing\n{output[-3000:]}")
    return json.loads(results[-1][len("RESULT "):])


CHECKS = r"""
import json
from pymol import cmd
names = cmd.get_names("all")
enabled = cmd.get_names("all", enabled_only=1)
counts = {n: cmd.count_atoms(n) for n in names if cmd.get_type(n) in ("object:molecule", "selection")}
# Each tunnel path's spheres (x, y, z, radius) and each tunnel selection's residues.
paths, residues = {}, {}
for n in names:
    if n.startswith("tunnel_") and n.endswith("_path"):
        spheres = []
        cmd.iterate_state(1, n, "spheres.append([x, y, z, vdw])", space={"spheres": spheres})
        paths[n] = spheres
    elif n.startswith("tunnel_") and cmd.get_type(n) == "selection":
        found = set()
        cmd.iterate(n, "found.add(chain + ':' + resn + ':' + resi)", space={"found": found})
        residues[n] = sorted(found)
cmd.set("ray_opaque_background", 1)
cmd.png("view.png", width=320, height=240, ray=1)
top = "%(top)s"
cmd.disable(top + "_space")
cmd.disable(top + "_center")
cmd.color("grey80", "byres " + top)
for name in names:  # the other sites' objects may hide it
    if name.endswith("_space") or (name.endswith("_cast") and name != top + "_cast"):
        cmd.disable(name)
cmd.enable(top + "_cast")
cmd.png("cast.png", width=320, height=240, ray=1)
cmd.disable(top + "_cast")
cmd.png("without_top.png", width=320, height=240, ray=1)
print("RESULT " + json.dumps({"names": names, "enabled": enabled, "counts": counts, "paths": paths,
                             "residues": residues}))
"""


def near_color_pixels(png, rgb):
    """Pixels of rgb's hue (within 12 degrees) and at least half its
    saturation: the site's colour under any shading, and seen through the
    transparent grey surface; all of them, those in the central quarter of
    the image, and the image's size."""
    import colorsys
    hue, saturation, _ = colorsys.rgb_to_hsv(*(c / 255 for c in rgb))
    image = Image.open(png).convert("RGB")
    width, height = image.size
    count = central = 0
    for k, p in enumerate(image.getdata()):
        h, s, v = colorsys.rgb_to_hsv(*(c / 255 for c in p))
        if s >= saturation / 2 and v > 0.15 and min(abs(h - hue), 1 - abs(h - hue)) < 12 / 360:
            count += 1
            x, y = k % width, k // width
            central += abs(x - width / 2) <= width / 4 and abs(y - height / 2) <= height / 4
    return count, central, width * height


def top_color(pml, name):
    m = re.search(r"^set_color ap_" + name + r", \[(\d+), (\d+), (\d+)\]$", pml, re.M)
    if not m:
        fail(f"no colour for {name}")
    return tuple(int(x) for x in m.groups())


def check_paths(report, got, min_paths):
    """Each tunnel and pore of report.json is a chain of spheres in PyMOL,
    one per profile point at its position with its radius, and its lining
    residues are the selection tunnel_N."""
    paths = [t for t in report["tunnels"] if t["kind"] in ("tunnel", "pore")]
    if len(paths) < min_paths:
        fail(f"{len(paths)} tunnel paths in report.json, the test needs {min_paths}")
    if set(got["paths"]) != {f"tunnel_{t['rank']}_path" for t in paths}:
        fail(f"path objects {sorted(got['paths'])} differ from report.json's {len(paths)} tunnels and pores")
    for t in paths:
        spheres = got["paths"][f"tunnel_{t['rank']}_path"]
        if len(spheres) != len(t["profile"]):
            fail(f"tunnel_{t['rank']}_path: {len(spheres)} spheres, the profile has {len(t['profile'])} points")
        # PyMOL keeps a molecule's atoms in an order of its own: each profile
        # point must have a sphere of its own at its place and of its radius.
        left = list(spheres)
        for point in t["profile"]:
            match = [s for s in left if max(abs(a - b) for a, b in zip(s, point)) <= 2e-3]
            if not match:
                fail(f"tunnel_{t['rank']}_path: no sphere at profile point {point}")
            left.remove(match[0])
        lining = sorted(r["id"] for r in t["lining_residues"])
        if got["residues"].get(f"tunnel_{t['rank']}") != lining:
            fail(f"tunnel_{t['rank']}: residues {got['residues'].get(f'tunnel_' + str(t['rank']))} "
                 f"are not report.json's {lining}")
    print(f"{len(paths)} tunnel paths, {sum(len(t['profile']) for t in paths)} spheres as in report.json")


def view_case(structure, object_name, *args, min_paths=1):
    casts = "--mesh" in args  # the casts are meshes: written when asked for
    tmp = tempfile.mkdtemp()
    try:
        pockets(structure, os.path.join(tmp, "out"), *args)
        # Moved (as a zip would carry it), opened from a third directory.
        os.makedirs(os.path.join(tmp, "elsewhere"))
        moved = os.path.join(tmp, "elsewhere", "shared_results")
        shutil.move(os.path.join(tmp, "out"), moved)
        os.makedirs(os.path.join(tmp, "cwd"))
        with open(os.path.join(moved, "report.json")) as f:
            report = json.load(f)
        with open(os.path.join(moved, "pockets.pml")) as f:
            pml = f.read()
        sites = report["sites"]
        top = f"{sites[0]['kind']}_{sites[0]['cavity_rank']}"
        got = pymol(os.path.join(tmp, "cwd"), os.path.join("..", "elsewhere", "shared_results", "pockets.pml"),
                    CHECKS % {"top": top})
        names, enabled, counts = set(got["names"]), set(got["enabled"]), got["counts"]
        expected_atoms = report["input"]["atoms_kept"]  # and the ligands, checked below
        if counts.get(object_name, 0) < expected_atoms:
            fail(f"object {object_name}: {counts.get(object_name)} atoms, expected >= {expected_atoms}")
        ligand_atoms = counts.get(object_name, 0) - report["input"]["atoms_kept"]
        if report["input"]["hetero_groups"] > 0 and (ligand_atoms <= 0 or counts.get("ligands") != ligand_atoms):
            fail(f"ligands: {counts.get('ligands')} atoms, {ligand_atoms} beyond the atoms searched")
        for kind in ("pockets", "voids"):
            for cavity in report[kind]:
                name = f"{kind[:-1]}_{cavity['rank']}"
                for part in (name, name + "_center"):
                    if part not in names:
                        fail(f"no object {part}")
                if counts[name] != len(cavity["lining_atoms"]):
                    fail(f"{name}: {counts[name]} atoms, report.json has {len(cavity['lining_atoms'])}")
        for site in sites:
            name = f"{site['kind']}_{site['cavity_rank']}_center"
            if (name in enabled) != (site["rank"] <= 12):
                fail(f"{name}: enabled is {name in enabled} at site rank {site['rank']}")
            cast = f"{site['kind']}_{site['cavity_rank']}_cast"
            if casts and (cast not in names or cast in enabled):  # loaded, shown on demand
                fail(f"{cast}: loaded is {cast in names}, enabled is {cast in enabled}")
            if not casts and cast in names:
                fail(f"{cast} loaded, but no meshes were asked for")
        for tunnel in (t for t in report["tunnels"] if t["kind"] == "cycle"):
            if f"tunnel_{tunnel['rank']}_bottleneck" not in names:
                fail(f"no tunnel_{tunnel['rank']}_bottleneck")
        check_paths(report, got, min_paths)
        keep = os.environ.get("ALPHAPOCKET_KEEP_PNG")  # to look at them
        if keep:
            for png in ("view.png", "cast.png", "without_top.png"):
                shutil.copy(os.path.join(tmp, "cwd", png), os.path.join(keep, f"{object_name}_{png}"))
        # The top site (report.json's first, whichever cavity that is) has its
        # colour, in the middle of the view (the script centres it), and the
        # colour goes when the site is disabled. The site may be small and
        # partly behind others (1a26A's is a 56 A^3 pocket): 0.25 % of the image.
        color = top_color(pml, top)
        if color != (228, 26, 28):
            fail(f"the top site {top} is {color}, not red (outputs/pocket_colors.hpp: the best site is red)")
        with_top, central, pixels = near_color_pixels(os.path.join(tmp, "cwd", "view.png"), color)
        cast, cast_central, _ = near_color_pixels(os.path.join(tmp, "cwd", "cast.png"), color)
        without_top, _, _ = near_color_pixels(os.path.join(tmp, "cwd", "without_top.png"), color)
        print(f"{top}: colour {color}, {with_top} of {pixels} pixels ({central} central); its cast alone "
              f"{cast} ({cast_central} central); {without_top} with it disabled")
        if with_top < 0.0025 * pixels or central < with_top / 2 or without_top > with_top / 4:
            fail(f"the top site's colour is not what shows in the middle: {with_top} pixels ({central} central), "
                 f"{without_top} without it")
        if casts and (cast < 0.0025 * pixels or cast_central < cast / 2 or without_top > cast / 4):
            fail(f"the top site's cast does not show in the middle: {cast} pixels ({cast_central} central), "
                 f"{without_top} without it")
        # No other site hides it: in the middle, no next site's colour
        # outnumbers the top site's more than twice.
        for site in sites[1:4]:
            other = f"{site['kind']}_{site['cavity_rank']}"
            _, other_central, _ = near_color_pixels(os.path.join(tmp, "cwd", "view.png"), top_color(pml, other))
            print(f"{other}: {other_central} central pixels of its colour")
            if other_central > 2 * central:
                fail(f"{other} hides the top site: {other_central} central pixels of its colour, {central} of the top's")
    finally:
        shutil.rmtree(tmp)


def pore_case():
    """Gramicidin A's pore (HOLE's radii, as cli/tunnels.sh runs it): its
    chain of spheres and lining residues in PyMOL, as report.json has them."""
    tmp = tempfile.mkdtemp()
    try:
        channels = os.path.join(ROOT, "tests", "data", "channels")
        pockets(os.path.join(channels, "1grm_single.pdb"), os.path.join(tmp, "out"), "--radii",
                os.path.join(channels, "simple.rad"), "--pores", "--keep-hetero")
        with open(os.path.join(tmp, "out", "report.json")) as f:
            report = json.load(f)
        if [t["kind"] for t in report["tunnels"] if t["kind"] != "cycle"] != ["pore"]:
            fail(f"expected one pore in gramicidin A: {[t['kind'] for t in report['tunnels']]}")
        checks = CHECKS.split("cmd.set(")[0] + 'print("RESULT " + json.dumps({"paths": paths, "residues": residues}))\n'
        check_paths(report, pymol(tmp, os.path.join("out", "pockets.pml"), checks), 1)
    finally:
        shutil.rmtree(tmp)


EVIL = "x\";'\\#;\u00e9\u4e2d"   # quotes, ';', '#', backslash, non-ASCII


def injection_case():
    tmp = tempfile.mkdtemp()
    try:
        st = gemmi.read_structure(os.path.join(ROOT, "tests", "data", "3stdA.pdb"))
        st.setup_entities()
        for chain in st[0]:
            chain.name = "A;" + EVIL[:2]
            for k, res in enumerate(chain):
                if k % 7 == 0:
                    res.name = "R;'"
                for atom in res:
                    if k % 5 == 0:
                        atom.name = "C\"" + EVIL[3:5]
        doc = st.make_mmcif_document()
        # A directory in the path lets the name hold a '/' after a newline:
        # PyMOL reads "/..." as a line of Python.
        folder = os.path.join(tmp, "x\nsystem touch PWNED\n")
        os.makedirs(folder)
        name = os.path.join(folder, "cmd.system('touch PWNED')\n" + EVIL + ".cif")
        doc.write_file(name)
        out = os.path.join(tmp, "out")
        pockets(name, out)
        run = subprocess.run([EXE, "-q", "pockets", name, "-o", os.path.join(tmp, "out2"), "--json"],
                             capture_output=True)
        report = json.loads(run.stdout.decode("utf-8"))
        with open(os.path.join(out, "report.json"), encoding="utf-8") as f:
            if json.load(f) != report:
                fail("report.json differs from --json")
        if report["input"]["file"] != name:
            fail(f"report.json input.file is {report['input']['file']!r}")
        pml = open(os.path.join(out, "pockets.pml"), encoding="utf-8", errors="replace").read()
        if "PWNED" in pml.replace("# alphapocket", "").split("\n", 1)[1]:
            fail("the name reaches a command line of pockets.pml")
        pymol(tmp, os.path.join(out, "pockets.pml"), 'print("RESULT " + "{}")\n')
        for root, dirs, files in os.walk(tmp):
            if "PWNED" in files:
                fail("PyMOL ran a command from the file name")
        cxc = open(os.path.join(out, "pockets.cxc"), encoding="ascii").read()
        problems = check_cxc.check(cxc)
        if problems:
            fail(f"pockets.cxc: {problems[:3]}")
        pdb = open(os.path.join(out, "pockets.pdb"), "rb").read().decode("ascii")
        for line in pdb.splitlines():
            if not re.fullmatch(r"(REMARK   1 [ -~]{0,69}|HETATM[ -~]{74}|END)", line):
                fail(f"pockets.pdb: not a well-formed record: {line!r}")
        for table in ("pockets.csv",):
            rows = list(csv.reader(io.StringIO(open(os.path.join(out, table), encoding="utf-8").read())))
            if len({len(r) for r in rows}) != 1 or len(rows) != len(report["pockets"]) + 1:
                fail(f"{table}: rows of different lengths or not one per pocket")
            if rows[1][rows[0].index("residues")].split()[0] != report["pockets"][0]["lining_residues"][0]["id"]:
                fail(f"{table}: residues {rows[1]!r} differ from report.json")
        cif = gemmi.cif.read(os.path.join(out, "structure.cif"))
        ids = cif.sole_block().find_loop("_atom_site.id")
        if len(ids) != report["input"]["atoms_kept"] + 0 and len(ids) < report["input"]["atoms_kept"]:
            fail(f"structure.cif: {len(ids)} atoms")
    finally:
        shutil.rmtree(tmp)


def cxc_case():
    tmp = tempfile.mkdtemp()
    try:
        pockets(os.path.join(ROOT, "examples", "data", "1a26A.pdb"), os.path.join(tmp, "out"))
        cxc = open(os.path.join(tmp, "out", "pockets.cxc"), encoding="ascii").read()
        problems = check_cxc.check(cxc)
        if problems:
            fail(f"pockets.cxc: {problems[:3]}")
        with open(os.path.join(tmp, "out", "report.json")) as f:
            best = json.load(f)["sites"][0]
        top = f"{best['kind']}_{best['cavity_rank']}"  # the view centres on the site ranked first
        for needed in ("open structure.cif\n", "marker #2.1 ", "name pocket_1 ", f"view {top} | #3.1\n",
                       "name ligands ", "marker #4.1 ", "marker #5.1 ", "rename #5.1 tunnel_",
                       "name tunnel_"):
            if needed not in cxc:
                fail(f"pockets.cxc has no {needed!r}")
        # With OBJ meshes the casts open, each as the lowest model id free
        # then (ChimeraX's rule), which the script's rename, color and hide use.
        pockets(os.path.join(ROOT, "examples", "data", "1a26A.pdb"), os.path.join(tmp, "obj"), "--mesh", "obj")
        cxc_obj = open(os.path.join(tmp, "obj", "pockets.cxc"), encoding="ascii").read()
        problems = check_cxc.check(cxc_obj)
        if problems:
            fail(f"pockets.cxc with --mesh obj: {problems[:3]}")
        models, opened = {1}, []
        lines = cxc_obj.splitlines()
        for k, line in enumerate(lines):
            m = re.match(r"marker #([0-9]+)\.", line)
            if m:
                models.add(int(m.group(1)))
            m = re.match(r"open (meshes/(pocket|void)_([0-9]+)\.obj)$", line)
            if m:
                if not os.path.isfile(os.path.join(tmp, "obj", m.group(1))):
                    fail(f"pockets.cxc opens {m.group(1)}, which is not there")
                free = min(i for i in range(1, len(models) + 2) if i not in models)
                models.add(free)
                want = f"rename #{free} {m.group(2)}_{m.group(3)}_cast"
                if lines[k + 1] != want or not lines[k + 2].startswith(f"color #{free} rgb("):
                    fail(f"pockets.cxc: after {line!r} expected {want!r}, found {lines[k + 1:k + 3]!r}")
                opened.append(m.group(1))
        with open(os.path.join(tmp, "obj", "report.json")) as f:
            report = json.load(f)
        meshes = sorted(c["mesh"] for kind in ("pockets", "voids") for c in report[kind])
        if sorted(opened) != meshes:
            fail(f"pockets.cxc opens {len(opened)} casts, report.json names {len(meshes)}")
        # The checker bites: a foreign command, a ';' and a name anywhere are refused.
        # Each tunnel or pore of report.json: as many markers in its #5.K as profile points.
        with open(os.path.join(tmp, "out", "report.json")) as f:
            paths = [t for t in json.load(f)["tunnels"] if t["kind"] in ("tunnel", "pore")]
        for k, t in enumerate(paths, 1):
            markers = len(re.findall(rf"^marker #5\.{k} position ", cxc, re.M))
            if markers != len(t["profile"]) or f"rename #5.{k} tunnel_{t['rank']}_path\n" not in cxc:
                fail(f"pockets.cxc: #5.{k} has {markers} markers, tunnel {t['rank']} {len(t['profile'])} points")
        for broken in ("open /x/1a26A.pdb\n", "show #1 atoms; system touch PWNED\n", "name pocket_1 /A:42\n",
                       "# a ; comment\n", "colour #1 red\n", "color #1 rgb(256,0,0)\n", "hide #1 atomz\n",
                       "transparency #1 150 target s\n", "view (pocket_1 | #3.1\n", "show undefined_name atoms\n",
                       "marker #2.9 position 1,2 radius 1\n"):
            if not check_cxc.check(cxc + broken):
                fail(f"check_cxc accepts {broken!r}")
    finally:
        shutil.rmtree(tmp)


if CASE == "pymol_1a26A":
    view_case(os.path.join(ROOT, "examples", "data", "1a26A.pdb"), "1a26A")
elif CASE == "pymol_3stdA":
    view_case(os.path.join(ROOT, "tests", "data", "3stdA.pdb"), "3stdA", "--mesh", "ply")
elif CASE == "pymol_1fkgA":
    view_case(os.path.join(ROOT, "tests", "data", "1fkgA.pdb"), "1fkgA", "--mesh", "ply")
elif CASE == "pymol_pore":
    pore_case()
elif CASE == "injection":
    injection_case()
elif CASE == "cxc_grammar_1a26A":
    cxc_case()
else:
    fail("unknown case")
