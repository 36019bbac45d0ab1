"""What the commands share: a command's parts, reading FILE, link values, JSON, common options."""

from __future__ import annotations

import json
import math
import pathlib
from collections.abc import Callable
from dataclasses import dataclass

from ..errors import GearlibError, InputError

__all__ = ["Command", "load_mechanism", "parse_link_values", "print_json", "show", "add_common", "constraints",
           "add_eta", "eta_spec", "ETA_HELP"]

ETA_HELP = ("ordinary efficiency of every mesh, in (0, 1]; default: Glover's 0.98 per external (and bevel) mesh "
            "and 0.99 per internal mesh")


@dataclass(frozen=True)
class Command:
    """One command: ``python -m gearlib NAME ...``; ``arguments(parser)`` adds its options and
    ``run(args)`` returns the exit status."""

    name: str
    help: str
    arguments: Callable
    run: Callable


def load_mechanism(spec: str):
    """A mechanism from a file path, or from the catalogue by name."""
    from .. import catalog
    from ..mechanism.io import load

    path = pathlib.Path(spec)
    if path.exists() or spec.endswith((".yaml", ".yml", ".json")) or "/" in spec:
        return load(path)
    if spec in catalog.names():
        return catalog.load(spec)
    return load(path)  # raises the "no such file" error


def parse_link_values(items, *, what: str = "--input", need_value: bool = True) -> dict:
    """``["3=26", "1/4=1"]`` -> ``{"3": "26", "1/4": "1"}`` (values stay text for the library to read)."""
    out = {}
    for item in items or ():
        key, sep, value = item.partition("=")
        if not key:
            raise GearlibError(f"{what} {item!r}: expected LINK=SPEED such as 3=26")
        if not sep:
            if need_value:
                raise GearlibError(f"{what} {item!r}: expected LINK=SPEED such as {item}=1")
            value = None
        if key.strip() in out:
            raise InputError(f"{what} {key.strip()} is given twice ({out[key.strip()]} and {value.strip() if value else ''});"
                             " give each link once")
        out[key.strip()] = None if value is None else value.strip()
    return out


def print_json(data) -> None:
    """Print *data* as JSON; a number that is not finite (which JSON cannot hold: ``Infinity``
    and ``NaN`` are not JSON) becomes ``null``."""
    print(json.dumps(_finite(data), indent=2, sort_keys=False, allow_nan=False))


def _finite(data):
    if isinstance(data, float):
        return data if math.isfinite(data) else None
    if isinstance(data, dict):
        return {k: _finite(v) for k, v in data.items()}
    if isinstance(data, (list, tuple)):
        return [_finite(v) for v in data]
    return data


def show(args, result) -> int:
    """Print *result*: its ``to_json()`` with ``--json``, else its text; the exit status 0."""
    if args.json:
        print_json(result.to_json())
    else:
        print(result)
    return 0


def add_common(p, *, inputs_help="input speed LINK=SPEED (or U/V=SPEED for U relative to V); repeat"):
    p.add_argument("file", metavar="FILE", help="mechanism file (YAML/JSON) or catalogue name")
    p.add_argument("--ground", help="the fixed link (default: the file's `ground`)")
    add_constraints(p)


def add_constraints(p):
    """``--held``, ``--joined`` and ``--gear`` (a gear of the file's schedule)."""
    p.add_argument("--held", action="append", default=[], metavar="LINK", help="also hold this link (a brake)")
    p.add_argument("--joined", action="append", default=[], metavar="U,V", help="make U and V turn together (a clutch)")
    p.add_argument("--gear", metavar="NAME",
                   help="engage the brakes and clutches of this gear of the file's `schedule` (e.g. 2nd)")


def constraints(args, mech=None):
    """``{"held": [...], "joined": [(u, v), ...]}`` from ``--held``, ``--joined`` and ``--gear``."""
    held, joined = list(args.held), []
    for item in args.joined:
        u, sep, v = item.partition(",")
        if not sep or not u.strip() or not v.strip() or "," in v:
            raise InputError(f"--joined {item!r}: expected two links U,V such as 2,5")
        joined.append((u.strip(), v.strip()))
    gear = getattr(args, "gear", None)
    if gear is not None:
        if mech is None:
            raise InputError("--gear needs the mechanism file")
        c = mech.gear_constraints(gear)
        held += c["held"]
        joined += c["joined"]
    return {"held": held, "joined": joined}


def add_eta(p):
    """``--eta`` and ``--eta-pair``, with the defaults stated."""
    p.add_argument("--eta", type=float, metavar="ETA", help=ETA_HELP)
    p.add_argument("--eta-pair", action="append", default=[], metavar="A,B=ETA",
                   help="ordinary efficiency of the mesh in which gear A drives gear B (either direction unless "
                        "B,A is also given); repeat")


def eta_spec(args, mech):
    """The ``eta=`` argument of :func:`gearlib.davies.efficiency` from ``--eta`` and ``--eta-pair``
    (None: Glover's defaults)."""
    eta = args.eta
    if eta is not None and not (0 < eta <= 1):
        raise InputError(f"--eta {eta}: an ordinary efficiency must be in (0, 1]")
    pairs = {}
    for item in args.eta_pair:
        key, sep, value = item.partition("=")
        a, comma, b = key.partition(",")
        if not sep or not comma or not a.strip() or not b.strip():
            raise InputError(f"--eta-pair {item!r}: expected A,B=ETA such as 1,2=0.97 (gear A drives gear B)")
        try:
            v = float(value)
        except ValueError:
            raise InputError(f"--eta-pair {item!r}: {value!r} is not a number") from None
        if not (0 < v <= 1):
            raise InputError(f"--eta-pair {item!r}: an ordinary efficiency must be in (0, 1]")
        gp, _ = mech.gear_pair(a.strip(), b.strip())
        pairs[(mech.resolve(a.strip()), mech.resolve(b.strip()))] = v
    if not pairs:
        return eta
    from ..davies.overall import GLOVER

    spec = dict(pairs)
    for gp in mech.gear_pairs:
        a, b = gp.gears
        if (a, b) in spec or (b, a) in spec:
            continue
        spec[gp.gears] = eta if eta is not None else GLOVER[gp.kind]
    return spec
