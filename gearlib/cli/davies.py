"""Command of chapter 5 (:mod:`gearlib.davies`).

``python -m gearlib efficiency FILE --input I --output O [--ground G] [--held L] [--joined U,V]
[--gear NAME] [--eta 0.98] [--eta-pair A,B=0.97] [--symbolic] [--json]``: the overall efficiency
of a one-degree-of-freedom train by Davies' method (chapter 5): the driver of every mesh, its
virtual (carrier-relative) power per unit input power, its Coulomb coefficient and its loss.
Brakes and clutches come from ``--held`` and ``--joined``, or from a gear of the file's schedule
(``--gear 3rd``). ``--eta`` sets one ordinary efficiency for every mesh; without it every mesh
gets Glover's typical value, 0.98 external (and bevel), 0.99 internal, and the output says so.
``--eta-pair A,B=0.97`` sets the mesh in which A drives B (both directions unless ``B,A`` is
also given); ``--symbolic`` prints the formula in the ordinary efficiencies ``eta_i_j``.

A train with more than one degree of freedom (a differential, a power-split device) is rated
at an operating point: ``--speed LINK=W`` for as many ports as it has freedoms and
``--torque LINK=T`` (the torque the outside applies) for the other ports, e.g.
``efficiency cyl_standard_differential --speed 2=26 --speed 3=30 --torque 1=-10``.
"""

from __future__ import annotations

import sympy

from ..errors import InputError
from ._args import ETA_HELP, Command, add_constraints, add_eta, constraints, eta_spec, load_mechanism, print_json

# ----------------------------------------------------------------------------- efficiency


def _efficiency_arguments(p):
    p.add_argument("file", metavar="FILE", help="mechanism file (YAML/JSON) or catalogue name")
    p.add_argument("--ground", help="the fixed link, common to every port (default: the file's `ground`)")
    p.add_argument("--input", metavar="LINK", help="input link (driven by the source torque) of a one-dof train")
    p.add_argument("--output", metavar="LINK", help="output link (loaded by the sink torque) of a one-dof train")
    add_eta(p)
    add_constraints(p)
    p.add_argument("--speed", action="append", default=[], metavar="LINK=W",
                   help="operating point of a train with several degrees of freedom: the speed of a port; "
                        "one per degree of freedom")
    p.add_argument("--torque", action="append", default=[], metavar="LINK=T",
                   help="operating point: the torque the outside applies to a port (a torque opposing the "
                        "port's speed takes power out); one per port beyond the degrees of freedom")
    p.add_argument("--port", action="append", default=[], metavar="LINK",
                   help="operating point: a further port with neither speed nor torque given")
    p.add_argument("--symbolic", action="store_true", help="give the formula in the ordinary efficiencies")
    p.add_argument("--json", action="store_true", help="print the result as JSON")


def eta_text(eta) -> str:
    """The ordinary efficiencies used, in words (the defaults are never silent)."""
    if eta is None:
        return "Glover's defaults: " + ETA_HELP.split("default: Glover's ", 1)[1]
    if isinstance(eta, dict):
        return "per mesh: " + ", ".join(f"{a},{b}={v}" for (a, b), v in eta.items())
    return f"{eta} for every mesh"


def _numbers(items, what):
    out = {}
    for item in items:
        key, sep, value = item.partition("=")
        if not sep or not key.strip():
            raise InputError(f"{what} {item!r}: expected LINK=VALUE such as 3=26")
        if key.strip() in out:
            raise InputError(f"{what} {key.strip()} is given twice; give each link once")
        try:
            out[key.strip()] = float(value)
        except ValueError:
            raise InputError(f"{what} {item!r}: {value!r} is not a number") from None
    return out


def _operating_run(args, mech, eta, cons) -> int:
    from ..davies.operating import operating_point

    if args.symbolic:
        raise InputError("--symbolic is for one-dof trains (--input/--output); an operating point is numeric")
    ports = list(args.port) + [x for x in (args.input, args.output) if x is not None]
    op = operating_point(mech, args.ground, speeds=_numbers(args.speed, "--speed"),
                         torques=_numbers(args.torque, "--torque"), ports=ports, eta=eta, **cons)
    if args.json:
        out = op.to_json()
        out["eta"] = eta_text(eta)
        print_json(out)
    else:
        print(op)
        print(f"ordinary efficiencies: {eta_text(eta)}")
    return 0


def _efficiency_run(args) -> int:
    from ..davies import efficiency

    mech = load_mechanism(args.file)
    eta = eta_spec(args, mech)
    cons = constraints(args, mech)
    if args.speed or args.torque:
        return _operating_run(args, mech, eta, cons)
    if args.input is None or args.output is None:
        raise InputError("give --input and --output (a one-dof train; add --held, --joined or --gear for its brakes "
                         "and clutches), or --speed and --torque for an operating point of a train with more freedoms")
    ground = args.ground if args.ground is not None else mech.ground
    numeric = efficiency(mech, ground, args.input, args.output, eta=eta, **cons)
    formula = None
    if args.symbolic:
        sym = efficiency(mech, ground, args.input, args.output, symbolic=True,
                         eta=eta if isinstance(eta, dict) else None, **cons)
        formula = sym.formula if sym.formula is not None else sym.value
    if args.json:
        out = numeric.to_json()
        out["eta"] = eta_text(eta)
        if formula is not None:
            out["formula"] = str(formula)
        print_json(out)
    else:
        print(numeric)
        print(f"ordinary efficiencies: {eta_text(eta)}")
        if formula is not None:
            print(f"formula: eta = {sympy.sstr(formula)}")
    return 0


COMMANDS = (
    Command("efficiency", "overall efficiency and power flow of a gear train (Davies' method); with --speed and "
            "--torque, a train of several degrees of freedom at an operating point", _efficiency_arguments,
            _efficiency_run),
)
