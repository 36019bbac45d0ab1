"""Checks for the exercises of chapter 0, the introduction (``exercises/00_introduction.ipynb``):
gear ratios, Willis' equation and the simple planetary of :mod:`gearlib.mechanism`.

Each exercise uses numbers the chapter does not show (the chapter's planetary has 24, 18 and
60 teeth, with the ring held); variants draw other ones.
"""

from __future__ import annotations

from fractions import Fraction

import sympy

from ._choice import Choice, Parts
from ._core import Prediction, register
from ._value import Mistake, Symbolic, Value

__all__ = ["intro_gear_ratio", "intro_planetary_ratio", "intro_sun_held", "intro_star", "intro_willis_frame",
           "intro_data_sheet"]


def _planetary(sun: int, planet: int, ring: int):
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict({
        "links": {1: "sun", 2: "planet", 3: "ring", 4: "carrier"},
        "turning_pairs": [[4, 1, "a"], [4, 3, "a"], [4, 2, "b"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [sun, planet]},
                       {"gears": [2, 3], "teeth": [planet, ring], "type": "internal"}],
    })


def _planetary_teeth(rng, sun=(16, 40), planet=(14, 40)) -> dict:
    s, p = rng.randint(*sun), rng.randint(*planet)
    return {"sun": s, "planet": p, "ring": s + 2 * p}


# ----------------------------------------------------------------------------- 0.1
@register(
    "intro_gear_ratio", exercise="0.1", title="The gear ratio of an external pair", stars=1, minutes=5,
    kind="compute",
    question="Two spur gears on a fixed frame mesh externally: gear 1 has N_1 = {N1} teeth, gear 2 has "
             "N_2 = {N2}. Give the gear ratio e_(1,2), sign included.",
    data={"N1": 21, "N2": 56},
    params=lambda rng: {"N1": rng.randint(12, 30), "N2": rng.randint(36, 90)},
    answer=Value("ratio", mistakes=[
        Mistake(lambda e, p: Fraction(-p["N2"], p["N1"]), "That is e_(2,1), gear 1's speed over gear 2's: e_(1,2) "
                "is omega_(2/c) / omega_(1/c), the second gear's speed over the first's."),
    ], generic="e_(1,2) is the speed of gear 2 over the speed of gear 1, both relative to the carrier (here the "
               "frame); an external mesh reverses the direction."),
)
def intro_gear_ratio(N1, N2):
    from ..mechanism.elements import GearPair

    return GearPair(gears=(1, 2), teeth=(N1, N2)).e


# ----------------------------------------------------------------------------- 0.2
@register(
    "intro_planetary_ratio", exercise="0.2", title="A planetary with the ring held, by hand", stars=2, minutes=15,
    kind="compute",
    question="A simple planetary has a sun of {sun} teeth, a planet of {planet} and a ring of {ring}. The ring is "
             "held and the sun drives. Write the two Willis equations by hand, eliminate the planet, and give the "
             "speed ratio omega_carrier / omega_sun.",
    data={"sun": 30, "planet": 21, "ring": 72},
    params=lambda rng: _planetary_teeth(rng),
    answer=Value("ratio", mistakes=[
        Mistake(lambda e, p: 1 - e, "That is the sun's speed relative to the carrier over the sun's speed; the "
                "question asks for the carrier's own speed (relative to the held ring)."),
        Mistake(lambda e, p: Fraction(p["ring"], p["sun"]), "That is N_ring/N_sun: write the two Willis equations "
                "relative to the carrier and eliminate the planet's speed."),
        Mistake(lambda e, p: Fraction(p["sun"], p["ring"]), "That is N_sun/N_ring, the size of the ratio of ring to "
                "sun with the carrier held; here the ring is held and the carrier turns."),
        Mistake(lambda e, p: Fraction(-p["sun"], p["planet"]), "That is e_(1,2), the sun-planet mesh alone; the "
                "planet also meshes the ring, and the carrier turns."),
    ], generic="Write the Willis equation of each mesh relative to the carrier, set the ring's speed to 0, and "
               "eliminate the planet's speed."),
)
def intro_planetary_ratio(sun, planet, ring):
    from ..mechanism.kinematics import ratio

    return ratio(_planetary(sun, planet, ring), output=4, input=1, ground=3)


