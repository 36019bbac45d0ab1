"""Checks for the exercises 5.7 to 5.10 and 5.12 of chapter 5
(``exercises/05_davies_efficiency.ipynb``): a closed-form efficiency, a train modelled with its
mesh efficiencies, mesh efficiencies chosen for a target, recirculation, self-locking. The
others are in :mod:`gearlib.check.davies`.

None of these trains is computed in the chapter: a planetary driven at its carrier (5.7), a
stepped-planet reducer (5.8), Laus's epicyclic train with a target efficiency (5.9) and with
teeth near its pole (5.12). Hints are those of efficiencies (input and output exchanged, the
loss, one mesh or the product of the meshes), never those of speed ratios.
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy

from ._choice import Choice, Parts, normalise
from ._core import Prediction, register
from ._design import Condition, Design
from ._model import Model, Scenario, _mechanism
from ._read import Unreadable, read
from ._spec import Spec, Verdict
from ._value import Mistake, Symbolic, Value

__all__ = ["davies_planetary_formula", "davies_model_efficiency", "davies_design_etas", "davies_why_carrier",
           "davies_self_locking"]


def _eta(rng, lo, hi) -> float:
    """An ordinary efficiency between lo/1000 and hi/1000, in steps of 0.005."""
    return rng.randrange(lo, hi + 1, 5) / 1000


# ----------------------------------------------------------------------------- 5.7
_E1, _E2, _ZS, _ZR = sympy.symbols("eta_1 eta_2 Z_s Z_r")
_E0 = _E1 * _E2


@register(
    "davies_planetary_formula", exercise="5.7", title="A planetary driven at its carrier, in closed form", stars=3,
    minutes=30, kind="derive",
    question="A simple planetary with the ring held: the carrier is the input and the sun the output (a speed "
             "increaser). The sun has Z_s teeth and the ring Z_r (one module); the sun-planet mesh has the ordinary "
             "efficiency eta_1 and the planet-ring mesh eta_2, whichever gear drives. Derive the overall efficiency "
             "in terms of eta_1, eta_2, Z_s and Z_r.",
    answer=Symbolic(("eta_1", "eta_2", "Z_s", "Z_r"), standard=False,
                    values=lambda p: {"eta_1": sympy.Rational(98, 100), "eta_2": sympy.Rational(99, 100), "Z_s": 24,
                                      "Z_r": 72},
                    mistakes=[
        Mistake(lambda e, p: (_ZS + _E0 * _ZR) / (_ZS + _ZR), "That is the efficiency with the sun as the input: "
                "there the sun drives the planet, seen from the carrier. Here the carrier drives: find which gear "
                "gives power to which relative to the carrier."),
        Mistake(lambda e, p: 1 / e, "You have exchanged input and output (1/eta): an efficiency is the output "
                "power over the input power, never above 1."),
        Mistake(lambda e, p: (_ZS + _ZR) / (_E0 * _ZS + _ZR), "That is above 1 whenever eta < 1: the ordinary "
                "efficiencies are applied against the carrier-relative power flow."),
        Mistake(lambda e, p: _E0, "That is the efficiency with the carrier held; here the carrier turns, and the "
                "meshes carry only part of the power relative to it."),
        Mistake(lambda e, p: _E0 * (_ZS + _ZR) / (_ZS + _E0 * _ZR), "That holds with the sun held and the ring as "
                "the output; here the ring is held and the sun is the output."),
        Mistake(lambda e, p: 1 - e, "That is the loss (1 - eta), not the efficiency."),
    ], generic="Balance the torques: T_sun + T_ring + T_carrier = 0. Relative to the carrier find which of sun and "
               "ring drives; the driven gear's torque is eta_1 eta_2 times what the lossless ratio gives (or 1/eta "
               "times, the other way round). Then eta = -P_sun/P_carrier."),
)
def davies_planetary_formula():
    from ..catalog import simple_planetary
    from ..davies import efficiency

    rs, rp, rr = sympy.symbols("r_s r_p r_r", positive=True)
    res = efficiency(simple_planetary(sun=24, ring=72), 3, 4, 1, symbolic=True,
                     radii={(1, 2): (rs, rp), (2, 3): (rp, rr)})
    plain = {s: sympy.Symbol(s.name) for s in res.formula.free_symbols}
    f = res.formula.xreplace(plain)
    return sympy.factor(f.subs({sympy.Symbol("r_p"): (_ZR - _ZS) / 2, sympy.Symbol("r_r"): _ZR,
                                sympy.Symbol("eta_2_1"): _E1, sympy.Symbol("eta_3_2"): _E2}))


# ----------------------------------------------------------------------------- 5.8
_ROLES = ("sun", "planet", "ring", "carrier")


def _stepped(sun, big, small, ring):
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict({
        "links": {1: "sun", 2: "planet", 3: "ring", 4: "carrier"},
        "turning_pairs": [[4, 1, "a"], [4, 3, "a"], [4, 2, "b"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [sun, big]},
                       {"gears": [2, 3], "teeth": [small, ring], "type": "internal"}],
    })


def _pair_key(key):
    if isinstance(key, str):
        parts = [x for x in key.replace("(", " ").replace(")", " ").replace(",", " ").replace("-", " ").split() if x]
    elif isinstance(key, (tuple, list)):
        parts = list(key)
    else:
        raise Unreadable("name each mesh by its two gears, such as ('sun', 'planet') or (1, 2)")
    if len(parts) != 2:
        raise Unreadable("name each mesh by its two gears, such as ('sun', 'planet') or (1, 2)")
    return parts


class _EfficiencyModel(Spec):
    """A train with its mesh efficiencies: ``{'model': <as for Model>, 'eta': {(gear, gear): eta}}``,
    gears named by their roles or link ids. Checked by its motion (:class:`Model`), then by its
    efficiency with *ground* held, *input* driven and *output* loaded."""

    def __init__(self, model: Model, ground: str, input: str, output: str):
        self.model, self.ports = model, (ground, input, output)
        self.form = ("a dict {'model': " + model.form + ", 'eta': {(gear, gear): efficiency, ...}}, the gears "
                     "named by their roles or link ids")

    def _split(self, answer):
        if answer is None:
            raise Unreadable("no answer yet: replace `None` with {'model': ..., 'eta': {...}}")
        if not isinstance(answer, Mapping):
            raise Unreadable(f"give {self.form}")
        keys = {normalise(k): k for k in answer if isinstance(k, str)}
        if set(keys) != {"model", "eta"} or len(answer) != 2:
            raise Unreadable("give a dict with two keys, 'model' (the mechanism) and 'eta' (the mesh efficiencies)")
        eta = answer[keys["eta"]]
        if not isinstance(eta, Mapping) or not 0 < len(eta) <= 20:
            raise Unreadable("'eta' is a dict {(gear, gear): efficiency}, one entry per mesh")
        out = {}
        for k, v in eta.items():
            r = read(v)
            if not (r.value.is_real and 0 < float(r.value) <= 1):
                raise Unreadable("each mesh efficiency is a number between 0 and 1")
            out[tuple(_pair_key(k))] = float(r.value)
        return answer[keys["model"]], out

    def check_form(self, answer) -> None:
        model, _ = self._split(answer)
        self.model.check_form(model)

    def _value(self, mech, roles, eta):
        from ..davies import efficiency

        def link(x):
            role = next((r for r in self.model.roles if normalise(r) == normalise(str(x))), None)
            if role is not None:
                return roles[role]
            try:
                return mech.resolve(x)
            except Exception:
                raise Unreadable(f"{x!r} is neither a role of this exercise nor a link of your model") from None

        given = {}
        for (a, b), v in eta.items():
            a, b = link(a), link(b)
            if not any(set(gp.gears) == {a, b} for gp in mech.gear_pairs):
                raise Unreadable(f"links {a} and {b} of your model do not mesh: 'eta' names the meshes")
            given[(a, b)] = v
        missing = [gp.gears for gp in mech.gear_pairs if not any(set(gp.gears) == set(k) for k in given)]
        if missing:
            raise Unreadable(f"give an efficiency for every mesh; the mesh {missing[0]} has none")
        g, i, o = (roles[r] for r in self.ports)
        res = efficiency(mech, g, i, o, eta=given)
        role_of = {link: role for role, link in roles.items()}
        losses = {frozenset(role_of.get(x, x) for x in m.gears): float(m.loss) for m in res.meshes}
        return float(res.value), losses

    def prepare(self, reference):
        mech, eta = reference
        out = self.model.prepare(mech)
        out["eta"] = dict(eta)
        out["efficiency"], out["losses"] = self._value(out["mech"], out["roles"], eta)
        return out

    def example(self, reference, params):
        return {"model": (reference["mech"], dict(reference["roles"])), "eta": dict(reference["eta"])}

    def judge(self, answer, reference, params) -> Verdict:
        from ..errors import GearlibError

        model, eta = self._split(answer)
        moves = self.model.judge(model, reference, params)
        if not moves.passed:
            return moves
        mech, roles = _mechanism(model)
        roles = self.model._roles(mech, roles)
        try:
            value, losses = self._value(mech, roles, eta)
        except GearlibError as err:
            return Verdict(False, f"Your model moves right, but its efficiency could not be computed: {err}")
        same = set(losses) == set(reference["losses"]) and all(
            abs(losses[k] - reference["losses"][k]) <= 1e-9 for k in losses)
        if abs(value - reference["efficiency"]) <= 1e-9 and same:
            return Verdict(True, "Well done: your model moves like the train described and loses power in each mesh "
                           "as it does", 1.0)
        if abs(value - reference["efficiency"]) <= 1e-9:
            return Verdict(False, "Your model moves like the train described and has its overall efficiency, but "
                           "not the loss of each mesh: check which mesh has which ordinary efficiency", 0.5)
        return Verdict(False, "Your model moves like the train described, but its efficiency differs: check which "
                       "mesh has which ordinary efficiency (the description gives one per mesh)", 0.5)


def _stepped_params(rng) -> dict:
    while True:
        sun, big, small = rng.randint(15, 30), rng.randint(28, 45), rng.randint(14, 24)
        if big > small + 5:
            return {"sun": sun, "big": big, "small": small, "ring": sun + big + small, "eta_sp": _eta(rng, 965, 985),
                    "eta_pr": _eta(rng, 985, 995)}


@register(
    "davies_model_efficiency", exercise="5.8", title="A stepped-planet reducer with its losses, as data", stars=2,
    minutes=25, kind="model",
    question="A reducer: the sun ({sun} teeth) is the input, the carrier the output, and the ring ({ring} teeth, "
             "internal) is held. The carrier holds a stepped planet: its larger gear ({big} teeth) meshes the sun "
             "with the ordinary efficiency {eta_sp}, its smaller gear ({small} teeth, on the same shaft) meshes the "
             "ring with {eta_pr}. Write it as data: {'model': <the dict of gl.Mechanism.from_dict, with links named "
             "'sun', 'planet', 'ring' and 'carrier'>, 'eta': {(gear, gear): efficiency, ...}}.",
    data={"sun": 20, "big": 40, "small": 16, "ring": 76, "eta_sp": 0.975, "eta_pr": 0.99},
    params=_stepped_params,
    answer=_EfficiencyModel(Model(_ROLES, [Scenario("ring", {"sun": 1}), Scenario("carrier", {"sun": 1}),
                                           Scenario("sun", {"ring": 1})]), "ring", "sun", "carrier"),
)
def davies_model_efficiency(sun, big, small, ring, eta_sp, eta_pr):
    return _stepped(sun, big, small, ring), {("sun", "planet"): eta_sp, ("planet", "ring"): eta_pr}


# ----------------------------------------------------------------------------- 5.9
def _laus(e13, e42) -> float:
    from ..catalog import load
    from ..davies import efficiency

    return float(efficiency(load("laus_epicyclic"), 1, 5, 2, eta={(1, 3): e13, (2, 3): e42}).value)


def _design_etas():
    return [
        Condition("realistic", lambda d, p: all(0.96 <= d[k] <= 0.995 for k in ("eta_13", "eta_42")),
                  "an ordinary efficiency of a good internal mesh lies between 0.96 and 0.995"),
        Condition("target", lambda d, p: p["target"] <= _laus(d["eta_13"], d["eta_42"]) <= p["target"] + 0.005,
                  lambda d, p: f"with these meshes the train has an efficiency of {_laus(d['eta_13'], d['eta_42']):.4f};"
                               f" it must lie between {p['target']} and {p['target'] + 0.005:.3f}"),
    ]


def _etas_example(p) -> dict:
    lo, hi = 0.96, 0.995
    for _ in range(30):  # bisection on one common value
        mid = (lo + hi) / 2
        if _laus(mid, mid) < p["target"] + 0.0025:
            lo = mid
        else:
            hi = mid
    return {"eta_13": lo, "eta_42": lo}


@register(
    "davies_design_etas", exercise="5.9", title="Choose the mesh efficiencies for a target", stars=2, minutes=20,
    kind="design",
    question="Laus's epicyclic train of the chapter (gl.catalog.load('laus_epicyclic'): annulus 1 held, carrier 5 "
             "in, annulus 2 out) must reach an overall efficiency between {target} and 0.005 above it. Choose the "
             "ordinary efficiencies eta_13 (annulus 1 with planet gear 3) and eta_42 (planet gear 4 with annulus 2), "
             "each between 0.96 and 0.995. Give {'eta_13': ..., 'eta_42': ...}.",
    data={"target": 0.92}, params=lambda rng: {"target": rng.choice((0.9, 0.91, 0.92, 0.93, 0.94))},
    answer=Design({"eta_13": "efficiency", "eta_42": "efficiency"}, _design_etas(), example=_etas_example),
)
def davies_design_etas(target):
    return None


# ----------------------------------------------------------------------------- 5.10
_OBSERVERS = Choice(["the carrier", "the frame", "the output annulus", "the planet"], synonyms={
    "the carrier": ["carrier", "link 5", "5"], "the frame": ["frame", "annulus 1", "link 1", "1", "housing"],
    "the output annulus": ["annulus 2", "output", "link 2", "2"], "the planet": ["planet", "link 3", "3"]},
    wrong={"the frame": "The frame's flows are the real power flow, which never exceeds the input power; the loss "
                        "of a mesh is set elsewhere.",
           "the output annulus": "The output annulus carries one port; its flows are virtual like the carrier's, but "
                                 "the ordinary efficiency is not defined from it.",
           "the planet": "Seen from the planet nothing flows through the meshes: a lossless mesh does no work on the "
                         "rolling of its own gears."})
_REASONS = {
    "A": "The frame is the only link that stands still, so only its flows are real power.",
    "B": "The output annulus carries the output port, so its flows decide the output power.",
    "C": "An ordinary efficiency is measured with the carrier held: a mesh loses (1 - eta) of the power it passes "
         "relative to its carrier, and that power can exceed the input power.",
    "D": "A loss is set by the real power flow, which never exceeds the input power.",
}


@register(
    "davies_why_carrier", exercise="5.10", title="Why the carrier's view sets the losses", stars=2, minutes=10,
    kind="concept",
    question="In Laus's epicyclic train (carrier 5 in, annulus 2 out, annulus 1 held) the flow through the mesh of "
             "annulus 1 and planet gear 3 is almost three times the input power seen from the carrier, and at most "
             "the input power seen from the frame. Whose view of the flow sets how much power the mesh loses ('the "
             "carrier', 'the frame', 'the output annulus' or 'the planet'), and why (reason 'A', 'B', 'C' or 'D')?",
    answer=Parts({"observer": ("the observer", _OBSERVERS), "reason": ("the reason", Choice(_REASONS, wrong={
        "A": "No link stands still except by convention: every motion in the network is relative.",
        "B": "The output power comes from the port torques; the question is how much a mesh loses.",
        "D": "Then an epicyclic train could not be less efficient than its meshes, and it is: its meshes lose a "
             "share of a larger power."}))}),
)
def davies_why_carrier():
    return {"observer": "the carrier", "reason": "C"}


# ----------------------------------------------------------------------------- 5.12
def _pole_train(z1, z2, z3, z4):
    from ..catalog import load

    return load("laus_epicyclic").with_gear_pair((1, 3), teeth=(z1, z3), radii=(z1 / 2, z3 / 2)).with_gear_pair(
        (2, 3), teeth=(z2, z4), radii=(z2, z4))


def _table5(p, eq) -> float:
    """Laus's eqs. (76)-(79) for the train of exercise 5.12 (module 1 mm on 1-3, 2 mm on 2-4)."""
    a, b, e = p["z1"] / 2 * p["z4"], p["z2"] * p["z3"] / 2, p["eta"] ** 2
    return {76: e * (a - b) / (a - e * b), 77: (b - a) / (b - e * a), 78: (b - e * a) / (b - a),
            79: (a - e * b) / (e * (a - b))}[eq]


