"""Mechanisms of the five source papers and the classic trains a student meets first.

Every entry is a YAML file in ``gearlib/catalog/data/`` (copy one to start your own), and
cites its source in ``mechanism.source``. Figures missing from the papers' text are
reconstructed as described in the book's :ref:`notes on the sources <sources>`.

>>> import gearlib as gl
>>> "car_differential" in gl.catalog.names()
True
>>> gl.catalog.simple_planetary(sun=30, ring=72).gear_pairs[1].teeth
(21, 72)
"""

from __future__ import annotations

import pathlib

from ..errors import DataFormatError, ToothNumberError
from ..mechanism._accept import CATALOGUE, catalogue_names, catalogue_path, load_catalogue
from ..mechanism.data import Mechanism

__all__ = [
    "names",
    "load",
    "path",
    "simple_pair",
    "compound_train",
    "simple_planetary",
    "car_differential",
    "humpage",
    "robotic_wrist",
    "simpson",
    "ravigneaux",
]

DATA = CATALOGUE


def names() -> list[str]:
    """Names of every catalogue entry (the YAML file names without ``.yaml``)."""
    return list(catalogue_names())


def path(name: str) -> pathlib.Path:
    """The YAML file of catalogue entry *name* (a name from :func:`names`, not a path)."""
    return catalogue_path(name)


def load(name: str) -> Mechanism:
    """The catalogue mechanism *name* (see :func:`names`)."""
    return load_catalogue(name)


def _with_teeth(mech: Mechanism, teeth: dict) -> Mechanism:
    for gears, t in teeth.items():
        mech = mech.with_gear_pair(gears, teeth=t)
    return mech


def simple_pair(driver: int = 20, driven: int = 60) -> Mechanism:
    """Two gears on fixed axes: pinion 1 and gear 2 on frame 0."""
    return _with_teeth(load("simple_pair"), {(1, 2): (driver, driven)})


def compound_train(stages=((20, 60), (15, 45))) -> Mechanism:
    """A two-stage compound train 1 -> 2 -> 3 on frame 0; ``stages`` are the tooth numbers
    of the pairs (1, 2) and (2, 3)."""
    if len(stages) != 2:
        raise DataFormatError(f"compound_train takes two stages of (driver, driven) teeth, got {stages!r}")
    return _with_teeth(load("compound_train"), {(1, 2): tuple(stages[0]), (2, 3): tuple(stages[1])})


def simple_planetary(sun: int = 24, ring: int = 60, planet: int | None = None) -> Mechanism:
    """Sun 1, planet 2, ring 3, carrier 4. The planet's teeth default to (ring - sun)/2,
    which the centre distance requires for equal modules."""
    if planet is None:
        if (ring - sun) % 2 or ring <= sun:
            raise ToothNumberError(
                f"simple_planetary: ring {ring} and sun {sun} give no whole planet (ring - sun must be even and "
                "positive); give `planet=` explicitly"
            )
        planet = (ring - sun) // 2
    return _with_teeth(load("simple_planetary"), {(1, 2): (sun, planet), (2, 3): (planet, ring)})


def car_differential() -> Mechanism:
    """Penaud and Alazard's car differential (example 2), with its two rolling bearings."""
    return load("car_differential")


def humpage() -> Mechanism:
    """Humpage's bevel reducer with Nelson and Cipra's teeth (20, 56, 24, 35, 76)."""
    return load("humpage")


def robotic_wrist() -> Mechanism:
    """Chen's three-dof geared robotic wrist, with symbolic gear ratios."""
    return load("chen_wrist")


def simpson() -> Mechanism:
    """The Simpson gear set (two planetaries sharing a sun)."""
    return load("simpson")


def ravigneaux() -> Mechanism:
    """The Ravigneaux gear set (one carrier, short and long pinions, two suns)."""
    return load("ravigneaux")
