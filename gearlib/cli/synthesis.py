"""Command of chapter 6 (:mod:`gearlib.synthesis`).

``python -m gearlib dgm FILE [--terminals N] [--all] [--json]``: admissible DGMs of a chain.

Runs the identification procedure of Chen, Yao and Lee on the chain in FILE (every ground
adjacent to N links, every N of its adjacent links as terminals) and prints each admissible
(ground, terminals) with its constraint equation; ``--all`` prints every assignment with its
redundant links, as CYL's Table 1.
"""

from __future__ import annotations

from ._args import Command, load_mechanism, print_json

# ----------------------------------------------------------------------------- dgm


def _dgm_arguments(p):
    p.add_argument("file", metavar="FILE", help="geared kinematic chain (YAML/JSON) or catalogue name")
    p.add_argument("--terminals", type=int, default=None, metavar="N",
                   help="number of terminals (default: the chain's dof + 1)")
    p.add_argument("--ground", action="append", default=None, metavar="LINK",
                   help="try only this ground (repeat for several)")
    p.add_argument("--all", action="store_true", help="every (ground, terminals), not only the admissible ones")
    p.add_argument("--json", action="store_true", help="print JSON")


def _row(ident, c) -> dict:
    return {
        "ground": c.ground,
        "terminals": list(c.terminals),
        "constraints": c.count,
        "equation": None if c.equation is None else f"{c.equation} = 0",
        "coefficients": None if c.coefficients is None else [str(a) for a in c.coefficients],
        "redundant": list(c.redundant),
        "n3_failures": list(c.n3_failures),
        "result": ident.result(c),
    }


def _dgm_run(args) -> int:
    from ..synthesis.dgm import identify

    mech = load_mechanism(args.file)
    ident = identify(mech, args.terminals, grounds=args.ground)
    chosen = ident.candidates if args.all else ident.admissible
    if args.json:
        print_json({
            "chain": mech.name,
            "terminals": ident.n_terminals,
            "grounds": list(ident.grounds),
            "assignments": [_row(ident, c) for c in chosen],
        })
        return 0
    print(f"{mech.name}: {ident.n_terminals} terminals; grounds adjacent to at least "
          f"{ident.n_terminals} links: {', '.join(map(str, ident.grounds)) or 'none'}")
    for c in chosen:
        terms = ", ".join(map(str, c.terminals))
        eq = f"{c.equation} = 0" if c.equation is not None else f"{c.count} constraints"
        print(f"ground {c.ground}, terminals {terms}: {eq}")
        if args.all:
            redundant = ", ".join(map(str, c.redundant)) or "none"
            print(f"    redundant links: {redundant}; {ident.result(c)}")
    if not chosen:
        print("no admissible assignment" if not args.all else "no assignment")
    return 0


COMMANDS = (
    Command("dgm", "admissible differential geared mechanisms of a chain (ground, terminals, constraint)",
            _dgm_arguments, _dgm_run),
)
