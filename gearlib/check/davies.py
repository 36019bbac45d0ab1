"""Checks for the exercises 5.1 to 5.6, 5.11 and 5.13 to 5.15 of chapter 5, Davies' efficiency
(``exercises/05_davies_efficiency.ipynb``); exercises 5.7 to 5.10 and 5.12 are in
:mod:`gearlib.check.efficiency`.

Efficiencies are checked as efficiencies (exchanged input and output, the loss instead of the
efficiency, one mesh or the product of the meshes), the friction coefficient as a length.
The chapter computes the simple pair with bearing efficiencies, the epicyclic train at 0.99
per mesh and Humpage's reducer at 0.98 and 0.99 per mesh: the exercises use bearing
coefficients (5.2), 0.98 per mesh (5.3), other teeth (5.4), a different efficiency per mesh
(5.5), other efficiencies (5.11), the ZF 8HP70 in second gear with other mesh efficiencies
(5.13), Chen, Yao and Lee's differential at another operating point (5.14) and a compound
train's coupling graph (5.15); variants draw other numbers.
"""

from __future__ import annotations

from fractions import Fraction

import sympy

from ._choice import Choice, LinkId, Parts
from ._core import register
from ._design import Matrix
from ._value import Mistake, Value

__all__ = ["davies_pair_zeta", "davies_pair_bearings", "davies_epicyclic_efficiency", "davies_recirculation",
           "davies_humpage_efficiency", "davies_humpage_driver", "davies_humpage_axis", "davies_second_gear",
           "davies_differential", "davies_circuit_matrix"]


def _eta(rng, lo=95, hi=99) -> float:
    return rng.randint(lo * 10, hi * 10) / 1000


def _pair_zeta(eta, driver_first=True):
    r1, r2 = 1, 2
    return r1 * r2 * (1 - eta) / (r1 + eta * r2) if driver_first else r1 * r2 * (1 - eta) / (r2 + eta * r1)


def _pair():
    from ..catalog import load

    return load("laus_simple_pair")


@register(
    "davies_pair_zeta", exercise="5.1", title="The friction coefficient of a mesh", stars=2, minutes=20,
    kind="compute",
    question="A spur pair with pitch radii r1 = 1 and r2 = 2 (gl.catalog.load('laus_simple_pair')), gear 1 "
             "driving, has the ordinary efficiency eta_12 = {eta}. Derive the Coulomb coefficient zeta of the mesh "
             "(a positive length, in the unit of the radii).",
    data={"eta": 0.97}, params=lambda rng: {"eta": _eta(rng)},
    answer=Value("length", figures=4, mistakes=[
        Mistake(lambda e, p: _pair_zeta(p["eta"], driver_first=False), "That is the coefficient for gear 2 "
                "driving gear 1. Here gear 1 drives: the power reaching gear 2 is eta_12 times the power gear 1 "
                "sends into the mesh."),
        Mistake(lambda e, p: 1 - p["eta"], "That is 1 - eta_12: zeta is a length (a lever arm), and it depends on "
                "both radii."),
        Mistake(lambda e, p: -e, "The size is right; the sign is not: zeta is asked as a positive length (the "
                "library's signed coefficient is minus it here)."),
    ], standard=False, generic="Write the mesh action as U (contact force) plus a friction torque zeta*U, take the "
                               "powers at gear 1 and gear 2 relative to the frame, and solve eta_12 = P_21/P_12 for "
                               "zeta."),
)
def davies_pair_zeta(eta):
    from ..davies import efficiency

    return abs(efficiency(_pair(), 0, 1, 2, eta=eta).meshes[0].zeta)


def _bearing_params(rng) -> dict:
    return {"eta": _eta(rng, 95, 99), "zA": rng.randint(5, 20) / 1000, "zB": rng.randint(10, 40) / 1000}


def _eq49(eta, zA, zB, swap=False, mesh=True) -> float:
    """Laus's eq. (49) for r1 = 1, r2 = 2, gear 1 driving, with the positive coefficients."""
    z = _pair_zeta(eta) if mesh else 0
    if swap:
        zA, zB = zB, zA
    return 1 * (2 - zB - z) / (2 * (1 + zA + z))


