"""The built HTML book, read as files: self-contained, every local link resolves, the
structure the landing page promises. Run after the book build (``make browser``, part of
``make test``); the browser test (``tests/test_browser.py``) then opens every page.

The last test, on JupyterLab's widget extension, needs no build.
"""

from __future__ import annotations

import json
import os
import pathlib
import re
import subprocess
import sys
from html.parser import HTMLParser
from urllib.parse import unquote, urlsplit

import pytest
import yaml

from notebook_tools import ROOT, notebooks

HTML = pathlib.Path(os.environ.get("BOOK_HTML", ROOT / "book" / "_build" / "html")).resolve()
book = pytest.mark.book
REMOTE = re.compile(r"^(https?:)?//", re.IGNORECASE)


class _Page(HTMLParser):
    """The ids, links and asset sources of one HTML page."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.ids: set[str] = set()
        self.links: list[tuple[str, str]] = []   # (tag.attribute, url)
        self.assets: list[tuple[str, str]] = []  # scripts, stylesheets, images, frames

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        for key in ("id", "name") if tag == "a" else ("id",):
            if a.get(key):
                self.ids.add(a[key])
        if tag == "a" and a.get("href") is not None:
            self.links.append(("a.href", a["href"]))
        elif tag == "link" and a.get("href"):
            rel = (a.get("rel") or "").lower()
            if rel in ("stylesheet", "preload", "icon", "shortcut icon", "modulepreload"):
                self.assets.append((f"link[{rel}]", a["href"]))
            else:
                self.links.append((f"link[{rel}]", a["href"]))
        elif tag in ("script", "img", "iframe", "source", "video", "audio", "embed") and a.get("src"):
            self.assets.append((f"{tag}.src", a["src"]))


def read_pages(root: pathlib.Path) -> dict[pathlib.Path, _Page]:
    """Every HTML page under ``root`` (assets folders excluded), parsed."""
    out = {}
    for path in sorted(root.rglob("*.html")):
        if {"_static", "_sources", "_images"} & set(path.relative_to(root).parts):
            continue
        parser = _Page()
        parser.feed(path.read_text(encoding="utf-8"))
        out[path] = parser
    return out


def remote_assets(root: pathlib.Path, pages: dict[pathlib.Path, _Page]) -> list[str]:
    """Scripts, stylesheets, images and frames that a page loads from another host."""
    return [f"{p.relative_to(root)}: {kind} {url}" for p, page in pages.items() for kind, url in page.assets
            if REMOTE.match(url)]


def broken_links(root: pathlib.Path, pages: dict[pathlib.Path, _Page]) -> list[str]:
    """Local links and asset sources whose file, or whose #anchor in that file, is missing."""
    broken = []
    for path, page in pages.items():
        for kind, url in page.links + page.assets:
            parts = urlsplit(url)
            if parts.scheme or parts.netloc:
                continue  # another host (links to the web are allowed), mailto:, data:, javascript:
            target = (path.parent / unquote(parts.path)).resolve() if parts.path else path
            where = f"{path.relative_to(root)}: {kind} {url}"
            if not target.exists():
                broken.append(f"{where} (no such file)")
            elif parts.fragment and target.suffix == ".html":
                ids = pages[target].ids if target in pages else set()
                if unquote(parts.fragment) not in ids:
                    broken.append(f"{where} (no #{unquote(parts.fragment)} there)")
    return broken


@pytest.fixture(scope="module")
def pages():
    assert (HTML / "index.html").is_file(), f"no built book in {HTML}: run `make book` first"
    return read_pages(HTML)


def _rel(path: pathlib.Path) -> str:
    return str(path.relative_to(HTML))


@book
def test_no_page_loads_a_script_stylesheet_or_image_from_another_host(pages):
    remote = remote_assets(HTML, pages)
    assert not remote, "the book must read offline:\n  " + "\n  ".join(remote)


