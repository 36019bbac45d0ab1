"""Command of chapter 4 (:mod:`gearlib.adjacency`).

``python -m gearlib frequencies FILE --ground G --input L=SPEED ... [--bearings FILE]
[--reference L] [--harmonics H] [--sidebands K] [--tolerance T] [--json | --csv]
[--plot OUT.png] [--contacts]``.

The fault frequencies of a mechanism at one operating point, in Hz, rpm and orders of a
reference shaft (the first input unless ``--reference``): shafts, gear meshes with their
harmonics and sidebands, per planetary set the planet pass and the local faults of sun,
planets and ring, hunting-tooth and assembly-phase lines, and the defect lines of every
rolling bearing. A speed carries its unit: ``--input 1=1480rpm``, ``1=24.7Hz``,
``1=155rad/s``; a bare number is in ``--unit`` (default rad/s). ``--plot OUT.png`` draws
the spectrum map; ``--csv`` prints one row per line; ``--contacts`` prints Penaud and
Alazard's table instead, one row per contact (mesh, tooth, bearing). Bearings come from the
mechanism file (``bearings:`` inside a turning pair) or from ``--bearings FILE``, a YAML/JSON
list such as::

    bearings:
      - {pair: [1, 7], name: bearing 1, pitch_diameter: 54, ball_diameter: 5, balls: 25,
         contact_angle: 15*deg, inner: 7}

Bearings in the file replace those the mechanism holds in the same turning pair.
"""

from __future__ import annotations

import pathlib

from ..adjacency.frequencies import CONVENTIONS, frequency_table
from ..errors import InputError
from ..mechanism.kinematics import METHODS, speeds
from ._args import Command, add_common, constraints, load_mechanism, parse_link_values, print_json

# ----------------------------------------------------------------------------- frequencies


def _frequencies_arguments(p):
    add_common(p)
    p.add_argument("--input", action="append", default=[], metavar="LINK=SPEED",
                   help="input speed, with its unit: 1=1480rpm, 1=24.7Hz, 1=155rad/s (U/V=SPEED for U relative "
                        "to V); repeat for several")
    p.add_argument("--unit", default=None, help="unit of bare numbers among the inputs: Hz, rpm or rad/s "
                                                "(default rad/s)")
    p.add_argument("--reference", metavar="LINK", help="the shaft whose orders are given (default: the first input)")
    p.add_argument("--bearings", metavar="BEARINGS_FILE",
                   help="YAML/JSON list of bearings, each with `pair: [a, b]` and its geometry")
    p.add_argument("--convention", choices=CONVENTIONS, default="standard",
                   help="bearing lines: standard (BPFO, BPFI, FTF, BSF, 2 x BSF) or paper (Penaud and Alazard's "
                        "Table A)")
    p.add_argument("--harmonics", type=int, default=1, metavar="H", help="harmonics 1..H of each line (default 1)")
    p.add_argument("--sidebands", type=int, default=0, metavar="K",
                   help="sidebands +/- 1..K around each modulated line (default 0)")
    p.add_argument("--tolerance", type=float, default=0.0, metavar="T",
                   help="relative speed uncertainty: each line gets a band f (1 +/- T)")
    p.add_argument("--method", choices=METHODS, default="exact", help="how the speeds are solved")
    out = p.add_mutually_exclusive_group()
    out.add_argument("--json", action="store_true", help="print the table as JSON")
    out.add_argument("--csv", action="store_true", help="print one CSV row per line")
    p.add_argument("--plot", metavar="OUT.png", help="draw the spectrum map into this image (.png, .svg, .pdf)")
    p.add_argument("--contacts", action="store_true",
                   help="Penaud and Alazard's table, one row per contact, in the unit of the speeds")


def _save_map(table, path: str) -> None:
    from matplotlib.figure import Figure

    from ..adjacency._faultmap import map_size
    from ..adjacency.monitoring import plot_fault_map

    target = pathlib.Path(path)
    suffix = target.suffix.lower().lstrip(".")
    if suffix not in ("png", "svg", "pdf"):
        raise InputError(f"--plot {path}: write the map as .png, .svg or .pdf")
    if not target.parent.is_dir():
        raise InputError(f"--plot {path}: no directory {str(target.parent)!r}")
    fig = Figure(figsize=map_size(table), facecolor="white")
    plot_fault_map(table, ax=fig.add_subplot())
    try:
        fig.savefig(target, dpi=150, bbox_inches="tight", facecolor="white")
    except OSError as err:
        raise InputError(f"--plot {path}: cannot write the image ({err.strerror or err})") from None


def _frequencies_run(args) -> int:
    from ..adjacency._units import convert_inputs
    from ..adjacency.monitoring import fault_table

    mech = load_mechanism(args.file)
    if args.bearings:
        from ..adjacency.frequencies import with_bearings

        mech = with_bearings(mech, args.bearings)
    inputs = parse_link_values(args.input)
    values, unit, _ = convert_inputs(inputs or None, args.unit)
    sol = speeds(mech, args.ground, values, method=args.method, **constraints(args, mech))
    if args.contacts:
        if args.plot or args.csv:
            raise InputError("--contacts prints Penaud and Alazard's table; --plot and --csv need the fault table")
        table = frequency_table(mech, sol, convention=args.convention, unit=unit)
        print_json(table.to_json()) if args.json else print(table)
        return 0
    table = fault_table(sol, unit=unit, reference=args.reference, harmonics=args.harmonics,
                        sidebands=args.sidebands, convention=args.convention, tolerance=args.tolerance)
    if args.plot:
        _save_map(table, args.plot)
    if args.json:
        print_json(table.to_json())
    elif args.csv:
        print(table.to_csv(), end="")
    else:
        print(table)
    return 0


COMMANDS = (
    Command("frequencies", "fault frequencies (Hz, rpm, orders): shafts, meshes, planetary faults, bearings",
            _frequencies_arguments, _frequencies_run),
)
