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
    for node in doctree.findall(nodes.Element):
        if type(node).__name__ not in ("exercise_title", "solution_title"):
            continue
        match = TITLE.match(node.astext())
        if match and all(isinstance(c, nodes.Text) for c in node.children):
            node.children = []
            node += nodes.Text(f"{match.group(1)} {match.group(2)}")


def setup(app):
    app.connect("doctree-resolved", tidy_titles)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
