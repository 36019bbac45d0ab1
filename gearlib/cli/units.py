"""``python -m gearlib units FILE [--json]``: the kinematic units and their common linkages."""

from __future__ import annotations

from ..units import kinematic_units
from . import load_mechanism, print_json

NAME = "units"
HELP = "the kinematic units of a mechanism, their types and the common linkages between them"


def add_arguments(p):
    p.add_argument("file", metavar="FILE", help="mechanism file (YAML/JSON) or catalogue name")
    p.add_argument("--json", action="store_true", help="print the units and linkages as JSON")


def run(args) -> int:
    frac = kinematic_units(load_mechanism(args.file))
    if args.json:
        print_json(frac.to_json())
    else:
        print(frac)
    return 0