@book
def test_no_stylesheet_imports_from_another_host():
    pattern = re.compile(r"""(@import\s+(url\()?|url\()\s*['"]?(https?:)?//""", re.IGNORECASE)
    remote = [str(p.relative_to(HTML)) for p in (HTML / "_static").rglob("*.css")
              if pattern.search(p.read_text(encoding="utf-8", errors="replace"))]
    assert not remote, f"stylesheets that fetch from another host: {remote}"


@book
def test_every_local_link_and_anchor_resolves(pages):
    broken = broken_links(HTML, pages)
    assert not broken, f"{len(broken)} broken links:\n  " + "\n  ".join(broken)


def test_the_link_checks_find_what_is_wrong(tmp_path):
    """The two checks above, on a small site with one fault of each kind (and correct links)."""
    (tmp_path / "sub").mkdir()
    (tmp_path / "pic.png").write_bytes(b"")
    (tmp_path / "index.html").write_text(
        '<h1 id="top">x</h1><a href="sub/page.html#there">ok</a> <a href="#top">ok</a>'
        '<a href="https://doi.org/10.1/x">web link: allowed</a> <a href="mailto:a@b.c">mail</a>'
        '<a href="sub/missing.html">missing page</a> <a href="sub/page.html#nowhere">missing anchor</a>'
        '<img src="pic.png"> <img src="gone.png">'
        '<script src="https://cdn.example.org/x.js"></script>'
        '<link rel="stylesheet" href="//cdn.example.org/x.css">'
    )
    (tmp_path / "sub" / "page.html").write_text('<p id="there">y</p><a href="../index.html#top">back</a>')
    site = read_pages(tmp_path)
    assert sorted(broken_links(tmp_path, site)) == [
        "index.html: a.href sub/missing.html (no such file)",
        "index.html: a.href sub/page.html#nowhere (no #nowhere there)",
        "index.html: img.src gone.png (no such file)",
    ]
    assert remote_assets(tmp_path, site) == [
        "index.html: script.src https://cdn.example.org/x.js",
        "index.html: link[stylesheet] //cdn.example.org/x.css",
    ]


def _toc_files() -> list[list[str]]:
    """The table of contents as parts, each a list of files (chapter first)."""
    toc = yaml.safe_load((ROOT / "book" / "_toc.yml").read_text())
    parts = []
    for part in toc["parts"]:
        files = []
        for chapter in part["chapters"]:
            files.append(chapter["file"])
            files += [s["file"] for s in chapter.get("sections", [])]
        parts.append(files)
    return [[toc["root"]], *parts]


@book
def test_every_entry_of_the_table_of_contents_is_built_and_in_the_navigation(pages):
    landing = HTML / "book" / "intro.html"
    assert landing in pages, "the landing page book/intro.html is not built"
    nav = {(landing.parent / urlsplit(url).path).resolve() for _, url in pages[landing].links
           if not urlsplit(url).scheme and urlsplit(url).path}
    for files in _toc_files():
        for f in files:
            built = HTML / f"{f}.html"
            assert built in pages, f"{f} is in book/_toc.yml but {built.relative_to(HTML)} is not built"
            assert built in nav or built == landing, f"the landing page does not link to {f}"


def test_each_chapter_part_has_its_exercises_then_its_solutions():
    for files in _toc_files()[1:]:
        chapters = [f for f in files if f.startswith("chapters/")]
        if not chapters:
            continue
        assert len(chapters) == 1, f"one chapter per part: {files}"
        stem = chapters[0].removeprefix("chapters/")
        assert files == [f"chapters/{stem}", f"exercises/{stem}", f"book/solutions/{stem}"], files


