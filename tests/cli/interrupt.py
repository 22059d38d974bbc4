#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Interrupted runs leave OUTDIR describing one run, and no temporaries.

`pockets` is stopped by SIGINT, SIGTERM or SIGKILL at random moments of a
run, half of them timed to fall into the write phase (when its hidden
sibling .OUTDIR.alphapocket-new appears). Runs alternate between two
option sets whose outputs differ (file names and content), so after every
kill OUTDIR must be byte for byte the previous state (absent, or the other
option set's complete run) or this run's complete output: never a mix,
never an empty OUTDIR or meshes/. After SIGINT/SIGTERM nothing else may be
left beside it; after SIGKILL only the hidden sibling, which the next run
removes. `batch` gets two SIGINTs (the second abandons the run): no hidden
file or directory left in its OUTDIR, every structure's directory whole.

Usage: interrupt.py ALPHAPOCKET REPO_ROOT CASE (pockets | batch_twice)
"""
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

exe, root, case = sys.argv[1:4]
pdb = os.path.join(root, "examples", "data", "1a26A.pdb")
rng = random.Random(19)


def fail(message):
    print(f"FAIL [{case}]: {message}", file=sys.stderr)
    sys.exit(1)


def snapshot(directory):
    """{relative path: bytes} of every file, '/' for directories; None if absent."""
    if not os.path.lexists(directory):
        return None
    files = {}
    for base, dirs, names in os.walk(directory):
        for d in dirs:
            files[os.path.relpath(os.path.join(base, d), directory) + "/"] = b""
        for n in names:
            with open(os.path.join(base, n), "rb") as f:
                files[os.path.relpath(os.path.join(base, n), directory)] = f.read()
    return files


def identity(path):
    """Which directory is at path (inode and change time), None if none."""
    try:
        st = os.stat(path)
    except FileNotFoundError:
        return None
    return st.st_ino, st.st_ctime_ns


def describe(state, refs):
    if state is None:
        return "absent"
    for name, ref in refs.items():
        if state == ref:
            return name
    return f"a mix of {len(state)} files"


def pockets_case(work):
    out = os.path.join(work, "out")
    # Coarse meshes: each run writes them all but takes a third of the time.
    option_sets = {"A": ["--mesh", "ply", "--mesh-resolution", "1.5"],
                   "B": ["--mesh", "obj", "--min-volume", "30", "--mesh-resolution", "1.5"]}
    refs = {}
    durations = []
    for name, options in option_sets.items():  # the complete outputs of each
        start = time.monotonic()
        subprocess.run([exe, "-q", "pockets", pdb, "-o", out] + options, check=True, stdout=subprocess.DEVNULL)
        durations.append(time.monotonic() - start)
        refs[name] = snapshot(out)
        shutil.rmtree(out)
    if refs["A"] == refs["B"] or set(refs["A"]) == set(refs["B"]):
        fail("the two option sets give the same files")
    run_time = max(durations)
    sibling = os.path.join(work, ".out.alphapocket-new")
    kills = int(os.environ.get("ALPHAPOCKET_KILLS", "36"))
    outcomes = {}
    state = None
    for i in range(kills):
        name = "AB"[i % 2]
        sig = [signal.SIGINT, signal.SIGTERM, signal.SIGKILL][i % 3]
        in_write = i % 4 >= 2
        stale = identity(sibling)  # left by an earlier SIGKILL: the next write removes it
        proc = subprocess.Popen([exe, "-q", "pockets", pdb, "-o", out] + option_sets[name],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if in_write:  # when the hidden sibling appears, then up to 4 ms
            deadline = time.monotonic() + 10 * run_time + 5
            while identity(sibling) in (None, stale) and proc.poll() is None and time.monotonic() < deadline:
                time.sleep(0.0005)
            time.sleep(rng.uniform(0, 0.004))
        else:
            time.sleep(rng.uniform(0, run_time))
        proc.send_signal(sig)
        rc = proc.wait()
        after = snapshot(out)
        if rc == 0:
            allowed = [refs[name]]
        else:
            if rc != 128 + sig and rc != -sig:
                fail(f"kill {i}: exit code {rc} after signal {sig}")
            allowed = [state, refs[name]]
        if after not in allowed:
            fail(f"kill {i} ({signal.Signals(sig).name}, {'write phase' if in_write else 'any time'}): OUTDIR is "
                 f"{describe(after, refs)}, expected {' or '.join(describe(a, refs) for a in allowed)}")
        left = sorted(set(os.listdir(work)) - {"out"})
        if left and (left != [".out.alphapocket-new"] or (sig != signal.SIGKILL and not (stale and rc != 0))):
            fail(f"kill {i} ({signal.Signals(sig).name}): left beside OUTDIR: {left}")
        key = (signal.Signals(sig).name, "write" if in_write else "random",
               "finished" if rc == 0 else "unchanged" if after == state else "replaced")
        outcomes[key] = outcomes.get(key, 0) + 1
        state = after
    # A complete run after it all removes what SIGKILL left.
    subprocess.run([exe, "-q", "pockets", pdb, "-o", out] + option_sets["A"], check=True,
                   stdout=subprocess.DEVNULL)
    if snapshot(out) != refs["A"] or os.listdir(work) != ["out"]:
        fail(f"the last run left {sorted(os.listdir(work))}")
    for key in sorted(outcomes):
        print(f"{key[0]:8} {key[1]:7} {key[2]:9} {outcomes[key]}")
    # The kills tested something: some fell into the write phase and stopped
    # the run there (else only the trivial outcomes were seen).
    if not any(n for (_, when, result), n in outcomes.items() if when == "write" and result != "finished"):
        fail(f"no kill stopped a run in its write phase: {outcomes}")


def hidden_entries(directory):
    return {os.path.join(b, n) for b, ds, ns in os.walk(directory) for n in ds + ns if n.startswith(".")}


def wait_for_hidden(directory, proc):
    """Until a hidden entry (a write in progress) appears in directory, at most 20 s."""
    deadline = time.monotonic() + 20
    before = hidden_entries(directory)
    while proc.poll() is None and time.monotonic() < deadline:
        if hidden_entries(directory) - before:
            return
        time.sleep(0.0005)


def batch_case(work):
    inputs = os.path.join(work, "in")
    os.mkdir(inputs)
    data = os.path.join(root, "tests", "data")
    for f in [pdb] + [os.path.join(data, n) for n in ("1fkgA.pdb", "1ytjA.pdb", "3stdA.pdb", "1UYD.pdb")]:
        shutil.copy(f, inputs)
    rounds = int(os.environ.get("ALPHAPOCKET_KILLS", "6"))
    interrupted = 0
    for i in range(rounds):
        out = os.path.join(work, f"o{i}")
        proc = subprocess.Popen([exe, "-q", "batch", inputs, "-o", out, "-j", "2", "--outputs",
                                 "report,csv,pml,pdb,meshes,tunnels"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        # The first signal when a structure's outputs are being written, the
        # second when the next one's are (or at once if none comes).
        for delay in (0, rng.uniform(0, 0.004)):
            wait_for_hidden(out, proc)
            time.sleep(delay)
            if proc.poll() is None:
                proc.send_signal(signal.SIGINT)
        rc = proc.wait()
        if rc not in (0, 130):
            fail(f"round {i}: exit code {rc}")
        interrupted += rc == 130
        hidden = hidden_entries(out)
        if hidden:
            fail(f"round {i}: left {hidden}")
        for entry in os.listdir(out):
            d = os.path.join(out, entry)
            if os.path.isdir(d):  # a structure's directory: whole
                files = snapshot(d)
                if not {"report.json", "pockets.pml", "meshes/"} <= set(files):
                    fail(f"round {i}: {entry}/ holds {sorted(files)}")
                json.loads(files["report.json"])
        print(f"round {i}: exit {rc}, {sum(os.path.isdir(os.path.join(out, e)) for e in os.listdir(out))} structures")
    if not interrupted:  # else no SIGINT landed while the run wrote
        fail(f"none of {rounds} runs was interrupted (exit 130)")


work = tempfile.mkdtemp()
try:
    {"pockets": pockets_case, "batch_twice": batch_case}[case](os.path.join(work, ""))
finally:
    shutil.rmtree(work, ignore_errors=True)
print(f"PASS [{case}]")
