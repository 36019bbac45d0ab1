"""Command of chapter 2 (:mod:`gearlib.units`).

``units FILE [--json]``: the kinematic units of a mechanism and their common linkages.
"""

from __future__ import annotations

from ..units.fractionation import kinematic_units
from ._args import Command, load_mechanism, show

# ----------------------------------------------------------------------------- units


def _units_arguments(p):
    p.add_argument("file", metavar="FILE", help="mechanism file (YAML/JSON) or catalogue name")
    p.add_argument("--json", action="store_true", help="print the units and linkages as JSON")


def _units_run(args) -> int:
    frac = kinematic_units(load_mechanism(args.file))
    return show(args, frac)


COMMANDS = (
    Command("units", "the kinematic units of a mechanism, their types and the common linkages between them",
            _units_arguments, _units_run),
)
