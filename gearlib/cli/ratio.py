"""``python -m gearlib ratio FILE --ground G --input I --output O [--symbolic] [--json]``."""

from __future__ import annotations

import sympy

from ..kinematics import _to_complex, format_value, ratio
from . import print_json
from .speeds import add_common, constraints
from . import load_mechanism

NAME = "ratio"
HELP = "the speed ratio output/input of a one-dof mechanism"


def add_arguments(p):
    add_common(p)
    p.add_argument("--input", required=True, metavar="LINK", help="input link (or U/V)")
    p.add_argument("--output", required=True, metavar="LINK", help="output link (or U/V)")
    p.add_argument("--relative-to", metavar="LINK", help="measure both speeds relative to this link (default: ground)")
    p.add_argument("--symbolic", action="store_true", help="also give the ratio in the gear-ratio symbols e_a_b")
    p.add_argument("--json", action="store_true", help="print {ratio: [re, im], expression: ...}")


def run(args) -> int:
    mech = load_mechanism(args.file)
    kw = dict(ground=args.ground, relative_to=args.relative_to, **constraints(args))
    value = None
    if not mech.is_symbolic:
        value = ratio(mech, args.output, args.input, **kw)
    expression = ratio(mech, args.output, args.input, method="symbolic", **kw) if (args.symbolic or value is None) else None
    if args.json:
        out = {"ratio": None}
        if value is not None:
            z = _to_complex(value)
            out["ratio"] = [z.real, z.imag]
        if expression is not None:
            out["expression"] = str(expression)
        print_json(out)
    else:
        if value is not None:
            print(f"ratio {args.output}/{args.input} = {format_value(value, 10)}")
        if expression is not None:
            print(f"symbolic: {sympy.sstr(expression)}")
    return 0