@register(
    "davies_pair_bearings", exercise="5.2", title="Mesh and bearing friction together", stars=2, minutes=20,
    kind="compute",
    question="The pair of exercise 5.1 (r1 = 1, r2 = 2, gear 1 driving) with eta_12 = {eta} also has Coulomb friction "
             "in its two bearings: revolute A (gear 1, the input shaft) with the positive coefficient zeta_A = {zA} "
             "and revolute B (gear 2, the output shaft) with zeta_B = {zB}, lengths in the unit of the radii (the "
             "friction torque is zeta times the bearing's radial force). What is the overall efficiency of the pair?",
    data={"eta": 0.97, "zA": 0.012, "zB": 0.03}, params=_bearing_params,
    answer=Value("efficiency", figures=4, mistakes=[
        Mistake(lambda e, p: p["eta"], "That is the mesh alone: the two bearings take their share as well."),
        Mistake(lambda e, p: _eq49(p["eta"], p["zA"], p["zB"], swap=True), "The two bearing coefficients are "
                "exchanged: the friction of bearing A adds to the lever arm of the input torque on gear 1, that of "
                "bearing B subtracts from the lever arm of the contact force on gear 2."),
        Mistake(lambda e, p: _eq49(p["eta"], p["zA"], p["zB"], mesh=False), "That leaves out the mesh: its "
                "coefficient zeta_12 (from eta_12) adds to both lever arms together with the bearings'."),
        Mistake(lambda e, p: p["eta"] * (1 - p["zA"]) * (1 - p["zB"]), "A Coulomb coefficient is a length (a lever "
                "arm of the radial force), not a share of the power: it enters the torque balance of each gear."),
    ], generic="Find zeta_12 from eta_12 first; then write the torque balance of each gear with the contact force "
               "and the bearing's friction torque zeta |U| (Laus's eq. 49), and take -P_B/P_A."),
)
def davies_pair_bearings(eta, zA, zB):
    from ..davies import efficiency

    return efficiency(_pair(), 0, 1, 2, eta=eta, bearings={"A": zA, "B": zB}).value


def _epicyclic(z2=60, z4=35):
    from ..catalog import load

    mech = load("laus_epicyclic")
    if (z2, z4) != (60, 35):
        mech = mech.with_gear_pair((2, 3), teeth=(z2, z4), radii=(z2, z4))
    return mech


@register(
    "davies_epicyclic_efficiency", exercise="5.3", title="Which formula: the epicyclic train", stars=2,
    minutes=20, kind="compute",
    question="Laus's epicyclic train of the chapter (gl.catalog.load('laus_epicyclic'): annulus 1 held, carrier 5 "
             "the input, annulus 2 the output; z = 80, 60, 30, 35, pitch radii 40, 60, 15 and 35 mm). Both meshes "
             "have the ordinary efficiency {eta}. Decide which gear drives in each mesh, choose the right formula "
             "of Table 5 and give the overall efficiency.",
    data={"eta": 0.98}, params=lambda rng: {"eta": _eta(rng, 96, 99)},
    answer=Value("efficiency", figures=4, meshes=lambda p: [p["eta"], p["eta"]], mistakes=[
        Mistake(lambda e, p: _epicyclic_formula(p["eta"], 78), "That is eq. (78), the formula for "
                "annulus 2 as the input: the input/output choice decides which formula applies, and here the "
                "carrier drives."),
        Mistake(lambda e, p: _epicyclic_formula(p["eta"], 77), "That is eq. (77), which holds when r1 > r2: "
                "compare the pitch radii (40 and 60 mm), not the tooth numbers (80 and 60)."),
    ], generic="Find which gear drives in each mesh from the virtual power flow relative to the carrier, then use "
               "the matching formula of Table 5."),
)
def davies_epicyclic_efficiency(eta):
    from ..davies import efficiency

    return efficiency(_epicyclic(), 1, 5, 2, eta=eta).value


