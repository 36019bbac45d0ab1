"""Checks for the introduction's exercises (``exercises/00_introduction.ipynb``)."""

from .. import catalog
from ..kinematics import ratio
from ._core import Hint, close, register


@register(
    "intro_gear_ratio",
    chapter="00",
    question="Gear ratio e_{1,2} of an external pair with N_1 = 20 and N_2 = 60.",
    hints=[Hint(lambda a, e: close(a, abs(e)), "The size is right; an external mesh reverses the direction.")],
    generic_hint="e_{1,2} is the speed of gear 2 over the speed of gear 1, both relative to the carrier.",
    standard_hints=True,
)
def intro_gear_ratio():
    return catalog.simple_pair(20, 60).gear_pairs[0].e


@register(
    "intro_planetary_ratio",
    chapter="00",
    question="Simple planetary, sun 24 and ring 60, ring held: omega_carrier / omega_sun.",
    hints=[
        Hint(lambda a, e: close(a, 1 - e), "That is the sun's speed relative to the carrier over the sun's speed; "
             "the question asks for the carrier's own speed (relative to the held ring)."),
        Hint(lambda a, e: close(a, 60 / 24), "That is N_ring/N_sun: write the two Willis equations relative to the "
             "carrier and eliminate the planet's speed."),
    ],
    generic_hint="Write the Willis equation of each mesh relative to the carrier, set the ring's speed to 0, and "
    "eliminate the planet's speed.",
)
def intro_planetary_ratio():
    return ratio(catalog.simple_planetary(24, 60), output=4, input=1, ground=3)
