"""Checks for chapter 4's exercises (``exercises/04_complex_adjacency.ipynb``).

The planetary of exercises 2 to 4: sun 1 (30 teeth), planet 2 (30), ring 3 (90) held,
carrier 4; the sun turns at 20 Hz. A ball bearing (D_m = 40 mm, d_b = 8 mm, Z = 9, no
contact angle) carries the planet on the carrier's pin: inner ring on 4, outer ring in 2.
"""

from .. import catalog
from ..adjacency.frequencies import frequency_table
from ..adjacency.matrix import speed_ratio_matrix
from ..mechanism.elements import Bearing
from ._core import Hint, close, register

PLANET_BEARING = Bearing(pitch_diameter=40, ball_diameter=8, balls=9, inner=4, name="planet bearing")


def _planetary_table(bearing: bool = False):
    mech = catalog.simple_planetary(sun=30, ring=90)
    bearings = [((4, 2), PLANET_BEARING)] if bearing else None
    return frequency_table(mech, ground=3, inputs={1: 20}, bearings=bearings, unit="Hz")


def _real(z):
    z = complex(z)
    return z.real if abs(z.imag) < 1e-12 * max(1.0, abs(z)) else z


def _same_size(a, e):
    return abs(abs(complex(a)) - abs(complex(e))) <= 1e-6 * abs(complex(e))


@register(
    "adjacency_planet_ratio",
    chapter="04",
    question="Penaud's example 1 with the carrier 4 held and the ring 2 driven: omega_3 / omega_2, a complex number.",
    hints=[
        Hint(lambda a, e: _same_size(a, e) and abs(complex(a).imag) < 1e-9,
             "The size is right, but a real number cannot point along the planet's axis: keep the phase of "
             "the complex gear ratio."),
        Hint(lambda a, e: _same_size(a, e), "The size is right; the direction is not. The phase of e_{2,3} = "
             "-T(2,3)/T(3,2) is pi + theta_2 - theta_3."),
        Hint(lambda a, e: close(abs(complex(a)), 1.0), "A speed ratio of size 1 means the whole train turns as one "
             "body: did you forget the constraint row that holds the carrier?"),
    ],
    generic_hint="Stack M with C = [0 0 0 1], take the null space (one column) and divide it by its entry for link 2.",
)
def adjacency_planet_ratio():
    mech = catalog.load("penaud_example_1")
    return _real(speed_ratio_matrix(mech, zero_speed=[4], normalize_to=[2])[2, 0])


def _frequency_hints():
    return [
        Hint(lambda a, e: complex(a).real < 0, "A frequency is a number of events per unit time: give its size, "
             "which is never negative."),
    ]


@register(
    "adjacency_mesh_frequency",
    chapter="04",
    question="Planetary 30/30/90, ring held, sun at 20 Hz: the mesh frequency of the sun-planet pair (Hz).",
    hints=_frequency_hints() + [
        Hint(lambda a, e: close(a, 600), "You multiplied the sun's teeth by the sun's speed relative to the frame. "
             "Teeth come into mesh at the speed relative to the carrier, and the carrier turns."),
        Hint(lambda a, e: close(a, 300), "You used the planet's speed relative to the frame; use its speed relative "
             "to the carrier, which holds the planet's axis."),
        Hint(lambda a, e: close(a, 1800), "That is the ring's teeth times the sun's speed; the ring is held, but the "
             "carrier is not."),
        Hint(lambda a, e: close(a, 150), "That is one tooth's frequency times 10: count the teeth of the gear whose "
             "speed relative to the carrier you used."),
    ],
    standard_hints=False,
    generic_hint="Find the carrier's speed first (ring held), then multiply a gear's teeth by its speed relative to "
    "the carrier.",
)
def adjacency_mesh_frequency():
    return _planetary_table().select(kind="mesh", pair=(1, 2))[0].frequency


@register(
    "adjacency_planet_tooth_frequency",
    chapter="04",
    question="Same planetary: how often does a defect on one tooth of the planet meet the sun (Hz)?",
    hints=_frequency_hints() + [
        Hint(lambda a, e: close(a, 10), "That is the planet's speed relative to the frame. The defective tooth meets "
             "the sun once per turn of the planet relative to the carrier."),
        Hint(lambda a, e: close(a, 450), "That is the mesh frequency: every tooth, not the one defective tooth."),
        Hint(lambda a, e: close(a, 5), "That is the carrier's speed; the planet turns relative to the carrier too."),
        Hint(lambda a, e: close(a, 20), "That is the sun's speed relative to the frame."),
    ],
    standard_hints=False,
    generic_hint="The defect meets the sun once per revolution of the planet relative to the carrier.",
)
def adjacency_planet_tooth_frequency():
    return _planetary_table().select(kind="tooth", pair=(1, 2), link=2)[0].frequency


@register(
    "adjacency_outer_ring_frequency",
    chapter="04",
    question="Same planetary, planet bearing D_m = 40 mm, d_b = 8 mm, Z = 9, alpha = 0, outer ring in the "
    "planet: the outer-ring defect frequency (Hz).",
    hints=_frequency_hints() + [
        Hint(lambda a, e: close(a, 36), "You used the planet's speed relative to the frame. The bearing only sees "
             "the speed of its inner ring relative to its outer ring: planet relative to carrier."),
        Hint(lambda a, e: close(a, 81), "That is the inner-ring frequency, (Z/2)(1 + d/D) f_r; the outer ring has "
             "(1 - d/D)."),
        Hint(lambda a, e: close(a, 67.5), "You left out the factor (1 - d cos(alpha)/D_m): the balls roll, so the "
             "cage that carries them does not turn at exactly half the relative speed."),
        Hint(lambda a, e: close(a, 135), "Z f_r counts every ball passing at the full relative speed; the cage "
             "carries the balls along at its own speed."),
    ],
    standard_hints=False,
    generic_hint="Take f_r = |omega_inner - omega_outer| and the standard BPFO = (Z/2)(1 - d cos(alpha)/D_m) f_r.",
)
def adjacency_outer_ring_frequency():
    return _planetary_table(bearing=True).select(kind="outer ring", pair=(4, 2))[0].frequency