def _epicyclic_formula(eta, eq: int):
    """Laus's eqs. (76)-(78) (Table 5) for the chapter's radii: r1 r4 = 1400, r2 r3 = 900."""
    e2, a, b = eta * eta, 1400, 900
    return {76: e2 * (a - b) / (a - e2 * b), 77: (b - a) / (b - e2 * a), 78: (b - e2 * a) / (b - a)}[eq]


def _recirculation_teeth(rng) -> dict:
    z4 = rng.randint(33, 45)
    return {"z2": z4 + 25, "z4": z4}


@register(
    "davies_recirculation", exercise="5.4", title="Power that recirculates", stars=2, minutes=15, kind="compute",
    question="In the same train replace annulus 2 and the planet gear 4 by gears with {z2} and {z4} teeth (still "
             "module 2 mm, so that r1 - r3 = r2 - r4 still holds). Without losses, how much power flows through "
             "the mesh between annulus 1 and planet gear 3, as seen from the carrier, per unit input power? "
             "Derive it from Laus's eq. (69).",
    data={"z2": 64, "z4": 39}, params=_recirculation_teeth,
    answer=Value("number", mistakes=[
        Mistake(lambda e, p: 1, "That is the real power flow (seen from the frame). Measure the flow from the "
                "carrier 5."),
        Mistake(lambda e, p: Fraction(14, 5), "That is the value for the chapter's train (60 and 35 teeth); the "
                "radii changed."),
        Mistake(lambda e, p: -e, "The size is right; the sign is not: with the carrier as input, annulus 1 drives "
                "gear 3 in this mesh."),
    ], standard=False, generic="Relative to the carrier the flow through mesh 1-3 is T_A t_A r1 r4 / (r1 r4 - r2 "
                               "r3), with the pitch radii in mm."),
)
def davies_recirculation(z2, z4):
    from ..davies import efficiency

    return efficiency(_epicyclic(z2, z4), 1, 5, 2, eta=1.0).mesh(1, 3).virtual_power


def _humpage_params(rng) -> dict:
    return {"eta12": _eta(rng, 97, 99), "eta25": _eta(rng, 97, 99), "eta43": _eta(rng, 97, 99)}


@register(
    "davies_humpage_efficiency", exercise="5.5", title="Humpage's reducer with three different meshes", stars=3,
    minutes=25, kind="compute",
    question="Humpage's bevel reducer with Nelson and Cipra's teeth (gl.catalog.humpage(): input 1, output 4, "
             "frame 5; radii 20, 56, 24, 35, 76), with the geometrically consistent planet axis, has the mesh "
             "efficiencies eta_12 = {eta12}, eta_25 = {eta25} and eta_43 = {eta43}. What is the overall "
             "efficiency?",
    data={"eta12": 0.99, "eta25": 0.98, "eta43": 0.985}, params=_humpage_params,
    answer=Value("efficiency", figures=4, meshes=lambda p: [p["eta12"], p["eta25"], p["eta43"]], mistakes=[
        Mistake(lambda e, p: _humpage({"eta12": 0.99, "eta25": 0.99, "eta43": 0.99}), "That is the efficiency with "
                "every mesh at 0.99, the chapter's case: here the three meshes differ."),
        Mistake(lambda e, p: _humpage(p, thesis_axis=True), "That is what the thesis's printed planet axis gives: "
                "use the axis consistent with the pitch cones (or the Willis equations)."),
    ], generic="Find which gear drives in each of the three meshes (seen from the carrier 6), then use the chapter's "
               "formula for shaft 1 as the input with the three mesh efficiencies and the radii 20, 56, 24, 35, 76."),
)
def davies_humpage_efficiency(eta12, eta25, eta43):
    return _humpage({"eta12": eta12, "eta25": eta25, "eta43": eta43})


