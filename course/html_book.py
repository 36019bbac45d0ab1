"""The course's HTML book: the book without its solution pages, beside the full book.

It is built by the same Jupyter Book configuration from a staged copy of the book's sources
(``--out/book-src``) in which every notebook is the one the last book build executed
(``book/_build/jupyter_execute``) and execution is off: no notebook runs twice, and the
pages show the same outputs as the full book. The table of contents is the book's less every
entry under ``book/solutions/``, so it keeps working as chapters and pages are added.
"""

from __future__ import annotations

import json
import os
import pathlib
import re
import shutil
import subprocess
import sys

import yaml

from .exercises import ROOT, CourseError

SOLUTIONS = "book/solutions"


def course_toc(toc: dict) -> dict:
    """*toc* (a Jupyter Book table of contents) without the solution pages."""

    def keep(entry) -> bool:
        return not (isinstance(entry, dict) and str(entry.get("file", "")).startswith(SOLUTIONS))

    def walk(node):
        if isinstance(node, dict):
            return {k: walk(v) for k, v in node.items()}
        if isinstance(node, list):
            return [walk(x) for x in node if keep(x)]
        return node

    return walk(toc)


def _files(toc: dict) -> list[str]:
    out = [toc["root"]]

    def walk(node):
        if isinstance(node, dict):
            if "file" in node:
                out.append(node["file"])
            for v in node.values():
                walk(v)
        elif isinstance(node, list):
            for v in node:
                walk(v)

    walk(toc)
    return out


def _restage(run: pathlib.Path, dest: pathlib.Path, drop_solution_notes: bool) -> None:
    """The executed notebook *run* as a page to build without executing: the values it glued,
    which myst-nb took out of its outputs into ``<name>.glue.json``, put back as the outputs
    they were (hidden ones, under their MIME prefix); on an exercise page, no pointer to the
    worked solutions, which the course book does not have."""
    nb = json.loads(run.read_text(encoding="utf-8"))
    glue = run.with_suffix(".glue.json")
    records = json.loads(glue.read_text(encoding="utf-8")) if glue.is_file() else {}
    hidden = []
    for output in records.values():
        prefix = output.get("metadata", {}).get("scrapbook", {}).get("mime_prefix", "")
        if prefix:  # a glue without display; a displayed one is still among the cell's outputs
            hidden.append({**output, "data": {prefix + k: v for k, v in output["data"].items()}})
    code = [c for c in nb["cells"] if c["cell_type"] == "code"]
    if hidden and not code:
        raise CourseError(f"{run.name}: glued values but no code cell to hold them")
    if hidden:
        code[0].setdefault("outputs", []).extend(hidden)
    for cell in nb["cells"]:
        if drop_solution_notes and cell["cell_type"] == "markdown":
            text = "".join(cell["source"]) if isinstance(cell["source"], list) else cell["source"]
            paragraphs = [p for p in text.split("\n\n") if not re.search(r"(?i)worked solutions", p)]
            cell["source"] = "\n\n".join(paragraphs)
    dest.write_text(json.dumps(nb, ensure_ascii=False), encoding="utf-8")


def stage(out: pathlib.Path) -> pathlib.Path:
    executed = ROOT / "book" / "_build" / "jupyter_execute"
    toc = course_toc(yaml.safe_load((ROOT / "book" / "_toc.yml").read_text(encoding="utf-8")))
    src = out / "book-src"
    shutil.rmtree(src, ignore_errors=True)
    (src / "book").mkdir(parents=True)
    for item in (ROOT / "book").iterdir():
        if item.name in ("_build", "solutions", "vendor", "_toc.yml", "_config.yml") or item.suffix == ".ipynb":
            continue
        (shutil.copytree if item.is_dir() else shutil.copy)(item, src / "book" / item.name)
    if not (ROOT / "book" / "vendor" / "_static").is_dir():
        raise CourseError("the book's JavaScript is not staged (book/vendor/_static): run make book first")
    shutil.copytree(ROOT / "book" / "vendor" / "_static", src / "book" / "vendor" / "_static")
    missing = []
    for page in _files(toc):
        source = ROOT / page
        if source.with_suffix(".md").is_file():
            dest = src / f"{page}.md"
            if not dest.exists():
                dest.parent.mkdir(parents=True, exist_ok=True)
                shutil.copy(source.with_suffix(".md"), dest)
        elif source.with_suffix(".ipynb").is_file():
            run = executed / f"{page}.ipynb"
            if not run.is_file() or run.stat().st_mtime < source.with_suffix(".ipynb").stat().st_mtime:
                missing.append(page)
                continue
            dest = src / f"{page}.ipynb"
            dest.parent.mkdir(parents=True, exist_ok=True)
            _restage(run, dest, drop_solution_notes=page.startswith("exercises/"))
    if missing:
        raise CourseError(f"the last book build did not execute {', '.join(missing)} (or they changed since): "
                          "run make book first")
    config = yaml.safe_load((ROOT / "book" / "_config.yml").read_text(encoding="utf-8"))
    config["execute"]["execute_notebooks"] = "off"
    config["title"] = f"{config['title']} (course edition)"
    (src / "book" / "_config.yml").write_text(yaml.safe_dump(config, sort_keys=False, allow_unicode=True),
                                              encoding="utf-8")
    (src / "book" / "_toc.yml").write_text(yaml.safe_dump(toc, sort_keys=False, allow_unicode=True), encoding="utf-8")
    return src


def build_html(out: pathlib.Path) -> pathlib.Path:
    src = stage(out)
    cmd = [sys.executable, str(ROOT / "book" / "build.py"), str(src), "--config", str(src / "book" / "_config.yml"),
           "--toc", str(src / "book" / "_toc.yml"), "--path-output", str(src), "-W", "-n", "--keep-going"]
    done = subprocess.run(cmd, cwd=src, capture_output=True, text=True, env={**os.environ, "PYTHONWARNINGS": ""})
    html = src / "_build" / "html"
    if done.returncode != 0 or not (html / "index.html").is_file():
        log = done.stdout + done.stderr
        warnings = [line for line in log.splitlines() if "WARNING" in line or "ERROR" in line]
        raise CourseError("the course book did not build:\n" + "\n".join(warnings[:20] or [log[-3000:]]))
    target = out / "html"
    shutil.rmtree(target, ignore_errors=True)
    shutil.move(str(html), str(target))
    return target
