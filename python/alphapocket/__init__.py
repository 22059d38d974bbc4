# SPDX-License-Identifier: Apache-2.0
"""alphapocket: cavities in molecules from exact 3D alpha shapes.

analyze(structure) finds the pockets, voids and tunnels of a structure as
`alphapocket pockets` does; surface(structure) measures its solvent-accessible
and molecular surfaces as `alphapocket surface` does; track(frames) follows the
pockets, voids and tunnels of a trajectory or an ensemble through time as
`alphapocket track` does (frames from an MDAnalysis Universe, or coordinates
as arrays); AlphaComplex(points) gives the alpha complex of any (weighted)
point cloud. A structure is a file path, a gemmi.Structure (python3-gemmi;
gemmi writes it as mmCIF text, read as a file would be: the same atom
selection, no binary coupling to gemmi),
or arrays given as keywords (coordinates=N x 3, radii=N, optional
atom_names, residue_names, elements, chains, residue_numbers). Long calls
release the GIL: threads run in parallel.

Errors raise alphapocket.BadInputError (the input cannot be used),
LimitExceededError (too large) or MisuseError (a wrong call), all subclasses
of alphapocket.Error, with the messages the command line prints.
"""

import json
import os

import numpy as np

from ._core import (AlphaComplex, BadInputError, Error, LimitExceededError, MisuseError, __version__)
from . import _core
from .trajectories import TrackResult, track

__all__ = ["analyze", "surface", "track", "TrackResult", "AlphaComplex", "Analysis", "Record", "Error", "BadInputError",
           "LimitExceededError", "MisuseError", "__version__"]

# The defaults of `alphapocket pockets`, read from the C++ option structs.
_ANALYZE_DEFAULTS = _core.analysis_defaults()
_SURFACE_DEFAULTS = _core.surface_defaults()
_SELECTION_KEYS = ("model", "chains", "keep_hydrogens", "keep_waters", "keep_hetero", "keep_cofactors",
                   "max_input_mb")
_ARRAY_KEYS = ("atom_names", "residue_names", "elements", "chains", "residue_numbers")


class Record:
    """One item of the report (a site, pocket, void, tunnel...): its keys as
    attributes; numeric lists (centres, profiles) as numpy arrays; residues
    as tuples (chain, name, number, insertion_code)."""

    def __init__(self, data):
        for key, value in data.items():
            setattr(self, key, _converted(key, value))

    def __repr__(self):
        return "Record(" + ", ".join(f"{k}={v!r}" for k, v in vars(self).items() if np.isscalar(v)) + ")"


def _numeric(values):
    return all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in values)


def _converted(key, value):
    if isinstance(value, dict):
        return Record(value)
    if not isinstance(value, list) or not value:
        return value
    if key.endswith("residues") and all(isinstance(r, dict) for r in value):
        return tuple((r["chain"], r["name"], r["number"], r["insertion_code"]) for r in value)
    if all(isinstance(v, dict) for v in value):
        return [Record(v) for v in value]
    if _numeric(value):
        return np.asarray(value, dtype=float)
    if all(isinstance(v, list) and _numeric(v) and len(v) == len(value[0]) for v in value):
        return np.asarray(value, dtype=float)  # rows of points (x, y, z) or profiles (x, y, z, r)
    return value


