"""Doctest set-up: every docstring example may assume ``import gearlib as gl`` and numpy as ``np``."""

import numpy as np
import pytest

import gearlib as gl


@pytest.fixture(autouse=True)
def _doctest_namespace(doctest_namespace):
    doctest_namespace["gl"] = gl
    doctest_namespace["np"] = np