@book
def test_solutions_are_on_their_own_pages_and_collapsed(pages):
    seen = 0
    for path in pages:
        html = path.read_text(encoding="utf-8")
        blocks = re.findall(r'<div class="([^"]*\bsolution\b[^"]*admonition[^"]*)"', html)
        if "solutions" not in path.parts:
            assert not blocks, f"{_rel(path)}: solutions belong on the pages in book/solutions/"
            continue
        seen += len(blocks)
        open_ = [b for b in blocks if "dropdown" not in b.split()]
        assert not open_, f"{_rel(path)}: {len(open_)} solutions are not collapsed (use :class: dropdown)"
    assert seen, "no solution block in the book (the introduction's solutions page has two)"


SOURCES = ("liu2004", "penaud", "laus2011", "chen2003", "chen1998")


def _bib_titles() -> dict[str, str]:
    text = (ROOT / "book" / "references.bib").read_text(encoding="utf-8")
    entries = re.findall(r"@\w+\{([^,\s]+),(.*?)\n\}", text, re.S)
    return {key: re.search(r"title\s*=\s*\{(.*?)\},?\s*\n", body, re.S).group(1) for key, body in entries}


@book
def test_the_bibliography_lists_the_five_source_papers(pages):
    titles = _bib_titles()
    html = (HTML / "book" / "bibliography.html").read_text(encoding="utf-8")
    text = " ".join(re.sub(r"<[^>]+>", " ", html).split()).lower()
    for key in SOURCES:
        assert key in titles, f"book/references.bib has no entry {key}"
        title = " ".join(titles[key].replace("{", "").replace("}", "").split()).lower()
        assert title in text, f"the bibliography page does not list {key} ({title})"


@book
def test_pages_with_widgets_embed_their_state_and_load_the_local_manager(pages):
    view_re = re.compile(r'<script type="application/vnd.jupyter.widget-view\+json">(.*?)</script>', re.S)
    state_re = re.compile(r'<script type="application/vnd.jupyter.widget-state\+json">(.*?)</script>', re.S)
    found = 0
    for path, page in pages.items():
        html = path.read_text(encoding="utf-8")
        views = view_re.findall(html)
        if not views:
            continue
        found += len(views)
        state = state_re.search(html)
        assert state, f"{_rel(path)} shows widgets but embeds no widget state"
        models = json.loads(state.group(1))["state"]
        for view in views:
            assert json.loads(view)["model_id"] in models, f"{_rel(path)}: a widget view has no model"
        # a snapshot cannot recompute: its sliders and lists are greyed out, not live-looking
        live = [m["model_name"] for m in models.values() if m["state"].get("disabled") is False]
        assert not live, f"{_rel(path)}: widget controls left enabled in the static book: {live}"
        scripts = [url for kind, url in page.assets if kind == "script.src"]
        for local in ("requirejs/require.js", "gearlib-widgets.js", "html-manager/embed-amd.js"):
            assert any(f"_static/{local}" in url for url in scripts), f"{_rel(path)} does not load {local}"
    assert found, "no page of the book shows a widget (the introduction has one)"


# gearlib's drawing vocabulary (draw_*, plot*, a result's .plot()) and matplotlib's subplots
DRAWS = re.compile(r"\b(?:draw_\w*|plot\w*|subplots)\s*\(")
IMAGE_IN_OUTPUT = re.compile(r'<div class="cell_output[^"]*">(?:(?!<div class="cell[ "]).)*?<img ', re.S)


def _code_cells(path: pathlib.Path) -> list[dict]:
    return [c for c in json.loads(path.read_text(encoding="utf-8"))["cells"] if c["cell_type"] == "code"]


