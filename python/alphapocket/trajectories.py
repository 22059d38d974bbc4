# SPDX-License-Identifier: Apache-2.0
"""alphapocket.track: pockets over a trajectory or an ensemble, followed
through time as `alphapocket track` does (docs/trajectories.md)."""

import csv
import io
import os
import tempfile
import warnings

import numpy as np

from . import _core


class TrackResult:
    """What track() found, as `alphapocket track` writes it: .frames (one
    dict per cavity per frame: frames.csv's rows), .tracks (tracks.csv's),
    .events (splits and merges: events.csv's), .frequency and .density
    (numpy grids (nx, ny, nz); point (i, j, k) at .origin + .spacing *
    (i, j, k)), .files (name -> text of each output file) and
    .write(outdir)."""

    def __init__(self, core):
        self.files = dict(core.files())
        self.frames = self._rows("frames.csv")
        self.tracks = self._rows("tracks.csv")
        self.events = self._rows("events.csv")
        self.frequency = core.frequency()
        self.density = core.density()
        self.origin = np.asarray(core.origin)
        self.spacing = core.spacing

    def _rows(self, name):
        return [{k: _csv_value(v) for k, v in row.items()} for row in csv.DictReader(io.StringIO(self.files[name]))]

    def write(self, outdir):
        """Writes the output files into outdir (created if missing); returns their names."""
        outdir = os.fspath(outdir)
        os.makedirs(outdir, exist_ok=True)
        for name, text in self.files.items():
            with open(os.path.join(outdir, name), "w", encoding="utf-8") as f:
                f.write(text)
        return list(self.files)


def _csv_value(text):
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return None if text == "" else text


def _is_universe(frames):
    return hasattr(frames, "trajectory") and hasattr(frames, "atoms")


def _universe_frames(universe):
    """(time, coordinates) of each frame of an MDAnalysis Universe, read as they are asked for."""
    for ts in universe.trajectory:
        yield ts.time, np.asarray(universe.atoms.positions, dtype=float)


def _array_frames(coordinates, times):
    for k, xyz in enumerate(coordinates):
        yield (None if times is None else float(times[k])), xyz


def track(frames, topology=None, times=None, **options):
    """Pockets, voids and tunnels over the frames of a trajectory or an
    ensemble, followed through time as `alphapocket track` does.
    `frames`: an MDAnalysis Universe (python3-mdanalysis: its atoms, every
    frame of its trajectory read one at a time), or coordinates (frames,
    atoms, 3) in A of every atom of `topology` (a PDB, mmCIF or GROMACS .gro
    file) in its file order, with `times` (ps; the frame numbers if None).
    Options: begin=0, end=None, stride=1 (frames taken, counted over all
    frames), grid_spacing=1, overlap=0.3 (Jaccard index of lining atoms for
    one identity), threads=1 (frames analysed at once; the results are the
    same for any number), and analyze()'s options. Returns a TrackResult."""
    from . import _ANALYZE_DEFAULTS, _options, MisuseError
    opts = _options("track", options, dict(_ANALYZE_DEFAULTS, **_core.track_defaults()))
    if not _is_universe(frames):
        if topology is None:
            raise MisuseError("track: coordinates need topology=, a structure file holding their atoms")
        coordinates = np.asarray(frames, dtype=float)
        if coordinates.ndim != 3 or coordinates.shape[2] != 3:
            raise MisuseError("track: expected coordinates of shape (frames, atoms, 3)")
        if times is not None and len(times) != len(coordinates):
            raise MisuseError(f"track: {len(times)} times for {len(coordinates)} frames")
        return TrackResult(_core.track_frames(os.fspath(topology), _array_frames(coordinates, times), opts))
    if topology is not None or times is not None:
        raise MisuseError("track: a Universe holds its topology and times")
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "topology.pdb")  # the Universe's atoms, in its order
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            frames.trajectory[0]
            frames.atoms.write(path)
        return TrackResult(_core.track_frames(path, _universe_frames(frames), opts))
