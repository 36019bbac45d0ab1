"""The built HTML book as a reader sees it: every page in headless Chromium, from disk, offline.

Run after the book build (``make browser``, part of ``make test``). Each built page is
opened from ``file://`` with the network cut off, and fails on

* a JavaScript exception, a console error or a resource that does not load;
* a request to anything but a local file (or data:/blob:);
* an equation MathJax did not render (a math element without MathJax output, a MathJax
  error, or raw ``$...$``/``\\(...\\)`` TeX in the text);
* an embedded widget that did not render (no view, zero size, "Loading widget..."),
  an empty cell output, or a broken image.

A screenshot of each chapter's first screen, and of its first widget, displayed equation
and figure, is saved under ``book/_build/screenshots``. Skipped (with the reason) only
where Chromium is missing.
"""

from __future__ import annotations

import json
import os
import pathlib
import re
import tempfile
from urllib.parse import urlsplit

import pytest

from chromium import Chromium, find_chromium
from notebook_tools import ROOT

pytestmark = pytest.mark.browser

# the built book; BOOK_HTML points elsewhere (a private build: --path-output DIR gives DIR/_build/html)
HTML = pathlib.Path(os.environ.get("BOOK_HTML", ROOT / "book" / "_build" / "html")).resolve()
SHOTS = HTML.parent / "screenshots"
LOCAL_SCHEMES = {"file", "data", "blob", "about"}
REFRESH = re.compile(r'<meta http-equiv="Refresh" content="0; url=([^"]+)"', re.IGNORECASE)
WIDTH, HEIGHT = 1280, 900
HEADER = 60  # the book's sticky header bar, in CSS pixels: screenshots of a region go below it


def built_pages() -> list[str]:
    """Every HTML page of the built book, relative to the html folder."""
    if not HTML.is_dir():
        return []
    return sorted(
        str(p.relative_to(HTML)) for p in HTML.rglob("*.html")
        if not {"_static", "_sources", "_images"} & set(p.relative_to(HTML).parts)
    )


# Wait until every embedded widget view has been rendered by the widgets manager.
WIDGETS_RENDERED = """
Array.from(document.querySelectorAll('script[type="application/vnd.jupyter.widget-view+json"]'))
  .every(s => s.previousElementSibling && s.previousElementSibling.classList.contains('widget-subarea')
              && s.previousElementSibling.childElementCount > 0)
"""

