"""Checks for chapter 4's exercises (``exercises/04_complex_adjacency.ipynb``).

Exercises 4.2 to 4.4 share a planetary gearbox the chapter does not show: sun 1 (30 teeth by
default), planet 2 (30), ring 3 (held), carrier 4; the sun turns at 20 Hz. A ball bearing
(D_m = 40 mm, d_b = 6 mm, Z = 9, no contact angle) carries the planet on the carrier's pin:
inner ring on 4, outer ring in 2. Variants draw other teeth and another sun speed.
"""

from __future__ import annotations

from fractions import Fraction

from ._core import register
from ._value import Hint, Mistake, Value
from ._compare import numeric

__all__ = ["adjacency_planet_ratio", "adjacency_mesh_frequency", "adjacency_planet_tooth_frequency",
           "adjacency_outer_ring_frequency"]

_BOX = {"sun": 30, "planet": 30, "f_sun": 20}


def _box(rng) -> dict:
    return {"sun": rng.randint(18, 40), "planet": rng.randint(18, 40), "f_sun": rng.choice((10, 12, 15, 20, 24, 25,
                                                                                              30, 40, 50))}


def _speeds(sun, planet, f_sun) -> dict:
    """Carrier, planet (absolute) and planet relative to the carrier, in Hz, by the classic
    formulas (ring held)."""
    ring = sun + 2 * planet
    f_c = Fraction(f_sun) * Fraction(sun, sun + ring)
    rel_sun = Fraction(f_sun) - f_c
    rel_planet = -Fraction(sun, planet) * rel_sun
    return {"ring": ring, "carrier": f_c, "rel_sun": rel_sun, "planet": f_c + rel_planet, "rel_planet": rel_planet}


def _table(sun, planet, f_sun, bearing: bool = False):
    from ..adjacency.frequencies import frequency_table
    from ..catalog import simple_planetary
    from ..mechanism.elements import Bearing

    mech = simple_planetary(sun=sun, ring=sun + 2 * planet, planet=planet)
    bearings = [((4, 2), Bearing(pitch_diameter=40, ball_diameter=6, balls=9, inner=4, name="planet bearing"))] \
        if bearing else None
    return frequency_table(mech, ground=3, inputs={1: f_sun}, bearings=bearings, unit="Hz")


def _same_size(a, e):
    return abs(abs(numeric(a)) - abs(numeric(e))) <= 1e-3 * abs(numeric(e))


@register(
    "adjacency_planet_ratio", exercise="4.1", title="A bevel planet on fixed axes", stars=2, minutes=20,
    kind="compute",
    question="Penaud and Alazard's bevel planet (example 1, gl.catalog.load('penaud_example_1'): sun 1, ring 2, "
             "planet 3, carrier 4), now with the carrier held and the ring driven. Build the constraint row C "
             "that holds link 4, stack it under M, take the null space and normalise it to the ring: give "
             "omega_3/omega_2, a complex number.",
    answer=Value("ratio", mistakes=[
        Hint(lambda a, e, p: _same_size(a, e) and abs(numeric(a).imag) < 1e-9, "The size is right, but a real "
             "number cannot point along the planet's axis: keep the phase of the complex gear ratio."),
        Hint(lambda a, e, p: _same_size(a, e), "The size is right; the direction is not. The phase of e_(2,3) = "
             "-T(2,3)/T(3,2) is pi + theta_2 - theta_3."),
        Mistake(lambda e, p: 1 / e, "You have the reciprocal, the ring over the planet: the question asks for "
                "omega_3/omega_2, the planet over the ring."),
        Hint(lambda a, e, p: abs(abs(numeric(a)) - 1) < 1e-9, "A speed ratio of size 1 means the whole train turns "
             "as one body: did you forget the constraint row that holds the carrier?"),
    ], standard=False, generic="Stack M with C = [0 0 0 1], take the null space (one column) and divide it by its "
                               "entry for link 2."),
)
def adjacency_planet_ratio():
    from ..catalog import load
    from ..mechanism.kinematics import ratio

    return ratio(load("penaud_example_1"), output=3, input=2, ground=4)  # exact: the weights are algebraic


_GEARBOX = ("A planetary gearbox: sun 1 with {sun} teeth, planet 2 with {planet}, ring 3 held (the teeth that "
            "fit), carrier 4 the output; the sun turns at {f_sun} Hz.")


