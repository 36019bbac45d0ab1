"""The course's HTML book (``make course``, after ``make book``): every page of the book but
the worked solutions, with no trace of them (no page, no link, no entry in the search index,
none of their text) and no answer anywhere. Needs the built course book
(``course/_build/html``; set ``COURSE_HTML`` to check another)."""

from __future__ import annotations

import json
import os
import pathlib
import re

import pytest
import yaml

import gearlib as gl
from course.html_book import course_toc
from course_tools import html_text
from gearlib.check import _core
from notebook_tools import ROOT
from test_exercise_leaks import leaks

pytestmark = pytest.mark.course_html

HTML = pathlib.Path(os.environ.get("COURSE_HTML", ROOT / "course" / "_build" / "html")).resolve()


@pytest.fixture(scope="module")
def pages():
    assert (HTML / "index.html").is_file(), f"no course book in {HTML}: make course"
    return {p.relative_to(HTML).as_posix(): html_text(p) for p in sorted(HTML.rglob("*.html"))}


def _toc_files(toc):
    out = [toc["root"]]

    def walk(node):
        if isinstance(node, dict):
            out.extend([node["file"]] if "file" in node else [])
            for v in node.values():
                walk(v)
        elif isinstance(node, list):
            for v in node:
                walk(v)

    walk(toc)
    return out


def test_every_page_but_the_solutions_is_there(pages):
    book = yaml.safe_load((ROOT / "book" / "_toc.yml").read_text())
    files = _toc_files(book)
    solutions = [f for f in files if f.startswith("book/solutions/")]
    assert solutions, "the book has solution pages"
    assert _toc_files(course_toc(book)) == [f for f in files if f not in solutions]
    for f in files:
        present = f"{f}.html" in pages
        assert present == (f not in solutions), f
    assert not list(HTML.rglob("solutions*")), "a file of the solutions is in the course book"


def test_no_link_and_no_search_entry_leads_to_a_solution():
    for page in HTML.rglob("*.html"):
        raw = page.read_text(encoding="utf-8")
        assert not re.search(r"""href=["'][^"']*solutions/""", raw), f"{page}: a link to a solution page"
    index = (HTML / "searchindex.js").read_text(encoding="utf-8")
    docnames = json.loads(re.search(r'"docnames":\s*(\[[^\]]*\])', index).group(1))
    assert docnames and not [d for d in docnames if "solutions" in d]


def _solution_sentences():
    """Sentences of the worked solutions' prose long enough to be theirs alone."""
    out = set()
    for path in sorted((ROOT / "book" / "solutions").glob("*.ipynb")):
        for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]:
            if cell["cell_type"] != "markdown":
                continue
            prose = re.sub(r"\$[^$]*\$|`[^`]*`|\*\*|\*", " ", "".join(cell["source"]))
            for sentence in re.split(r"(?<=[.!?])\s+", prose):
                words = re.findall(r"[A-Za-z']+", sentence)
                if len(words) >= 12 and not sentence.lstrip().startswith((":", "#")):
                    out.add(" ".join(words))
    return out


def test_none_of_the_worked_solutions_is_in_it(pages):
    sentences = _solution_sentences()
    assert len(sentences) > 20
    text = {name: " ".join(re.findall(r"[A-Za-z']+", content)) for name, content in pages.items()}
    found = [(s[:60], name) for s in sentences for name, t in text.items() if s in t]
    assert not found, found[:5]


def test_no_answer_in_its_chapter_or_on_a_page_of_the_whole_book(pages):
    """Each answer is searched for by value (as tests/test_exercise_leaks.py does) on its own
    chapter's pages and on every page that belongs to no chapter (the API page's format
    examples, the notation, the lecturers' page ...). Another chapter may print the same
    number for its own reasons."""
    found = []
    chapter_of = {name: re.match(r"(chapters|exercises)/(\d+)_", name) for name in pages}
    for name in gl.check.names():
        check = gl.check.get(name)
        texts = {p: t for p, t in pages.items() if not chapter_of[p] or chapter_of[p].group(2) == check.chapter}
        reference = _core._reference(check)[1]
        for page, content in texts.items():
            hit = leaks(content, reference)
            if hit:
                found.append(f"{check.exercise} {name}: {hit[:3]} on {page}")
    assert not found, "\n".join(found)