# ----------------------------------------------------------------------------- 0.3
_E12, _E23 = sympy.Symbol("e_1_2"), sympy.Symbol("e_2_3")


@register(
    "intro_sun_held", exercise="0.3", title="The planetary in symbols, with the sun held", stars=2, minutes=15,
    kind="derive",
    question="In the chapter's planetary (sun 1, planet 2, ring 3, carrier 4) hold the sun instead of the ring "
             "and drive the ring. Derive omega_4 / omega_3 in the gear-ratio symbols e_1_2 and e_2_3.",
    answer=Symbolic(("e_1_2", "e_2_3"), values=lambda p: {"e_1_2": Fraction(-24, 18), "e_2_3": Fraction(18, 60)},
                    mistakes=[
        Mistake(lambda e, p: _E12 * _E23 / (_E12 * _E23 - 1), "That is the carrier over the sun with the ring "
                "held, the chapter's case; here the sun is held (omega_1 = 0) and the ring drives."),
        Mistake(lambda e, p: 1 - _E12 * _E23, "That is omega_3/omega_4, the ring over the carrier: the question "
                "asks for the carrier over the ring."),
        Mistake(lambda e, p: 1 / (1 - _E12), "Only the sun-planet mesh appears: the planet's speed must be "
                "eliminated with the planet-ring mesh as well."),
    ], generic="Write omega_2 - omega_4 = e_1_2 (omega_1 - omega_4) and omega_3 - omega_4 = e_2_3 (omega_2 - "
               "omega_4), put omega_1 = 0, and eliminate omega_2."),
)
def intro_sun_held():
    from ..mechanism.kinematics import ratio

    return ratio(_planetary(24, 18, 60), output=4, input=3, ground=1, method="symbolic")


# ----------------------------------------------------------------------------- 0.4
_STAR = Choice(["same way, faster", "same way, slower", "opposite way, faster", "opposite way, slower"])


def _star_truth(reference, params):
    r = Fraction(params["sun"], params["ring"])
    return "opposite way, " + ("slower" if r < 1 else "faster")


@register(
    "intro_star", exercise="0.4", title="Predict, then compute: the carrier held", stars=1, minutes=10,
    kind="predict",
    question="A planetary with a sun of {sun} teeth, planets of {planet} and a ring of {ring} has its carrier "
             "held, and the sun drives. First predict how the ring turns compared with the sun (same way or "
             "opposite way, faster or slower) and record it; then compute omega_ring / omega_sun.",
    data={"sun": 22, "planet": 25, "ring": 72},
    params=lambda rng: _planetary_teeth(rng),
    answer=Value("ratio", mistakes=[
        Mistake(lambda e, p: Fraction(-p["sun"], p["planet"]), "That is the planet's speed over the sun's; continue "
                "through the planet-ring mesh to the ring."),
        Mistake(lambda e, p: Fraction(-p["planet"], p["ring"]), "That is e_(2,3) with the wrong sign: the whole train "
                "runs from the sun through the planet to the ring, and the planet-ring mesh is internal."),
    ]),
    predict=Prediction(_STAR, _star_truth, "With the carrier held every axis is fixed: the external sun-planet mesh "
                       "reverses the direction, the internal planet-ring mesh keeps it, and the larger ring turns "
                       "slower than the sun."),
)
def intro_star(sun, planet, ring):
    from ..mechanism.kinematics import ratio

    return ratio(_planetary(sun, planet, ring), output=3, input=1, ground=4)


# ----------------------------------------------------------------------------- 0.5
_FRAME = Choice(["the frame", "the carrier", "gear a", "gear b"], synonyms={
    "the frame": ["frame", "housing", "ground"], "the carrier": ["carrier", "arm", "c"],
    "gear a": ["a", "the first gear"], "gear b": ["b", "the second gear"]},
    wrong={"the frame": "The frame holds both gear axes only when it is the pair's carrier: in a planetary the "
                        "planet's axis moves relative to the frame."},
    generic="Relative to one of the two gears, that gear does not turn at all: the ratio would be 0 or undefined.")