@register(
    "adjacency_mesh_frequency", exercise="4.2", title="The mesh frequency of a planetary", stars=1, minutes=10,
    kind="compute",
    question=_GEARBOX + " How many teeth come into mesh per second between the sun and the planet? Give the mesh "
                        "frequency in Hz.",
    data=_BOX, params=_box,
    answer=Value("frequency", mistakes=[
        Mistake(lambda e, p: p["sun"] * p["f_sun"], "You multiplied the sun's teeth by the sun's speed relative to "
                "the frame. Teeth come into mesh at the speed relative to the carrier, and the carrier turns."),
        Mistake(lambda e, p: p["planet"] * abs(_speeds(**p)["planet"]), "You used the planet's speed relative to "
                "the frame; use its speed relative to the carrier, which holds the planet's axis."),
        Mistake(lambda e, p: _speeds(**p)["ring"] * p["f_sun"], "That is the ring's teeth times the sun's speed; "
                "the ring is held, but the carrier is not."),
    ], generic="Find the carrier's speed first (ring held), then multiply a gear's teeth by its speed relative to "
               "the carrier."),
)
def adjacency_mesh_frequency(sun, planet, f_sun):
    return _table(sun, planet, f_sun).select(kind="mesh", pair=(1, 2))[0].frequency


@register(
    "adjacency_planet_tooth_frequency", exercise="4.3", title="A chipped planet tooth", stars=1, minutes=10,
    kind="compute",
    question=_GEARBOX + " One tooth of the planet is chipped. How many times per second does that tooth meet the "
                        "sun? Give the frequency in Hz.",
    data=_BOX, params=_box,
    answer=Value("frequency", mistakes=[
        Mistake(lambda e, p: abs(_speeds(**p)["planet"]), "That is the planet's speed relative to the frame. The "
                "defective tooth meets the sun once per turn of the planet relative to the carrier."),
        Mistake(lambda e, p: p["sun"] * _speeds(**p)["rel_sun"], "That is the mesh frequency: every tooth, not the "
                "one defective tooth."),
        Mistake(lambda e, p: _speeds(**p)["carrier"], "That is the carrier's speed; the planet turns relative to "
                "the carrier too."),
        Mistake(lambda e, p: p["f_sun"], "That is the sun's speed relative to the frame."),
    ], generic="The defect meets the sun once per revolution of the planet relative to the carrier."),
)
def adjacency_planet_tooth_frequency(sun, planet, f_sun):
    return _table(sun, planet, f_sun).select(kind="tooth", pair=(1, 2), link=2)[0].frequency


def _bpfo(f_r, inner=False, factor=True):
    z, d, big = 9, Fraction(6), Fraction(40)
    return Fraction(z, 2) * ((1 + d / big) if inner else (1 - d / big) if factor else 1) * f_r


@register(
    "adjacency_outer_ring_frequency", exercise="4.4", title="A defect on a planet bearing's outer ring", stars=2,
    minutes=15, kind="compute",
    question=_GEARBOX + " The planet turns on a ball bearing on the carrier's pin: inner ring on the pin (link 4), "
                        "outer ring in the planet (link 2); D_m = 40 mm, d_b = 6 mm, Z = 9 balls, no contact angle. "
                        "At what frequency (Hz) does a defect on the outer ring repeat?",
    data=_BOX, params=_box,
    answer=Value("frequency", mistakes=[
        Mistake(lambda e, p: _bpfo(abs(_speeds(**p)["planet"])), "You used the planet's speed relative to the "
                "frame. The bearing only sees the speed of its inner ring relative to its outer ring: planet "
                "relative to carrier."),
        Mistake(lambda e, p: _bpfo(abs(_speeds(**p)["rel_planet"]), inner=True), "That is the inner-ring "
                "frequency, (Z/2)(1 + d/D) f_r; the outer ring has (1 - d/D)."),
        Mistake(lambda e, p: _bpfo(abs(_speeds(**p)["rel_planet"]), factor=False), "You left out the factor "
                "(1 - d cos(alpha)/D_m): the cage carrying the balls does not turn at exactly half the relative "
                "speed."),
        Mistake(lambda e, p: 9 * abs(_speeds(**p)["rel_planet"]), "Z f_r counts every ball passing at the full "
                "relative speed; the cage carries the balls along at its own speed."),
    ], generic="Take f_r = |omega_inner - omega_outer| and the standard BPFO = (Z/2)(1 - d cos(alpha)/D_m) f_r."),
)
def adjacency_outer_ring_frequency(sun, planet, f_sun):
    return _table(sun, planet, f_sun, bearing=True).select(kind="outer ring", pair=(4, 2))[0].frequency