def _humpage(p, thesis_axis=False):
    from ..catalog import humpage
    from ..davies import efficiency

    eta = {(1, 2): p["eta12"], (5, 2): p["eta25"], (2, 4): p["eta43"]}
    if thesis_axis:
        from ..davies.examples import laus_humpage_geometry

        return efficiency(humpage(), 5, 1, 4, eta=eta, check=False, **laus_humpage_geometry(printed_axis=True)).value
    return efficiency(humpage(), 5, 1, 4, eta=eta).value


@register(
    "davies_humpage_driver", exercise="5.6", title="Who drives when the reducer runs backwards", stars=2,
    minutes=10, kind="compute",
    question="Drive Humpage's reducer from its output shaft 4 (frame 5 still held, shaft 1 now the output). In "
             "the mesh between the planet 2 and the fixed gear 5, which link drives the other, as seen from the "
             "carrier 6? Give the link id.",
    answer=LinkId(links=lambda p: [1, 2, 4, 5, 6], wrong={
        2: "With shaft 1 as the input the planet drives gear 5; reversing the ports reverses every carrier-relative "
           "flow."},
        generic="Take the lossless virtual power flow of the mesh relative to the carrier 6: its sign says which "
                "gear gives power to the other."),
)
def davies_humpage_driver():
    from ..catalog import humpage
    from ..davies import efficiency

    return efficiency(humpage(), 5, 4, 1, eta=0.98).mesh(5, 2).driver


# ----------------------------------------------------------------------------- 5.11
def _axis_params(rng) -> dict:
    return _axis_data(rng.choice((0.95, 0.955, 0.96, 0.965, 0.97, 0.975, 0.985)))


def _axis_data(eta) -> dict:
    return {"eta": eta, "x_printed": round(_humpage({"eta12": eta, "eta25": eta, "eta43": eta}, thesis_axis=True), 4)}


_AXIS_STEPS = Choice(["1", "2", "3", "4"], wrong={
    "1": "Step 1 is right: with one module the pitch radii are in the ratio of the teeth, and only ratios of radii "
         "enter the efficiency.",
    "3": "Step 3 is right: each pitch point lies on both gears' pitch cones.",
    "4": "Step 4 is right for this train: gear 1 drives gear 2, the planet drives gear 5 and gear 4 drives gear 3 "
         "(the chapter's turning conditions)."})


@register(
    "davies_humpage_axis", exercise="5.11", title="Find the mistake: Humpage's planet axis", stars=2, minutes=20,
    kind="mistake",
    question="A report rates Humpage's reducer (gl.catalog.humpage(): input 1, output 4, frame 5, carrier 6; pitch "
             "radii 20, 56, 24, 35, 76) at {eta} per mesh. (1) One module, so the pitch radii are the tooth numbers. "
             "(2) The planet axis points along (-(r5 - r1)/(2 r2), sqrt(4 r2^2 - (r5 - r1)^2)/(2 r2)) in the plane "
             "x = 0. (3) The pitch points C, D and E of the three meshes lie on the pitch cones through the apex. "
             "(4) Gear 1 drives gear 2, the planet drives gear 5, gear 4 drives gear 3, and each mesh's efficiency "
             "is applied in that direction. It finds an efficiency of {x_printed}. Which step is wrong, and what is "
             "the efficiency?",
    data=_axis_data(0.97), params=_axis_params,
    answer=Parts({"step": ("the step", _AXIS_STEPS), "efficiency": ("the efficiency", Value(
        "efficiency", figures=4, meshes=lambda p: [p["eta"]] * 3, mistakes=[
            Mistake(lambda e, p: p["x_printed"], "That is the report's value: correct the wrong step first."),
            Mistake(lambda e, p: [_humpage({"eta12": x, "eta25": x, "eta43": x}) for x in (0.98, 0.99)],
                    "That is the chapter's value for another mesh efficiency."),
        ]))}),
)
def davies_humpage_axis(eta, x_printed):
    return {"step": "2", "efficiency": _humpage({"eta12": eta, "eta25": eta, "eta43": eta})}


# ----------------------------------------------------------------------------- 5.13
def _rate(rng, lo, hi) -> float:
    """An ordinary efficiency between lo/1000 and hi/1000, in steps of 0.005."""
    return rng.randrange(lo, hi + 1, 5) / 1000


