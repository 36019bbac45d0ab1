"""Command of chapter 5 (:mod:`gearlib.davies`).

``python -m gearlib efficiency FILE --ground G --input I --output O [--eta 0.98] [--symbolic] [--json]``.

The overall efficiency of a one-degree-of-freedom train by Davies' method (chapter 5): the
driver of every mesh, its virtual (carrier-relative) power per unit input power, its
Coulomb coefficient and its loss. ``--eta`` sets one ordinary efficiency for every mesh
(default: Glover's 0.98 external, 0.99 internal); ``--eta-pair A,B=0.97`` sets one mesh;
``--symbolic`` prints the formula in the ordinary efficiencies ``eta_i_j`` (``i`` drives ``j``).
"""

from __future__ import annotations

import sympy

from ..errors import InputError
from ._args import Command, load_mechanism, print_json

# ----------------------------------------------------------------------------- efficiency


def _efficiency_arguments(p):
    p.add_argument("file", metavar="FILE", help="mechanism file (YAML/JSON) or catalogue name")
    p.add_argument("--ground", help="the fixed link, common to both ports (default: the file's `ground`)")
    p.add_argument("--input", required=True, metavar="LINK", help="input link (driven by the source torque)")
    p.add_argument("--output", required=True, metavar="LINK", help="output link (loaded by the sink torque)")
    p.add_argument("--eta", type=float, metavar="ETA", help="ordinary efficiency of every mesh, in (0, 1]")
    p.add_argument("--eta-pair", action="append", default=[], metavar="A,B=ETA",
                   help="ordinary efficiency of the mesh between gears A and B; repeat")
    p.add_argument("--held", action="append", default=[], metavar="LINK", help="also hold this link (a brake)")
    p.add_argument("--symbolic", action="store_true", help="give the formula in the ordinary efficiencies")
    p.add_argument("--json", action="store_true", help="print the result as JSON")


def _eta_spec(args):
    spec: dict = {}
    for item in args.eta_pair:
        key, sep, value = item.partition("=")
        a, comma, b = key.partition(",")
        if not sep or not comma:
            raise InputError(f"--eta-pair {item!r}: expected A,B=ETA such as 1,2=0.97")
        try:
            spec[(a.strip(), b.strip())] = float(value)
        except ValueError:
            raise InputError(f"--eta-pair {item!r}: {value!r} is not a number") from None
    return spec


def _efficiency_run(args) -> int:
    from ..davies import efficiency

    mech = load_mechanism(args.file)
    pairs = _eta_spec(args)
    eta = args.eta
    if pairs:
        resolved = {}
        for (a, b), value in pairs.items():
            gp, _ = mech.gear_pair(a, b)
            resolved[gp.gears] = value
        eta = {gp.gears: resolved.get(gp.gears, args.eta) for gp in mech.gear_pairs}
        if args.eta is None:
            eta = {k: v for k, v in eta.items() if v is not None}
    if eta is not None and not isinstance(eta, dict) and not (0 < eta <= 1):
        raise InputError(f"--eta {eta}: an ordinary efficiency must be in (0, 1]")
    ground = args.ground if args.ground is not None else mech.ground
    numeric = efficiency(mech, ground, args.input, args.output, eta=eta, held=args.held)
    formula = None
    if args.symbolic:
        sym = efficiency(mech, ground, args.input, args.output, symbolic=True, held=args.held,
                         eta=eta if isinstance(eta, dict) else None)
        formula = sym.formula if sym.formula is not None else sym.value
    if args.json:
        out = numeric.to_json()
        if formula is not None:
            out["formula"] = str(formula)
        print_json(out)
    else:
        print(numeric)
        if formula is not None:
            print(f"formula: eta = {sympy.sstr(formula)}")
    return 0


COMMANDS = (
    Command("efficiency", "overall efficiency and power flow of a one-dof gear train (Davies' method)",
            _efficiency_arguments, _efficiency_run),
)
