"""Checks for chapter 6's exercises (``exercises/06_differential_synthesis.ipynb``).

The chapter works GKC 5-7-2 and the eight-link chain through and lists the seven-link DGMs;
the exercises take the atlas chain GKC 7-2-7, which the chapter does not show, and count over
the seven-link atlas. Expected answers are computed by :mod:`gearlib.synthesis`.
"""

from __future__ import annotations

import functools
import sympy

from ._choice import Choice, LinkId, LinkSet, Parts
from ._compare import proportional
from ._core import register
from ._spec import Spec, Verdict
from ._read import Unreadable, read
from ._value import Mistake, Value

__all__ = ["synth_ground_links", "synth_constraint", "synth_redundant_links", "synth_many_grounds",
           "synth_two_constraints", "CHAIN"]

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


class _Constraint(Spec):
    """A linear relation among terminal speeds, ``a1*omega_t1 + ...`` or ``[a1, ...]``, up to a
    non-zero factor."""

    def __init__(self, terminals, ratios):
        self.terminals, self.ratios = tuple(terminals), tuple(ratios)
        self.form = ("an expression " + " + ".join(f"a{k + 1}*omega_{t}" for k, t in enumerate(self.terminals))
                     + " (the '= 0' left out), or the list of its coefficients")

    def prepare(self, reference):
        return [sympy.sympify(c) for c in reference]

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
        return sum(c * sympy.Symbol(f"omega_{t}") for c, t in zip(reference, self.terminals))

    def judge(self, answer, reference, params) -> Verdict:
        ws = [sympy.Symbol(f"omega_{t}") for t in self.terminals]
        if isinstance(answer, (list, tuple)):
            if len(answer) != len(ws):
                raise Unreadable(f"give {len(ws)} coefficients, one per terminal {', '.join(map(str, self.terminals))}")
            coeffs = [read(c, names=True).value for c in answer]
        else:
            expr = sympy.expand(read(answer, names=True).value)
            expr = expr.xreplace({s: sympy.Symbol(s.name) for s in expr.free_symbols})
            coeffs = [expr.coeff(w) for w in ws]
            if sympy.expand(expr - sum(a * w for a, w in zip(coeffs, ws))) != 0:
                return Verdict(False, "Write the constraint as " + self.form)
        names = {s.name for c in coeffs for s in sympy.sympify(c).free_symbols}
        if any(n.startswith("omega_") for n in names):
            return Verdict(False, "The coefficients depend only on gear ratios, not on speeds")
        extra = sorted(names - set(self.ratios))
        if extra:
            return Verdict(False, f"Your answer uses {', '.join(extra)}, which this chain does not have")
        if all(sympy.sympify(c) == 0 for c in coeffs):
            return Verdict(False, "Every coefficient is zero: that is no constraint")
        if proportional(coeffs, reference):
            return Verdict(True, "Well done: any non-zero multiple of the constraint is the same constraint", 1.0)
        for i in range(len(coeffs)):
            flipped = [-c if j == i else c for j, c in enumerate(coeffs)]
            if proportional(flipped, reference):
                return Verdict(False, "One coefficient has the wrong sign: each circuit row reads "
                               "omega_b - e omega_a + (e - 1) omega_c = 0 with the ratio e = e_a_b")
        return Verdict(False, "Set the ground's speed to zero in the four circuit equations, then eliminate the "
                       "non-terminal speeds one at a time (a speed that appears in one equation only just defines "
                       "that link's speed)")


_T2 = (3, 4, 6)


@register(
    "synth_constraint", exercise="6.2", title="The constraint among three terminals", stars=2, minutes=25,
    kind="derive",
    question=f"In {CHAIN} hold link 2 and take links 3, 4 and 6 as the terminals. Write the four fundamental "
             "circuit equations by hand (gl.willis_equations(chain) confirms them), eliminate the other speeds and "
             "give the constraint a1*omega_3 + a2*omega_4 + a3*omega_6 (leave out '= 0') in the ratios e_1_4, "
             "e_2_5, e_3_7, e_6_7. Any non-zero multiple is right.",
    answer=_Constraint(_T2, ("e_1_4", "e_2_5", "e_3_7", "e_6_7")),
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
