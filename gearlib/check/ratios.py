"""Checks for the exercises 1.9 to 1.13 of chapter 1 (``exercises/01_graph_representation.ipynb``):
speeds and ratios of the chapter's differential and Humpage reducer with other speeds and
teeth, a bevel sign convention, and the design of a planetary reduction.
"""

from __future__ import annotations

import math
from fractions import Fraction

import sympy

from ._choice import Choice, Parts
from ._core import register
from ._design import Condition, Design
from ._value import Mistake, Symbolic, Value

__all__ = ["graph_case_symbolic", "graph_differential_pinion", "graph_bevel_sign", "graph_humpage_ratio",
           "graph_design_planetary"]


# ----------------------------------------------------------------------------- 1.9
_W3, _W4, _E35, _E45 = sympy.symbols("omega_3 omega_4 e_3_5 e_4_5")


@register(
    "graph_case_symbolic", exercise="1.9", title="Why the case turns at the mean of the wheels", stars=2,
    minutes=15, kind="derive",
    question="In the chapter's car differential the planet 5 meshes both side gears 3 and 4 on the case 7 (the "
             "carrier). From the Willis equations of the pairs (3, 5) and (4, 5), derive the case's speed omega_7 "
             "in terms of omega_3, omega_4, e_3_5 and e_4_5 (without assuming equal side gears).",
    answer=Symbolic(("omega_3", "omega_4", "e_3_5", "e_4_5"), mistakes=[
        Mistake(lambda e, p: (_W3 + _W4) / 2, "That is the special case e_4_5 = -e_3_5 (equal side gears facing "
                "each other); the question asks for the general formula."),
        Mistake(lambda e, p: (_E45 * _W3 - _E35 * _W4) / (_E45 - _E35), "The two ratios are exchanged: the "
                "equation of pair (3, 5) multiplies omega_3 - omega_7."),
    ], generic="Write omega_5 - omega_7 = e_3_5 (omega_3 - omega_7) and omega_5 - omega_7 = e_4_5 (omega_4 - "
               "omega_7), eliminate omega_5 and solve for omega_7."),
)
def graph_case_symbolic():
    w5, w7 = sympy.symbols("omega_5 omega_7")
    sol = sympy.solve([w5 - w7 - _E35 * (_W3 - w7), w5 - w7 - _E45 * (_W4 - w7)], [w5, w7], dict=True)[0]
    return sol[w7]


# ----------------------------------------------------------------------------- 1.10
def _wheels(rng) -> dict:
    a = rng.randint(12, 40)
    return {"w3": a, "w4": a + rng.choice((-1, 1)) * rng.randint(1, 8)}


def _pinion(w3, w4):
    from ..catalog import car_differential
    from ..mechanism.kinematics import speeds

    return speeds(car_differential(), ground=1, inputs={3: w3, 4: w4})[2]


@register(
    "graph_differential_pinion", exercise="1.10", title="The pinion of a differential", stars=1, minutes=10,
    kind="compute",
    question="In the chapter's car differential (pinion 2 with 13 teeth, crown 65 on the case 7; the catalogue "
             "gives the pinion-crown pair e_(2,7) = -1/5 for its chosen axis directions) the wheel shafts 3 and 4 "
             "turn at {w3} and {w4} rad/s, the frame held. How fast does the pinion turn, in rad/s, in the same "
             "convention?",
    data={"w3": 20, "w4": 24},
    params=_wheels,
    answer=Value("speed", mistakes=[
        Mistake(lambda e, p: Fraction(p["w3"] + p["w4"], 2), "That is the case's speed (the mean of the wheels); "
                "the pinion drives the crown wheel on the case."),
        Mistake(lambda e, p: -e, "The size is right; the sign is not: with e_(2,7) = -1/5, omega_7 = e_(2,7) "
                "omega_2."),
        Mistake(lambda e, p: [Fraction(p["w3"] + p["w4"], 10), Fraction(-(p["w3"] + p["w4"]), 10)],
                "You multiplied by N_pinion/N_crown; the pinion is the small gear, so it turns faster than the "
                "case."),
    ], generic="First find the case speed from the two wheels (exercise 1.9), then use the Willis equation of "
               "the pinion-crown pair, whose carrier is the frame."),
)
def graph_differential_pinion(w3, w4):
    return _pinion(w3, w4)


