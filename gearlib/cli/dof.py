"""``python -m gearlib dof FILE``: degrees of freedom by the counting rules and by rank."""

from __future__ import annotations

from ..mobility import dof
from . import load_mechanism, print_json

NAME = "dof"
HELP = "degrees of freedom, by the mobility counts and by the rank of the Willis equations"


def add_arguments(p):
    p.add_argument("file", metavar="FILE", help="mechanism file (YAML/JSON) or catalogue name")
    p.add_argument("--json", action="store_true")


def run(args) -> int:
    mob = dof(load_mechanism(args.file))
    if args.json:
        print_json({"dof": mob.rank, "planar": mob.planar, "count": mob.count, "explanation": list(mob.explanation)})
    else:
        print(mob)
    return 0
