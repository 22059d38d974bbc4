#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Rebuilds alphapocket's ligandability model from ../shared/data (see training/README.md).

    /usr/bin/python3 training/train.py [--alphapocket EXE] [--data DIR] [--work DIR] [--model KIND]

Runs `alphapocket pockets --features` on every structure of the training sets (--train, default
pockets-train and pockets-train-pb) and the dev sets (--dev, default pockets-dev and pockets-dev-pb), labels
each cavity by bench/ligand_sites' rules (a hit when its centre is within 4 A of a ligand atom, any copy of
it), fits the trees on the training sets only (fixed seeds), calibrates their margin by isotonic regression on
out-of-fold margins of a grouped (by structure) 5-fold cross-validation, and writes
molecule/data/ligandability.json, training/features.csv.gz (the training cavities' features) and the test
fixture tests/data/ligandability/pockets-dev.csv (every pockets-dev site's features with scikit-learn's
margin and probability). Prints the cross-validated figures on the training sets, the figures on the dev
sets for both rankings and reliability tables. --check fits on training/features.csv.gz instead (CTest).
"""
import argparse
import csv
import gzip
import io
import json
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

import numpy as np
from joblib import Parallel, delayed
from sklearn.ensemble import GradientBoostingClassifier, RandomForestClassifier
from sklearn.isotonic import IsotonicRegression
from sklearn.model_selection import GroupKFold

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MODEL = os.path.join(ROOT, "molecule", "data", "ligandability.json")
FIXTURE = os.path.join(ROOT, "tests", "data", "ligandability", "pockets-dev.csv")
# Every training cavity's features as alphapocket wrote them: --check fits on these instead of running
# alphapocket on every training structure, and compares SAMPLE's rows with a fresh run.
FEATURES = os.path.join(ROOT, "training", "features.csv.gz")
SAMPLE = [("pockets-train", "2w1aC"), ("pockets-train-pb", "7M41_YQG")]  # small; one of two chains
HIT = 4.0    # A, DCC and DCA
MERGE = 1.7  # A, residues of one ligand
SITE_VOLUME = 150             # molecule::kLigandSiteVolume: the smallest void (free space) the model compares
VOID_VOLUME = 150             # molecule::kLigandVoidVolume: the smallest void (MS volume) that holds a ligand
MIN_SITE_PROBABILITY = 0.08   # molecule::kMinSiteProbability: candidates below it are no sites
BAG = 5                       # gradient-boosted models averaged, seeds 0..BAG-1
TREES, RATE, DEPTH = 100, 0.1, 3  # each one's trees, learning rate and depth
MAX_FEATURES = 0.5            # the share of the features a split looks at
CLUSTER_RADIUS = 10.0         # molecule::kSiteClusterRadius (A)
CLUSTER_SHARE = 0.6           # molecule::kSiteClusterShare
RECENTERING_RADIUS = 6.0      # molecule::kRecenteringRadius (A)
BURIED_POINT_ATOMS = 95       # molecule::kBuriedPointAtoms
LEADING = ["kind", "cavity_rank", "site_rank", "center_x", "center_y", "center_z"]
TRAILING = ["ligandability", "probability", "rank_score"]  # alphapocket's own margin, probability and rank score


def read_ds(dataset):
    ds = [f for f in os.listdir(dataset) if f.endswith(".ds")]
    entries = []
    for line in open(os.path.join(dataset, ds[0])):
        words = line.split()
        if len(words) < 2 or words[0].startswith("#") or words[0] == "HEADER:":
            continue
        entries.append((words[0], words[1].split(",")))
    return entries


def read_ligands(path, codes):
    """The dataset's ligands: listed HETATM residues, heavy atoms, merged when closer than 1.7 A."""
    residues, altloc_of = {}, {}
    for line in open(path):
        if not line.startswith("HETATM") or line[17:20].strip() not in codes:
            continue
        element = line[76:78].strip() or line[12:14].strip().lstrip("0123456789")
        if element.upper() in ("H", "D"):
            continue
        key = (line[21], line[22:26], line[26], line[17:20])
        alt = line[16]
        if alt != " ":  # one conformer per residue: the first altloc seen
            if altloc_of.setdefault(key, alt) != alt:
                continue
        residues.setdefault(key, []).append([float(line[30:38]), float(line[38:46]), float(line[46:54])])
    parts = [np.array(v) for v in residues.values()]
    group = list(range(len(parts)))

    def find(i):
        while group[i] != i:
            i = group[i]
        return i
    for i in range(len(parts)):
        for j in range(i + 1, len(parts)):
            d = np.linalg.norm(parts[i][:, None, :] - parts[j][None, :, :], axis=2)
            if d.min() < MERGE:
                a, b = find(i), find(j)
                group[max(a, b)] = min(a, b)
    ligands = {}
    for i, p in enumerate(parts):
        ligands.setdefault(find(i), []).append(p)
    return [np.vstack(v) for v in ligands.values()]


def read_sdf(path):
    """The heavy atoms of every molecule of an SD file of V2000 molfiles (PoseBusters' ligands.sdf: every copy
    of the ligand of interest)."""
    lines, mols, i = open(path).read().split("\n"), [], 0
    while i + 3 < len(lines):
        if not lines[i + 3].rstrip().endswith("V2000"):
            raise SystemExit(f"{path}: not an SD file of V2000 molfiles")
        n = int(lines[i + 3][:3])
        atoms = [[float(x) for x in l.split()[:3]] for l in lines[i + 4:i + 4 + n] if l.split()[3] not in ("H", "D")]
        mols.append(np.array(atoms))
        while not lines[i].startswith("$$$$"):
            i += 1
        i += 1
    return mols


def dataset_entries(dataset):
    """(name, structure file, ligands) of a COACH420 set (a .ds file; each ligand a target) or a PoseBusters one
    (ENTRY/protein.pdb.gz, ENTRY/ligands.sdf: every copy of the ligand, one target)."""
    if any(f.endswith(".ds") for f in os.listdir(dataset)):
        return [(os.path.splitext(f)[0], os.path.join(dataset, f),
                 lambda f=f, codes=codes: read_ligands(os.path.join(dataset, f), codes)) for f, codes in read_ds(dataset)]
    return [(n, os.path.join(dataset, n, "protein.pdb.gz"), lambda n=n: read_sdf(os.path.join(dataset, n, "ligands.sdf")))
            for n in sorted(os.listdir(dataset))]


def chain_count(path):
    """Protein chains of a PDB file (ATOM records' chain ids)."""
    with (gzip.open if path.endswith(".gz") else open)(path, "rt") as f:
        return len({line[21] for line in f if line.startswith("ATOM")})


def featurize(exe, entries, copies, work):
    """Runs alphapocket on (name, structure file, ligands) entries, its outputs in `work` (kept: a cache), and
    returns (name, header, rows, ligands, buried surface points, whether the entry's ligand copies are one
    target, protein chains) of each. The meshes are no features: a 10 A lattice makes them (3/4 of a run at
    the default 0.5 A) take no time."""
    os.makedirs(work, exist_ok=True)

    def one(entry):
        name, path, ligands = entry
        out = os.path.join(work, name)
        features, points = out + ".csv", out + ".points.csv"
        if not (os.path.exists(features) and os.path.exists(points)):
            subprocess.run([exe, "-q", "pockets", path, "-o", out, "--outputs", "report", "--features", features,
                            "--surface-points", points, "--tunnels-from", "none", "--ranking", "geometric",
                            "--mesh-resolution", "10"], check=True, stdout=subprocess.DEVNULL)
        with open(features) as f:
            rows = list(csv.reader(f))
        surface = np.loadtxt(points, delimiter=",", skiprows=1, ndmin=2)
        buried = surface[surface[:, 3] >= BURIED_POINT_ATOMS, :3]
        return name, rows[0], rows[1:], ligands(), buried, copies, chain_count(path)
    with ThreadPoolExecutor(2) as pool:
        return list(pool.map(one, entries))


def is_posebusters(dataset):
    return not any(f.endswith(".ds") for f in os.listdir(dataset))


def run_alphapocket(exe, dataset, work, first=None):
    """Every cavity of the first `first` (all by default) structures of a set: see featurize."""
    return featurize(exe, dataset_entries(dataset)[:first], is_posebusters(dataset), work)


def cached_columns(header):
    """The columns of alphapocket's features file that training/features.csv.gz keeps: not site_rank nor the
    model's margin and probability, which change with the model."""
    return [i for i, h in enumerate(header) if h != "site_rank" and h not in TRAILING]


def write_feature_cache(structures, set_of):
    """training/features.csv.gz: every cavity of the training structures, alphapocket's text (gzip without a
    time stamp: the same features give the same bytes)."""
    keep = cached_columns(structures[0][1])
    out = io.StringIO()
    out.write(",".join(["set", "structure"] + [structures[0][1][i] for i in keep]) + "\n")
    for (name, _, rows, *_), set_name in zip(structures, set_of):
        for r in rows:
            out.write(",".join([set_name, name] + [r[i] for i in keep]) + "\n")
    with open(FEATURES, "wb") as f:
        f.write(gzip.compress(out.getvalue().encode(), 9, mtime=0))


def read_feature_cache(data):
    """The training structures as featurize gives them, from training/features.csv.gz and the data's ligands
    (no buried surface points nor chain counts: the figures need a run of alphapocket)."""
    with gzip.open(FEATURES, "rt") as f:
        lines = list(csv.reader(f))
    columns = lines[0][2:]
    header = columns[:2] + ["site_rank"] + columns[2:] + TRAILING
    by_structure = {}
    for r in lines[1:]:
        by_structure.setdefault((r[0], r[1]), []).append(r[2:4] + ["nan"] + r[4:] + ["nan"] * len(TRAILING))
    structures, set_of, ligands = [], [], {}
    for set_name, name in by_structure:
        if set_name not in ligands:
            dataset = os.path.join(data, set_name)
            ligands[set_name] = ({n: l for n, _, l in dataset_entries(dataset)}, is_posebusters(dataset))
        loaders, copies = ligands[set_name]
        structures.append((name, header, by_structure[(set_name, name)], loaders[name](), None, copies, 0))
        set_of.append(set_name)
    return structures, np.array(set_of)


def table(structures):
    """Feature matrix, labels and bookkeeping of all cavities of all structures; candidate: whether the model
    compares a cavity (molecule::site_candidates: a pocket, or a void of at least SITE_VOLUME; which pockets
    alphapocket leaves out depends on the model, so they are all fitted and ranked); holds: a void that holds
    a ligand (molecule::holds_ligand), a site whatever its probability; cpp: alphapocket's margin and
    probability of each."""
    header = structures[0][1]
    assert header[:len(LEADING)] == LEADING and header[-len(TRAILING):] == TRAILING, header
    names = header[len(LEADING):-len(TRAILING)]
    X, dca, dcc, group, centers, ids, cpp = [], [], [], [], [], [], []
    for g, (name, h, rows, ligands, *_) in enumerate(structures):
        assert h == header, name
        for r in rows:
            c = np.array([float(x) for x in r[3:6]])
            X.append([float(x) for x in r[len(LEADING):-len(TRAILING)]])
            cpp.append([float(x) for x in r[-len(TRAILING):]])
            dca.append(any(np.linalg.norm(l - c, axis=1).min() <= HIT for l in ligands))
            dcc.append(any(np.linalg.norm(l.mean(axis=0) - c) <= HIT for l in ligands))
            group.append(g)
            centers.append(c)
            ids.append([name, r[0], r[1]])
    X = np.array(X)
    is_void, sa = X[:, names.index("is_void")] == 1, X[:, names.index("sa_volume")]
    candidate = ~is_void | (sa >= SITE_VOLUME)
    holds = is_void & ((sa >= SITE_VOLUME) | (X[:, names.index("ms_volume")] >= VOID_VOLUME))
    return (names, X, np.array(dca, int), np.array(dcc, int), np.array(group), candidate, holds,
            np.array(centers), ids, np.array(cpp))


def cluster_centers(centers, prob):
    """molecule::cluster_site_centers: the centres of sites in rank order (centres and probabilities in that
    order). Best first, a site no better one has taken takes the lower-ranked ones not yet taken within
    CLUSTER_RADIUS whose probability is at least CLUSTER_SHARE of its own; its centre becomes their
    probability-weighted mean (its own included)."""
    out, taken = centers.copy(), np.zeros(len(centers), bool)
    for i in range(len(centers)):
        if taken[i]:
            continue
        near = np.linalg.norm(centers - centers[i], axis=1) <= CLUSTER_RADIUS
        members = np.where(near & ~taken & (prob >= CLUSTER_SHARE * prob[i]) & (np.arange(len(centers)) > i))[0]
        if len(members):
            taken[members] = True
            m = np.concatenate([[i], members])
            out[i] = (prob[m, None] * centers[m]).sum(axis=0) / prob[m].sum()
    return out


def recenter(centers, buried):
    """molecule::center_sites_on_buried_surface: each centre the mean of the buried surface points within
    RECENTERING_RADIUS of it, if any."""
    out = centers.copy()
    for i, c in enumerate(centers):
        near = buried[np.linalg.norm(buried - c, axis=1) <= RECENTERING_RADIUS]
        if len(near):
            out[i] = near.mean(axis=0)
    return out


def figures(structures, group, sites, log_score, centers, key, prob=None, subset=None):
    """DCC and DCA at top-1 and top-3 of the sites (a mask) ranked by `key` (larger first; ties: the
    geometric order, by log_score, then pockets before voids, each in its order: the rows' order); with
    `prob` (the probability ranking), at their clusters' centres moved onto the buried surface. Targets:
    each ligand, or an entry's copies of its ligand together (any copy hits); `subset`: the structures
    scored (all by default). Returns the fractions, the targets and the median number of sites."""
    hits = {"dcc": [0, 0], "dca": [0, 0]}
    total, counts = 0, []
    for g, (name, _, _, ligands, buried, copies, _) in enumerate(structures):
        if subset is not None and not subset[g]:
            continue
        idx = np.where((group == g) & sites)[0]
        counts.append(len(idx))
        idx = idx[np.argsort(-log_score[idx], kind="stable")]         # geometric order first
        idx = idx[np.argsort(-key[idx], kind="stable")]
        ranked = centers[idx] if prob is None else recenter(cluster_centers(centers[idx], prob[idx]), buried)
        targets = [ligands] if copies else [[l] for l in ligands]
        total += len(targets)
        for t_ in targets:
            for crit in ("dcc", "dca"):
                for t, k in enumerate((1, 3)):
                    top = ranked[:k]
                    if crit == "dcc":
                        ok = any(np.linalg.norm(l.mean(axis=0) - c) <= HIT for c in top for l in t_)
                    else:
                        ok = any(np.linalg.norm(l - c, axis=1).min() <= HIT for c in top for l in t_)
                    hits[crit][t] += ok
    return {c: [h / max(total, 1) for h in v] for c, v in hits.items()}, total, float(np.median(counts or [0]))


class Bagged:
    """The mean margin of gradient-boosted models that differ only in their seed: one model's top site moves
    with its seed, the mean less."""

    def __init__(self, models):
        self.models = models

    def decision_function(self, X):
        return np.mean([m.decision_function(X) for m in self.models], axis=0)

    @property
    def feature_importances_(self):
        return np.mean([m.feature_importances_ for m in self.models], axis=0)


class Hybrid:
    """A classifier, whose calibrated margin is each candidate's probability (and decides which pockets are sites),
    and a ranker, whose margin orders the sites: both bagged over the same seeds."""

    def __init__(self, classifier, ranker):
        self.classifier, self.ranker = classifier, ranker
        self.models = classifier.models + ranker.models

    def decision_function(self, X):
        return self.classifier.decision_function(X)

    @property
    def feature_importances_(self):
        return self.classifier.feature_importances_


class PairwiseRanker:
    """xgboost's gradient-boosted trees fitted to rank each structure's ligand sites above its other candidates
    (rank:pairwise, a group per structure) rather than to classify each candidate on its own; kept as the model
    file's trees, which give the margin (in double, as alphapocket sums them)."""

    def __init__(self, trees, rate, depth, max_features, seed):
        self.params = {"objective": "rank:pairwise", "eta": rate, "max_depth": depth, "subsample": 0.8,
                       "colsample_bynode": max_features, "seed": seed, "nthread": 1, "tree_method": "exact",
                       "base_score": 0.5}
        self.rounds = trees

    def fit(self, X, y, group):
        import xgboost  # Debian's python3-xgboost
        order = np.argsort(group, kind="stable")
        data = xgboost.DMatrix(X[order], label=y[order])
        data.set_group(np.unique(group[order], return_counts=True)[1])
        booster = xgboost.train(self.params, data, num_boost_round=self.rounds)
        raw = json.loads(booster.save_raw("json").decode())
        self.init = float(raw["learner"]["learner_model_param"]["base_score"])
        self.trees = [xgboost_tree(t) for t in raw["learner"]["gradient_booster"]["model"]["trees"]]
        gain = booster.get_score(importance_type="total_gain")
        self.feature_importances_ = np.array([gain.get(f"f{i}", 0.0) for i in range(X.shape[1])])
        self.feature_importances_ /= max(self.feature_importances_.sum(), 1e-300)
        return self

    def decision_function(self, X):
        return self.init + sum(tree_values(t, X) for t in self.trees)


def xgboost_tree(t):
    """An xgboost tree in the model file's layout. xgboost sends x left when float(x) < condition, the file when
    float(x) <= threshold: the threshold is the float just below the condition."""
    leaf = [l < 0 for l in t["left_children"]]
    return {"feature": [-1 if z else int(f) for f, z in zip(t["split_indices"], leaf)],
            "threshold": [0.0 if z else float(np.nextafter(np.float32(c), np.float32(-np.inf)))
                          for c, z in zip(t["split_conditions"], leaf)],
            "left": [int(x) for x in t["left_children"]], "right": [int(x) for x in t["right_children"]],
            "value": [float(np.float32(c)) if z else 0.0 for c, z in zip(t["split_conditions"], leaf)]}


def tree_values(t, X):
    """The leaf values a tree of the model file's layout gives the rows of X (a feature's value as a float)."""
    X32 = X.astype(np.float32)
    feature, threshold, left, right, value = (np.array(t[k]) for k in ("feature", "threshold", "left", "right", "value"))
    node = np.zeros(len(X), int)
    inner = left[node] >= 0
    while inner.any():
        n = node[inner]
        node[inner] = np.where(X32[inner, feature[n]] <= threshold[n], left[n], right[n])
        inner = left[node] >= 0
    return value[node]


def make_model(a, first_seed=0):
    """The model of the options: a.bag gradient-boosted models of seeds first_seed.. (ranking, classifying or
    both: hybrid), or a random forest."""
    if a.model == "hybrid":
        classify, rank = (make_model(argparse.Namespace(**{**vars(a), "model": m}), first_seed) for m in ("gb", "rank"))
        return Hybrid(classify, rank)
    if a.model == "rank":
        return Bagged([PairwiseRanker(a.trees, a.rate, a.depth, a.max_features, seed)
                       for seed in range(first_seed, first_seed + a.bag)])
    if a.model == "gb":
        return Bagged([GradientBoostingClassifier(n_estimators=a.trees, learning_rate=a.rate, max_depth=a.depth,
                                                  subsample=0.8, max_features=a.max_features, min_samples_leaf=5,
                                                  random_state=seed)
                       for seed in range(first_seed, first_seed + a.bag)])
    return RandomForestClassifier(n_estimators=300, min_samples_leaf=3, max_features=0.3, random_state=0)


def fit_one(model, X, y, group):
    return model.fit(X, y, group) if isinstance(model, PairwiseRanker) else model.fit(X, y)


def fit_models(jobs, n_jobs):
    """Fits (model, X, y, structure of each row) jobs, a bagged model's members each on its own, on n_jobs
    processes (the fits are deterministic: the same models whatever n_jobs)."""
    tasks = [(m, X, y, g) for model, X, y, g in jobs
             for m in (model.models if isinstance(model, (Bagged, Hybrid)) else [model])]
    fitted = iter(Parallel(n_jobs=n_jobs)(delayed(fit_one)(m, X, y, g) for m, X, y, g in tasks))
    out = []
    for model, *_ in jobs:
        if isinstance(model, Hybrid):
            out.append(Hybrid(Bagged([next(fitted) for _ in model.classifier.models]),
                              Bagged([next(fitted) for _ in model.ranker.models])))
        elif isinstance(model, Bagged):
            out.append(Bagged([next(fitted) for _ in model.models]))
        else:
            out.append(next(fitted))
    return out


def margin(model, X):
    if isinstance(model, (Bagged, Hybrid)):
        return model.decision_function(X)
    return model.predict_proba(X)[:, 1]


def rank_score(model, X):
    """The score that orders the sites: a hybrid's ranker's margin, another model's margin."""
    return margin(model.ranker if isinstance(model, Hybrid) else model, X)


def export(model, names, iso, trained_on):
    if isinstance(model, Hybrid):  # the classifier's model, the ranker's trees as its "ranking"
        out, ranker = export(model.classifier, names, iso, trained_on), export(model.ranker, names, iso, trained_on)
        out["kind"] += " (probability), " + ranker["kind"] + " (ranking)"
        out["ranking"] = {k: ranker[k] for k in ("init", "scale", "trees")}
        return out
    if isinstance(model, Bagged) and isinstance(model.models[0], PairwiseRanker):  # the mean of their margins
        assert len({m.init for m in model.models}) == 1
        return {"format": "alphapocket ligandability model 1", "kind": f"{len(model.models)} x xgboost rank:pairwise",
                "trained_on": "+".join(trained_on), "features": names, "init": model.models[0].init,
                "scale": 1.0 / len(model.models), "trees": [t for m in model.models for t in m.trees],
                "calibration": {"x": [float(x) for x in iso.X_thresholds_], "y": [float(y) for y in iso.y_thresholds_]}}
    if isinstance(model, Bagged):  # the same init (the prior log-odds) and learning rate in every member
        inits = {float(m._raw_predict_init(np.zeros((1, len(names)), dtype=np.float32))[0, 0]) for m in model.models}
        assert len(inits) == 1, inits
        init = inits.pop()
        scale = float(model.models[0].learning_rate) / len(model.models)
        estimators = [e[0] for m in model.models for e in m.estimators_]
        values = [e.tree_.value[:, 0, 0] for e in estimators]
    else:
        init, scale = 0.0, 1.0 / len(model.estimators_)
        estimators = model.estimators_
        values = [e.tree_.value[:, 0, 1] / e.tree_.value[:, 0, :].sum(axis=1) for e in estimators]
    trees = []
    for e, v in zip(estimators, values):
        t = e.tree_
        trees.append({"feature": [int(f) if l >= 0 else -1 for f, l in zip(t.feature, t.children_left)],
                      "threshold": [float(x) if l >= 0 else 0.0 for x, l in zip(t.threshold, t.children_left)],
                      "left": [int(x) for x in t.children_left], "right": [int(x) for x in t.children_right],
                      "value": [float(x) if l < 0 else 0.0 for x, l in zip(v, t.children_left)]})
    kind = f"{len(model.models)} x GradientBoostingClassifier" if isinstance(model, Bagged) else type(model).__name__
    return {"format": "alphapocket ligandability model 1", "kind": kind,
            "trained_on": "+".join(trained_on), "features": names, "init": init, "scale": scale, "trees": trees,
            "calibration": {"x": [float(x) for x in iso.X_thresholds_],
                            "y": [float(y) for y in iso.y_thresholds_]}}


def model_text(model):
    """The model file's text: compact JSON, each float at the shortest that reads back exactly."""
    return json.dumps(model, separators=(",", ":")) + "\n"


def reliability(p, y, bins=(0, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0001)):
    lines = ["| predicted | n | mean predicted | observed rate |", "|---|---|---|---|"]
    for lo, hi in zip(bins[:-1], bins[1:]):
        m = (p >= lo) & (p < hi)
        if m.sum():
            lines.append(f"| {lo:.2f}-{min(hi, 1):.2f} | {m.sum()} | {p[m].mean():.3f} | {y[m].mean():.3f} |")
    return "\n".join(lines)


def run_sample(a):
    """A fresh alphapocket run on SAMPLE, each structure's rows (features and alphapocket's margin and
    probability), or None when its features are not training/features.csv.gz's (printed)."""
    with open(FEATURES, "rb") as f:
        cached = list(csv.reader(io.StringIO(gzip.decompress(f.read()).decode())))
    runs = []
    with tempfile.TemporaryDirectory(prefix="alphapocket_training_") as work:
        for set_name, name in SAMPLE:
            dataset = os.path.join(a.data, set_name)
            entry = [e for e in dataset_entries(dataset) if e[0] == name]
            (_, header, fresh, *_), = featurize(a.alphapocket, entry, is_posebusters(dataset), work)
            keep = cached_columns(header)
            if [header[i] for i in keep] != cached[0][2:] or \
                    [[r[i] for i in keep] for r in fresh] != [r[2:] for r in cached if r[:2] == [set_name, name]]:
                print(f"FAIL: alphapocket's features of {set_name}/{name} are not training/features.csv.gz's: "
                      "alphapocket changed, rerun training/train.py", file=sys.stderr)
                return None
            print(f"{set_name}/{name}: alphapocket's features of its {len(fresh)} cavities are the cache's")
            runs.append((set_name + "/" + name, header, fresh))
    return runs


def check(a, rebuilt, iso, names, runs):
    """0 when the rebuilt model is the committed one, scikit-learn gives the fixture's margins, probabilities and
    rank scores (alphapocket's own agree with them: test_ligandability.cpp) and alphapocket's of every cavity of
    the sample `runs` (run_sample) to 1e-6; else prints what differs and returns 1."""
    problems = []
    text = model_text(export(rebuilt, names, iso, a.train.split(",")))
    with open(MODEL) as f:
        committed = f.read()
    if committed != text:
        committed, text = json.loads(committed), json.loads(text)
        differ = [k for k in sorted(set(committed) | set(text)) if committed.get(k) != text.get(k)]
        problems.append("the rebuilt model is not molecule/data/ligandability.json byte for byte; differing: "
                        + (", ".join(differ) or "only the text"))
    with open(FIXTURE) as f:
        rows = list(csv.reader(f))
    assert rows[0][3:-3] == names, "the fixture's features are not the model's"
    X = np.array([[float(x) for x in r[3:-3]] for r in rows[1:]])
    want = np.array([[float(x) for x in r[-3:]] for r in rows[1:]])
    m = margin(rebuilt, X)
    worst = np.abs(want - np.column_stack([m, iso.predict(m), rank_score(rebuilt, X)])).max(axis=0)
    print(f"{len(X)} pockets-dev sites of the fixture: scikit-learn vs the fixture, largest difference "
          f"{worst[0]:.3g} (margin), {worst[1]:.3g} (probability), {worst[2]:.3g} (rank score)")
    if not worst.max() <= 1e-9:
        problems.append("scikit-learn's margins, probabilities or rank scores of tests/data/ligandability/pockets-dev.csv's "
                        "sites are not the fixture's")
    for name, header, fresh in runs:
        X = np.array([[float(r[i]) for i in range(len(header)) if header[i] in names] for r in fresh])
        m = margin(rebuilt, X)
        cpp = np.array([[float(x) for x in r[-len(TRAILING):]] for r in fresh])
        worst = np.abs(cpp - np.column_stack([m, iso.predict(m), rank_score(rebuilt, X)])).max(axis=0)
        print(f"{name}: alphapocket vs scikit-learn, largest difference {worst[0]:.3g} (margin), "
              f"{worst[1]:.3g} (probability), {worst[2]:.3g} (rank score)")
        if not worst.max() <= 1e-6:
            problems.append(f"alphapocket's margins, probabilities or rank scores of {name} differ from scikit-learn's "
                            "by more than 1e-6")
    for p in problems:
        print("FAIL: " + p, file=sys.stderr)
    return 1 if problems else 0


def cross_validated(a, Xfit, y, group, fit_rows, seeds):
    """The out-of-fold margins and rank scores of a grouped (by structure) 5-fold cross-validation, the folds, the
    isotonic calibration fitted on those margins, and the models of `seeds` seed sets fitted on every row; all
    fits run at once on a.jobs processes."""
    folds = list(GroupKFold(5).split(Xfit, y, group))
    everything = np.arange(len(y))
    jobs = [(make_model(a), tr) for tr, _ in folds] + [(make_model(a, s * a.bag), everything) for s in range(seeds)]
    models = fit_models([(m, Xfit[r[fit_rows[r]]], y[r[fit_rows[r]]], group[r[fit_rows[r]]]) for m, r in jobs], a.jobs)
    oof, oof_rank = np.zeros(len(y)), np.zeros(len(y))
    for (_, te), m in zip(folds, models):
        oof[te], oof_rank[te] = margin(m, Xfit[te]), rank_score(m, Xfit[te])
    iso = IsotonicRegression(out_of_bounds="clip", y_min=0, y_max=1).fit(oof, y)
    return folds, oof, oof_rank, iso, models[len(folds):]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--alphapocket", default=os.path.join(ROOT, "build", "apps", "alphapocket"))
    ap.add_argument("--data", default=os.path.join(ROOT, "..", "shared", "data"))
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "training"),
                    help="features are cached here (delete it after changing alphapocket)")
    ap.add_argument("--model", default="hybrid", choices=["hybrid", "gb", "rank", "rf"])
    ap.add_argument("--bag", type=int, default=BAG, help="gradient-boosted models averaged (seeds 0..BAG-1)")
    ap.add_argument("--trees", type=int, default=TREES, help="trees of each gradient-boosted model")
    ap.add_argument("--rate", type=float, default=RATE, help="their learning rate")
    ap.add_argument("--depth", type=int, default=DEPTH, help="their depth")
    ap.add_argument("--max-features", type=float, default=MAX_FEATURES,
                    help="the share of the features each split of theirs looks at")
    ap.add_argument("--min-probability", type=float, default=MIN_SITE_PROBABILITY,
                    help="the figures' sites: candidates of at least this probability (alphapocket's cut by default)")
    ap.add_argument("--label", default="dca", choices=["dca", "dcc", "both"])
    ap.add_argument("--all-cavities", action="store_true", help="fit on every cavity, not the sites only")
    ap.add_argument("--drop", default="", help="comma-separated features to leave out (for experiments)")
    ap.add_argument("--train", default="pockets-train,pockets-train-pb",
                    help="comma-separated sets of --data to fit on, SET:N for the first N of a set")
    ap.add_argument("--dev", default="pockets-dev,pockets-dev-pb",
                    help="comma-separated sets only predicted, to choose and report (pockets-dev among them: the "
                         "test fixture is its sites'); e.g. pockets-dev,pockets-dev-pb")
    ap.add_argument("--seeds", type=int, default=1,
                    help="fit this many seed sets (seeds 0..BAG-1, BAG..2BAG-1, ...) and print the spread of the dev "
                         "figures; the first is the model written")
    ap.add_argument("--no-write", action="store_true", help="write neither the model nor the fixture")
    ap.add_argument("--jobs", type=int, default=2, help="processes fitting the models")
    ap.add_argument("--check", action="store_true",
                    help="write nothing; fit on training/features.csv.gz and fail unless the model is the committed "
                         "one, the fixture's margins are scikit-learn's and a fresh alphapocket run on a few training "
                         "structures gives the cached features and scikit-learn's margins to 1e-6 (a CTest test)")
    a = ap.parse_args()

    def load(sets):
        structures, set_of = [], []
        for spec in sets:  # SET or SET:N, the first N structures of SET (in its order)
            name, _, first = spec.partition(":")
            st = run_alphapocket(a.alphapocket, os.path.join(a.data, name), os.path.join(a.work, name),
                                 int(first) if first else None)
            structures += st
            set_of += [name] * len(st)
        return structures, np.array(set_of)
    if a.check:
        runs = run_sample(a)
        if runs is None:
            sys.exit(1)
        train, tset = read_feature_cache(a.data)
        if list(dict.fromkeys(tset)) != [s.partition(":")[0] for s in a.train.split(",")]:
            raise SystemExit("--check fits on training/features.csv.gz, whose sets are " + ",".join(dict.fromkeys(tset)))
    else:
        train, tset = load(a.train.split(","))
    names, X, dca, dcc, group, candidate, holds, centers, _, _ = table(train)
    y = {"dca": dca, "dcc": dcc, "both": dca & dcc}[a.label]
    dropped = [n for n in a.drop.split(",") if n]
    keep = [i for i, n in enumerate(names) if n not in dropped]
    # Left-out features are kept as columns the trees never split on (the C++ side computes all).
    Xfit = X.copy()
    Xfit[:, [i for i in range(len(names)) if i not in keep]] = 0
    fit_rows = np.ones(len(y), bool) if a.all_cavities else candidate
    folds, oof, oof_rank, iso, models = cross_validated(a, Xfit, y, group, fit_rows, 1 if a.check else a.seeds)
    if a.check:
        sys.exit(check(a, models[0], iso, names, runs))

    dev, dset = load(a.dev.split(","))
    set_names = lambda specs: [s.partition(":")[0] for s in specs.split(",")]
    if "pockets-dev" not in set_names(a.dev) or any(d in set_names(a.train) for d in set_names(a.dev)):
        raise SystemExit("--dev must hold pockets-dev (the test fixture) and no training set")
    dnames, dX, ddca, ddcc, dgroup, dcandidate, dholds, dcenters, dids, dcpp = table(dev)
    assert dnames == names
    # Reliability of the calibration, itself cross-fitted (each fold mapped by the others' isotonic fit).
    oof_p = np.zeros(len(y))
    for tr, te in folds:
        oof_p[te] = IsotonicRegression(out_of_bounds="clip", y_min=0, y_max=1).fit(oof[tr], y[tr]).predict(oof[te])
    dXfit = dX.copy()
    dXfit[:, [i for i in range(len(names)) if i not in keep]] = 0
    is_void, dis_void = X[:, names.index("is_void")] == 1, dX[:, names.index("is_void")] == 1
    log_score, dlog_score = X[:, names.index("log_score")], dX[:, names.index("log_score")]
    chains = [st[6] > 1 for st in train]
    dchains = [st[6] > 1 for st in dev]
    fmt = lambda f: f"DCC {f['dcc'][0]:.3f} / {f['dcc'][1]:.3f}  DCA {f['dca'][0]:.3f} / {f['dca'][1]:.3f}"

    def report(label, structures, set_of, multi, g_, sites, ls, c_, key, prob):
        """One line per set (PoseBusters: also its single- and multi-chain entries)."""
        out = {}
        for name in dict.fromkeys(set_of):
            parts = [("", set_of == name)]
            if name.endswith("-pb"):
                parts += [(" single-chain", (set_of == name) & ~np.array(multi)),
                          (" multi-chain", (set_of == name) & np.array(multi))]
            for part, subset in parts:
                f, n, med = figures(structures, g_, sites, ls, c_, key, prob, subset)
                out[name + part] = f
                print(f"{label} {name + part:28s} ({n:3d}): {fmt(f)}  median sites {med:g}")
        return out

    # Several seeds: the spread of the dev figures (the shipped model is the first).
    shipped = None
    spread = {}
    for s_, model in enumerate(models):
        dm_s, dr_s = margin(model, dXfit), rank_score(model, dXfit)
        dp_s = iso.predict(dm_s)
        dsites_s = (dcandidate & ~dis_void & (dp_s >= a.min_probability)) | dholds
        print(f"seeds {s_ * a.bag}-{s_ * a.bag + a.bag - 1}:")
        for k, f in report("  dev", dev, dset, dchains, dgroup, dsites_s, dlog_score, dcenters, dr_s, dp_s).items():
            spread.setdefault(k, []).append(f)
        if shipped is None:
            shipped, dm, dr, dp, dsites = model, dm_s, dr_s, dp_s, dsites_s
    model = shipped
    if a.seeds > 1:
        for k, fs_ in spread.items():
            print(f"spread over {a.seeds} seed sets, {k:28s}: " + "  ".join(
                f"{c.upper()}@{t} {min(f[c][i] for f in fs_):.3f}-{max(f[c][i] for f in fs_):.3f}"
                for c in ("dcc", "dca") for i, t in enumerate((1, 3))))

    # The sites: the candidates alphapocket keeps (out of fold on the training folders).
    sites = (candidate & ~is_void & (oof_p >= a.min_probability)) | holds
    print(f"model {a.model}, label {a.label}, {'all cavities' if a.all_cavities else 'sites'}, "
          f"{len(names) - len(dropped)} features; {fit_rows.sum()} training rows ({y[fit_rows].sum()} positive) "
          f"from {len(train)} structures")
    report("train CV", train, tset, chains, group, sites, log_score, centers, oof_rank, oof_p)
    report("train geometric", train, tset, chains, group, sites, log_score, centers, log_score, None)
    report("dev", dev, dset, dchains, dgroup, dsites, dlog_score, dcenters, dr, dp)
    report("dev geometric", dev, dset, dchains, dgroup, dsites, dlog_score, dcenters, dlog_score, None)
    for label, structures, g_, cand, s_, c_ in (("train", train, group, candidate, sites, centers),
                                               ("dev", dev, dgroup, dcandidate, dsites, dcenters)):
        missed = [sum(not any(np.linalg.norm(l - c, axis=1).min() <= HIT for c in c_[(g_ == g) & m])
                      for g, st in enumerate(structures) for l in st[3]) for m in (cand, s_)]
        counts = [((g_ == g) & m).sum() for m in (cand, s_) for g in range(len(structures))]
        print(f"{label}: {missed[0]} ligands (copies) have no candidate centre within {HIT} A of an atom, {missed[1]} "
              f"no site centre; median candidates {np.median(counts[:len(structures)]):g}, "
              f"sites {np.median(counts[len(structures):]):g} per structure")
    s = candidate
    print(f"Brier (candidates, out-of-fold, cross-fitted calibration): {np.mean((oof_p[s] - y[s]) ** 2):.4f}, "
          f"base rate {y[s].mean():.3f}")
    print("reliability, both training folders' candidates out-of-fold:\n" + reliability(oof_p[s], y[s]))
    ds_ = dcandidate
    dy = {"dca": ddca, "dcc": ddcc, "both": ddca & ddcc}[a.label]
    print("reliability, both dev folders' candidates:\n" + reliability(dp[ds_], dy[ds_]))
    imp = sorted(zip(model.feature_importances_, names), reverse=True)[:16]
    print("top features: " + ", ".join(f"{n} {v:.3f}" for v, n in imp))
    ds_ = dcandidate & (dset[dgroup] == "pockets-dev")  # the fixture: pockets-dev's candidates
    if a.no_write:
        return
    with open(MODEL, "w") as f:
        f.write(model_text(export(model, names, iso, a.train.split(","))))
    write_feature_cache(train, tset)
    with open(FIXTURE, "w") as f:
        f.write("structure,kind,cavity_rank," + ",".join(names) + ",margin,probability,rank_score\n")
        for i in np.where(ds_)[0]:
            f.write(",".join(dids[i] + [repr(float(x)) for x in dX[i]] +
                             [repr(float(dm[i])), repr(float(dp[i])), repr(float(dr[i]))]) + "\n")
    print("wrote molecule/data/ligandability.json, training/features.csv.gz and tests/data/ligandability/pockets-dev.csv")


if __name__ == "__main__":
    main()
