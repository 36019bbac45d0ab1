"""Commands of chapter 3 (:mod:`gearlib.gains`).

``gains FILE --ground G --input I --output O [--symbolic] [--json]``: the propagation path
through the kinematic units and the global gain.

``shifts FILE [--eta ETA] [--eta-pair A,B=ETA] [--k K] [--no-efficiency] [--json | --csv [--table T]]``:
the shift table of a transmission's schedule (:func:`gearlib.shift_table`): every gear's exact
ratio, step and efficiency, the slip of every open element, the power flow, and every
combination of its shift elements classified.
"""

from __future__ import annotations

import sympy

from ..gains.propagation import theta
from ..gains.relation import propagate
from ..mechanism.kinematics import _to_complex, format_value
from ._args import Command, add_common, add_eta, constraints, eta_spec, load_mechanism, print_json

# ----------------------------------------------------------------------------- gains


def _gains_arguments(p):
    add_common(p)
    p.add_argument("--input", action="append", required=True, metavar="LINK",
                   help="input link (or U/V); repeat for each degree of freedom")
    p.add_argument("--output", required=True, metavar="LINK", help="output link (or U/V)")
    p.add_argument("--symbolic", action="store_true", help="also give the gain in the gear-ratio symbols e_a_b")
    p.add_argument("--json", action="store_true", help="print steps, local gains and the relation as JSON")


def _number(v):
    if isinstance(v, sympy.Basic) and v.free_symbols:
        return None
    z = _to_complex(v)
    return [z.real, z.imag]


def _gains_run(args) -> int:
    mech = load_mechanism(args.file)
    prop = propagate(mech, args.output, args.input, ground=args.ground, **constraints(args, mech))
    exact = prop.relation()
    symbolic = prop.relation("symbolic") if (args.symbolic or mech.is_symbolic) else None
    gains = prop.gains
    if args.json:
        out = {
            "steps": [str(s) for s in prop.steps],
            "expression": str(prop.expression()),
            "local_gains": {str(g.symbol): {"unit": g.unit.name, "type": g.unit.label, "rule": g.rule,
                                            "expression": str(g.expression)} for g in gains},
            "relation": {f"{u}/{v}": {"value": _number(c), "exact": str(c)} for (u, v), c in exact.items()},
        }
        if symbolic is not None:
            for (u, v), c in symbolic.items():
                out["relation"][f"{u}/{v}"]["expression"] = str(c)
        print_json(out)
        return 0
    for s in prop.steps:
        print(s)
    print(f"{theta(*prop.output)} = {sympy.sstr(prop.expression())}")
    for g in gains:
        rule = f"rule {g.rule}" if g.rule else "no rule"
        print(f"  {g.symbol} = {sympy.sstr(g.expression)}  ({g.unit.name} {g.unit.label}, {rule})")
    for (u, v), c in exact.items():
        print(f"gain {theta(*prop.output)} / {theta(u, v)} = {format_value(c, 10)}")
        if symbolic is not None:
            print(f"  symbolic: {sympy.sstr(symbolic[(u, v)])}")
    return 0


# ----------------------------------------------------------------------------- shifts


def _shifts_arguments(p):
    p.add_argument("file", metavar="FILE", help="transmission file (YAML/JSON) with shift_elements and schedule, "
                                                "or catalogue name (e.g. zf_8hp70)")
    p.add_argument("--ground", help="the housing (default: the file's `ground`)")
    p.add_argument("--input", metavar="LINK", help="input shaft (default: the file's first `inputs` entry)")
    p.add_argument("--output", metavar="LINK", help="output shaft (default: the file's `output`)")
    add_eta(p)
    p.add_argument("--k", action="append", type=int, default=None, metavar="K",
                   help="classify every combination of K engaged elements (repeat; default: as many as the "
                        "schedule's gears engage)")
    p.add_argument("--no-efficiency", action="store_true", help="kinematics only (no efficiency, no power flow)")
    out = p.add_mutually_exclusive_group()
    out.add_argument("--json", action="store_true", help="print the whole table as JSON")
    out.add_argument("--csv", action="store_true", help="print one table as CSV (see --table)")
    p.add_argument("--table", choices=("gears", "combinations"), default="gears",
                   help="with --csv: the gears of the schedule (default) or the classified combinations")


def _shifts_run(args) -> int:
    from ..gains.schedule import schedule_table

    mech = load_mechanism(args.file)
    table = schedule_table(mech, eta=eta_spec(args, mech), k=args.k, efficiency=not args.no_efficiency,
                           ground=args.ground, input=args.input, output=args.output)
    if args.json:
        print_json(table.to_json())
    elif args.csv:
        print(table.to_csv(args.table), end="")
    else:
        print(table)
    return 0


COMMANDS = (
    Command("gains", "the unit-by-unit propagation path from input(s) to output and the global gain",
            _gains_arguments, _gains_run),
    Command("shifts", "the shift table of a transmission: ratio, step, slips, efficiency and power flow of every "
            "gear, and every combination of its shift elements classified", _shifts_arguments, _shifts_run),
)
