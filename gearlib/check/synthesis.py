"""Checks for exercises 6.1 to 6.6 of chapter 6 (``exercises/06_differential_synthesis.ipynb``):
the atlas chain GKC 7-2-7, counts over the atlas. Exercises 6.7 to 6.9 (a double-planet centre
differential) are in :mod:`gearlib.check.differentials`, 6.10 to 6.12 (eight-link chains) in
:mod:`gearlib.check.synthesis_eight`.

The chapter works GKC 5-7-2 and CYL's eight-link chain through and lists the seven-link DGMs;
the exercises take the atlas chain GKC 7-2-7, which the chapter does not show, count over the
seven-link atlas, and count the fractionated chains the chapter leaves out. Expected answers
are computed by :mod:`gearlib.synthesis`.
"""

from __future__ import annotations

import functools
import re

import sympy

from ._choice import Choice, LinkId, LinkSet, Parts
from ._compare import equivalent, proportional
from ._core import Prediction, register
from ._spec import Spec, Verdict
from ._read import Unreadable, read
from ._value import Mistake, Value

__all__ = ["synth_ground_links", "synth_constraint", "synth_redundant_links", "synth_many_grounds",
           "synth_two_constraints", "synth_fractionated_six", "CHAIN", "Constraint"]

CHAIN = "GKC 7-2-7"
"""The atlas chain of exercises 6.1, 6.2, 6.3 and 6.5:
``next(m for m in gl.atlas.geared_chains(7, 2) if m.name == "GKC 7-2-7")``."""


@functools.lru_cache(maxsize=1)
def _chain():
    from ..synthesis import atlas

    return next(m for m in atlas.geared_chains(7, 2) if m.name == CHAIN)


_GET = f"chain = next(m for m in gl.atlas.geared_chains(7, 2) if m.name == '{CHAIN}')"


@register(
    "synth_ground_links", exercise="6.1", title="Which links can be the ground", stars=1, minutes=10,
    kind="compute",
    question=f"Take the atlas chain {CHAIN} ({_GET}). Which links may be the ground of a three-terminal DGM by "
             "characteristic N2? Work it out from the turning pairs and their axis labels, not with gl.identify.",
    answer=LinkSet(what="possible ground links",
                   too_few="A ground needs at least three links coaxial with it (N2): count the links on each of its "
                           "axes, through every coaxial group it belongs to.",
                   too_many="Count only links coaxial with the candidate (a path of thin edges with one label), not "
                            "links it meshes with."),
)
def synth_ground_links():
    from ..synthesis.dgm import identify

    return identify(_chain()).grounds


class Constraint(Spec):
    """A linear relation among terminal speeds, ``a1*omega_t1 + ...`` or ``[a1, ...]``, up to a
    non-zero factor (projective equivalence). CYL's ``gamma_a_b`` (``γ_{a,b}``) is read as
    ``e_a_b``. The reference function returns the coefficients; the check keeps the equation
    ``sum a_i omega_i``. ``name_extra=False`` does not name a ratio the chain does not have
    (when finding it is the exercise)."""

    def __init__(self, terminals, ratios, *, name_extra: bool = True,
                 generic: str = "Set the ground's speed to zero in the circuit equations, then eliminate the "
                                "non-terminal speeds one at a time (a speed that appears in one equation only "
                                "just defines that link's speed)"):
        self.terminals, self.ratios = tuple(terminals), tuple(ratios)
        self.name_extra, self.generic = name_extra, generic
        self.omegas = [sympy.Symbol(f"omega_{t}") for t in self.terminals]
        self.form = ("an expression " + " + ".join(f"a{k + 1}*omega_{t}" for k, t in enumerate(self.terminals))
                     + " (the '= 0' left out), or the list of its coefficients")

    def prepare(self, reference):
        return sum(sympy.sympify(c) * w for c, w in zip(reference, self.omegas))

    def check_form(self, answer) -> None:
        if isinstance(answer, (list, tuple)):
            if len(answer) != len(self.terminals):
                raise Unreadable(f"give {len(self.terminals)} coefficients, one per terminal "
                                 f"{', '.join(map(str, self.terminals))}")
            for c in answer:
                read(c, names=True)
        else:
            read(answer, names=True)

    def example(self, reference, params):
        return reference

    def _coefficients(self, answer):
        """The coefficients of the answer (sympy), or a message saying why there are none."""
        ws = self.omegas
        if isinstance(answer, (list, tuple)):
            self.check_form(answer)
            return [_as_e(read(c, names=True).value) for c in answer]
        expr = _as_e(read(answer, names=True).value)
        coeffs = [sympy.diff(expr, w) for w in ws]  # no expansion: a power of a sum stays small
        if any(c.has(w) for c in coeffs for w in ws):
            return "The constraint is linear in the speeds: each term is a coefficient times one omega"
        if not equivalent(expr - sum(a * w for a, w in zip(coeffs, ws)), 0):
            return "Write the constraint as " + self.form
        return coeffs

    def judge(self, answer, reference, params) -> Verdict:
        coeffs = self._coefficients(answer)
        if isinstance(coeffs, str):
            return Verdict(False, coeffs)
        names = {s.name for c in coeffs for s in c.free_symbols}
        if any(n.startswith("omega_") for n in names):
            return Verdict(False, "The coefficients depend only on gear ratios, not on speeds")
        extra = sorted(names - set(self.ratios))
        if extra and self.name_extra:
            return Verdict(False, f"Your answer uses {', '.join(extra)}, which this chain does not have")
        if extra:
            return Verdict(False, "Your answer uses a ratio this chain does not have: each e_a_b must name the gear "
                           "pair (a, b) of one of its fundamental circuits")
        if all(equivalent(c, 0) for c in coeffs):
            return Verdict(False, "Every coefficient is zero: that is no constraint")
        ref = [sympy.diff(reference, w) for w in self.omegas]
        if proportional(coeffs, ref):
            return Verdict(True, "Well done: any non-zero multiple of the constraint is the same constraint", 1.0)
        for i in range(len(coeffs)):
            flipped = [-c if j == i else c for j, c in enumerate(coeffs)]
            if proportional(flipped, ref):
                return Verdict(False, "One coefficient has the wrong sign: each circuit row reads "
                               "omega_b - e omega_a + (e - 1) omega_c = 0 with the ratio e = e_a_b")
        return Verdict(False, self.generic)


