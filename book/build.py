"""``jupyter-book build`` with Sphinx reading the pages in parallel (used by ``make book``).

Jupyter Book 1's command line has no ``-j`` option, but its Sphinx call takes ``jobs``. Reading
a page executes its notebook, so with two worker processes the notebooks run two at a time,
each worker taking the next page when it is done, largest first. The arguments are those of
``jupyter-book build``; the number of workers comes from ``JB_JOBS`` (default: the number
of CPUs, at most 4; ``JB_JOBS=1`` builds serially).

    python book/build.py . --config book/_config.yml --toc book/_toc.yml --path-output book -W -n --keep-going
"""

import functools
import os
import sys

import jupyter_book.sphinx
from jupyter_book.cli.main import main

jobs = int(os.environ.get("JB_JOBS") or min(4, os.cpu_count() or 1))
# JB_DOCTREES: another doctree folder (the PDF build reads a copy of the HTML build's, make pdf)
doctrees = {"doctreedir": os.environ["JB_DOCTREES"]} if os.environ.get("JB_DOCTREES") else {}
jupyter_book.sphinx.build_sphinx = functools.partial(jupyter_book.sphinx.build_sphinx, jobs=jobs, **doctrees)


def _declare_parallel_safe(ext):
    setup = ext.setup

    def parallel_setup(app):
        return {**(setup(app) or {}), "parallel_read_safe": True, "parallel_write_safe": True}

    ext.setup = parallel_setup


def _declare_jupyter_book_extensions_parallel_safe():
    """Two of Jupyter Book's extensions do not say whether they are safe for parallel
    reading, so Sphinx would read serially (and warn, which -W makes an error). Both are:

    * sphinx_multitoc_numbering only replaces the toctree collector's
      ``assign_section_numbers``, which Sphinx runs in the main process after the workers'
      environments are merged;
    * sphinx_jupyterbook_latex (``latex: use_jupyterbook_latex`` in book/_config.yml, for the
      PDF) keeps nothing in the environment: its read-time transforms only mark up each
      page's own doctree (skipped by the HTML writer); the rest runs in the LaTeX build's
      post-transforms and its ``builder-inited``."""
    import sphinx_jupyterbook_latex
    import sphinx_multitoc_numbering

    _declare_parallel_safe(sphinx_multitoc_numbering)
    _declare_parallel_safe(sphinx_jupyterbook_latex)


_declare_jupyter_book_extensions_parallel_safe()


def _one_page_per_chunk(source_dir: str):
    """Sphinx hands each worker a fixed chunk of pages in name order (for 26 pages on two
    workers: chunks of 11, 11 and 4), which put every chapter in one chunk: one worker ran
    the chapters' notebooks one after another while the other sat idle for most of the
    build. One page per chunk, the largest sources first (a longest-first schedule), keeps
    both workers busy. Sphinx cuts the pages it writes with the same function; writing a
    page is quick, so the one-page chunks cost a few process starts there."""
    import pathlib

    import sphinx.builders

    root = pathlib.Path(source_dir)

    def size(docname: str) -> int:
        return max((p.stat().st_size for p in root.glob(f"{docname}.*") if p.is_file()), default=0)

    def make_chunks(arguments, nproc, maxbatch=10):
        return [[doc] for doc in sorted(arguments, key=size, reverse=True)]

    sphinx.builders.make_chunks = make_chunks


if __name__ == "__main__":
    _one_page_per_chunk(sys.argv[1] if len(sys.argv) > 1 else ".")
    sys.exit(main(["build", *sys.argv[1:]]))