_REASONS = {
    "A": "Relative to it both gear axes stand still, so the pair is an ordinary pair of gears on fixed axes, "
         "and the speeds are in the inverse ratio of the teeth.",
    "B": "It is the link that is held in every mechanism of the book.",
    "C": "Its speed is zero, so the relative speeds are the absolute ones.",
    "D": "Any link would do: a ratio of two speeds does not depend on the link they are measured from.",
}
_REASON = Choice(_REASONS, wrong={
    "B": "A carrier need not be held: in a planetary with the ring held, the carrier turns.",
    "C": "The carrier of the planet's meshes turns in most planetaries; Willis' equation holds all the same.",
    "D": "The ratio changes with the reference: in the chapter's planetary (omega_2/omega_1) is not "
         "(omega_2 - omega_4)/(omega_1 - omega_4)."})


@register(
    "intro_willis_frame", exercise="0.5", title="Why Willis' ratio is taken relative to the carrier", stars=1,
    minutes=5, kind="concept",
    question="The gear ratio e_(a,b) of a gear pair is the ratio of the two gears' speeds relative to one link. "
             "Which link ('the frame', 'the carrier', 'gear a' or 'gear b'), and why (reason 'A', 'B', 'C' or 'D' "
             "of the exercise)?",
    answer=Parts({"link": ("the link", _FRAME), "reason": ("the reason", _REASON)}),
)
def intro_willis_frame():
    return {"link": "the carrier", "reason": "A"}


# ----------------------------------------------------------------------------- 0.6
_SHEET = {
    "A": "The planet does not fit between the sun and the ring: with one module, N_ring = N_sun + 2 N_planet.",
    "B": "A ring gear must have an even number of teeth.",
    "C": "The sun must have more teeth than the planet.",
    "D": "With the ring held, the carrier would turn backwards.",
}


def _sheet(rng) -> dict:
    sun, planet = rng.randint(16, 40), rng.randint(14, 36)
    return {"sun": sun, "planet": planet, "printed_ring": sun + 2 * planet + rng.choice((-6, -4, -3, 3, 4, 6))}


@register(
    "intro_data_sheet", exercise="0.6", title="Find the mistake in a data sheet", stars=1, minutes=10,
    kind="mistake",
    question="A data sheet lists a simple planetary, all gears of one module, with a sun of {sun} teeth, planets of "
             "{planet} and a ring of {printed_ring}. These numbers cannot all be right. Give (a) the condition they "
             "break (reason 'A', 'B', 'C' or 'D'), (b) the ring's number of teeth if the sun and the planets are "
             "right, and (c) with that ring held and the sun driving, the ratio omega_carrier / omega_sun.",
    data={"sun": 21, "planet": 27, "printed_ring": 72},
    params=_sheet,
    answer=Parts({
        "reason": ("the reason", Choice(_SHEET, wrong={
            "B": "Rings with an odd number of teeth are made and run; the trouble is elsewhere.",
            "C": "Planets larger than the sun are common (a large reduction needs them).",
            "D": "With the ring held the carrier always turns the same way as the sun; the trouble is elsewhere."})),
        "ring": ("the ring's teeth", Value("count", mistakes=[
            Mistake(lambda e, p: p["sun"] + p["planet"], "Across the ring's pitch diameter lie the sun and two "
                    "planets, one on each side."),
            Mistake(lambda e, p: p["printed_ring"], "That is the printed number, which does not fit."),
        ], generic="Lay the pitch diameters across the centre: the ring's spans the sun's and two planets'.")),
        "ratio": ("the ratio", Value("ratio", mistakes=[
            Mistake(lambda e, p: Fraction(p["sun"], p["sun"] + p["printed_ring"]), "That uses the printed ring, "
                    "which does not fit: use the ring of part (b)."),
        ])),
    }),
)
def intro_data_sheet(sun, planet, printed_ring):
    from ..mechanism.kinematics import ratio

    ring = sun + 2 * planet
    return {"reason": "A", "ring": ring, "ratio": ratio(_planetary(sun, planet, ring), output=4, input=1, ground=3)}
