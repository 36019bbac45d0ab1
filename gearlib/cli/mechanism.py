"""Commands of chapters 0 and 1 (:mod:`gearlib.mechanism`).

* ``speeds FILE --ground G --input L=V ... [--json]``: every link's speed;
* ``ratio FILE --ground G --input I --output O [--symbolic] [--json]``: a speed ratio;
* ``dof FILE``: degrees of freedom by the counting rules and by rank;
* ``sketch FILE --output OUT.svg|.png|.pdf [--lever [--gear G]]``: the kinematic sketch (or,
  with ``--lever``, the lever diagram, with a gear's speeds) drawn to a file.
"""

from __future__ import annotations

import sympy

from ..mechanism.kinematics import METHODS, _to_complex, format_value, ratio, speeds
from ..mechanism.mobility import dof
from ..errors import InputError
from ._args import Command, add_common, add_constraints, constraints, load_mechanism, parse_link_values, print_json

# ----------------------------------------------------------------------------- speeds


def _speeds_arguments(p):
    add_common(p)
    p.add_argument("--input", action="append", default=[], metavar="LINK=SPEED",
                   help="input speed LINK=SPEED (or U/V=SPEED for U relative to V); repeat for several")
    p.add_argument("--method", choices=METHODS, default="exact")
    p.add_argument("--json", action="store_true", help="print {dof, speeds: {link: [re, im]}}")


def _speeds_run(args) -> int:
    mech = load_mechanism(args.file)
    inputs = parse_link_values(args.input)
    sol = speeds(mech, args.ground, inputs, method=args.method, **constraints(args, mech))
    if args.json:
        print_json(sol.to_json())
    else:
        print(sol)
        print(f"degrees of freedom: {sol.dof}")
    return 0


# ----------------------------------------------------------------------------- ratio


def _ratio_arguments(p):
    add_common(p)
    p.add_argument("--input", required=True, metavar="LINK", help="input link (or U/V)")
    p.add_argument("--output", required=True, metavar="LINK", help="output link (or U/V)")
    p.add_argument("--relative-to", metavar="LINK", help="measure both speeds relative to this link (default: ground)")
    p.add_argument("--symbolic", action="store_true", help="also give the ratio in the gear-ratio symbols e_a_b")
    p.add_argument("--json", action="store_true", help="print {ratio: [re, im], expression: ...}")


def _ratio_run(args) -> int:
    mech = load_mechanism(args.file)
    kw = dict(ground=args.ground, relative_to=args.relative_to, **constraints(args, mech))
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


# ----------------------------------------------------------------------------- dof


def _dof_arguments(p):
    p.add_argument("file", metavar="FILE", help="mechanism file (YAML/JSON) or catalogue name")
    p.add_argument("--ground", help="the fixed link (default: the file's `ground`)")
    add_constraints(p)
    p.add_argument("--json", action="store_true")


def _dof_run(args) -> int:
    mech = load_mechanism(args.file)
    mob = dof(mech, args.ground, **constraints(args, mech))
    if args.json:
        print_json({"dof": mob.rank, "planar": mob.planar, "count": mob.count, "explanation": list(mob.explanation)})
    else:
        print(mob)
    return 0


# ----------------------------------------------------------------------------- sketch

_FORMATS = (".svg", ".png", ".pdf")


def _sketch_arguments(p):
    p.add_argument("file", metavar="FILE", help="mechanism file (YAML/JSON) or catalogue name")
    p.add_argument("--output", "-o", required=True, metavar="OUT", help="the drawing: OUT.svg, OUT.png or OUT.pdf")
    p.add_argument("--lever", action="store_true", help="draw the lever diagram of its planetary sets instead")
    p.add_argument("--gear", metavar="G", help="with --lever: draw the speeds of gear G of the file's schedule")
    p.add_argument("--names", action="store_true", help="write each link's name after its id")
    p.add_argument("--dpi", type=int, default=150, help="resolution of a .png (default 150)")


def _sketch_run(args) -> int:
    import pathlib

    from matplotlib.figure import Figure

    out = pathlib.Path(args.output)
    if out.suffix.lower() not in _FORMATS:
        raise InputError(f"--output {args.output!r}: give a file ending in {', '.join(_FORMATS)}")
    if args.gear is not None and not args.lever:
        raise InputError("--gear draws a gear's speeds on the lever diagram: add --lever")
    if args.dpi <= 0:
        raise InputError(f"--dpi {args.dpi}: give a positive resolution such as 150")
    mech = load_mechanism(args.file)
    if args.lever:
        from ..gains.lever import lever_diagram
        from ..gains.lever_plot import draw_levers

        diag = lever_diagram(mech)
        if args.gear is not None:
            mech.gear_state(args.gear)  # an unknown gear: its error, before drawing
        fig = Figure(figsize=(min(9.0, 3.2 + 1.9 * len(diag.levers)), 4.2), facecolor="white")
        draw_levers(diag, ax=fig.subplots(), state=args.gear)
        what = f"lever diagram ({len(diag.levers)} lever{'s' if len(diag.levers) != 1 else ''})"
    else:
        from ..mechanism.sketch import draw_sketch, figure_size, sketch_layout

        sk = sketch_layout(mech)
        fig = Figure(figsize=figure_size(sk), facecolor="white")
        draw_sketch(mech if args.names else sk, ax=fig.subplots(), names=args.names)
        what = f"kinematic sketch ({sk.mode} section)" if sk.mode != "fixed" else "kinematic sketch (fixed axes)"
    fig.savefig(out, dpi=args.dpi, facecolor="white", bbox_inches="tight")
    print(f"{what} of {mech.name!r} written to {out}")
    return 0


COMMANDS = (
    Command("speeds", "every link's angular velocity for given input speeds", _speeds_arguments, _speeds_run),
    Command("ratio", "the speed ratio output/input of a one-dof mechanism", _ratio_arguments, _ratio_run),
    Command("dof", "degrees of freedom, by the mobility counts and by the rank of the Willis equations",
            _dof_arguments, _dof_run),
    Command("sketch", "draw the kinematic sketch (or, with --lever, the lever diagram) to an SVG, PNG or PDF file",
            _sketch_arguments, _sketch_run),
)