@book
@pytest.mark.parametrize("notebook", [str(p.relative_to(ROOT)) for p in notebooks()])
def test_every_cell_that_draws_shows_its_figure_in_the_book(notebook):
    """A cell that calls a drawing function shows a figure on its page. (A kernel that inherits
    MPLBACKEND=Agg draws nowhere: the book would build, every figure missing.)"""
    source = ROOT / notebook
    executed = HTML.parent / "jupyter_execute" / notebook
    assert executed.is_file(), f"the build did not keep the executed {notebook} in {executed.parent}"
    drawing = [i for i, c in enumerate(_code_cells(source)) if DRAWS.search("".join(c["source"]))]
    cells = _code_cells(executed)
    blank = [i + 1 for i in drawing
             if not any(k.startswith("image/") for o in cells[i].get("outputs", []) for k in o.get("data", {}))]
    assert not blank, f"{notebook}: code cells {blank} draw but show no figure (is MPLBACKEND set for the kernel?)"
    page = (HTML / notebook).with_suffix(".html").read_text(encoding="utf-8")
    shown = len(IMAGE_IN_OUTPUT.findall(page))
    assert shown >= len(drawing), f"{notebook}: {len(drawing)} cells draw, {shown} cell outputs on its page show an image"


def test_jupyterlab_has_the_widgets_extension_enabled():
    jupyter = pathlib.Path(sys.executable).with_name("jupyter")
    out = subprocess.run([str(jupyter), "labextension", "list"], capture_output=True, text=True,
                         env={**os.environ, "JUPYTER_PREFER_ENV_PATH": "1", "NO_COLOR": "1"})
    listing = re.sub(r"\x1b\[[0-9;]*m", "", out.stdout + out.stderr)
    line = next((x for x in listing.splitlines() if "@jupyter-widgets/jupyterlab-manager" in x), "")
    assert "enabled" in line and "OK" in line, f"ipywidgets' JupyterLab extension is not active:\n{listing}"


def _offline_book():
    """The book's Sphinx extension (book/_ext/offline_book.py), loaded from its file."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("offline_book", ROOT / "book" / "_ext" / "offline_book.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_build_stops_when_the_vendored_javascript_is_missing(tmp_path):
    from types import SimpleNamespace

    from sphinx.errors import ExtensionError

    ext = _offline_book()
    (tmp_path / "static" / "mathjax").mkdir(parents=True)
    (tmp_path / "static" / "mathjax" / "tex-mml-chtml.js").write_text("")
    config = SimpleNamespace(mathjax_path="mathjax/tex-mml-chtml.js", html_static_path=["static"],
                             nb_ipywidgets_js={"requirejs/require.js": {}, "https://cdn.example.org/x.js": {}})
    app = SimpleNamespace(builder=SimpleNamespace(format="html"), config=config, confdir=str(tmp_path), srcdir="")
    with pytest.raises(ExtensionError, match=r"requirejs/require\.js.*make vendor"):
        ext.check_vendored_assets(app)
    (tmp_path / "static" / "requirejs").mkdir()
    (tmp_path / "static" / "requirejs" / "require.js").write_text("")
    ext.check_vendored_assets(app)  # all local files present; remote ones are reported after the build


def test_pages_keep_one_copy_of_each_script_and_no_thebe_loader():
    from types import SimpleNamespace

    ext = _offline_book()

    def asset(filename, **attributes):
        return SimpleNamespace(filename=filename, attributes=attributes)

    thebe = asset(None, body='const THEBE_JS_URL = "https://unpkg.com/thebe@0.8.2/lib/index.js"')
    scripts = [asset("_static/doctools.js"), asset(None, body="var a = 1;"), thebe,
               asset("_static/sphinx-thebe.js", **{"async": "async"}), asset("", body="var a = 1;"),
               asset("_static/doctools.js")]
    context = {"script_files": scripts, "css_files": []}
    app = SimpleNamespace(config=SimpleNamespace(html_theme_options={"launch_buttons": {"thebe": False}}))
    ext.tidy_assets(app, "page", "page.html", context, None)
    assert [(s.filename, s.attributes) for s in context["script_files"]] == [
        ("_static/doctools.js", {}), (None, {"body": "var a = 1;"})]
    assert ext.REMOTE.search('<script src="https://cdn.example.org/x.js"></script>')
    assert ext.REMOTE.search("<link rel='stylesheet' href='//cdn.example.org/x.css'>")
    assert not ext.REMOTE.search('<script src="../_static/mathjax/tex-mml-chtml.js"></script>')
