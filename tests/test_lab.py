"""The chapters in JupyterLab, as a reader runs them: widgets live, driven by a real browser.

A JupyterLab server of the project's environment (the one ``make lab`` starts) serves a
copy of ``chapters/`` from a temporary folder (so nothing in the working tree is ever
saved over), on 127.0.0.1 only. Headless Chromium opens each chapter, runs every cell
(*Run > Run All Cells*) and checks that no cell raises, that every widget renders, and
that moving a widget's first slider makes the kernel redraw its figure. It fails on a
request to any other host. Skipped (with the reason) only where Chromium is missing. Run
by ``make browser``; ``make test`` runs it beside the unit tests and the book build (it
needs no built book).
"""

from __future__ import annotations

import json
import os
import pathlib
import re
import secrets
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
from urllib.parse import urlsplit

import pytest

from chromium import Chromium, find_chromium
from notebook_tools import ROOT

pytestmark = pytest.mark.browser

# beside the book's other screenshots (a book build keeps this folder); made when a shot is
# taken, as the build may start at the same time on a fresh checkout
SHOTS = pathlib.Path(os.environ.get("BOOK_HTML", ROOT / "book" / "_build" / "html")).resolve().parent / "screenshots"
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"


def chapters() -> list[str]:
    """Every chapter, the largest first: each worker takes the next when it is done, so the
    long ones do not come last (a longest-first schedule)."""
    paths = sorted((ROOT / "chapters").glob("*.ipynb"), key=lambda p: (-p.stat().st_size, p.name))
    return [p.name for p in paths]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def lab():
    """(base URL, token, Chromium page): a private JupyterLab and a browser tab for it."""
    executable = find_chromium()
    if executable is None:
        pytest.skip("Chromium not found ($CHROMIUM, chromium, chromium-browser): install Debian's "
                    "chromium (`apt-get install chromium`; `make test` does it where it can) "
                    "to run the chapters in JupyterLab in a real browser")
    with tempfile.TemporaryDirectory(prefix="book-lab-") as tmp:
        tmp = pathlib.Path(tmp)
        shutil.copytree(ROOT / "chapters", tmp / "root" / "chapters",
                        ignore=shutil.ignore_patterns(".ipynb_checkpoints"))
        # never autosave (and so never write a notebook); no question about Jupyter news; keep
        # every cell in the page (JupyterLab 4 otherwise detaches cells scrolled out of view,
        # and a widget cell's output area would be missing when the test reads it)
        for plugin, value in (("docmanager-extension/plugin", {"autosave": False}),
                              ("apputils-extension/notification", {"fetchNews": "false"}),
                              ("notebook-extension/tracker", {"windowingMode": "none"})):
            path = tmp / "settings" / "@jupyterlab" / f"{plugin}.jupyterlab-settings"
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(json.dumps(value))
        port, token = _free_port(), secrets.token_hex(16)
        env = {**os.environ, "JUPYTER_PREFER_ENV_PATH": "1", "JUPYTER_CONFIG_DIR": str(tmp / "config"),
               "JUPYTER_RUNTIME_DIR": str(tmp / "runtime"), "JUPYTERLAB_SETTINGS_DIR": str(tmp / "settings"),
               "JUPYTERLAB_WORKSPACES_DIR": str(tmp / "workspaces")}
        env.pop("MPLBACKEND", None)  # JupyterLab's kernel draws inline, as for a reader
        args = [str(pathlib.Path(sys.executable).with_name("jupyter")), "lab", "--no-browser",
                "--ip=127.0.0.1", f"--port={port}", "--ServerApp.port_retries=0",
                f"--IdentityProvider.token={token}", f"--ServerApp.root_dir={tmp / 'root'}",
                "--expose-app-in-browser", "--LabApp.news_url=None",
                "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate"]
        if os.geteuid() == 0:
            args.append("--allow-root")
        log = open(tmp / "lab.log", "wb")
        server = subprocess.Popen(args, env=env, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
        base = f"http://127.0.0.1:{port}"
        try:
            end = time.monotonic() + 90
            while True:
                try:
                    urllib.request.urlopen(f"{base}/api/status?token={token}", timeout=2).close()
                    break
                except OSError:
                    if server.poll() is not None or time.monotonic() > end:
                        log.flush()
                        pytest.fail(f"JupyterLab did not start:\n{(tmp / 'lab.log').read_text()[-3000:]}")
                    time.sleep(0.3)
            with Chromium(executable, str(tmp), allow_hosts=["127.0.0.1"]) as browser:
                yield base, token, browser.new_page(width=1280, height=900)
        finally:
            server.terminate()
            try:
                server.wait(timeout=20)
            except subprocess.TimeoutExpired:
                server.kill()
                server.wait()
            log.close()


NOTEBOOK = "jupyterapp.shell.currentWidget"
KERNEL_IDLE = (f"window.jupyterapp && {NOTEBOOK} && {NOTEBOOK}.sessionContext"
               f" && {NOTEBOOK}.sessionContext.session && {NOTEBOOK}.sessionContext.session.kernel"
               f" && {NOTEBOOK}.sessionContext.session.kernel.status === 'idle'")

# After Run All: errors, and every widget output's rendered view, cell by cell.
CELLS = """
(() => {
  const cells = NOTEBOOK.content.widgets.filter(c => c.model.type === 'code');
  const out = {unexecuted: 0, errors: [], widgets: []};
  cells.forEach((cell, i) => {
    if (cell.model.executionCount === null) out.unexecuted += 1;
    const outputs = cell.model.outputs.toJSON();
    outputs.filter(o => o.output_type === 'error')
           .forEach(o => out.errors.push(`code cell ${i + 1}: ${o.ename}: ${o.evalue}`));
    if (outputs.some(o => o.data && o.data['WIDGET_VIEW'])) {
      const view = cell.node.querySelector('.jp-OutputArea-output .jupyter-widgets');
      const area = cell.node.querySelector('.jp-OutputArea');
      const text = area ? area.textContent : '';
      const box = view ? view.getBoundingClientRect() : {width: 0, height: 0};
      out.widgets.push({cell: i, rendered: !!view && box.height > 10,
                        failed: /Error displaying widget|Loading widget/.test(text),
                        control: cell.node.querySelector('.noUi-handle') ? 'slider'
                               : cell.node.querySelector('.jp-OutputArea-output select') ? 'select' : null,
                        image: !!cell.node.querySelector('.jp-OutputArea-output img')});
    }
  });
  return out;
})()
""".replace("NOTEBOOK", NOTEBOOK).replace("WIDGET_VIEW", WIDGET_VIEW)


# What the kernel shows in a widget: its images and the text outside its controls (a
# slider's read-out changes in the browser alone).
ANSWER = """cell => {
  const area = cell.querySelector('.jp-OutputArea-output');
  const controls = '.widget-slider, .widget-dropdown, .widget-select, .widget-toggle-buttons, '
                 + '.widget-text, .widget-checkbox, .widget-select-multiple, select';
  const walker = document.createTreeWalker(area, NodeFilter.SHOW_TEXT);
  let text = '';
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    if (!n.parentElement.closest(controls)) text += n.textContent;
  }
  return Array.from(area.querySelectorAll('img')).map(i => i.src).join() + '|' + text;
}"""


def _cell(index: int) -> str:
    return f"{NOTEBOOK}.content.widgets.filter(c => c.model.type === 'code')[{index}].node"


# Opens a chapter in the JupyterLab already loaded, as File > Open does (the app is loaded
# once per browser tab, not once per chapter); true once it is the current widget.
OPEN = ("jupyterapp.commands.execute('docmanager:open', {path: PATH, factory: 'Notebook'})"
        ".then(w => w.context.ready).then(() => jupyterapp.shell.currentWidget"
        " && jupyterapp.shell.currentWidget.context.path === PATH)")

# Closes the current chapter: its kernel shut down, its tab closed without saving.
CLOSE = (f"(w => {{ w.context.model.dirty = false; return w.sessionContext.shutdown().then(() => w.dispose()); }})"
         f"({NOTEBOOK})")


@pytest.mark.parametrize("chapter", chapters())
def test_chapter_runs_in_jupyterlab_with_live_widgets(lab, chapter):
    base, token, page = lab
    path = json.dumps(f"chapters/{chapter}")
    if page.evaluate("!!(window.jupyterapp && jupyterapp.shell)") is not True:   # the tab's first chapter
        page.goto(f"{base}/lab/tree/chapters/{chapter}?token={token}&reset", timeout=60)
    else:   # this chapter's requests and errors only
        page.requests.clear()
        page.errors.clear()
        assert page.evaluate(OPEN.replace("PATH", path), timeout=60) is True, f"{chapter}: JupyterLab did not open it"
    assert page.wait_for(KERNEL_IDLE, timeout=120), f"{chapter}: the notebook or its kernel did not start"
    try:
        _run_and_check(page, chapter)
    finally:  # stop this chapter's kernel and close it; the next chapter starts its own
        page.evaluate(CLOSE)


def _run_and_check(page, chapter):
    finished = page.evaluate("jupyterapp.commands.execute('notebook:run-all-cells')", timeout=600)
    assert page.wait_for(KERNEL_IDLE, timeout=120), f"{chapter}: the kernel is still busy after Run All"
    seen = page.evaluate(CELLS)
    assert not seen["errors"], f"{chapter} raises in JupyterLab:\n  " + "\n  ".join(seen["errors"])
    assert finished is True and seen["unexecuted"] == 0, f"{chapter}: Run All stopped before the end"

    problems = []
    for w in seen["widgets"]:
        where = f"the widget in code cell {w['cell'] + 1}"
        if w["failed"] or not w["rendered"]:
            problems.append(f"{where} did not render")
            continue
        if not w["control"]:
            continue
        # move its first slider one step, or pick the next entry of its first list, as a
        # reader would; the kernel must answer with a new figure or a new text
        cell = _cell(w["cell"])
        shown = f"({ANSWER})({cell})"
        before = page.evaluate(shown)
        if w["control"] == "slider":  # the keyboard moves a focused slider handle one step
            page.evaluate(f"{cell}.scrollIntoView(); {cell}.querySelector('.noUi-handle').focus()")
            page.press("ArrowRight", 39)
        else:  # JupyterLab keeps the arrow keys for itself: choose the entry as a click would
            page.evaluate(f"{cell}.scrollIntoView(); (s => {{ s.selectedIndex = (s.selectedIndex + 1)"
                          f" % s.options.length; s.dispatchEvent(new Event('change', {{bubbles: true}})); }})"
                          f"({cell}.querySelector('.jp-OutputArea-output select'))")
        if not page.wait_for(f"{shown} !== {json.dumps(before)}", timeout=60):
            problems.append(f"{where}: the kernel did not answer a move of its first {w['control']} "
                            "with a new figure or text")
    stem = re.sub(r"[^\w.-]+", "_", chapter.removesuffix(".ipynb"))
    if seen["widgets"]:
        page.evaluate(f"{_cell(seen['widgets'][0]['cell'])}.scrollIntoView()")
    SHOTS.mkdir(parents=True, exist_ok=True)
    page.screenshot(str(SHOTS / f"lab_{stem}.png"))

    remote = sorted({u for u in page.requests
                     if urlsplit(u).scheme not in ("data", "blob") and urlsplit(u).hostname != "127.0.0.1"})
    problems += [f"requested a URL on another host: {u}" for u in remote]
    problems += page.errors
    assert not problems, f"{chapter} in JupyterLab:\n  " + "\n  ".join(dict.fromkeys(problems))
