"""The command line: ``python -m gearlib <command> FILE ...``, for numbers without a notebook.

Each command is a small module in this package with ``NAME``, ``HELP``,
``add_arguments(parser)`` and ``run(args) -> int``; a chapter adds its command by adding a
module. FILE is a YAML or JSON mechanism file, or the name of a catalogue entry
(``python -m gearlib catalog`` lists them). Errors in the input print one line and exit
with status 2; ``--json`` prints machine-readable output.
"""

from __future__ import annotations

import argparse
import importlib
import json
import pathlib
import pkgutil
import sys

from ..errors import GearlibError

__all__ = ["main", "load_mechanism", "parse_link_values", "print_json", "build_parser"]


def load_mechanism(spec: str):
    """A mechanism from a file path, or from the catalogue by name."""
    from .. import catalog
    from ..io import load

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


def _commands() -> dict:
    mods = {}
    for info in sorted(pkgutil.iter_modules(__path__), key=lambda i: i.name):
        if info.name.startswith("_"):
            continue
        mod = importlib.import_module(f"{__name__}.{info.name}")
        mods[mod.NAME] = mod
    return mods


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        self.print_usage(sys.stderr)
        self.exit(2, f"{self.prog}: error: {message}\n")


def build_parser():
    parser = _Parser(prog="python -m gearlib", description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    commands = _commands()
    for name, mod in commands.items():
        p = sub.add_parser(name, help=mod.HELP, description=mod.HELP)
        mod.add_arguments(p)
        p.set_defaults(_run=mod.run)
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args._run(args) or 0)
    except GearlibError as err:
        print(f"gearlib {args.command}: error: {err}", file=sys.stderr)
        return 2
    except (OSError, RecursionError) as err:
        print(f"gearlib {args.command}: error: {err}", file=sys.stderr)
        return 2
