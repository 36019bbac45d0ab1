"""``python -m gearlib``: the command line (see :mod:`gearlib.cli`)."""

from .cli import main

if __name__ == "__main__":
    raise SystemExit(main())
