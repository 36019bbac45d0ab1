"""Shared fixtures for the tests."""

import copy
import os

import pytest
from hypothesis import settings

PLANETARY = {
    "name": "planetary",
    "links": {1: "sun", 2: "planet", 3: "ring", 4: "carrier"},
    "turning_pairs": [[4, 1, "a"], [4, 3, "a"], [4, 2, "b"]],
    "gear_pairs": [
        {"gears": [1, 2], "teeth": [24, 18]},
        {"gears": [2, 3], "teeth": [18, 60], "type": "internal"},
    ],
}


@pytest.fixture
def planetary_data():
    """A valid simple planetary as plain data (a fresh copy each time)."""
    return copy.deepcopy(PLANETARY)


# Property and fuzz tests: `make test` (and CI) runs a fixed, reproducible set of examples, so a red
# run can be replayed exactly. `HYPOTHESIS_PROFILE=explore make unit` draws fresh random examples to
# hunt for new failures; add any it finds as explicit regression tests.
settings.register_profile("ci", derandomize=True, print_blob=True)
settings.register_profile("explore", derandomize=False, print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))
