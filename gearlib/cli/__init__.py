"""The command line: ``python -m gearlib <command> FILE ...``, for numbers without a notebook.

The commands live beside the methods they run, one module per subpackage of gearlib
(:mod:`.mechanism`: ``speeds``, ``ratio``, ``dof``; :mod:`.units`; :mod:`.gains`;
:mod:`.adjacency`: ``frequencies``; :mod:`.davies`: ``efficiency``; :mod:`.synthesis`: ``dgm``
and ``atlas``; :mod:`.linkages`: ``linkage``; and :mod:`.catalog`), each listing its
``COMMANDS``; a chapter adds a command to its module's list. FILE is a YAML or JSON mechanism
file, or the name of a catalogue entry (``python -m gearlib catalog`` lists them; the
``linkage`` command reads linkage files and :func:`gearlib.linkages.names`). Errors in the input print one line and exit
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
    from . import adjacency, catalog, davies, gains, linkages, mechanism, synthesis, units

    found = {}
    for mod in (catalog, mechanism, units, gains, adjacency, davies, synthesis, linkages):
        for command in mod.COMMANDS:
            found[command.name] = command
    return dict(sorted(found.items()))


class _Parser(argparse.ArgumentParser):
    last_error = None  # the message of the last usage error, for --json

    def error(self, message):
        _Parser.last_error = f"{self.prog}: error: {message}"
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


def _fail(message: str, as_json: bool) -> int:
    """One line on stderr, and with ``--json`` a JSON object on stdout too; status 2."""
    print(message, file=sys.stderr)
    if as_json:
        print_json({"error": message})
    return 2


def _quiet_broken_pipe() -> int:
    """The reader went away (``| head``): stop quietly, without a traceback at exit."""
    import os

    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):  # stdout without a file descriptor (captured in a test)
        pass
    return 0


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    as_json = "--json" in argv
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exit_:
        if as_json and exit_.code not in (0, None):
            print_json({"error": _Parser.last_error or "invalid arguments"})
        raise

    def warn(message, category, filename, lineno, file=None, line=None):
        print(f"gearlib {args.command}: warning: {message}", file=sys.stderr)

    with warnings.catch_warnings():  # a gearlib warning (a set that cannot be assembled) is one line
        warnings.simplefilter("always", GearlibWarning)
        warnings.showwarning = warn
        return _run(args, as_json)


def _run(args, as_json: bool) -> int:
    try:
        status = int(args._run(args) or 0)
        sys.stdout.flush()
        return status
    except BrokenPipeError:
        return _quiet_broken_pipe()
    except GearlibError as err:
        return _fail(f"gearlib {args.command}: error: {err}", as_json)
    except (OSError, RecursionError) as err:
        return _fail(f"gearlib {args.command}: error: {err}", as_json)