# What the reader sees, collected after MathJax and the widgets are done.
INSPECT = r"""
(async () => {
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
    await MathJax.startup.promise;
  }
  await Promise.all(Array.from(document.images).map(img => img.complete ? null :
    new Promise(done => { img.onload = img.onerror = done; })));

  const SKIP = 'script, style, pre, code, textarea, .highlight, mjx-container, mjx-assistive-mml, .math';
  const text = root => {
    const walker = document.createTreeWalker(root, NodeFilter.SHOW_TEXT);
    let out = '';
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      if (!n.parentElement.closest('script, style')) out += n.textContent;
    }
    return out.trim();
  };
  const visible = el => el.checkVisibility({visibilityProperty: true, opacityProperty: false});
  const where = el => {
    const cell = el.closest('.cell, section');
    const head = cell && cell.querySelector('h1, h2, h3');
    return head ? head.textContent.replace('#', '').trim() : '';
  };

  const unrendered = Array.from(document.querySelectorAll('.math'))
    .filter(el => !el.querySelector('mjx-container'))
    .map(el => el.textContent.trim().slice(0, 80));

  const mathErrors = Array.from(document.querySelectorAll('mjx-merror'))
    .map(el => (el.getAttribute('data-mjx-error') || el.textContent).slice(0, 120));

  const rawTex = [];
  const TEX = /\$[^$\n]+\$|\\\(|\\\)|\\\[|\\\]|\\begin\{/;
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    if (n.parentElement.closest(SKIP)) continue;
    const m = n.textContent.match(TEX);
    if (m) rawTex.push(n.textContent.trim().slice(0, 100));
  }

  const widgets = [];
  const views = document.querySelectorAll('script[type="application/vnd.jupyter.widget-view+json"]');
  views.forEach((s, i) => {
    const area = s.previousElementSibling;
    const id = JSON.parse(s.textContent).model_id;
    if (!area || !area.classList.contains('widget-subarea') || area.childElementCount === 0) {
      widgets.push(`widget ${i + 1} (model ${id}) did not render`);
      return;
    }
    const box = area.getBoundingClientRect();
    if (visible(area) && (box.height < 10 || box.width < 10)) {
      widgets.push(`widget ${i + 1} (model ${id}) is empty (${box.width}x${box.height} px)`);
    }
    if (/Loading widget|Error displaying widget/.test(area.textContent)) {
      widgets.push(`widget ${i + 1} (model ${id}) shows "${area.textContent.trim().slice(0, 60)}"`);
    }
    area.querySelectorAll('img').forEach(img => {
      if (!img.naturalWidth) widgets.push(`widget ${i + 1} (model ${id}) has an image that did not load`);
    });
  });
  if (/Loading widget\.\.\./.test(document.body.innerText)) widgets.push('the page shows "Loading widget..."');

  const emptyOutputs = Array.from(document.querySelectorAll('.cell_output'))
    .filter(el => !text(el) && !el.querySelector('img, svg, canvas, mjx-container, table, iframe, video, .widget-subarea > *')
                  || (visible(el) && el.getBoundingClientRect().height === 0))
    .map(el => `an empty cell output (section "${where(el)}")`);

  const brokenImages = Array.from(document.images)
    .filter(img => !img.naturalWidth)
    .map(img => `image ${img.getAttribute('src')} did not load`);

  // page regions for screenshots: the first widget's cell, displayed equation and figure
  const clip = el => {
    if (!el || !visible(el)) return null;
    const box = el.getBoundingClientRect();
    return {x: 0, y: Math.max(0, box.top + window.scrollY - 12), width: document.documentElement.clientWidth,
            height: Math.min(box.height + 24, 1600)};
  };
  const area = document.querySelector('.widget-subarea');
  const firstWidget = clip(area && area.closest('.cell'));
  const display = document.querySelector('div.math mjx-container, .cell_output .math mjx-container');
  const firstEquation = clip(display && (display.closest('.cell') || display.closest('div.math').parentElement));
  const figure = document.querySelector('.cell_output img');
  const firstFigure = clip(figure && figure.closest('.cell'));

  return {title: document.title, unrendered, mathErrors, rawTex, widgets, emptyOutputs, brokenImages,
          widgetCount: views.length, mathCount: document.querySelectorAll('mjx-container').length,
          firstWidget, firstEquation, firstFigure};
})()
"""


@pytest.fixture(scope="module")
def page():
    executable = find_chromium()
    if executable is None:
        pytest.skip("Chromium not found ($CHROMIUM, chromium, chromium-browser): install Debian's "
                    "chromium (`apt-get install chromium`; `make test` does it where it can) "
                    "to check the built book in a real browser")
    SHOTS.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="book-browser-") as workdir, Chromium(executable, workdir) as browser:
        yield browser.new_page(width=WIDTH, height=HEIGHT)


def inspect(page, url: str, *, widget_timeout: float = 30) -> tuple[list[str], dict]:
    """Open ``url`` and list what a reader would find wrong there; also return what was seen."""
    page.goto(url, timeout=90)  # the API page (1.2 MB) took over 30 s beside three other test chains
    page.wait_for(WIDGETS_RENDERED, timeout=widget_timeout)  # a widget that never renders is reported below
    seen = page.evaluate(INSPECT, timeout=60)
    remote = sorted({u for u in page.requests if urlsplit(u).scheme not in LOCAL_SCHEMES})
    problems = (
        [f"requested a non-local URL: {u}" for u in remote]
        + page.errors
        + [f"unrendered equation: {t!r}" for t in seen["unrendered"]]
        + [f"MathJax error: {t!r}" for t in seen["mathErrors"]]
        + [f"raw TeX in the text: {t!r}" for t in seen["rawTex"]]
        + seen["widgets"] + seen["emptyOutputs"] + seen["brokenImages"]
    )
    return list(dict.fromkeys(problems)), seen


