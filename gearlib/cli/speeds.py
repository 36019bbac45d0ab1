"""``python -m gearlib speeds FILE --ground G --input L=V ... [--json]``: every link's speed."""

from __future__ import annotations

from ..kinematics import METHODS, speeds
from . import load_mechanism, parse_link_values, print_json

NAME = "speeds"
HELP = "every link's angular velocity for given input speeds"


def add_common(p, *, inputs_help="input speed LINK=SPEED (or U/V=SPEED for U relative to V); repeat"):
    p.add_argument("file", metavar="FILE", help="mechanism file (YAML/JSON) or catalogue name")
    p.add_argument("--ground", help="the fixed link (default: the file's `ground`)")
    p.add_argument("--held", action="append", default=[], metavar="LINK", help="also hold this link (a brake)")
    p.add_argument("--joined", action="append", default=[], metavar="U,V", help="make U and V turn together (a clutch)")


def constraints(args):
    joined = []
    for item in args.joined:
        u, sep, v = item.partition(",")
        if not sep:
            from ..errors import InputError

            raise InputError(f"--joined {item!r}: expected two links U,V")
        joined.append((u.strip(), v.strip()))
    return {"held": args.held, "joined": joined}


def add_arguments(p):
    add_common(p)
    p.add_argument("--input", action="append", default=[], metavar="LINK=SPEED",
                   help="input speed LINK=SPEED (or U/V=SPEED for U relative to V); repeat for several")
    p.add_argument("--method", choices=METHODS, default="exact")
    p.add_argument("--json", action="store_true", help="print {dof, speeds: {link: [re, im]}}")


def run(args) -> int:
    mech = load_mechanism(args.file)
    inputs = parse_link_values(args.input)
    sol = speeds(mech, args.ground, inputs, method=args.method, **constraints(args))
    if args.json:
        print_json(sol.to_json())
    else:
        print(sol)
        print(f"degrees of freedom: {sol.dof}")
    return 0
