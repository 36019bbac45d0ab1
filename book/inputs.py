"""The digest of everything a book build reads, so that ``make book`` and ``make test`` build
the book again only when one of its inputs changed.

    python book/inputs.py        # prints the digest (SHA-256, hex)

The inputs are every file under ``chapters/``, ``exercises/``, ``book/`` (its sources, the
pinned JavaScript), ``gearlib/`` (the code and data every notebook runs) and ``course/`` (the
course's HTML book is built from the same pages), with ``environment.txt``,
``pyproject.toml`` and the ``Makefile``; build outputs, caches and installed packages
(``_build``, ``__pycache__``, ``node_modules``, the staged ``vendor/_static``) are not. A
build records the digest it was made from in ``book/_build/.inputs``; the PDF and the
course's book record the digest of the build they were made from.
"""

from __future__ import annotations

import hashlib
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
FOLDERS = ("chapters", "exercises", "book", "gearlib", "course")
FILES = ("environment.txt", "pyproject.toml", "Makefile")
SKIPPED = {"_build", "__pycache__", "node_modules", ".ipynb_checkpoints", ".pytest_cache", ".hypothesis"}


def _files(root: pathlib.Path = ROOT):
    for name in FILES:
        yield root / name
    for folder in FOLDERS:
        for path in sorted((root / folder).rglob("*")):
            rel = path.relative_to(root)
            if SKIPPED & set(rel.parts) or rel.parts[:3] == ("book", "vendor", "_static"):
                continue
            if path.is_file() and path.suffix != ".pyc":
                yield path


def digest(root: pathlib.Path = ROOT) -> str:
    h = hashlib.sha256()
    for path in _files(root):
        h.update(str(path.relative_to(root)).encode() + b"\0")
        h.update(hashlib.sha256(path.read_bytes()).digest() if path.is_file() else b"missing")
    return h.hexdigest()


if __name__ == "__main__":
    sys.stdout.write(digest() + "\n")