def _eight_eta(p) -> dict:
    from ..catalog import load

    return {gp.gears: p["eta_int"] if gp.kind == "internal" else p["eta_ext"] for gp in load("zf_8hp70").gear_pairs}


def _set(e0, k, sun_in) -> float:
    """A simple set: ring held, sun in, carrier out (sun_in) or sun held, carrier in, ring out."""
    return (1 + e0 * k) / (1 + k) if sun_in else e0 * (1 + k) / (e0 * k + 1)


def _gear_values(p) -> dict:
    e0 = p["eta_ext"] * p["eta_int"]
    set2, set4 = _set(e0, 96 / 48, False), _set(e0, 85 / 23, True)
    return {"set2": set2, "set4": set4}


@register(
    "davies_second_gear", exercise="5.13", title="Second gear of an eight-speed transmission", stars=3, minutes=40,
    kind="compute",
    question="The ZF 8HP70 of the chapter (gl.catalog.load('zf_8hp70')) in second gear: brakes A and B and clutch E "
             "engaged. Every external (sun-planet) mesh has the ordinary efficiency {eta_ext} and every internal "
             "(planet-ring) mesh {eta_int}. Find which planetary sets roll and how power passes through them, and "
             "give the efficiency of second gear.",
    data={"eta_ext": 0.975, "eta_int": 0.985},
    params=lambda rng: {"eta_ext": _rate(rng, 965, 985), "eta_int": _rate(rng, 980, 995)},
    answer=Value("efficiency", figures=4, meshes=lambda p: [p["eta_ext"], p["eta_int"]] * 2, mistakes=[
        Mistake(lambda e, p: _gear_values(p)["set4"], "That is set 4 alone, first gear's efficiency: in second "
                "gear clutch E feeds sun 4 from ring 2, and set 2 rolls as well."),
        Mistake(lambda e, p: _gear_values(p)["set2"], "That is set 2 alone: set 4 rolls too, and the two sets are "
                "in series."),
        Mistake(lambda e, p: (p["eta_ext"] * p["eta_int"]) ** 2, "That treats both sets as if their carriers were "
                "held; in each rolling set the carrier turns, and the meshes carry only part of the power."),
        Mistake(lambda e, p: _gear_values({"eta_ext": 0.98, "eta_int": 0.99})["set2"]
                * _gear_values({"eta_ext": 0.98, "eta_int": 0.99})["set4"],
                "That is the chapter's second gear, with Glover's 0.98 and 0.99."),
    ], generic="Brakes A and B lock set 1, so ring 4 stands still; set 2 has its sun held and its carrier driven. "
               "Find the members of each rolling set that are input and output, apply the formula of a simple set "
               "to each, and multiply along the path of the power."),
)
def davies_second_gear(eta_ext, eta_int):
    from ..catalog import load
    from ..davies import efficiency

    return efficiency(load("zf_8hp70"), 0, 1, 8, eta=_eight_eta({"eta_ext": eta_ext, "eta_int": eta_int}),
                      held=[2, 3], joined=[(5, 6)]).value


# ----------------------------------------------------------------------------- 5.14
def _split(p) -> dict:
    """The hand solution: the case torque, then the planet's two meshes in the case frame."""
    t_case = p["eta_pc"] * 5 * p["torque"]
    slow = t_case / (1 + p["eta_pl"] ** 2)
    fast = p["eta_pl"] ** 2 * slow
    eff = (slow * p["w_slow"] + fast * p["w_fast"]) / (p["torque"] * 5 * (p["w_slow"] + p["w_fast"]) / 2)
    return {"case": t_case, "slow": slow, "fast": fast, "efficiency": eff}


def _diff_params(rng) -> dict:
    slow = rng.randint(20, 30)
    return {"w_slow": slow, "w_fast": slow + rng.randint(3, 9), "torque": rng.choice((8, 10, 12, 15, 20)),
            "eta_pc": _rate(rng, 960, 985), "eta_pl": _rate(rng, 970, 990)}


