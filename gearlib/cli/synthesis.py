"""Commands of chapter 6 (:mod:`gearlib.synthesis`).

* ``dgm FILE [--terminals N] [--all] [--json]``: admissible DGMs of a chain. Runs the
  identification procedure of Chen, Yao and Lee on the chain in FILE (every ground adjacent
  to N links, every N of its adjacent links as terminals) and prints each admissible
  (ground, terminals) with its constraint equation; ``--all`` prints every assignment with
  its redundant links, as CYL's Table 1.
* ``atlas [--links N [N ...]] [--dof F] [--workers W] [--save FILE] [--json]``: counts the geared
  kinematic chains with N links (up to nine) at both levels, displacement graphs and
  rotation graphs, beside the published counts; ``--save`` writes the counts with their
  provenance in the form :func:`gearlib.synthesis.stored_counts` reads (``make bench`` so
  makes the book's nine-link counts).
"""

from __future__ import annotations

from ..errors import GearlibError
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


# ----------------------------------------------------------------------------- atlas

_LEVEL_NAMES = {"coaxial": "displacement graphs", "kinematic": "rotation graphs"}
_FRACTIONATED = {"exclude": False, "include": True, "only": "only"}


def _atlas_arguments(p):
    p.add_argument("--links", type=int, nargs="+", default=[8], metavar="N",
                   help="number of links, 2 to 9 (default 8); several numbers count each in turn")
    p.add_argument("--dof", type=int, default=1, metavar="F", help="degrees of freedom (default 1)")
    p.add_argument("--fractionated", choices=tuple(_FRACTIONATED), default="exclude",
                   help="leave out fractionated chains (default, as the atlases do), include them, or count only them")
    p.add_argument("--workers", type=int, default=1, metavar="W", help="processes to share the work (default 1)")
    p.add_argument("--save", metavar="FILE", help="write the counts with their provenance (command, date, "
                                                  "machine, time, memory) as JSON to FILE")
    p.add_argument("--json", action="store_true", help="print JSON")


def _commit() -> str:
    """gearlib's git commit, ``-dirty`` when its files differ from it; ``""`` outside a checkout."""
    import pathlib
    import subprocess

    root = pathlib.Path(__file__).resolve().parents[2]
    try:
        head = subprocess.run(["git", "-C", str(root), "rev-parse", "HEAD"], capture_output=True, text=True,
                              timeout=10, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", str(root), "status", "--porcelain", "--", "gearlib"],
                               capture_output=True, text=True, timeout=10, check=True).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return ""
    return head + ("-dirty" if dirty else "")


def _levels(counts, found) -> list[dict]:
    published = [p for p in counts.PUBLISHED_COUNTS
                 if (p.links, p.dof) == (found.links, found.dof) and found.fractionated is False]
    return [{"level": level, "graphs": _LEVEL_NAMES[level], "enumerated": found.count(level),
             "published": [{"count": p.count, "source": p.source, "note": p.note,
                            "agrees": None if p.count is None else p.count == found.count(level)}
                           for p in published if p.level == level]} for level in ("coaxial", "kinematic")]


def _atlas_run(args) -> int:
    import json
    import pathlib
    import shlex

    from ..synthesis import counts

    checks = [("--links", n, 2, counts.MAX_COUNT_LINKS) for n in args.links]
    for option, value, low, high in checks + [("--dof", args.dof, 1, None), ("--workers", args.workers, 1, 64)]:
        if value < low or (high is not None and value > high):
            span = f"from {low} to {high}" if high is not None else f"at least {low}"
            raise GearlibError(f"{option} must be {span}, got {value}")
    frac = _FRACTIONATED[args.fractionated]
    found = [counts.chain_counts(n, args.dof, fractionated=frac, workers=args.workers) for n in args.links]
    if args.save:
        command = f"python -m gearlib atlas --links {' '.join(map(str, args.links))} --dof {args.dof}"
        command += f" --fractionated {args.fractionated}" if args.fractionated != "exclude" else ""
        command += f" --workers {args.workers}" if args.workers != 1 else ""
        data = counts.record(found, command=f"{command} --save {shlex.quote(args.save)}", commit=_commit())
        pathlib.Path(args.save).write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    if args.json:
        print_json({"atlas": [{"links": c.links, "dof": c.dof, "fractionated": c.fractionated,
                               "seconds": round(c.seconds, 3), "cpu_seconds": round(c.cpu_seconds, 3),
                               "levels": _levels(counts, c)} for c in found]})
        return 0
    which = {False: "non-fractionated", True: "fractionated or not", "only": "fractionated"}[frac]
    for c in found:
        print(f"geared kinematic chains with {c.links} links and {c.dof} degree(s) of freedom, {which}; "
              f"enumerated in {c.seconds:.1f} s ({c.cpu_seconds:.1f} s of processor time)")
        for row in _levels(counts, c):
            line = f"  {row['level']:9s}  {row['graphs']:19s}  {row['enumerated']:7d}"
            for p in row["published"]:
                if p["count"] is not None:
                    verdict = "agrees" if p["agrees"] else f"differs by {row['enumerated'] - p['count']:+d}"
                    line += f"   published {p['count']} ({p['source']}): {verdict}"
            print(line)
    if args.save:
        print(f"saved to {args.save}")
    return 0


COMMANDS = (
    Command("atlas", "count the geared kinematic chains with N links (up to 9) at both levels, beside the "
            "published counts", _atlas_arguments, _atlas_run),
    Command("dgm", "admissible differential geared mechanisms of a chain (ground, terminals, constraint)",
            _dgm_arguments, _dgm_run),
)