def _as_e(expr):
    """*expr* with plain symbols, CYL's ``gamma_a_b`` renamed ``e_a_b``."""
    return expr.xreplace({s: sympy.Symbol(re.sub(r"^gamma_", "e_", s.name)) for s in expr.free_symbols})


_T2 = (3, 4, 6)


@register(
    "synth_constraint", exercise="6.2", title="The constraint among three terminals", stars=2, minutes=25,
    kind="derive",
    question=f"In {CHAIN} hold link 2 and take links 3, 4 and 6 as the terminals. Write the four fundamental "
             "circuit equations by hand (gl.willis_equations(chain) confirms them), eliminate the other speeds and "
             "give the constraint a1*omega_3 + a2*omega_4 + a3*omega_6 (leave out '= 0') in the ratios e_1_4, "
             "e_2_5, e_3_7, e_6_7. Any non-zero multiple is right.",
    answer=Constraint(_T2, ("e_1_4", "e_2_5", "e_3_7", "e_6_7"), generic="Set the ground's speed to zero in the four "
                      "circuit equations, then eliminate the non-terminal speeds one at a time (a speed that appears "
                      "in one equation only just defines that link's speed)"),
)
def synth_constraint():
    from ..synthesis.dgm import terminal_constraint

    return terminal_constraint(_chain(), _T2, ground=2).coefficients


@register(
    "synth_redundant_links", exercise="6.3", title="Redundant links", stars=2, minutes=10, kind="compute",
    question=f"For the constraint of exercise 6.2 ({CHAIN}, ground 2, terminals 3, 4, 6), which links are "
             "redundant?",
    answer=LinkSet(what="redundant links",
                   too_few="Look for each non-terminal's gear ratios (as a gear and as a carrier) in the constraint.",
                   too_many="A link is redundant only if none of the ratios of its circuits appears in the "
                            "constraint."),
)
def synth_redundant_links():
    from ..synthesis.dgm import terminal_constraint

    return terminal_constraint(_chain(), _T2, ground=2).redundant


@functools.lru_cache(maxsize=1)
def _grounds_counts():
    from ..synthesis import atlas
    from ..synthesis.dgm import identify

    return tuple(len(identify(m).grounds) for m in atlas.geared_chains(7, 2))


