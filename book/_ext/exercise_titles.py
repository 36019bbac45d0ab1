"""Sphinx extension: exercises numbered by chapter, "Exercise 1.3: title".

sphinx-exercise numbers exercises through the whole book and puts a custom title in
brackets. The book's exercises are written ``:::{exercise} 1.3: The Willis matrix · ★★ ·
15 min`` with ``:nonumber:``, which sphinx-exercise renders "Exercise (1.3: ...)"; this
extension drops the brackets once the titles are resolved, in the exercise and in the
"Solution to" title of its solution.
"""

from __future__ import annotations

import re

from docutils import nodes

TITLE = re.compile(r"^(Exercise|Solution to Exercise) \((\d+\.\d+:.*)\)$", re.S)


def tidy_titles(app, doctree, docname):
    for node in doctree.findall(nodes.title):  # sphinx-exercise has made its titles plain titles by now
        if not TITLE.match(node.astext()):
            continue
        texts = list(node.findall(nodes.Text))  # the solution's title links to its exercise: keep the link
        opening = next((t for t in texts if str(t) == " ("), None)
        if opening is None or not str(texts[-1]).endswith(")"):
            continue
        opening.parent.replace(opening, nodes.Text(" "))
        last = texts[-1]
        last.parent.replace(last, nodes.Text(str(last)[:-1]))


def setup(app):
    app.connect("doctree-resolved", tidy_titles)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
