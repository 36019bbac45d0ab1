"""Make .venv hold exactly what environment.txt pins (run by the Makefile after pip install).

``pip install -r`` adds and changes packages but never removes one that a new pin no longer
pulls in (for example rfc3987-syntax after jsonschema was held below 4.25), so a warm .venv
would drift from a fresh one. This removes every installed distribution that
environment.txt does not name, except pip's own tools and the editable gearlib.
"""

import importlib.metadata as md
import pathlib
import re
import subprocess
import sys

KEEP = {"pip", "setuptools", "wheel", "gearlib"}


def norm(name: str) -> str:
    return re.sub(r"[-_.]+", "-", name).lower()


def main() -> int:
    req = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "environment.txt")
    pins = {norm(line.split("==")[0]) for line in req.read_text().splitlines()
            if "==" in line and not line.lstrip().startswith("#")}
    extra = sorted({norm(d.metadata["Name"]) for d in md.distributions()} - pins - KEEP)
    if extra:
        print(f"removing packages environment.txt no longer pins: {', '.join(extra)}")
        subprocess.check_call([sys.executable, "-m", "pip", "uninstall", "-y", "-q", *extra])
    return 0


if __name__ == "__main__":
    sys.exit(main())
