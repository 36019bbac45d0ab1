"""Sphinx extension: number figures, tables, equations and exercises by chapter (Fig. 2.3, (1.4),
Exercise 3.4).

Loaded by ``book/_config.yml`` (``sphinx.local_extensions``). Sphinx numbers figures through
the whole book (or by section numbers, which would make the introduction chapter 1); the
book's chapters are numbered by their files (``chapters/00_introduction``,
``exercises/03_unit_gains``, ``book/solutions/05_davies_efficiency``). After Sphinx assigns its
numbers, this renumbers every numbered object of such a page as ``(chapter, k)``, counting
each kind (figure, table, displayed equation, exercise) from 1 in page order. References
(``{numref}``, ``{eq}``, ``{ref}`` to an exercise) follow. A chapter's exercise page numbers
its exercises N.1, N.2, ... like the chapter numbers its figures.
"""

from __future__ import annotations

import re

CHAPTER = re.compile(r"(?:^|/)(\d\d)_[^/]+$")


def chapter_of(docname: str) -> int | None:
    """The chapter number of a page (``chapters/02_kinematic_units`` -> 2), or None."""
    m = CHAPTER.search(docname)
    return int(m.group(1)) if m else None


def renumber(app, env):
    changed = []
    for docname, kinds in env.toc_fignumbers.items():
        chapter = chapter_of(docname)
        if chapter is None:
            continue
        for ids in kinds.values():
            for k, (node_id, number) in enumerate(list(ids.items()), start=1):
                if number != (chapter, k):
                    ids[node_id] = (chapter, k)
                    changed.append(docname)
    return sorted(set(changed))


def setup(app):
    # after Sphinx's own toctree collector has assigned its numbers (default priority 500)
    app.connect("env-get-updated", renumber, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
