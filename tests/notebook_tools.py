"""Notebook housekeeping used by `make strip` and by the tests.

    python tests/notebook_tools.py strip chapters exercises book/solutions
"""

from __future__ import annotations

import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
NOTEBOOK_DIRS = ("chapters", "exercises", "book")


def notebooks(dirs=NOTEBOOK_DIRS) -> list[pathlib.Path]:
    """Every committed notebook under the given directories (build output excluded)."""
    out = []
    for d in dirs:
        for p in sorted((ROOT / d).rglob("*.ipynb")):
            if "_build" in p.parts or ".ipynb_checkpoints" in p.parts:
                continue
            out.append(p)
    return out


def cells_with_outputs(path: pathlib.Path) -> list[int]:
    nb = json.loads(path.read_text(encoding="utf-8"))
    return [
        i
        for i, c in enumerate(nb.get("cells", []))
        if c.get("cell_type") == "code" and (c.get("outputs") or c.get("execution_count") is not None)
    ]


def strip(path: pathlib.Path) -> bool:
    """Remove outputs and execution counts; return True if the file changed."""
    text = path.read_text(encoding="utf-8")
    nb = json.loads(text)
    for c in nb.get("cells", []):
        if c.get("cell_type") == "code":
            c["outputs"] = []
            c["execution_count"] = None
        c.get("metadata", {}).pop("execution", None)
    nb.get("metadata", {}).pop("widgets", None)
    new = json.dumps(nb, indent=1, ensure_ascii=False) + "\n"
    if new != text:
        path.write_text(new, encoding="utf-8")
        return True
    return False


if __name__ == "__main__":
    if len(sys.argv) < 2 or sys.argv[1] != "strip":
        sys.exit(__doc__)
    dirs = sys.argv[2:] or NOTEBOOK_DIRS
    for p in notebooks([pathlib.Path(d).resolve().relative_to(ROOT) for d in dirs]):
        if strip(p):
            print(f"stripped {p.relative_to(ROOT)}")
