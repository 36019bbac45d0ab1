"""Notebook housekeeping used by `make strip`, `make nbval-repeat` and by the tests.

    python tests/notebook_tools.py strip chapters exercises book/solutions
    python tests/notebook_tools.py repeat 3 chapters exercises book/solutions

``repeat N`` executes every notebook N times, each in a fresh kernel (two at a time), and
compares what nbval would compare: text, LaTeX and SVG outputs after the sanitize rules of
``tests/nbval_sanitize.cfg``, except in cells tagged ``nbval-ignore-output`` (timings). It
prints each cell whose output changed between runs and exits 1 if any did.
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
        if (ROOT / d).is_file():
            out.append(ROOT / d)
            continue
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


COMPARED = ("text/plain", "text/latex", "text/markdown", "image/svg+xml")


def sanitize_rules(path: pathlib.Path = ROOT / "tests" / "nbval_sanitize.cfg") -> list:
    """``[(compiled regex, replacement)]`` from an nbval sanitize file."""
    import re

    rules, regex = [], None
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("regex:"):
            regex = line.split(":", 1)[1].strip()
        elif line.startswith("replace:") and regex is not None:
            rules.append((re.compile(regex), line.split(":", 1)[1].strip()))
            regex = None
    return rules


def compared_outputs(path: pathlib.Path) -> list:
    """Execute *path* in a fresh kernel; per code cell, the sanitized outputs nbval compares
    (None for cells tagged ``nbval-ignore-output``)."""
    import nbformat
    from nbclient import NotebookClient

    nb = nbformat.read(path, as_version=4)
    NotebookClient(nb, timeout=600, kernel_name="python3",
                   resources={"metadata": {"path": str(path.parent)}}).execute()
    rules = sanitize_rules()
    out = []
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        if "nbval-ignore-output" in cell.get("metadata", {}).get("tags", []):
            out.append(None)
            continue
        parts = []
        for o in _coalesce_streams(cell.outputs):
            texts = [o.get("text", "")] if o.output_type == "stream" else [
                f"{k}: {o.data[k]}" for k in COMPARED if k in o.get("data", {})]
            if o.output_type == "error":
                texts = [f"{o.ename}: {o.evalue}"]
            for text in texts:
                for regex, replacement in rules:
                    text = regex.sub(replacement, text)
                parts.append(text)
        out.append(parts)
    return out


def _coalesce_streams(outputs) -> list:
    """Join consecutive stream outputs of the same stream, as nbval does: how printed text
    is split into messages depends on timing, not on the notebook."""
    out = []
    for o in outputs:
        if o.output_type == "stream" and out and out[-1].output_type == "stream" and out[-1].name == o.name:
            out[-1] = {**out[-1], "text": out[-1]["text"] + o.text}
            out[-1] = type(o)(out[-1])
        else:
            out.append(o)
    return out


def repeat(runs: int, dirs) -> int:
    """Run every notebook *runs* times; report cells whose outputs differ. Returns 0 or 1."""
    from concurrent.futures import ProcessPoolExecutor

    paths = notebooks(dirs)
    jobs = [(p, k) for k in range(runs) for p in paths]
    with ProcessPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(compared_outputs, [p for p, _ in jobs]))
    by_path: dict = {}
    for (p, _), r in zip(jobs, results):
        by_path.setdefault(p, []).append(r)
    changed = 0
    for p, runs_of_p in by_path.items():
        first = runs_of_p[0]
        for i, cell in enumerate(first):
            other = next((r[i] for r in runs_of_p[1:] if r[i] != cell), None)
            if other is not None:
                import difflib

                changed += 1
                print(f"{p.relative_to(ROOT)}: code cell {i + 1} printed different output between runs")
                diff = difflib.unified_diff("\n".join(cell).splitlines(), "\n".join(other).splitlines(), lineterm="",
                                            n=0)
                print("    " + "\n    ".join(list(diff)[2:8]))
    print(f"{len(paths)} notebooks x {runs} runs: {changed} cell(s) with output that changed")
    return 1 if changed else 0


if __name__ == "__main__":
    command = sys.argv[1] if len(sys.argv) > 1 else ""
    if command == "strip":
        dirs = sys.argv[2:] or NOTEBOOK_DIRS
        for p in notebooks([pathlib.Path(d).resolve().relative_to(ROOT) for d in dirs]):
            if strip(p):
                print(f"stripped {p.relative_to(ROOT)}")
    elif command == "repeat" and len(sys.argv) > 2:
        dirs = sys.argv[3:] or NOTEBOOK_DIRS
        sys.exit(repeat(int(sys.argv[2]), [pathlib.Path(d).resolve().relative_to(ROOT) for d in dirs]))
    else:
        sys.exit(__doc__)
