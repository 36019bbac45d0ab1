"""The whole-book PDF (``make pdf``: book/_build/latex/book.pdf), read with poppler-utils'
pdfinfo, pdftotext and pdfimages: every part and chapter is in it, every figure and widget
snapshot, every solution, no output that only HTML could show, and xelatex's log has no
missing glyph and no unresolved reference.
"""

from __future__ import annotations

import json
import os
import pathlib
import re
import shutil
import subprocess

import pytest
import yaml

from notebook_tools import ROOT

LATEX = pathlib.Path(os.environ.get("BOOK_LATEX", ROOT / "book" / "_build" / "latex")).resolve()
PDF = LATEX / "book.pdf"
EXECUTED = ROOT / "book" / "_build" / "jupyter_execute"

pytestmark = [
    pytest.mark.pdf,
    pytest.mark.skipif(not shutil.which("pdftotext"), reason="needs poppler-utils (pdfinfo, pdftotext)"),
]


def _run(*cmd: str) -> str:
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


def _plain(text: str) -> str:
    """Compare text as words: one space, straight quotes, no ligatures or hyphenation."""
    text = text.replace("\u2019", "'").replace("\u2018", "'").replace("\u201c", '"').replace("\u201d", '"')
    text = text.replace("\ufb01", "fi").replace("\ufb02", "fl").replace("\ufb00", "ff")
    text = re.sub(r"-\s*\n\s*", "-", text)
    return " ".join(text.split()).lower()


@pytest.fixture(scope="module")
def pdf_text() -> str:
    assert PDF.is_file(), f"no {PDF.relative_to(ROOT)}: run make pdf"
    return _plain(_run("pdftotext", "-enc", "UTF-8", str(PDF), "-"))


def _toc():
    return yaml.safe_load((ROOT / "book" / "_toc.yml").read_text(encoding="utf-8"))


def _files(entries):
    for entry in entries:
        yield entry["file"]
        yield from _files(entry.get("sections", []))


def _title(docname: str) -> str:
    """The first level-1 heading of a page (notebook or Markdown)."""
    nb = ROOT / f"{docname}.ipynb"
    if nb.is_file():
        text = "\n".join("".join(c["source"]) for c in json.loads(nb.read_text(encoding="utf-8"))["cells"]
                         if c["cell_type"] == "markdown")
    else:
        text = (ROOT / f"{docname}.md").read_text(encoding="utf-8")
    title = re.search(r"^# (.+)$", text, re.M).group(1)
    return re.sub(r"[`*]", "", title)


def test_the_pdf_has_a_plausible_number_of_pages():
    info = _run("pdfinfo", str(PDF))
    pages = int(re.search(r"^Pages:\s+(\d+)", info, re.M).group(1))
    assert 120 <= pages <= 400, f"book.pdf has {pages} pages (176 when this test was written)"


def test_every_part_and_every_page_title_is_in_the_pdf(pdf_text):
    missing = []
    for part in _toc()["parts"]:
        if _plain(part["caption"]) not in pdf_text:
            missing.append(f"part {part['caption']!r}")
        for docname in _files(part["chapters"]):
            if _plain(_title(docname)) not in pdf_text:
                missing.append(f"{docname}: {_title(docname)!r}")
    assert not missing, "not in book.pdf: " + "; ".join(missing)


def test_parts_are_latex_parts_and_chapters_are_chapters():
    tex = (LATEX / "book.tex").read_text(encoding="utf-8")
    assert len(re.findall(r"\\part\{", tex)) == len(_toc()["parts"]), "one \\part per part of book/_toc.yml"
    chapters = [f for p in _toc()["parts"] for f in (c["file"] for c in p["chapters"])]
    assert len(re.findall(r"\\chapter\{", tex)) == len(chapters), "one \\chapter per chapter of book/_toc.yml"


def test_every_solution_is_in_the_pdf(pdf_text):
    sources = sorted((ROOT / "book" / "solutions").glob("*.ipynb"))
    expected = sum(len(re.findall(r"^(?:```|:::)\{solution\}", "".join(c["source"]), re.M))
                   for nb in sources for c in json.loads(nb.read_text(encoding="utf-8"))["cells"])
    found = pdf_text.count("solution to exercise")
    assert expected and found == expected, f"{found} solutions in book.pdf, {expected} in book/solutions"


def test_every_figure_and_widget_snapshot_is_in_the_pdf():
    """Each image output of the executed notebooks (a matplotlib figure, or the PNG snapshot
    that gearlib's widgets add to their display data) is an image in the PDF."""
    outputs = sum(1 for nb in EXECUTED.rglob("*.ipynb")
                  for c in json.loads(nb.read_text(encoding="utf-8"))["cells"]
                  for o in c.get("outputs", []) if "image/png" in o.get("data", {}))
    listing = _run("pdfimages", "-list", str(PDF)).splitlines()[2:]
    images = sum(1 for line in listing if line.split()[2] == "image")  # soft masks are listed apart
    assert outputs and images >= outputs, f"{images} images in book.pdf, {outputs} image outputs in the notebooks"


@pytest.mark.parametrize("text", ["VBox(children=", "HBox(children=", "<IPython.core.display", " object at 0x",
                                  "Solution(mechanism=", "ShiftTable(mechanism="])
def test_no_output_falls_back_to_a_bare_repr(pdf_text, text):
    """An output the LaTeX build cannot show (HTML, a widget view) falls back to text/plain:
    each object the book displays has a readable text, Markdown or PNG form."""
    assert _plain(text) not in pdf_text


def test_xelatex_found_every_glyph_and_reference():
    log = (LATEX / "book.log").read_text(encoding="utf-8", errors="replace")
    problems = sorted(set(re.findall(r"^(Missing character: .*?)!?$", log, re.M))
                      | set(re.findall(r"^(LaTeX Warning: (?:Reference|Citation|Hyper reference) .*)$", log, re.M))
                      | set(re.findall(r"^(LaTeX Warning: There were undefined references.*)$", log, re.M)))
    assert not problems, "\n".join(problems)


def test_nothing_runs_far_into_the_margin():
    """Long code lines wrap (Sphinx's sphinxVerbatim); a table or a word that does not fit
    shows as an overfull box. A few points are invisible; more is text cut at the edge."""
    log = (LATEX / "book.log").read_text(encoding="utf-8", errors="replace")
    wide = [(float(pt), where) for pt, where in re.findall(r"^Overfull \\hbox \(([\d.]+)pt too wide\) (.*)$", log, re.M)]
    assert not [w for w in wide if w[0] > 10], "\n".join(f"{pt}pt {where}" for pt, where in wide if pt > 10)
