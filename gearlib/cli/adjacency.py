"""Command of chapter 4 (:mod:`gearlib.adjacency`).

``python -m gearlib frequencies FILE --ground G --input L=V ... [--bearings FILE] [--json]``.

Every contact frequency of a mechanism at one operating point: the mesh and tooth-defect
lines of each gear pair (relative to its carrier) and the defect lines of each rolling
bearing. Bearings come from the mechanism file (``bearings:`` inside a turning pair) or
from ``--bearings FILE``, a YAML/JSON list such as::

    bearings:
      - {pair: [1, 7], name: bearing 1, pitch_diameter: 54, ball_diameter: 5, balls: 25,
         contact_angle: 15*deg, inner: 7}

Bearings in the file replace those the mechanism holds in the same turning pair. The
frequencies are in the unit of the input speeds (``--unit`` only labels them).
"""

from __future__ import annotations

from ..adjacency.frequencies import CONVENTIONS, frequency_table
from ..mechanism.kinematics import METHODS, speeds
from ._args import Command, add_common, constraints, load_mechanism, parse_link_values, show

# ----------------------------------------------------------------------------- frequencies


def _frequencies_arguments(p):
    add_common(p)
    p.add_argument("--input", action="append", default=[], metavar="LINK=SPEED",
                   help="input speed LINK=SPEED (or U/V=SPEED for U relative to V); repeat for several")
    p.add_argument("--bearings", metavar="BEARINGS_FILE",
                   help="YAML/JSON list of bearings, each with `pair: [a, b]` and its geometry")
    p.add_argument("--convention", choices=CONVENTIONS, default="standard",
                   help="bearing formulas: standard (SKF/Harris) or paper (Penaud and Alazard's Table A)")
    p.add_argument("--unit", default="rad/s", help="unit of the input speeds, for the labels (default rad/s)")
    p.add_argument("--method", choices=METHODS, default="exact", help="how the speeds are solved")
    p.add_argument("--json", action="store_true",
                   help="print {unit, convention, speeds: {link: [re, im]}, rows: [{pair, kind, frequency, ...}]}")


def _frequencies_run(args) -> int:
    mech = load_mechanism(args.file)
    if args.bearings:
        from ..adjacency.frequencies import with_bearings

        mech = with_bearings(mech, args.bearings)
    sol = speeds(mech, args.ground, parse_link_values(args.input), method=args.method, **constraints(args, mech))
    table = frequency_table(mech, sol, convention=args.convention, unit=args.unit)
    return show(args, table)


COMMANDS = (
    Command("frequencies", "mesh, tooth-defect and bearing-defect frequencies for given input speeds",
            _frequencies_arguments, _frequencies_run),
)
