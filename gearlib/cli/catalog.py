"""The catalogue command: ``catalog [NAME]`` lists the catalogue, or prints one entry as YAML.
"""

from __future__ import annotations

from .. import catalog
from ._args import Command

# ----------------------------------------------------------------------------- catalog


def _catalog_arguments(p):
    p.add_argument("name", nargs="?", help="an entry to print")


def _catalog_run(args) -> int:
    if args.name:
        print(catalog.path(args.name).read_text(encoding="utf-8"), end="")
        return 0
    for name in catalog.names():
        m = catalog.load(name)
        print(f"{name:28s} {m.name}")
    return 0


COMMANDS = (
    Command("catalog", "list the catalogue of mechanisms, or print one entry's file",
            _catalog_arguments, _catalog_run),
)
