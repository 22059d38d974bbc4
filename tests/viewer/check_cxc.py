#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""A reader of pockets.cxc by ChimeraX's documented command grammar, not by
the forms alphapocket writes (ChimeraX is not in Debian, so its parser
cannot run in the tests): each line is a comment or one command whose
arguments follow the usage line of the ChimeraX User Guide (open, rename,
hide, show, color, name, style, surface, transparency, marker, view),
with atom specifications parsed by the guide's atom-spec grammar
(hierarchy #model/chain:residue@atom, @@attribute comparisons, named
selections, element symbols, &, |, ~ and parentheses), colors as rgb(),
hex or a name, percentages in [0, 100] and the documented targets.
Besides, the rules of a script that must stay safe and portable: no ';'
(a command separator) anywhere, files opened by relative paths inside the
output directory, selections named before use, and atoms picked by serial
number only (chain and residue names come from the input file).

    check_cxc.py FILE   exits 1 naming the first line that breaks them."""
import re
import sys

NUMBER = r"-?(?:[0-9]+\.?[0-9]*|\.[0-9]+)"
MODEL = r"#[0-9]+(?:-[0-9]+)?(?:\.[0-9]+(?:-[0-9]+)?)*"
# An attribute test: @@name, @@name op value (the guide's "atom attribute").
ATTRIBUTE = r"@@[A-Za-z_][A-Za-z0-9_]*(?:(?:=|!=|>=|<=|>|<)" + NUMBER + r")?"
# Hierarchy below a model: /chain :residue @atom (any of them), or an attribute test.
HIERARCHY = r"(?:/[A-Za-z0-9,]+)?(?::[A-Za-z0-9,-]+)?(?:@[A-Za-z0-9,*]+)?"
ELEMENTS = {"H", "C", "N", "O", "S", "P", "F", "Cl", "Br", "I", "Zn", "Fe", "Mg", "Ca", "Na", "K", "Mn", "Cu"}
BUILTIN = {"protein", "ligand", "ion", "solvent", "nucleic", "sel", "all"}
NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
TARGETS = re.compile(r"[abcfmprs]+")  # atoms bonds cartoons f(ill) models pseudobonds ribbons surfaces
WHAT = {"atoms", "bonds", "pseudobonds", "pbonds", "cartoons", "cartoon", "ribbons", "surfaces", "models"}
STYLES = {"stick", "ball", "sphere"}
COLOR_SCHEMES = {"byhetero", "byelement", "bychain", "bypolymer"}
COLOR_NAMES = {"red", "green", "blue", "white", "black", "gray", "grey", "yellow", "cyan", "magenta", "orange",
               "tan", "purple", "pink", "salmon", "lightgray", "lightgrey"}


class Problem(Exception):
    pass


def spec_terms(text):
    """Tokens of an atom spec: operators, parentheses and terms."""
    return re.findall(r"[&|~()]|[^\s&|~()]+", text)


def check_spec(text, names, allow_empty=False):
    """An atom specification: terms joined by & or |, each maybe after ~ or
    in parentheses. A term is a model with its hierarchy, a hierarchy of
    model #1 by attribute, an element symbol, a builtin class or a name
    defined earlier."""
    tokens = spec_terms(text)
    if not tokens:
        if allow_empty:
            return
        raise Problem("an empty atom specification")
    depth, expect_term = 0, True
    for t in tokens:
        if expect_term:
            if t == "~":
                continue
            if t == "(":
                depth += 1
                continue
            if t in "&|)":
                raise Problem(f"'{t}' where an atom specification term belongs")
            if not (re.fullmatch(ATTRIBUTE, t) or t in ELEMENTS or t in BUILTIN or t in names):
                if not re.fullmatch(f"(?:{MODEL})?{HIERARCHY}", t):
                    raise Problem(f"not an atom specification term: {t!r}")
                if re.search(r"[/:@]", t):
                    raise Problem(f"atoms named by chain, residue or atom name (from the input file): {t!r}")
            expect_term = False
        else:
            if t == ")":
                depth -= 1
                if depth < 0:
                    raise Problem("unbalanced ')'")
            elif t in "&|":
                expect_term = True
            else:
                raise Problem(f"two terms without an operator: {t!r}")
    if expect_term or depth:
        raise Problem("an incomplete atom specification")


def check_color(word):
    m = re.fullmatch(r"rgb\(([0-9]+),([0-9]+),([0-9]+)\)", word)
    if m:
        if any(int(v) > 255 for v in m.groups()):
            raise Problem(f"an rgb() component above 255: {word}")
    elif not (re.fullmatch(r"#[0-9a-fA-F]{6}", word) or word in COLOR_NAMES):
        raise Problem(f"not a color: {word!r}")


def take_option(args, keyword):
    """The value of a trailing 'keyword value' pair, removed from args."""
    if len(args) >= 2 and args[-2] == keyword:
        value = args[-1]
        del args[-2:]
        return value
    return None


def check_command(line, names):
    words = line.split()
    command, args = words[0], words[1:]
    if command == "open":  # open filename
        if len(args) != 1:
            raise Problem("open takes one file name here")
        path = args[0]
        if path.startswith("/") or ".." in path.split("/") or "\\" in path:
            raise Problem(f"a file outside the output directory: {path!r}")
    elif command == "rename":  # rename model-spec new-name
        if len(args) != 2 or not re.fullmatch(MODEL, args[0]) or not re.fullmatch(r"[A-Za-z0-9_.+-]+", args[1]):
            raise Problem("rename takes a model and a name")
    elif command in ("hide", "show"):  # hide|show [atom-spec] [what]
        if args and args[-1] in WHAT:
            args = args[:-1]
        check_spec(" ".join(args), names, allow_empty=True)
    elif command == "color":  # color spec color-name|scheme [what] [target string]
        target = take_option(args, "target")
        if target is not None and not TARGETS.fullmatch(target):
            raise Problem(f"not a target: {target!r}")
        if args and args[-1] in WHAT:
            args = args[:-1]
        if not args:
            raise Problem("color needs a color")
        if args[-1] not in COLOR_SCHEMES:
            check_color(args[-1])
        check_spec(" ".join(args[:-1]), names)
    elif command == "name":  # name name spec
        if len(args) < 2 or not NAME.fullmatch(args[0]) or args[0] in BUILTIN or args[0] in ELEMENTS:
            raise Problem("name takes a new name and a specification")
        check_spec(" ".join(args[1:]), names)
        names.add(args[0])
    elif command == "style":  # style [atom-spec] stick|ball|sphere
        if not args or args[-1] not in STYLES:
            raise Problem("style needs stick, ball or sphere")
        check_spec(" ".join(args[:-1]), names, allow_empty=True)
    elif command in ("surface", "view"):  # surface|view [atom-spec]
        check_spec(" ".join(args), names, allow_empty=True)
    elif command == "transparency":  # transparency [spec] percent [target string]
        target = take_option(args, "target")
        if target is not None and not TARGETS.fullmatch(target):
            raise Problem(f"not a target: {target!r}")
        if not args or not re.fullmatch(NUMBER, args[-1]) or not 0 <= float(args[-1]) <= 100:
            raise Problem("transparency needs a percentage in [0, 100]")
        check_spec(" ".join(args[:-1]), names, allow_empty=True)
    elif command == "marker":  # marker #model position x,y,z [color c] [radius r]
        if not args or not re.fullmatch(MODEL, args[0]):
            raise Problem("marker needs a model")
        options = args[1:]
        if len(options) % 2:
            raise Problem("marker options come in pairs")
        seen = dict(zip(options[::2], options[1::2]))
        if set(seen) - {"position", "color", "radius"} or "position" not in seen or len(seen) * 2 != len(options):
            raise Problem("marker takes position, color and radius once each")
        if not re.fullmatch(",".join([NUMBER] * 3), seen["position"]):
            raise Problem(f"not a position: {seen['position']!r}")
        if "color" in seen:
            check_color(seen["color"])
        if "radius" in seen and not (re.fullmatch(NUMBER, seen["radius"]) and float(seen["radius"]) > 0):
            raise Problem(f"not a radius: {seen['radius']!r}")
    else:
        raise Problem(f"not a ChimeraX command of this grammar: {command!r}")


def check(text):
    """The problems of a script's text, one string each."""
    problems, names = [], set()
    for number, line in enumerate(text.split("\n"), 1):
        if ";" in line:
            problems.append(f"line {number}: a ';': {line!r}")
        elif line.startswith("#") or line == "":
            if any(ord(c) < 0x20 or ord(c) > 0x7e for c in line):
                problems.append(f"line {number}: a comment not in printable ASCII: {line!r}")
        elif line != line.strip() or any(ord(c) < 0x20 or ord(c) > 0x7e for c in line):
            problems.append(f"line {number}: spaces around it or not printable ASCII: {line!r}")
        else:
            try:
                check_command(line, names)
            except Problem as p:
                problems.append(f"line {number}: {p}: {line!r}")
    if not text.endswith("\n"):
        problems.append("no final newline")
    return problems


if __name__ == "__main__":
    with open(sys.argv[1], encoding="ascii") as f:
        found = check(f.read())
    for p in found:
        print(f"{sys.argv[1]}: {p}", file=sys.stderr)
    sys.exit(1 if found else 0)
