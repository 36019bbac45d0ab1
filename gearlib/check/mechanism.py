"""Checks for the exercises of chapters 0 and 1 (``exercises/00_introduction.ipynb``,
``exercises/01_graph_representation.ipynb``): the methods of :mod:`gearlib.mechanism`."""

from fractions import Fraction

from .. import catalog
from ..mechanism.kinematics import ratio, speeds
from ..mechanism.mobility import dof
from ._core import Hint, close, register


# ----------------------------------------------------------------------------- chapter 0
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


# ----------------------------------------------------------------------------- chapter 1
@register(
    "graph_carrier",
    chapter="01",
    question="Liu-Chen automatic transmission: the carrier of gear pair (3, 5).",
    hints=[
        Hint(lambda a, e: close(a, 5) or close(a, 3), "That link is one of the two gears of the pair; the carrier is a "
             "third link."),
        Hint(lambda a, e: close(a, 1) or close(a, 2) or close(a, 8), "That link is coaxial with gear 5, but the "
             "carrier must also hold the planet 3 on another axis."),
    ],
    generic_hint="Look for the link joined by turning pairs to gear 3 on one axis and to gear 5 on another.",
    standard_hints=False,
)
def graph_carrier():
    gp, _ = catalog.load("liu_chen_transmission").gear_pair(3, 5)
    return gp.carrier


@register(
    "graph_dof_simpson",
    chapter="01",
    question="Degrees of freedom of the Simpson gear set with the housing held.",
    hints=[
        Hint(lambda a, e: close(a, e - 1), "That is one brake too many: with only the housing held, no other link "
             "is fixed yet."),
        Hint(lambda a, e: close(a, e + 1), "Count again: seven links, six turning pairs, four gear pairs."),
    ],
    generic_hint="Count with F = J_R - J_G (the turning pairs form a tree), then confirm with gl.dof.",
    standard_hints=False,
)
def graph_dof_simpson():
    return dof(catalog.simpson(), 0).rank


@register(
    "graph_compound_ratio",
    chapter="01",
    question="Compound train with stages (18, 54) and (12, 48): omega_3 / omega_1.",
    hints=[Hint(lambda a, e: close(a, -e), "Two external meshes reverse the direction twice.")],
    generic_hint="Each stage multiplies the speed by -N_driver/N_driven; the intermediate shaft carries both gears.",
)
def graph_compound_ratio():
    return ratio(catalog.compound_train(((18, 54), (12, 48))), output=3, input=1, ground=0)


@register(
    "graph_differential_pinion",
    chapter="01",
    question="Car differential, wheels at 20 and 24 rad/s: the pinion's speed in rad/s.",
    hints=[
        Hint(lambda a, e: close(a, 22), "That is the case's speed (the mean of the wheels); the pinion drives the "
             "crown wheel on the case."),
        Hint(lambda a, e: close(a, -e), "The size is right; pinion and crown form an external pair, so they turn "
             "opposite ways."),
        Hint(lambda a, e: close(a, -22 * Fraction(13, 65)) or close(a, 22 * Fraction(13, 65)),
             "You multiplied by N_pinion/N_crown; the pinion is the small gear, so it turns faster than the case."),
    ],
    generic_hint="First find the case speed from the two wheels, then use the Willis equation of the pinion-crown pair.",
    standard_hints=False,
)
def graph_differential_pinion():
    return speeds(catalog.car_differential(), ground=1, inputs={3: 20, 4: 24})[2]


@register(
    "graph_humpage_ratio",
    chapter="01",
    question="Humpage reducer (teeth 20, 56, 24, 35, 76), frame held: omega_4 / omega_1.",
    hints=[
        Hint(lambda a, e: close(a, Fraction(20, 96)), "That is the carrier's speed ratio; continue to the output gear 4."),
        Hint(lambda a, e: close(a, Fraction(24 * 20, 35 * 56)), "You used the planet as if its carrier were fixed; the "
             "carrier 6 turns, so work with speeds relative to it."),
    ],
    generic_hint="Write the three Willis equations relative to the carrier 6, set omega_5 = 0, and eliminate the "
    "planet and the carrier.",
)
def graph_humpage_ratio():
    return ratio(catalog.humpage(), output=4, input=1, ground=5)
