# Long calls release the GIL: 4 threads give the serial results.
from concurrent.futures import ThreadPoolExecutor

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