# ----------------------------------------------------------------------------- 1.11
_BEVEL = {
    "A": "Only the description changed: the sign of a bevel ratio says how the chosen axis directions relate, "
         "and the pinion turns exactly as before.",
    "B": "The pinion now turns the other way.",
    "C": "Bevel gears always turn the same way, so the ratio must be positive.",
    "D": "The sign of a bevel ratio is fixed by the tooth numbers.",
}


@register(
    "graph_bevel_sign", exercise="1.11", title="Bevel gears: a sign by convention", stars=2, minutes=15,
    kind="concept",
    question="In exercise 1.10 reverse the positive direction chosen for the pinion's axis (the gears themselves "
             "unchanged). With the wheels at {w3} and {w4} rad/s, give (a) e_(2,7) in the new convention, (b) "
             "the pinion's speed omega_2 in rad/s in the new convention, and (c) what changed physically "
             "(reason 'A', 'B', 'C' or 'D').",
    data={"w3": 18, "w4": 25},
    params=_wheels,
    answer=Parts({
        "ratio": ("e_(2,7)", Value("ratio", standard=False, mistakes=[
            Mistake(lambda e, p: -e, "That is the ratio of the old convention: reversing one axis direction "
                    "reverses the sign of every speed measured about it."),
            Mistake(lambda e, p: [1 / e, -1 / e], "e_(2,7) is omega_(7/1) over omega_(2/1): the crown's speed over "
                    "the pinion's.")])),
        "pinion": ("the pinion's speed", Value("speed", standard=False, mistakes=[
            Mistake(lambda e, p: -e, "That is the pinion's speed in the old convention: in the new one it is "
                    "measured about the reversed axis."),
            Mistake(lambda e, p: Fraction(p["w3"] + p["w4"], 2), "That is the case's speed (the mean of the "
                    "wheels).")])),
        "reason": ("the reason", Choice(_BEVEL, wrong={
            "B": "Nothing moved differently: only the sign with which the same rotation is written changed.",
            "C": "Perpendicular shafts do not turn 'the same way' or 'opposite ways': the sign depends on the "
                 "directions chosen for the two axes.",
            "D": "The tooth numbers fix the size of the ratio, not its sign."}))}),
)
def graph_bevel_sign(w3, w4):
    return {"ratio": Fraction(1, 5), "pinion": -_pinion(w3, w4), "reason": "A"}


# ----------------------------------------------------------------------------- 1.12
def _humpage(n1, n2, n3, n4, n5):
    from ..catalog import humpage

    m = humpage()
    m = m.with_gear_pair((1, 2), teeth=(n1, n2), ratio=Fraction(n1, n2), radii=(n1, n2))
    m = m.with_gear_pair((5, 2), teeth=(n5, n2), ratio=Fraction(-n5, n2), radii=(n5, n2))
    return m.with_gear_pair((2, 4), teeth=(n3, n4), ratio=Fraction(-n3, n4), radii=(n3, n4))


def _humpage_teeth(rng) -> dict:
    while True:
        n1, n2, n5 = rng.randint(16, 30), rng.randint(40, 64), rng.randint(60, 90)
        n3, n4 = rng.randint(16, 30), rng.randint(24, 44)
        if 0 < abs(n4 * n2 - n3 * n5) <= 60:
            return {"n1": n1, "n2": n2, "n3": n3, "n4": n4, "n5": n5}