class Analysis:
    """What analyze() found: .sites (each with .cavity, its pocket or void),
    .pockets, .voids, .tunnels, .ligands (Records, as report.json holds
    them: each ligand with the site holding it),
    .report (report.json as a dict), .to_json() (report.json's text) and
    .write(outdir) (the files of `alphapocket pockets`)."""

    def __init__(self, core):
        self._core = core
        self._text = core.report_json()
        self.report = json.loads(self._text)
        for key in ("sites", "pockets", "voids", "tunnels", "ligands"):
            setattr(self, key, [Record(r) for r in self.report.get(key, [])])
        for site in self.sites:  # its pocket or void, with the lining residues and MS volume
            site.cavity = (self.pockets if site.kind == "pocket" else self.voids)[site.cavity_rank - 1]

    def to_json(self):
        """report.json's text, byte for byte."""
        return self._text

    def features_csv(self):
        """The ligandability model's features of every pocket, then every
        void, as CSV text: the file `alphapocket pockets --features` writes."""
        return self._core.features_csv()

    def features(self):
        """The same as columns: a dict from the CSV's header names (kind,
        cavity_rank, site_rank, center_x.., the model's features,
        ligandability, probability, rank_score) to numpy arrays (kind: a list of str);
        pandas.DataFrame(analysis.features()) makes a table of it."""
        lines = self.features_csv().splitlines()
        names = lines[0].split(",")
        rows = [line.split(",") for line in lines[1:]]
        columns = {"kind": [r[0] for r in rows]}
        for j, name in enumerate(names[1:], start=1):
            dtype = int if name in ("cavity_rank", "site_rank") else float
            columns[name] = np.array([dtype(r[j]) for r in rows], dtype=dtype)
        return columns

    def write(self, outdir):
        """Writes report.json, pockets.csv, the viewer scripts... into outdir
        as `alphapocket pockets -o outdir` does; returns the names written."""
        return self._core.write(os.fspath(outdir))


def _is_gemmi(structure):
    return type(structure).__module__.split(".")[0] == "gemmi"


def _gemmi_mmcif(structure):
    """gemmi's mmCIF of the structure, with ATOM/HETATM (group_PDB, which
    gemmi leaves out by default): what tells ligands from the polymer."""
    import gemmi
    groups = gemmi.MmcifOutputGroups(True)
    groups.group_pdb = True
    return structure.make_mmcif_document(groups).as_string()


def _input(structure, kwargs):
    """("path", path, None), ("text", name, mmCIF text) for a gemmi.Structure
    (gemmi writes it, the core reads it as a file: the same selection, no
    binary coupling), or ("arrays", name, arrays) for the core."""
    if isinstance(structure, (str, os.PathLike)):
        return "path", os.fspath(structure), None
    if _is_gemmi(structure):
        return "text", structure.name or "gemmi structure", _gemmi_mmcif(structure)
    if structure is None and "coordinates" in kwargs:
        arrays = {k: kwargs.pop(k) for k in ("coordinates", "radii") + _ARRAY_KEYS if k in kwargs}
        return "arrays", kwargs.pop("name", "arrays"), arrays
    raise MisuseError("analyze/surface: give a file path, a gemmi.Structure or coordinates=... (and radii=...)")


def _hetero_option(options):
    """keep_hetero: True (all), False, or residue codes ("ZN,HEM" or a list),
    as --keep-hetero[=CODES]: the core's keep_hetero and keep_hetero_codes."""
    value = options["keep_hetero"]
    if isinstance(value, bool):
        codes = []
    else:
        codes = [c.strip().upper() for c in (value.split(",") if isinstance(value, str) else value)]
        bad = [c for c in codes if not (0 < len(c) <= 5 and c.isascii() and c.isalnum())]
        if bad:
            raise MisuseError(f"keep_hetero: {bad[0]!r} is not a residue code (1-5 letters and digits, e.g. ZN,HEM)")
    options["keep_hetero"] = value is True or "ALL" in codes
    options["keep_hetero_codes"] = [c for c in codes if c != "ALL"]
    options["keep_cofactors"] = bool(options["keep_cofactors"])


def _core_arrays(arrays):
    xyz = np.ascontiguousarray(arrays["coordinates"], dtype=float)
    radii = arrays.get("radii")
    radii = None if radii is None else np.ascontiguousarray(radii, dtype=float)
    names = {k: (None if arrays.get(k) is None else list(arrays[k])) for k in _ARRAY_KEYS}
    return xyz, radii, names


