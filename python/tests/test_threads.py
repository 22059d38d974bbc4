# SPDX-License-Identifier: Apache-2.0
# Long calls release the GIL: 4 threads give the serial results, and other
# Python threads keep running during each long call.
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import alphapocket
from conftest import DATA, PDB, SMALL

FILES = [PDB, DATA / "1fkgA.pdb", DATA / "3stdA.pdb", SMALL]


def test_four_threads_equal_serial():
    serial = [alphapocket.analyze(f).to_json() for f in FILES]
    with ThreadPoolExecutor(4) as pool:
        parallel = list(pool.map(lambda f: alphapocket.analyze(f).to_json(), FILES))
    assert parallel == serial
    with ThreadPoolExecutor(4) as pool:
        areas = list(pool.map(lambda f: alphapocket.surface(f).ms_area, FILES))
    assert areas == [alphapocket.surface(f).ms_area for f in FILES]


def longest_pause(call):
    """Runs call() in a thread while this one counts: (the call's seconds,
    the longest this thread went without running). A call holding the GIL
    stops this thread for all of its time."""
    done = threading.Event()
    seconds = []

    def work():
        start = time.perf_counter()
        call()
        seconds.append(time.perf_counter() - start)
        done.set()

    interval = sys.getswitchinterval()
    sys.setswitchinterval(0.001)
    try:
        worker = threading.Thread(target=work)
        worst = 0.0
        last = time.perf_counter()
        worker.start()
        while True:  # the first pause counts from the start, the last up to the end
            now = time.perf_counter()
            worst = max(worst, now - last)
            last = now
            if done.is_set():
                break
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    return seconds[0], worst


def test_long_calls_let_other_threads_run():
    # Enough points for every call to take well over 0.1 s on a fast machine
    # (the spectrum's exact rounding got 10 times cheaper: 0.08 s at 12,000).
    points = np.random.default_rng(0).normal(size=(60000, 3))
    complex_ = alphapocket.AlphaComplex(points)
    calls = {"analyze": lambda: alphapocket.analyze(PDB, tunnels_from="none"),
             "surface": lambda: alphapocket.surface(PDB),
             "AlphaComplex": lambda: alphapocket.AlphaComplex(points),
             "spectrum": lambda: complex_.spectrum,
             "persistence": lambda: complex_.persistence()}
    for name, call in calls.items():
        seconds, pause = longest_pause(call)
        assert seconds > 0.1, f"{name}: too short a call to tell ({seconds:.3f} s)"
        assert pause < seconds / 2, f"{name}: other threads stopped for {pause:.3f} of {seconds:.3f} s"


def test_threads_option_gives_the_serial_results():
    # 1a26A's 13 pockets are measured on 3 threads in another order than
    # one thread's; the report must not show it.
    serial = alphapocket.analyze(PDB, tunnels_from="none").to_json()
    assert alphapocket.analyze(PDB, tunnels_from="none", threads=3).to_json() == serial
    for bad in (0, -1, 5000):
        try:
            alphapocket.analyze(PDB, threads=bad)
        except alphapocket.MisuseError as e:
            assert str(e) == f"threads: {bad} is not in 1..4096"
        else:
            raise AssertionError(f"threads={bad} accepted")
