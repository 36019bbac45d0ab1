"""The built HTML book read as a textbook: nothing points outside the book, every figure of a
chapter is numbered, captioned and described, key equations are numbered by chapter, and no
bare glued value or unlabelled number stands on a page. Run after the book build (``make
book``, part of ``make test``), like ``tests/test_book.py``.
"""

from __future__ import annotations

import functools
import json
import os
import pathlib
import re

import pytest
from bs4 import BeautifulSoup

from notebook_tools import ROOT

HTML = pathlib.Path(os.environ.get("BOOK_HTML", ROOT / "book" / "_build" / "html")).resolve()
pytestmark = pytest.mark.book

# Documents the authors had and readers do not: the notes and digest the book was written
# from, its reviews. The book's own page is "Notes on the sources" (book/sources.md).
OUTSIDE = re.compile(r"\bdigest\b|\bseed[ -]notes?\b|\bthesis-digest\b|/shared/|\breviews?/", re.IGNORECASE)
NOTES = re.compile(r"notes on the sources", re.IGNORECASE)
CHAPTERS = sorted((ROOT / "chapters").glob("[0-9][0-9]_*.ipynb"))
# a file name or a content hash is not a description
NO_ALT = re.compile(r"^(?:|.*\.(?:png|svg|jpe?g|gif)|[0-9a-f]{16,}.*)$", re.IGNORECASE)


@functools.cache
def _soup(path: pathlib.Path) -> BeautifulSoup:
    return BeautifulSoup(path.read_text(encoding="utf-8"), "html.parser")


def _main(soup: BeautifulSoup):
    return soup.find("main") or soup.find("article") or soup


def _pages() -> list[pathlib.Path]:
    return [p for p in sorted(HTML.rglob("*.html"))
            if not {"_static", "_sources", "_images"} & set(p.relative_to(HTML).parts)
            and p.name not in ("genindex.html", "search.html", "py-modindex.html")]


def _chapter_page(nb: pathlib.Path) -> pathlib.Path:
    return HTML / "chapters" / f"{nb.stem}.html"


@pytest.fixture(scope="module", autouse=True)
def _built():
    assert (HTML / "index.html").is_file(), f"no built book in {HTML}: run `make book` first"


def test_no_page_names_a_document_outside_the_book():
    """No page sends the reader to the digest, the seed notes or the reviews; every mention of
    the notes on the sources is a link to the book's own page."""
    found = []
    for path in _pages():
        main = _main(_soup(path))
        text = main.get_text(" ")
        for m in OUTSIDE.finditer(text):
            found.append(f"{path.relative_to(HTML)}: ...{text[max(0, m.start() - 60):m.end() + 30]!r}...")
        if path.name == "sources.html":
            continue
        for node in main.find_all(string=NOTES):
            link = node.find_parent("a")
            if link is None or "sources" not in (link.get("href") or ""):
                found.append(f"{path.relative_to(HTML)}: 'notes on the sources' without a link to them")
    assert not found, "\n".join(found)


@pytest.mark.parametrize("notebook", CHAPTERS, ids=[p.stem for p in CHAPTERS])
def test_every_image_has_a_description(notebook):
    """Every image of a chapter page carries alt text that says what it shows (not a file name)."""
    main = _main(_soup(_chapter_page(notebook)))
    bare = [img.get("src", "?") for img in main.find_all("img") if NO_ALT.match(img.get("alt") or "")]
    assert not bare, f"{notebook.stem}: {len(bare)} images without a description: {bare[:3]}"


@pytest.mark.parametrize("notebook", CHAPTERS, ids=[p.stem for p in CHAPTERS])
def test_every_figure_is_numbered_by_chapter_and_captioned(notebook):
    """Every image a chapter's cells draw stands in a figure numbered "Fig. N.k" (N the
    chapter) with a caption; widget snapshots are figures too."""
    chapter = int(notebook.stem[:2])
    main = _main(_soup(_chapter_page(notebook)))
    loose, wrong = [], []
    for img in main.find_all("img"):
        figure = img.find_parent("figure")
        caption = figure.find("figcaption") if figure else None
        number = caption.find(class_="caption-number") if caption else None
        if number is None or not caption.get_text(strip=True).removeprefix(number.get_text(strip=True)).strip():
            loose.append(img.get("src", "?"))
        elif not re.fullmatch(rf"Fig\.\s*{chapter}\.\d+", number.get_text(strip=True)):
            wrong.append(number.get_text(strip=True))
    assert not loose, f"{notebook.stem}: {len(loose)} images outside a numbered, captioned figure: {loose[:3]}"
    assert not wrong, f"{notebook.stem}: figures not numbered by chapter {chapter}: {wrong}"
    numbers = [n.get_text(strip=True) for n in main.select("figcaption .caption-number")]
    assert len(numbers) == len(set(numbers)), f"{notebook.stem}: a figure number twice: {numbers}"


@pytest.mark.parametrize("notebook", CHAPTERS, ids=[p.stem for p in CHAPTERS])
def test_key_equations_are_numbered_by_chapter(notebook):
    """Each chapter numbers its key displayed equations (N.k), and the text refers to them."""
    chapter = int(notebook.stem[:2])
    main = _main(_soup(_chapter_page(notebook)))
    numbers = [e.get_text(strip=True).rstrip("#").strip() for e in main.select("span.eqno")]
    assert numbers, f"{notebook.stem}: no numbered equation"
    bad = [n for n in numbers if not re.fullmatch(rf"\({chapter}\.\d+\)", n)]
    assert not bad, f"{notebook.stem}: equations not numbered by chapter {chapter}: {bad}"
    refs = [a for a in main.find_all("a", href=True) if "#equation-" in a["href"]]
    assert refs, f"{notebook.stem}: no reference to a numbered equation in the text"


def _glue_calls(source: str) -> list[str]:
    """The argument text of every ``glue(...)`` call in a cell's source (balanced brackets)."""
    calls = []
    for m in re.finditer(r"\bglue\(", source):
        depth, i = 1, m.end()
        while i < len(source) and depth:
            depth += {"(": 1, ")": -1}.get(source[i], 0)
            i += 1
        calls.append(source[m.end():i - 1])
    return calls


@pytest.mark.parametrize("notebook", CHAPTERS, ids=[p.stem for p in CHAPTERS])
def test_no_bare_glued_value_or_quoted_string_on_the_page(notebook):
    """A glued value shows inside a sentence, never as a bare output box of its own
    (``glue(..., display=False)``), and a glued string never prints with its quotes."""
    cells = json.loads(notebook.read_text(encoding="utf-8"))["cells"]
    shown = [call[:50] for c in cells if c["cell_type"] == "code"
             and not {"remove-output", "remove-cell"} & set(c["metadata"].get("tags", []))
             for call in _glue_calls("".join(c["source"])) if not re.search(r"display\s*=\s*False", call)]
    assert not shown, f"{notebook.stem}: glue calls that print their value bare: {shown}"
    main = _main(_soup(_chapter_page(notebook)))
    # Sphinx's smart quotes turn the repr 'text' of a glued str into ‘text’ on the page:
    # match straight and curly quotes alike
    quote = "['\"\u2018\u2019\u201c\u201d]"
    # a glue role renders as span.pasted-text ({glue:text}) or span.output.text_plain ({glue:})
    quoted = [s.get_text() for s in main.select("span.pasted-text, span.output.text_plain")
              if re.fullmatch(rf"\s*{quote}.*{quote}\s*", s.get_text())]
    assert not quoted, f"{notebook.stem}: glued strings shown with their quotes: {quoted}"
