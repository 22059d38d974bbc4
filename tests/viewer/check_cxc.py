#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""A strict reader of pockets.cxc: every line must be a comment or one of
the ChimeraX commands alphapocket writes, with arguments of exactly the
form it writes them (ChimeraX is not in Debian, so its parser cannot run
in the tests). Each form below follows the ChimeraX User Guide's usage line
of that command. A ';' (ChimeraX's command separator) is refused anywhere.

    check_cxc.py FILE   exits 1 naming the first line that is not ours."""
import re
import sys

NAME = r"[A-Za-z0-9_]+"
MODEL = r"#[0-9]+(?:\.[0-9]+)?"
NUM = r"-?[0-9]+\.[0-9]{3}"
RGB = r"rgb\([0-9]{1,3},[0-9]{1,3},[0-9]{1,3}\)"
ATOMS = r"\(#1 & @@serial_number(?:=[0-9]+|>=[0-9]+ & @@serial_number<=[0-9]+)\)"
SPEC = ATOMS + r"(?: \| " + ATOMS + r")*"
NAMED = r"(?:pocket|void|tunnel)_[0-9]+|ligands"

FORMS = [
    r"open structure\.cif",
    r"rename #1 " + NAME,
    r"hide #1 atoms",
    r"show #1 cartoons",
    r"color #1 " + RGB,
    r"name (?:" + NAMED + r") " + SPEC,
    r"show (?:" + NAMED + r") atoms",
    r"style (?:" + NAMED + r") stick",
    r"color ligands byhetero",
    r"color (?:" + NAMED + r") & C " + RGB,
    r"surface #1",
    r"color #1 " + RGB + r" target s",
    r"transparency #[1-5] [0-9]{1,3} target [as]",
    r"marker #[2-5]\.[0-9]+ position " + NUM + "," + NUM + "," + NUM + " color " + RGB + " radius " + NUM,
    r"rename #[2-4]\.[0-9]+ (?:pocket|void)_[0-9]+_(?:space|center)",
    r"rename #4\.[0-9]+ tunnel_[0-9]+_bottleneck",
    r"rename #5\.[0-9]+ tunnel_[0-9]+_path",
    r"hide #[23]\.[0-9]+ models",
    r"open meshes/(?:pocket|void)_[0-9]+\.(?:obj|stl)",
    r"rename #[0-9]+ (?:pocket|void)_[0-9]+_cast",
    r"color #[0-9]+ " + RGB,
    r"transparency #[0-9]+ [0-9]{1,3} target s",
    r"hide #[0-9]+ models",
    r"view #1",
    r"view (?:pocket|void)_[0-9]+ \| #3\.1",
]
PATTERN = re.compile("(?:" + "|".join(FORMS) + ")")


def check(text):
    """The problems of a script's text, one string each."""
    problems = []
    for number, line in enumerate(text.split("\n"), 1):
        if ";" in line:
            problems.append(f"line {number}: a ';': {line!r}")
        elif line.startswith("# ") or line == "":
            if any(ord(c) < 0x20 or ord(c) > 0x7e for c in line):
                problems.append(f"line {number}: a comment not in printable ASCII: {line!r}")
        elif not PATTERN.fullmatch(line):
            problems.append(f"line {number}: not one of our commands: {line!r}")
    if not text.endswith("\n"):
        problems.append("no final newline")
    return problems


if __name__ == "__main__":
    with open(sys.argv[1], encoding="ascii") as f:
        found = check(f.read())
    for p in found:
        print(f"{sys.argv[1]}: {p}", file=sys.stderr)
    sys.exit(1 if found else 0)