def _options(caller, options, defaults):
    """`options` over `defaults` (which name every option), as the core takes them."""
    unknown = set(options) - set(defaults)
    if unknown:
        raise MisuseError(caller + ": unknown option(s) " + ", ".join(sorted(unknown)))
    opts = dict(defaults, **options)
    opts["chains"] = list(opts["chains"])
    _hetero_option(opts)
    opts["radii"] = os.fspath(opts["radii"])
    if isinstance(opts["tunnels_from"], int):
        opts["tunnels_from"] = str(opts["tunnels_from"])
    return opts


def analyze(structure=None, **options):
    """Pockets, voids, sites and tunnels of a structure (see the module doc);
    options as `alphapocket pockets` names them: probe=1.4, min_volume=1,
    model, chains=[...], keep_hydrogens, keep_waters, keep_hetero (True, or
    residue codes: "ZN,HEM" or ["ZN", "HEM"]), keep_cofactors, min_plddt,
    radii (a radius file), tunnels_from="auto", tunnel_probe=0.9, pores,
    mesh="ply", outputs="report,csv,pml,pdb,tunnels" (what write() writes: any of
    report,csv,pml,pdb,meshes,tunnels, or "all"; the meshes only when named),
    ranking="probability" (sites by the ligandability model's probability,
    each site's .probability; "geometric": by .score), max_input_mb=512
    (larger structure files, after gzip decompression, raise
    LimitExceededError), threads=1 (threads measuring the cavities, as
    `pockets -j`; the results are identical for any number)."""
    kind, source, data = _input(structure, options)
    opts = _options("analyze", options, _ANALYZE_DEFAULTS)
    if kind == "path":
        return Analysis(_core.analyse_path(source, opts))
    if kind == "text":
        return Analysis(_core.analyse_text(source, data, opts))
    return Analysis(_core.analyse_arrays(source, *_core_arrays(data), opts))


class SurfaceResult:
    """sa_area, sa_volume (A^2, A^3), ms_area, ms_volume (None with
    excluded=False), atom_areas and atom_volumes (numpy, per atom: the SA
    area of its sphere, the SA volume of its ball in its power cell; they
    sum to sa_area and sa_volume), ms_atom_areas and ms_atom_volumes (numpy,
    per atom: the MS surface's area and the volume it encloses inside the
    atom's power cell; they sum to ms_area and ms_volume; None with
    excluded=False or per_atom=False), atoms."""

    def __init__(self, d):
        self.__dict__.update(d)

    def __repr__(self):
        return (f"SurfaceResult(atoms={self.atoms}, sa_area={self.sa_area:.3f}, sa_volume={self.sa_volume:.3f}, "
                f"ms_area={self.ms_area}, ms_volume={self.ms_volume})")


def surface(structure=None, probe=_SURFACE_DEFAULTS["probe"], excluded=_SURFACE_DEFAULTS["excluded"], per_atom=True,
            **selection):
    """Solvent-accessible (SA) and solvent-excluded (MS) area and volume, as
    `alphapocket surface --json --per-atom`; excluded=False skips the MS
    surface (--sa-only), per_atom=False its split per atom (about 3.5 times
    the MS time). Selection: model, chains, keep_hydrogens, keep_waters,
    keep_hetero, keep_cofactors; max_input_mb=512 as in analyze()."""
    kind, source, data = _input(structure, selection)
    sel = {key: _ANALYZE_DEFAULTS[key] for key in _SELECTION_KEYS}
    unknown = set(selection) - set(sel)
    if unknown:
        raise MisuseError("surface: unknown option(s) " + ", ".join(sorted(unknown)))
    sel.update(selection)
    sel["chains"] = list(sel["chains"])
    _hetero_option(sel)
    if kind == "path":
        return SurfaceResult(_core.surface_path(source, float(probe), bool(excluded), bool(per_atom), sel))
    if kind == "text":
        return SurfaceResult(_core.surface_text(source, data, float(probe), bool(excluded), bool(per_atom), sel))
    return SurfaceResult(_core.surface_arrays(*_core_arrays(data), float(probe), bool(excluded), bool(per_atom)))