@register(
    "davies_differential", exercise="5.14", title="A differential in a turn, with friction", stars=3, minutes=30,
    kind="compute",
    question="Chen, Yao and Lee's differential (gl.catalog.load('cyl_standard_differential'): housing 0, pinion 1, "
             "side gears 2 and 3, planet 4 on the case 5; the crown on the case has five times the pinion's teeth) "
             "in a turn: wheel 2 at {w_slow} rad/s, wheel 3 at {w_fast} rad/s, the pinion driven with a torque of "
             "{torque} N m. The pinion-crown mesh has the ordinary efficiency {eta_pc}, each planet mesh {eta_pl}. "
             "Give (a) the size of the torque on the faster wheel (N m) and (b) the efficiency.",
    data={"w_slow": 24, "w_fast": 31, "torque": 12, "eta_pc": 0.97, "eta_pl": 0.985}, params=_diff_params,
    answer=Parts({
        "torque": ("the torque on the faster wheel", Value("number", standard=False, mistakes=[
            Mistake(lambda e, p: _split(p)["slow"], "That is the torque on the slower wheel: seen from the case, the "
                    "slower side gear drives the planet and the planet drives the faster one, which gets less."),
            Mistake(lambda e, p: _split(p)["case"] / 2, "That is an equal split: it holds without friction in the "
                    "planet's meshes."),
            Mistake(lambda e, p: 5 * p["torque"] / 2, "That is the lossless split: the pinion-crown mesh and the "
                    "planet's meshes both take their share."),
            Mistake(lambda e, p: -e, "Give the size of the torque."),
        ], generic="Find the case's torque from the pinion-crown mesh; then, seen from the case, find which side "
                   "gear drives the planet and split the case's torque between the wheels.")),
        "efficiency": ("the efficiency", Value("efficiency", figures=4,
                                               meshes=lambda p: [p["eta_pc"], p["eta_pl"], p["eta_pl"]])),
    }),
)
def davies_differential(w_slow, w_fast, torque, eta_pc, eta_pl):
    from ..catalog import load
    from ..davies import operating_point

    op = operating_point(load("cyl_standard_differential"), 0, speeds={2: w_slow, 3: w_fast},
                         torques={1: -torque}, eta={(5, 1): eta_pc, (4, 2): eta_pl, (4, 3): eta_pl})
    fast = next(port for port in op.ports if port.link == 3)
    return {"torque": abs(fast.torque), "efficiency": op.efficiency}


# ----------------------------------------------------------------------------- 5.15
@register(
    "davies_circuit_matrix", exercise="5.15", title="The circuit matrix of a compound train", stars=2, minutes=15,
    kind="compute",
    question="The compound train gl.catalog.compound_train() as a coupling graph: frame 0, input gear 1, compound "
             "gear 2, output gear 3; couplings A (revolute, 0 -> 1, the input port), B (revolute, 0 -> 3, the output "
             "port), C (mesh, 1 -> 2), D (mesh, 2 -> 3), E (revolute, 0 -> 2). With the spanning tree A, B, C, write "
             "the circuit matrix B: one row per chord (D, then E), each circuit oriented along its chord, one column "
             "per coupling (A, B, C, D, E).",
    answer=Matrix(rows="circuits of the chords D and E", columns="couplings A, B, C, D, E", mistakes=[
        Mistake(lambda e, p: -e, "Each circuit is oriented along its chord: the chord's own entry is +1."),
    ], generic="Go along the chord from its tail to its head, then back to its tail through the tree: +1 for a "
               "coupling passed in its direction, -1 against it, 0 for one not in the circuit."),
)
def davies_circuit_matrix():
    from ..catalog import compound_train
    from ..davies import network

    net = network(compound_train(), 0, 1, 3)
    names = [c.name for c in net.couplings]
    if names != ["A", "B", "C", "D", "E"]:  # the statement names the couplings; the library must agree
        raise ValueError(f"the couplings are {names}")
    return sympy.Matrix(net.B)
