"""Checks for chapter 6's exercises (``exercises/06_differential_synthesis.ipynb``).

Expected answers are computed by :mod:`gearlib.synthesis` and :mod:`gearlib.synthesis.atlas`; the
messages give hints, never the answer.
"""

from __future__ import annotations

import sympy

from .. import catalog
from ..synthesis import atlas
from ..synthesis import dgm as synthesis
from ._core import Hint, as_value, close, register, register_custom

_GKC = "cyl_gkc_5_7_2"


def _links(answer) -> set:
    """A set of link ids from a list, tuple, set or text such as ``"1, 3"``."""
    if answer is None:
        raise ValueError("No answer yet: replace `None` with your answer.")
    if isinstance(answer, str):
        answer = [x for x in answer.replace(",", " ").split() if x]
    if isinstance(answer, (int, sympy.Integer)) and not isinstance(answer, bool):
        answer = [answer]
    try:
        items = list(answer)
    except TypeError:
        raise ValueError("Give the links as a list such as [1, 2].") from None
    out = set()
    for x in items:
        try:
            out.add(int(str(x).strip()))
        except ValueError:
            raise ValueError(f"{x!r} is not a link number.") from None
    return out


def _set_check(expected_fn, *, what: str, too_few: str, too_many: str):
    def accept(answer):
        try:
            got = _links(answer)
        except ValueError as err:
            return False, str(err)
        expected = set(expected_fn())
        if got == expected:
            return True, "Well done."
        missing, extra = expected - got, got - expected
        if missing and not extra:
            return False, f"Some {what} are missing ({len(missing)}). {too_few}"
        if extra and not missing:
            return False, f"{len(extra)} of these are not {what}. {too_many}"
        return False, f"Not quite: {len(missing)} missing and {len(extra)} that should not be there. {too_few}"

    return accept


def _grounds():
    return synthesis.identify(catalog.load(_GKC)).grounds


register_custom(
    "synth_ground_links",
    _set_check(_grounds, what="possible ground links",
               too_few="A ground needs at least three links coaxial with it (N2): count the links on each of "
                       "its axes, through every coaxial group it belongs to.",
               too_many="Count only links coaxial with the candidate (one axis label path), not links it meshes with."),
    chapter="06",
    question="GKC 5-7-2: every link that can be the ground of a three-terminal DGM (N2).",
)


def _redundant():
    return synthesis.terminal_constraint(catalog.load(_GKC), (3, 5, 7), ground=4).redundant


register_custom(
    "synth_redundant_links",
    _set_check(_redundant, what="redundant links",
               too_few="Eliminate the non-terminal speeds, then look for each non-terminal's gear ratios "
                       "(as a gear and as a carrier) in the result.",
               too_many="A link is redundant only if none of the ratios of its circuits appears in the constraint."),
    chapter="06",
    question="GKC 5-7-2, ground 4, terminals 3, 5, 7: the redundant links.",
)


def _differential_constraint(answer):
    """Accept ``a1*omega_1 + a2*omega_2 + a3*omega_3`` or ``[a1, a2, a3]`` up to a factor."""
    expected = synthesis.terminal_constraint(catalog.load("cyl_standard_differential"), (1, 2, 3), ground=0)
    ws = [sympy.Symbol(f"omega_{t}") for t in (1, 2, 3)]
    try:
        value = as_value(answer)
    except Exception as err:  # unreadable answers get the reader's own words back
        return False, str(err)[0].upper() + str(err)[1:] + "."
    if isinstance(value, sympy.MatrixBase):
        coeffs = list(value)
    else:
        expr = sympy.expand(value)
        coeffs = [expr.coeff(w) for w in ws]
        if sympy.expand(expr - sum(a * w for a, w in zip(coeffs, ws))) != 0:
            return False, "Write the constraint as a1*omega_1 + a2*omega_2 + a3*omega_3 (the '= 0' left out)."
    if len(coeffs) != 3:
        return False, "Give three coefficients, one per terminal 1, 2, 3."
    if any(sympy.sympify(c).free_symbols & set(ws) for c in coeffs):
        return False, "The coefficients depend only on gear ratios, not on speeds."
    extra = set().union(*(sympy.sympify(c).free_symbols for c in coeffs)) - expected.ratios
    if extra:
        return False, f"Your answer uses {', '.join(sorted(map(str, extra)))}, which the constraint does not need."
    if synthesis.proportional(coeffs, expected.coefficients):
        return True, "Well done: any non-zero multiple of the constraint is the same constraint."
    if sympy.sympify(coeffs[0]) == 0:
        return False, "The input (link 1) must appear in the constraint (C1)."
    for i in range(3):
        flipped = [-c if j == i else c for j, c in enumerate(coeffs)]
        if synthesis.proportional(flipped, expected.coefficients):
            return False, ("One coefficient has the wrong sign: each circuit row reads "
                           "w_b - e w_a + (e - 1) w_c = 0 with the ratio e = e_a_b.")
    return False, ("Eliminate the planet (4) and the case (5): write the three circuit equations with omega_0 = 0 "
                   "and combine the two side-gear rows first.")


register_custom(
    "synth_differential_constraint",
    _differential_constraint,
    chapter="06",
    question="Standard differential, ground 0: the constraint among omega_1, omega_2, omega_3 "
             "(in e_4_2, e_4_3, e_5_1), up to a factor.",
)


@register(
    "synth_seven_link_dgms",
    chapter="06",
    question="How many admissible three-terminal seven-link non-fractionated DGMs does the atlas give?",
    hints=[Hint(lambda a, e: close(a, 50), "That is the number of chains, not of DGMs: most chains give none."),
           Hint(lambda a, e: close(a, 1), "GKC 5-7-2 gives one; other chains of the atlas give more.")],
    generic_hint="Run gl.synthesis.identify on every chain of gl.atlas.geared_chains(7, 2) and count the "
                 "admissible assignments.",
    standard_hints=False,
)
def synth_seven_link_dgms():
    return len(synthesis.synthesize(7, 3))


@register(
    "synth_six_link_rotation_graphs",
    chapter="06",
    question="How many non-fractionated two-dof six-link chains differ in their gear pairs and carriers?",
    hints=[Hint(lambda a, e: close(a, len(atlas.geared_chains(6, 2))), "That counts coaxial arrangements too; "
                "chains with the same gear pairs and carriers count once here."),
           Hint(lambda a, e: close(a, len(atlas.geared_chains(6, 2, fractionated=True, level="kinematic"))),
                "Leave out the fractionated chains (two one-dof chains sharing a link).")],
    generic_hint="Use gl.atlas.geared_chains with level='kinematic'.",
    standard_hints=False,
)
def synth_six_link_rotation_graphs():
    return len(atlas.geared_chains(6, 2, level="kinematic"))
