"""``python -m gearlib catalog [NAME]``: list the catalogue, or print one entry as YAML."""

from __future__ import annotations

from .. import catalog

NAME = "catalog"
HELP = "list the catalogue of mechanisms, or print one entry's file"


def add_arguments(p):
    p.add_argument("name", nargs="?", help="an entry to print")


def run(args) -> int:
    if args.name:
        print(catalog.path(args.name).read_text(encoding="utf-8"), end="")
        return 0
    for name in catalog.names():
        m = catalog.load(name)
        print(f"{name:28s} {m.name}")
    return 0
