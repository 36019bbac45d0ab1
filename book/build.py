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
jupyter_book.sphinx.build_sphinx = functools.partial(jupyter_book.sphinx.build_sphinx, jobs=jobs)


def _declare_multitoc_parallel_safe():
    """Jupyter Book's sphinx_multitoc_numbering does not say whether it is safe for parallel
    reading, so Sphinx would read serially (and warn, which -W makes an error). It only
    replaces the toctree collector's ``assign_section_numbers``, which Sphinx runs in the
    main process after the workers' environments are merged, so it is safe: say so."""
    import sphinx_multitoc_numbering as ext

    setup = ext.setup

    def parallel_setup(app):
        return {**(setup(app) or {}), "parallel_read_safe": True, "parallel_write_safe": True}

    ext.setup = parallel_setup


_declare_multitoc_parallel_safe()


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
