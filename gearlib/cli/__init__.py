"""The command line: ``python -m gearlib <command> FILE ...``, for numbers without a notebook.

The commands live beside the methods they run, one module per subpackage of gearlib
(:mod:`.mechanism`: ``speeds``, ``ratio``, ``dof``; :mod:`.units`; :mod:`.gains`;
:mod:`.adjacency`: ``frequencies``; :mod:`.davies`: ``efficiency``; :mod:`.synthesis`: ``dgm``
and ``atlas``; :mod:`.linkages`: ``linkage``; and :mod:`.catalog`), each listing its
``COMMANDS``; a chapter adds a command to its module's list. FILE is a YAML or JSON mechanism
file, or the name of a catalogue entry (``python -m gearlib catalog`` lists them; the
``linkage`` command reads linkage files and :func:`gearlib.linkages.names`). Errors in the input print one line and exit
with status 2; warnings (a planetary set that cannot be assembled) print one line each and
the command goes on; ``--json`` prints machine-readable output, valid JSON on every path
(errors included, as ``{"error": ...}``). On a terminal or file whose encoding cannot show
``∠`` or Greek letters they are written in ASCII (``/_``, ``omega``); a reader that goes away
(``| head``) ends the command quietly.
"""

from __future__ import annotations

import argparse
import codecs
import os
import sys
import unicodedata
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


_ASCII = {"\u2220": "/_", "\u2212": "-", "\u2013": "-", "\u2014": "--", "\u2192": "->", "\u2190": "<-",
          "\u00d7": "x", "\u00b7": "*", "\u00b0": " deg", "\u2264": "<=", "\u2265": ">=", "\u2248": "~",
          "\u2026": "...", "\u2032": "'", "\u00b1": "+/-", "\u221e": "inf", "\u2260": "!=", "\u00b2": "^2",
          "\u00b3": "^3", "\u2009": " ", "\u00a0": " ", "\u202f": " "}


def _ascii(char: str) -> str:
    if char in _ASCII:
        return _ASCII[char]
    name = unicodedata.name(char, "")
    if name.startswith("GREEK"):  # GREEK SMALL LETTER OMEGA -> omega, CAPITAL -> Omega
        word = name.split()[-1].lower()
        return word.capitalize() if "CAPITAL" in name else word
    decomposed = unicodedata.normalize("NFKD", char).encode("ascii", "ignore").decode()
    return decomposed or "?"


def _fallback(err):
    """Codec error handler: a character the output's encoding lacks, written in ASCII."""
    return "".join(_ascii(c) for c in err.object[err.start:err.end]), err.end


codecs.register_error("gearlib-ascii", _fallback)


def _readable_streams() -> None:
    """Streams whose encoding lacks ``∠`` or Greek letters write them in ASCII (only those:
    a UTF-8 terminal is left as it is)."""
    for stream in (sys.stdout, sys.stderr):
        try:
            "\u2220\u03c9\u03b7\u2212".encode(getattr(stream, "encoding", None) or "utf-8")
            continue
        except (UnicodeEncodeError, LookupError):
            pass
        try:
            stream.reconfigure(errors="gearlib-ascii")
        except (AttributeError, ValueError, OSError):  # a stream without reconfigure (a test's capture)
            pass


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    as_json = "--json" in argv
    _readable_streams()
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
    except (OSError, RecursionError, MemoryError) as err:
        return _fail(f"gearlib {args.command}: error: {' '.join(str(err).split()) or type(err).__name__}", as_json)
    except KeyboardInterrupt:
        _fail(f"gearlib {args.command}: interrupted", as_json)
        return 130
    except Exception as err:  # a bug: still one line (and valid JSON); GEARLIB_TRACEBACK=1 shows where
        if os.environ.get("GEARLIB_TRACEBACK"):
            raise
        text = " ".join(str(err).split())[:300]
        _fail(f"gearlib {args.command}: internal error ({type(err).__name__}: {text}); this is a bug in gearlib, "
              "please report it (GEARLIB_TRACEBACK=1 shows where)", as_json)
        return 1
