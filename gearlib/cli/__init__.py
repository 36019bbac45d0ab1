"""The command line: ``python -m gearlib <command> FILE ...``, for numbers without a notebook.

The commands live beside the methods they run, one module per subpackage of gearlib
(:mod:`.mechanism`: ``speeds``, ``ratio``, ``dof``; :mod:`.units`; :mod:`.gains`;
:mod:`.adjacency`: ``frequencies``; :mod:`.davies`: ``efficiency``; :mod:`.synthesis`: ``dgm``;
and :mod:`.catalog`), each listing its ``COMMANDS``; a chapter adds a command to its
module's list. FILE is a YAML or JSON mechanism file, or the name of a catalogue entry
(``python -m gearlib catalog`` lists them). Errors in the input print one line and exit
with status 2; warnings (a planetary set that cannot be assembled) print one line each and
the command goes on; ``--json`` prints machine-readable output.
"""

from __future__ import annotations

import argparse
import sys
import warnings

from ..errors import GearlibError, GearlibWarning
from ._args import load_mechanism, parse_link_values, print_json

__all__ = ["main", "load_mechanism", "parse_link_values", "print_json", "build_parser"]


def _commands() -> dict:
    from . import adjacency, catalog, davies, gains, mechanism, synthesis, units

    found = {}
    for mod in (catalog, mechanism, units, gains, adjacency, davies, synthesis):
        for command in mod.COMMANDS:
            found[command.name] = command
    return dict(sorted(found.items()))


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        self.print_usage(sys.stderr)
        self.exit(2, f"{self.prog}: error: {message}\n")


def build_parser():
    parser = _Parser(prog="python -m gearlib", description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    commands = _commands()
    for name, command in commands.items():
        p = sub.add_parser(name, help=command.help, description=command.help)
        command.arguments(p)
        p.set_defaults(_run=command.run)
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)

    def warn(message, category, filename, lineno, file=None, line=None):
        print(f"gearlib {args.command}: warning: {message}", file=sys.stderr)

    with warnings.catch_warnings():  # a gearlib warning (a set that cannot be assembled) is one line
        warnings.simplefilter("always", GearlibWarning)
        warnings.showwarning = warn
        return _run(args)


def _run(args) -> int:
    try:
        return int(args._run(args) or 0)
    except GearlibError as err:
        print(f"gearlib {args.command}: error: {err}", file=sys.stderr)
        return 2
    except (OSError, RecursionError) as err:
        print(f"gearlib {args.command}: error: {err}", file=sys.stderr)
        return 2
