"""What the commands share: a command's parts, reading FILE, link values, JSON, common options."""

from __future__ import annotations

import json
import pathlib
from collections.abc import Callable
from dataclasses import dataclass

from ..errors import GearlibError, InputError

__all__ = ["Command", "load_mechanism", "parse_link_values", "print_json", "show", "add_common", "constraints"]


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
        out[key.strip()] = None if value is None else value.strip()
    return out


def print_json(data) -> None:
    print(json.dumps(data, indent=2, sort_keys=False))


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
    p.add_argument("--held", action="append", default=[], metavar="LINK", help="also hold this link (a brake)")
    p.add_argument("--joined", action="append", default=[], metavar="U,V", help="make U and V turn together (a clutch)")


def constraints(args):
    joined = []
    for item in args.joined:
        u, sep, v = item.partition(",")
        if not sep:
            raise InputError(f"--joined {item!r}: expected two links U,V")
        joined.append((u.strip(), v.strip()))
    return {"held": args.held, "joined": joined}