@pytest.mark.parametrize("name", built_pages() or ["index.html"])
def test_page_reads_offline(page, name):
    path = HTML / name
    assert path.is_file(), f"{name} is not built: run `make book` first"
    redirect = REFRESH.search(path.read_text(encoding="utf-8"))
    if redirect:  # index.html sends the reader to the landing page: check that this page arrives
        target = (path.parent / redirect.group(1)).resolve()
        assert target.is_file(), f"{name} redirects to {redirect.group(1)}, which is not built"
        page.goto(path.as_uri())
        arrived = f"location.href === {json.dumps(target.as_uri())} && document.readyState === 'complete'"
        assert page.wait_for(arrived), f"{name} did not redirect to {redirect.group(1)}"
        path = target
    problems, seen = inspect(page, path.as_uri())

    stem = re.sub(r"[^\w.-]+", "_", name.removesuffix(".html"))
    if name.startswith("chapters/"):
        page.screenshot(str(SHOTS / f"{stem}.png"))
        for part in ("Widget", "Equation", "Figure"):
            if seen[f"first{part}"]:
                page.screenshot(str(SHOTS / f"{stem}--{part.lower()}.png"), clip=seen[f"first{part}"], below=HEADER)
    assert not problems, f"{name} ({seen['title']}):\n  " + "\n  ".join(problems)


FAULTS = r"""<!DOCTYPE html><html><head><title>faults</title>
<script>window.MathJax = {options: {processHtmlClass: "tex2jax_process|mathjax_process|math|output_area"}}</script>
<script defer src="STATIC/mathjax/tex-mml-chtml.js"></script>
</head><body><section><h2>faults</h2>
<p>fine: <span class="math notranslate nohighlight">\(e_{1,2} = -N_1/N_2\)</span></p>
<p>raw: the gear ratio $e_{a,b}$ left as text</p>
<p>bad TeX: <span class="math notranslate nohighlight">\(\frac{1}\)</span></p>
<p>never typeset: <span class="math notranslate nohighlight">\omega_4</span></p>
<div class="cell_output"></div>
<div class="cell_output"><script type="application/vnd.jupyter.widget-view+json">
{"version_major": 2, "version_minor": 0, "model_id": "nomodel"}</script></div>
<img src="missing-figure.png" alt="">
<script>notAFunction();</script>
<script src="https://cdn.offline-check.invalid/widgets.js"></script>
</section></body></html>
"""


def test_the_browser_checks_find_what_is_wrong(page, tmp_path):
    """The checks above, on a page with one fault of each kind (and one correct equation)."""
    assert (HTML / "_static" / "mathjax" / "tex-mml-chtml.js").is_file(), "build the book first (make book)"
    faulty = tmp_path / "faults.html"
    faulty.write_text(FAULTS.replace("STATIC", (HTML / "_static").as_uri()), encoding="utf-8")
    problems, seen = inspect(page, faulty.as_uri(), widget_timeout=1)
    report = "\n".join(problems)
    expected = [
        "requested a non-local URL: https://cdn.offline-check.invalid/widgets.js",
        "JavaScript exception: ReferenceError: notAFunction is not defined",
        "raw TeX in the text: 'raw: the gear ratio $e_{a,b}$ left as text'",
        "MathJax error:",
        "unrendered equation: '\\\\omega_4'",  # repr() doubles the backslash
        "widget 1 (model nomodel) did not render",
        'an empty cell output (section "faults")',
        "missing-figure.png did not load",
    ]
    for fault in expected:
        assert fault in report, f"not reported: {fault}\nreported:\n{report}"
    assert seen["mathCount"] >= 1, "MathJax rendered nothing on the test page"