@register(
    "graph_humpage_ratio", exercise="1.12", title="Humpage's reducer with other teeth", stars=3, minutes=30,
    kind="compute",
    question="Humpage's reducer (gl.catalog.humpage(): input 1, compound planet 2, output 4, frame 5, carrier 6) "
             "gets new gears: input gear 1 with {n1} teeth, planet gear of {n2} teeth meshing gear 1 and the "
             "fixed gear 5 ({n5} teeth), planet gear of {n3} teeth meshing the output gear 4 ({n4} teeth). With "
             "the catalogue's sign convention (e_(1,2) = +N_1/N_2, e_(5,2) = -N_5/N_2, e_(2,4) = -N_3/N_4), "
             "derive omega_4/omega_1 by hand, as an exact fraction.",
    data={"n1": 18, "n2": 50, "n3": 21, "n4": 30, "n5": 70},
    params=_humpage_teeth,
    answer=Value("ratio", exact=True, mistakes=[
        Mistake(lambda e, p: Fraction(p["n1"], p["n1"] + p["n5"]), "That is the carrier's speed ratio; continue to "
                "the output gear 4."),
        Mistake(lambda e, p: Fraction(-p["n1"] * p["n3"], p["n2"] * p["n4"]), "You used the planet as if its "
                "carrier were fixed; the carrier 6 turns, so work with speeds relative to it."),
    ], generic="Write the three Willis equations relative to the carrier 6, set omega_5 = 0, and eliminate the "
               "planet and the carrier."),
)
def graph_humpage_ratio(n1, n2, n3, n4, n5):
    from ..mechanism.kinematics import ratio

    return ratio(_humpage(n1, n2, n3, n4, n5), output=4, input=1, ground=5)


# ----------------------------------------------------------------------------- 1.13
def _reduction(d) -> Fraction:
    return 1 + Fraction(d["ring"], d["sun"])


def _design_conditions():
    return [
        Condition("tooth numbers", lambda d, p: all(17 <= d[k] <= 150 for k in ("sun", "planet", "ring")),
                  "every gear needs at least 17 teeth (no undercut) and at most 150."),
        Condition("concentric", lambda d, p: d["ring"] == d["sun"] + 2 * d["planet"],
                  "with one module the planet fits between sun and ring only when N_ring = N_sun + 2 N_planet."),
        Condition("reduction", lambda d, p: abs(_reduction(d) / Fraction(p["target"]) - 1) <= Fraction(1, 100),
                  lambda d, p: f"your reduction omega_sun/omega_carrier is {float(_reduction(d)):.4g}; the target "
                               f"is {p['target']} within 1 %."),
        Condition("equal spacing", lambda d, p: (d["sun"] + d["ring"]) % p["planets"] == 0,
                  lambda d, p: f"{p['planets']} planets can be spaced equally only when (N_sun + N_ring)/"
                               f"{p['planets']} is a whole number."),
        Condition("clearance", lambda d, p: d["planet"] + 2 < (d["sun"] + d["planet"]) * math.sin(math.pi / p["planets"]),
                  "neighbouring planets would touch: their tips need N_planet + 2 < (N_sun + N_planet) "
                  "sin(180 degrees / number of planets)."),
    ]


def _design_example(p):
    conditions = _design_conditions()
    for sun in range(17, 151):
        for planet in range(17, 151):
            d = {"sun": sun, "planet": planet, "ring": sun + 2 * planet}
            if all(c.test(d, p) for c in conditions):
                return d
    return None


def _design_params(rng) -> dict:
    while True:
        p = {"target": f"{rng.randint(40, 80) / 10:.1f}", "planets": rng.choice((3, 4))}
        if _design_example(p) is not None:
            return p


@register(
    "graph_design_planetary", exercise="1.13", title="Design a planetary reduction", stars=3, minutes=30,
    kind="design",
    question="Choose the teeth of a simple planetary (ring held, sun in, carrier out) with {planets} planets "
             "equally spaced, so that the reduction omega_sun/omega_carrier is {target} within 1 %. Every gear "
             "has 17 to 150 teeth, all gears have one module (concentric), and neighbouring planets must not "
             "touch. Give {'sun': ..., 'planet': ..., 'ring': ...}.",
    data={"target": "5.6", "planets": 3},
    params=_design_params,
    answer=Design({"sun": "teeth", "planet": "teeth", "ring": "teeth"}, _design_conditions(),
                  example=_design_example),
)
def graph_design_planetary(target, planets):
    return None