@register(
    "synth_many_grounds", exercise="6.4", title="Chains with many possible grounds", stars=2, minutes=15,
    kind="explore",
    question="Of the fifty non-fractionated two-dof seven-link chains (gl.atlas.geared_chains(7, 2)), how many "
             "have at least four links that may be the ground of a three-terminal DGM (N2)?",
    answer=Value("count", mistakes=[
        Mistake(lambda e, p: sum(1 for n in _grounds_counts() if n == 4), "That counts the chains with exactly "
                "four; 'at least four' includes more."),
        Mistake(lambda e, p: sum(1 for n in _grounds_counts() if n >= 3), "That counts the chains with three or "
                "more."),
        Mistake(lambda e, p: len(_grounds_counts()), "That is every chain."),
    ], generic="Loop over the chains and count len(gl.identify(chain).grounds) >= 4."),
)
def synth_many_grounds():
    return sum(1 for n in _grounds_counts() if n >= 4)


_TWO = {
    "A": "Two equations among three terminal speeds leave only one of them free: the mechanism has one degree of "
         "freedom between its terminals, not the two a three-terminal differential needs (C1 asks for exactly "
         "one equation).",
    "B": "One of the terminals does not turn about the ground.",
    "C": "A non-terminal link appears in only one circuit.",
    "D": "Two equations make the mechanism over-constrained: it cannot move at all.",
}


@register(
    "synth_two_constraints", exercise="6.5", title="A choice that gives two constraints", stars=3, minutes=25,
    kind="concept",
    question=f"Among the (ground, terminals) candidates of {CHAIN} that gl.identify examines, one gives two "
             "constraints instead of one. Find it by hand (ground and terminals) and say why it is not a DGM "
             "(reason 'A', 'B', 'C' or 'D').",
    answer=Parts({
        "ground": ("the ground", LinkId(links=lambda p: list(range(1, 8)))),
        "terminals": ("the terminals", LinkSet(what="terminals")),
        "reason": ("the reason", Choice(_TWO, wrong={
            "B": "Every candidate's terminals turn about the ground: that is how they are chosen (C3).",
            "C": "That is the N3 screen, which leads to redundant links, not to a second equation.",
            "D": "The chain still moves: its two degrees of freedom remain, but they are shared differently."}))}),
)
def synth_two_constraints():
    from ..synthesis.dgm import identify

    two = [c for c in identify(_chain()).candidates if c.count == 2]
    return {"ground": two[0].ground, "terminals": two[0].terminals, "reason": "A"}


# ----------------------------------------------------------------------------- 6.6
_MORE = Choice(["none", "1 to 3", "4 to 9", "10 or more"], synonyms={
    "none": ["0", "zero", "no more"], "10 or more": ["ten or more", "10+", "more than 9"]})


@functools.lru_cache(maxsize=1)
def _six_counts():
    from ..synthesis import atlas

    return {(frac, level): len(atlas.geared_chains(6, 2, fractionated=frac, level=level))
            for frac in (False, True, "only") for level in ("coaxial", "kinematic")}


@register(
    "synth_fractionated_six", exercise="6.6", title="Predict, then count: the chains the atlas leaves out",
    stars=1, minutes=10, kind="predict",
    question="The atlas of two-dof six-link chains that CYL use (Tsai and Lin) has two rotation graphs, because "
             "it leaves out the fractionated chains. First predict how many rotation graphs the fractionated "
             "two-dof six-link chains add ('none', '1 to 3', '4 to 9' or '10 or more') and record it; then count "
             "them with gl.atlas.geared_chains (fractionated='only', level='kinematic').",
    answer=Value("count", mistakes=[
        Mistake(lambda e, p: _six_counts()[(True, "kinematic")], "That counts the non-fractionated rotation graphs "
                "too: the question asks how many the fractionated ones add."),
        Mistake(lambda e, p: _six_counts()[("only", "coaxial")], "That counts displacement graphs (chains that "
                "differ only in which links are coaxial count apart): count rotation graphs, level='kinematic'."),
        Mistake(lambda e, p: _six_counts()[(True, "coaxial")], "That counts every displacement graph, "
                "non-fractionated ones included: count the fractionated rotation graphs only."),
    ], generic="Count the rotation graphs (level='kinematic') of the fractionated chains only "
               "(fractionated='only') with six links and two degrees of freedom."),
    predict=Prediction(_MORE, lambda ref, p: ("none" if ref == 0 else "1 to 3" if ref <= 3 else "4 to 9" if ref <= 9
                                              else "10 or more"),
                       "Most small two-dof chains are fractionated: two one-dof chains (such as a planetary and a "
                       "gear pair on a carrier) that share a link. Chen and Yao (2000) had already synthesised the "
                       "fractionated differentials by splitting them into two such parts; CYL search the "
                       "non-fractionated chains, where that split does not exist."),
)
def synth_fractionated_six():
    return _six_counts()[("only", "kinematic")]
