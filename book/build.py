"""``jupyter-book build`` with Sphinx reading the pages in parallel (used by ``make book``).

Jupyter Book 1's command line has no ``-j`` option, but its Sphinx call takes ``jobs``. Reading
a page executes its notebook, so with two worker processes the notebooks run two at a time
and the build takes about half as long on a two-core machine. The arguments are those of
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

if __name__ == "__main__":
    sys.exit(main(["build", *sys.argv[1:]]))