def _pole_params(rng) -> dict:
    while True:
        z1, z3 = rng.randint(64, 84), rng.randint(30, 40)
        if (z1 - z3) % 2:
            continue
        z2 = rng.randint(34, 44)
        z4 = z2 - (z1 - z3) // 2
        eta = _eta(rng, 970, 985)
        a, b = z1 / 2 * z4, z2 * z3 / 2
        if 16 <= z4 <= z2 - 12 and z1 / 2 < z2 and eta**2 - 0.02 < b / a < 0.995:
            return {"z1": z1, "z2": z2, "z3": z3, "z4": z4, "eta": eta}


_WAYS = Choice(["higher than forwards", "lower than forwards, but positive", "zero or negative: the train locks"],
               synonyms={"higher than forwards": ["higher"], "lower than forwards, but positive": ["lower", "positive"],
                         "zero or negative: the train locks": ["locks", "negative", "zero or negative", "self-locking"]})


def _locks(reference, params) -> str:
    x = float(reference)
    if x <= 0:
        return "zero or negative: the train locks"
    return "higher than forwards" if x > _table5(params, 76) else "lower than forwards, but positive"


@register(
    "davies_self_locking", exercise="5.12", title="Predict, then compute: driving a reducer backwards", stars=2,
    minutes=20, kind="predict",
    question="Laus's epicyclic train with teeth z1 = {z1}, z3 = {z3} (module 1 mm) and z2 = {z2}, z4 = {z4} (module 2 "
             "mm), both meshes {eta}: a reducer of high ratio, carrier 5 in, annulus 2 out. Now drive it backwards, "
             "annulus 2 in and carrier 5 out (annulus 1 still held). First predict its efficiency ('higher than "
             "forwards', 'lower than forwards, but positive', 'zero or negative: the train locks') and record it; "
             "then compute it (the number the method gives, whatever its sign).",
    data={"z1": 74, "z2": 38, "z3": 36, "z4": 19, "eta": 0.98}, params=_pole_params,
    answer=Value("number", standard=False, mistakes=[
        Mistake(lambda e, p: _table5(p, 76), "That is the efficiency forwards (carrier in): driving from annulus 2 "
                "reverses every carrier-relative power flow, and the formula changes."),
        Mistake(lambda e, p: 1 / e, "You have exchanged input and output (eta -> 1/eta)."),
        Mistake(lambda e, p: [_table5(p, 77), _table5(p, 79)], "That formula is written for the other sign of r1 - "
                "r2: compare the pitch radii of the two annuli."),
        Mistake(lambda e, p: 1 - e, "That is 1 - eta, the loss, not the efficiency."),
        Mistake(lambda e, p: -e, "The size is right but the sign is not: with annulus 2 driving, annulus 2 drives "
                "planet gear 4 relative to the carrier, and planet gear 3 drives annulus 1."),
    ], generic="With annulus 2 as the input, find which gear drives in each mesh relative to the carrier, choose the "
               "formula of Table 5 for input 2 and the sign of r1 - r2, and evaluate it with the pitch radii."),
    predict=Prediction(_WAYS, _locks, lambda p: "Near the pole (r1 r4 close to r2 r3) the meshes carry many times "
                       "the input power relative to the carrier. Forwards that costs efficiency; backwards " + (
                           "the losses exceed what the input brings, and no torque at annulus 2 turns the carrier: "
                           "the train is self-locking, like a worm drive." if _table5(p, 78) <= 0 else
                           "it costs more still, and a little lower mesh efficiency would lock the train.")),
)
def davies_self_locking(z1, z2, z3, z4, eta):
    from ..davies import efficiency

    return efficiency(_pole_train(z1, z2, z3, z4), 1, 2, 5, eta=eta).value
