"""Running ``python -m gearlib`` from the tests.

:func:`run` calls the command line's ``main`` in this process with its output captured
(a subprocess costs a second of interpreter start and imports per call); it returns what
``subprocess.run`` would, exit status included, also when argparse exits. The real
``python -m gearlib`` in a subprocess (:func:`run_subprocess`) is tested once for a result
and once for an error in ``tests/test_cli.py``, and the exit status, the single stderr line
and the absence of a traceback are the same through either.
"""

from __future__ import annotations

import contextlib
import io
import subprocess
import sys

from notebook_tools import ROOT


def run(*args: str) -> subprocess.CompletedProcess:
    """``python -m gearlib ARGS`` in this process: returncode, stdout and stderr as text."""
    from gearlib.cli import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main(list(args))
        except SystemExit as exit_:  # argparse's usage errors
            status = exit_.code if isinstance(exit_.code, int) else 1
    return subprocess.CompletedProcess(["python", "-m", "gearlib", *args], status, out.getvalue(), err.getvalue())


def run_subprocess(*args: str) -> subprocess.CompletedProcess:
    """``python -m gearlib ARGS`` in a new interpreter, as a user runs it."""
    return subprocess.run([sys.executable, "-m", "gearlib", *args], capture_output=True, text=True, cwd=ROOT)
