"""Checks for exercises 6.7 to 6.9 of chapter 6 (``exercises/06_differential_synthesis.ipynb``):
a double-planet centre differential, which the chapter does not show. A sun and a ring turn
on the central axis with the carrier; each planet pair on the carrier has an inner planet that
meshes the sun and an outer planet that meshes the ring, and the two planets mesh each other.
With the housing held it is a three-terminal differential (sun, ring, carrier), as in C1 to
C3 of the chapter: exercise 6.7 models it as data, 6.8 finds how it splits a torque, 6.9
chooses its teeth for an equal split.

Geometry (exercise 6.9): one module for every gear, tips one module beyond the pitch circle;
the inner planet's centre is at (N_sun + N_inner)/2 from the axis, the outer planet's at
(N_ring - N_outer)/2, and the two are (N_inner + N_outer)/2 apart. With the ring held, moving
the carrier on by one pair (2 pi / k) turns the sun by (N_ring - N_sun)/k teeth, so k pairs can
be spaced equally only when that is a whole number.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ._choice import Choice, Parts
from ._core import register
from ._design import Condition, Design
from ._model import Model, Scenario
from ._value import Mistake, Value

__all__ = ["diff_model", "diff_torque_split", "diff_equal_split"]

ROLES = ("housing", "carrier", "sun", "ring", "inner planet", "outer planet")


def _centre_differential(sun: int, inner: int, outer: int, ring: int):
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict({
        "name": "double-planet centre differential",
        "links": {0: "housing", 1: "sun", 2: "inner planet", 3: "outer planet", 4: "ring", 5: "carrier"},
        "turning_pairs": [[0, 5, "a"], [5, 1, "a"], [5, 4, "a"], [5, 2, "b"], [5, 3, "c"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [sun, inner]}, {"gears": [2, 3], "teeth": [inner, outer]},
                       {"gears": [3, 4], "teeth": [outer, ring], "type": "internal"}],
    })


# ----------------------------------------------------------------------------- geometry of a design
def _radii(d) -> tuple:
    """Centre radii of the inner and outer planet, and their centre distance (module 1)."""
    return (d["sun"] + d["inner"]) / 2, (d["ring"] - d["outer"]) / 2, (d["inner"] + d["outer"]) / 2


def _mesh_each_other(d) -> bool:
    a1, a2, dist = _radii(d)
    return a1 > 0 and a2 > 0 and abs(a1 - a2) < dist < a1 + a2


def _clear_of_sun_and_ring(d) -> bool:
    return d["ring"] - d["sun"] - 2 * d["outer"] > 4 and d["ring"] - d["sun"] - 2 * d["inner"] > 4


def _planets(d, k: int) -> list:
    """``(x, y, tip radius, pair, kind)`` of every planet, pairs spaced 2 pi / k apart."""
    a1, a2, dist = _radii(d)
    phi = math.acos(max(-1.0, min(1.0, (a1 * a1 + a2 * a2 - dist * dist) / (2 * a1 * a2))))
    out = []
    for j in range(k):
        t = 2 * math.pi * j / k
        out.append((a1 * math.cos(t), a1 * math.sin(t), (d["inner"] + 2) / 2, j, "inner"))
        out.append((a2 * math.cos(t + phi), a2 * math.sin(t + phi), (d["outer"] + 2) / 2, j, "outer"))
    return out


def _neighbours_clear(d, k: int) -> bool:
    if not _mesh_each_other(d):
        return False
    planets = _planets(d, k)
    for i, (x1, y1, r1, j1, k1) in enumerate(planets):
        for x2, y2, r2, j2, k2 in planets[i + 1:]:
            if j1 == j2 and k1 != k2:
                continue  # the two planets of one pair mesh
            if math.hypot(x1 - x2, y1 - y2) <= r1 + r2:
                return False
    return True


def _split(d) -> Fraction:
    """|T_sun| / |T_carrier| with the ring driven: N_sun / (N_ring - N_sun)."""
    return Fraction(d["sun"], d["ring"] - d["sun"])


def _conditions():
    def torque_message(d, p):
        side = "less" if _split(d) < 1 else "more"
        return (f"the sun's axle gets {side} torque than the carrier's: with the ring driven the output torques are "
                "in the ratio of their coefficients in the constraint among sun, ring and carrier (exercise 6.8); "
                "make them equal within 1 %")

    return [
        Condition("tooth numbers", lambda d, p: all(14 <= d[k] <= 200 for k in ("sun", "inner", "outer", "ring")),
                  "every gear needs 14 to 200 teeth"),
        Condition("equal torque", lambda d, p: d["ring"] > d["sun"] and abs(_split(d) - 1) <= Fraction(1, 100),
                  torque_message),
        Condition("planets mesh", lambda d, p: _mesh_each_other(d),
                  "the two planets of a pair cannot mesh each other: their centres are (N_inner + N_outer)/2 apart, "
                  "at (N_sun + N_inner)/2 and (N_ring - N_outer)/2 from the axis, and those three lengths must form "
                  "a triangle"),
        Condition("clear of sun and ring", lambda d, p: _clear_of_sun_and_ring(d),
                  "a planet touches a central gear it does not mesh: the outer planet must clear the sun, and the "
                  "inner planet the ring (tips one module beyond the pitch circles)"),
        Condition("equal spacing", lambda d, p: (d["ring"] - d["sun"]) % p["pairs"] == 0,
                  lambda d, p: f"{p['pairs']} pairs cannot be spaced equally: with the ring held, moving the carrier "
                               f"on by one pair turns the sun by (N_ring - N_sun)/{p['pairs']} teeth, which must be a "
                               "whole number"),
        Condition("neighbouring pairs", lambda d, p: _neighbours_clear(d, p["pairs"]),
                  "planets of neighbouring pairs overlap: make the planets smaller or the central gears larger"),
    ]


def _design_example(p):
    conditions = _conditions()
    for sun in range(14, 150):
        for ring in range(2 * sun - 3, 2 * sun + 4):
            if abs(Fraction(sun, ring - sun) - 1) > Fraction(1, 100) or (ring - sun) % p["pairs"]:
                continue
            largest = (ring - sun - 5) // 2  # clear of sun and ring
            for inner in range(14, largest + 1):
                for outer in range(14, largest + 1):
                    d = {"sun": sun, "inner": inner, "outer": outer, "ring": ring}
                    if all(c.test(d, p) for c in conditions):
                        return d
    return None


# ----------------------------------------------------------------------------- teeth of 6.7 and 6.8
def _feasible(d) -> bool:
    return (all(14 <= d[k] <= 200 for k in ("sun", "inner", "outer", "ring")) and _mesh_each_other(d)
            and _clear_of_sun_and_ring(d) and abs(_split(d) - 1) > Fraction(1, 10))


def _teeth(rng) -> dict:
    while True:
        d = {"sun": rng.randint(20, 40), "inner": rng.randint(14, 20), "outer": rng.randint(14, 20)}
        d["ring"] = d["sun"] + 2 * max(d["inner"], d["outer"]) + rng.randint(5, 24)
        if _feasible(d):
            return d


_BOOK = {"sun": 30, "inner": 17, "outer": 19, "ring": 78}


# ----------------------------------------------------------------------------- 6.7
@register(
    "diff_model", exercise="6.7", title="From a description to data: a double-planet differential", stars=2,
    minutes=20, kind="model",
    question="A centre differential for a four-wheel-drive car: a housing; a carrier turning in the housing on the "
             "central axis; a sun gear ({sun} teeth) and an internal ring gear ({ring} teeth) turning on the central "
             "axis; on the carrier, planet pairs, each an inner planet ({inner} teeth, meshing the sun) and an outer "
             "planet ({outer} teeth, meshing the ring), on their own pins, the two planets of a pair meshing each "
             "other. Model one planet pair (the others repeat its motion) as data for gl.Mechanism.from_dict, with "
             "the links named 'housing', 'carrier', 'sun', 'ring', 'inner planet' and 'outer planet'.",
    data=_BOOK,
    params=_teeth,
    answer=Model(ROLES, [Scenario("housing", {"sun": 1, "ring": 0}), Scenario("housing", {"sun": 0, "carrier": 1}),
                         Scenario("housing", {"ring": 3, "carrier": -2})]),
)
def diff_model(sun, inner, outer, ring):
    return _centre_differential(sun, inner, outer, ring)


# ----------------------------------------------------------------------------- 6.8
_WHY = {
    "A": "With no losses the power that enters at the terminals adds up to zero, T_s omega_s + T_r omega_r + "
         "T_c omega_c = 0, for every motion the differential allows; those motions are all the speeds that satisfy "
         "the constraint, so the torques are perpendicular to all of them, that is a multiple of the coefficients.",
    "B": "Each torque is inversely proportional to its terminal's speed, as in a pair of gears.",
    "C": "Each of the sun, the ring and the carrier takes a torque in proportion to its number of teeth.",
    "D": "No gear is fixed to the housing, so the three terminal torques add up to zero.",
}


@register(
    "diff_torque_split", exercise="6.8", title="How a differential splits a torque", stars=2, minutes=20,
    kind="concept",
    question="In the centre differential of exercise 6.7, with a sun of {sun} teeth and a ring of {ring} (the "
             "planets do not matter here), the ring is driven and the sun and the carrier drive the two axles. With "
             "no losses and steady speeds, give (a) the ratio |T_sun| / |T_carrier| of the torques the two axles "
             "get, and (b) why the three terminal torques are proportional to the coefficients of the constraint "
             "a_s omega_s + a_r omega_r + a_c omega_c = 0 (reason 'A', 'B', 'C' or 'D').",
    data={"sun": _BOOK["sun"], "ring": _BOOK["ring"]},
    params=lambda rng: {k: v for k, v in _teeth(rng).items() if k in ("sun", "ring")},
    answer=Parts({
        "ratio": ("the torque ratio", Value("number", standard=False, mistakes=[
            Mistake(lambda e, p: 1 / e, "That is the carrier's torque over the sun's: the question asks for the "
                    "sun's over the carrier's."),
            Mistake(lambda e, p: Fraction(p["sun"], p["ring"]), "That is the sun's torque over the ring's (the "
                    "input): compare the two outputs, the sun and the carrier."),
            Mistake(lambda e, p: Fraction(p["ring"] - p["sun"], p["ring"]), "That is the carrier's torque over the "
                    "ring's (the input): compare the two outputs, the sun and the carrier."),
            Mistake(lambda e, p: Fraction(p["sun"], p["sun"] + p["ring"]), "That ratio belongs to a simple planetary "
                    "(one planet per pair): here two external meshes and one internal mesh join sun and ring, "
                    "relative to the carrier."),
            Mistake(lambda e, p: 1, "The two axles get equal torque only for particular teeth (exercise 6.9); work "
                    "out the constraint first."),
        ], generic="Write the three Willis equations relative to the carrier, eliminate the two planets to get the "
                   "constraint among sun, ring and carrier, and compare the coefficients of the sun and the "
                   "carrier.")),
        "reason": ("the reason", Choice(_WHY, wrong={
            "B": "That holds in a one-dof train, whose speeds are tied in a fixed proportion; a differential's "
                 "terminal speeds are not, yet its torques are.",
            "C": "The carrier has no teeth and still takes a torque: the proportion comes from the motions the "
                 "mechanism allows, not from the teeth of each terminal.",
            "D": "True here, and it makes the three torques add up to zero; but that is one equation, which does not "
                 "say how the torques split."}))}),
)
def diff_torque_split(sun, ring):
    return {"ratio": _split({"sun": sun, "ring": ring}), "reason": "A"}


# ----------------------------------------------------------------------------- 6.9
def _pairs(rng) -> dict:
    return {"pairs": rng.choice((3, 4, 5))}


@register(
    "diff_equal_split", exercise="6.9", title="Design: teeth for an equal torque split", stars=3, minutes=35,
    kind="design",
    question="Choose the teeth of the centre differential of exercise 6.7 (ring driven, sun and carrier to the "
             "axles) so that the two axles get equal torque within 1 %, with {pairs} planet pairs equally spaced. "
             "All gears have one module, every gear has 14 to 200 teeth, the inner planet meshes the sun and the "
             "outer planet, the outer planet meshes the ring, and no planet may touch a gear it does not mesh (tips "
             "one module beyond the pitch circle). Give {'sun': ..., 'inner': ..., 'outer': ..., 'ring': ...}.",
    data={"pairs": 3},
    params=_pairs,
    answer=Design({"sun": "teeth", "inner": "teeth", "outer": "teeth", "ring": "teeth"}, _conditions(),
                  example=_design_example),
)
def diff_equal_split(pairs):
    return None
