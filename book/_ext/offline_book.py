"""Sphinx extension: keep the HTML book self-contained, so that it reads offline.

Loaded by ``book/_config.yml`` (``sphinx.local_extensions``). It

* stops the build early, with the command that fixes it, when the JavaScript the book
  ships (MathJax, require.js, the Jupyter widgets HTML manager; installed from npm by
  ``make vendor``) is missing from ``html_static_path``;
* removes duplicate ``<script>``/``<link>`` entries from each page (Sphinx 7.4 lists an
  inline script added after the builder starts twice, and a second ``const`` declaration
  is a JavaScript error), and drops sphinx-thebe's loader, which would fetch Thebe from a
  CDN and is unused while the book has no Thebe launch button;
* warns (an error under ``-W``) about every page that still loads a script or a
  stylesheet from another host;
* disables the controls of every embedded widget: a widget in the static book is the
  snapshot taken when the book was built, and a slider that moves without changing the
  picture would mislead (the caption under it says how to run it live).
"""

from __future__ import annotations

import json
import os
import pathlib
import re

from sphinx.errors import ExtensionError
from sphinx.util import logging

logger = logging.getLogger(__name__)

REMOTE = re.compile(
    r"""<(?:script|link)\b[^>]*\b(?:src|href)\s*=\s*["']?(?:https?:)?//[^"'\s>]+""", re.IGNORECASE
)


def _static_file(app, name: str) -> bool:
    return any((pathlib.Path(app.confdir or app.srcdir) / d / name).is_file() for d in app.config.html_static_path)


def check_vendored_assets(app):
    """Every local script the pages load must be in one of the static folders."""
    if app.builder.format != "html":
        return
    wanted = [app.config.mathjax_path, *getattr(app.config, "nb_ipywidgets_js", {})]
    missing = [name for name in wanted if "://" not in name and not _static_file(app, name)]
    if missing:
        raise ExtensionError(
            f"the book's JavaScript is missing from html_static_path ({', '.join(missing)}): "
            "run `make vendor` (installs MathJax, require.js and the widgets manager from npm), "
            "or build with `make book`"
        )


def _thebe_enabled(app) -> bool:
    options = app.config.html_theme_options or {}
    return bool((options.get("launch_buttons") or {}).get("thebe"))


def _key(asset):
    return (os.fspath(asset.filename or ""), tuple(sorted(asset.attributes.items())))


def tidy_assets(app, pagename, templatename, context, doctree):
    """Drop duplicate scripts and stylesheets (and Thebe's unused loader) from one page."""
    for name in ("script_files", "css_files"):
        assets = context.get(name)
        if not assets:
            continue
        seen, kept = set(), []
        for asset in assets:
            key = _key(asset)
            if key in seen:
                continue
            if name == "script_files" and not _thebe_enabled(app) and (
                key[0].endswith("sphinx-thebe.js") or "THEBE_JS_URL" in asset.attributes.get("body", "")
            ):
                continue
            seen.add(key)
            kept.append(asset)
        assets[:] = kept


WIDGET_STATE = re.compile(r'(<script type="application/vnd\.jupyter\.widget-state\+json">)(.*?)(</script>)', re.S)


def _disabled(match) -> str:
    state = json.loads(match.group(2))
    for model in state.get("state", {}).values():
        if "disabled" in model.get("state", {}):
            model["state"]["disabled"] = True
    return match.group(1) + json.dumps(state) + match.group(3)


def disable_widget_controls(app, exception):
    """Every widget control of every built page disabled (a snapshot cannot recompute)."""
    if exception is not None or app.builder.format != "html":
        return
    for page in sorted(pathlib.Path(app.outdir).rglob("*.html")):
        if "_static" in page.parts:
            continue
        text = page.read_text(encoding="utf-8")
        if "widget-state+json" in text:
            page.write_text(WIDGET_STATE.sub(_disabled, text), encoding="utf-8")


def report_remote_assets(app, exception):
    """Warn about every built page that loads a script or stylesheet from another host."""
    if exception is not None or app.builder.format != "html":
        return
    outdir = pathlib.Path(app.outdir)
    for page in sorted(outdir.rglob("*.html")):
        if "_static" in page.parts:
            continue
        for match in REMOTE.finditer(page.read_text(encoding="utf-8")):
            logger.warning(
                "%s loads %s from another host: the book must read offline "
                "(ship the file in book/_static or book/vendor)",
                page.relative_to(outdir), match.group(0)[:160],
                type="offline_book", subtype="remote",
            )


def setup(app):
    app.connect("builder-inited", check_vendored_assets)
    app.connect("html-page-context", tidy_assets, priority=900)
    app.connect("build-finished", report_remote_assets)
    app.connect("build-finished", disable_widget_controls)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
