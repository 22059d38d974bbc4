#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The include graph keeps the layering of docs/architecture.md.

Reads every #include "..." of libalpha/, molecule/ and apps/ and checks:
  - no cycle between files; a header and its source count as one unit
    (x.cpp's includes are x's), so a cycle through a source is one too;
  - no arrow up the layers: libalpha -> molecule -> apps; inside libalpha
    up its folders util -> numerics -> triangulation -> complex -> flow ->
    union -> mesh; inside molecule up the stages util -> structure ->
    cavities -> ranking -> outputs -> batch -> (analysis.cpp, trajectory);
    a public header (include/alpha/x.hpp, include/molecule/x.hpp) is in the
    folder of its source, a libalpha header without one in the highest
    folder of what it includes;
  - the installed headers (libalpha/include, molecule/include) include only
    installed headers;
  - every quoted include names a file of the tree.
Usage: include_graph.py REPO_ROOT   prints each violation; exit 1 if any.
"""
import re
import sys
from pathlib import Path

# molecule's stages, lowest first; files at molecule/src's top level
# (analysis.cpp) run a structure through all of them.
STAGES = ["util", "structure", "cavities", "ranking", "outputs", "batch", "", "trajectory"]
LEVEL = {stage: i for i, stage in enumerate(STAGES)}
# libalpha's folders, lowest first.
FOLDERS = ["util", "numerics", "triangulation", "complex", "flow", "union", "mesh"]
NAMES = {"libalpha": FOLDERS, "molecule": STAGES}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)

root = Path(sys.argv[1]).resolve()
problems = []
unit_of = {}  # file -> unit name
level_of = {}  # unit -> (layer, level within molecule)
public = set()  # installed headers


def unit(layer, stem, level):
    name = f"{layer}:{stem}"
    level_of.setdefault(name, (layer, level))
    return name


def files(folder, patterns=("*.cpp", "*.hpp")):
    for pattern in patterns:
        yield from sorted((root / folder).rglob(pattern))


# libalpha's folders, molecule's stages and apps: one unit per file stem
# (include/alpha/x.hpp, src/<folder>/x.cpp and src/<folder>/x.hpp are x).
header_only = []  # libalpha's installed headers without a source
for f in files("libalpha/src"):
    rel = f.relative_to(root / "libalpha/src")
    if len(rel.parts) != 2 or rel.parts[0] not in FOLDERS:
        problems.append(f"{f.relative_to(root)}: not in one of include_graph.py's FOLDERS")
        continue
    unit_of[f] = unit("libalpha", f.stem, FOLDERS.index(rel.parts[0]))
for f in files("libalpha/include"):
    public.add(f)
    if f"libalpha:{f.stem}" in level_of:
        unit_of[f] = f"libalpha:{f.stem}"
    else:
        header_only.append(f)
sources = {}  # molecule stem -> stage of its source
for f in files("molecule/src"):
    rel = f.relative_to(root / "molecule/src")
    stage = rel.parts[0] if len(rel.parts) > 1 else ""
    if stage not in LEVEL:
        problems.append(f"{f.relative_to(root)}: stage '{stage}' is not in include_graph.py's STAGES")
        continue
    sources[f.stem] = stage
    unit_of[f] = unit("molecule", f.stem, LEVEL[stage])
for f in files("molecule/include"):
    public.add(f)
    if f.stem not in sources:
        problems.append(f"{f.relative_to(root)}: an installed header with no source in molecule/src/<stage>/")
        continue
    unit_of[f] = unit("molecule", f.stem, LEVEL[sources[f.stem]])
for f in files("apps"):
    unit_of[f] = unit("apps", f.stem, 0)
LAYER = {"libalpha": 0, "molecule": 1, "apps": 2}


def resolve(f, name):
    """The file a quoted include of f names, searched as the build does."""
    candidates = [f.parent / name]
    top = f.relative_to(root).parts[0]
    if top == "libalpha":
        candidates.append(root / "libalpha/src" / name)
    if top in ("libalpha", "molecule", "apps"):
        candidates.append(root / "libalpha/include" / name)
    if top in ("molecule", "apps"):
        candidates += [root / "molecule/include" / name, root / "molecule/src" / name]
    for c in candidates:
        if c.is_file():
            return c.resolve()
    return None


# A header-only installed header is in the highest folder of what it
# includes (the lowest that keeps its own arrows down).
while header_only:
    ready = [f for f in header_only
             if all(resolve(f, n) not in header_only for n in INCLUDE.findall(f.read_text(errors="replace")))]
    if not ready:
        problems.append("installed headers including each other: " + ", ".join(f.name for f in header_only))
        break
    for f in ready:
        targets = [unit_of.get(resolve(f, n)) for n in INCLUDE.findall(f.read_text(errors="replace"))]
        unit_of[f] = unit("libalpha", f.stem, max([level_of[v][1] for v in targets if v], default=0))
        header_only.remove(f)

edges = {}  # unit -> {unit: example "file -> include"}
for f, u in unit_of.items():
    for name in INCLUDE.findall(f.read_text(errors="replace")):
        if name.startswith("alphapocket/"):  # generated version header
            continue
        target = resolve(f, name)
        where = f"{f.relative_to(root)}: #include \"{name}\""
        if target is None:
            problems.append(f"{where} names no file of the tree")
            continue
        if f in public and target not in public:
            problems.append(f"{where}: an installed header includes one that is not installed")
        v = unit_of.get(target)
        if v is None or v == u:
            continue
        (layer_u, level_u), (layer_v, level_v) = level_of[u], level_of[v]
        if LAYER[layer_v] > LAYER[layer_u] or (layer_u == layer_v != "apps" and level_v > level_u):
            names = NAMES.get(layer_u)
            problems.append(f"{where}: an arrow up, from {names[level_u] or 'src'} to {names[level_v] or 'src'}"
                            if layer_u == layer_v else f"{where}: an arrow up, from {layer_u} to {layer_v}")
        edges.setdefault(u, {})[v] = where

# Cycles: Tarjan's strongly connected components, iteratively.
index, low, on_stack, stack, components = {}, {}, set(), [], []
for start in sorted(level_of):
    if start in index:
        continue
    work = [(start, iter(sorted(edges.get(start, {}))))]
    index[start] = low[start] = len(index)
    stack.append(start)
    on_stack.add(start)
    while work:
        u, it = work[-1]
        v = next(it, None)
        if v is not None:
            if v not in index:
                index[v] = low[v] = len(index)
                stack.append(v)
                on_stack.add(v)
                work.append((v, iter(sorted(edges.get(v, {})))))
            elif v in on_stack:
                low[u] = min(low[u], index[v])
            continue
        work.pop()
        if work:
            low[work[-1][0]] = min(low[work[-1][0]], low[u])
        if low[u] == index[u]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == u:
                    break
            if len(component) > 1:
                components.append(sorted(component))
for component in components:
    members = set(component)
    links = [edges[u][v] for u in component for v in sorted(edges.get(u, {})) if v in members]
    problems.append("a cycle between " + ", ".join(component) + ":\n    " + "\n    ".join(links))

for p in problems:
    print(p)
print(f"{len(unit_of)} files, {sum(map(len, edges.values()))} arrows between units: "
      + ("OK" if not problems else f"{len(problems)} problem(s)"))
sys.exit(1 if problems else 0)
