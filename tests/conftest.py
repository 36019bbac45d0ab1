"""Shared fixtures for the tests."""

import copy

import pytest

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
