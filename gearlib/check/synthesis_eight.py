"""Checks for exercises 6.10 to 6.12 of chapter 6 (``exercises/06_differential_synthesis.ipynb``):
three eight-link chains of the atlas that the chapter does not show. Exercise 6.10 asks for a
ground and terminals that make one of them an admissible DGM (any admissible answer passes,
and a wrong one is told which condition it breaks); 6.11 gives another's constraint with one
misprinted symbol, as CYL's eq. (9) has; 6.12 gives a third's list of possible terminals with
one link left out, as CYL's case 6 does.

The chains are stored here as data (:data:`EIGHT_LINK`), so that a check does not enumerate
the atlas; the page takes them from ``gl.atlas.geared_chains(8, 2)`` by name, and a test
compares the two.
"""

from __future__ import annotations

import functools
import re
from itertools import combinations


from ._choice import Choice, LinkId, Parts, _collection, _link
from ._core import register
from ._design import Condition, Design
from ._read import Unreadable
from ._spec import Spec, Verdict
from .synthesis import Constraint

__all__ = ["synth_design_dgm", "synth_misprint", "synth_left_out", "EIGHT_LINK", "eight_link"]


def _circuits(name: str) -> list:
    return [(gp["gears"][0], gp["gears"][1], gp["carrier"]) for gp in EIGHT_LINK[name]["gear_pairs"]]


def _chain_data(name, turning_pairs, circuits) -> dict:
    return {"name": name, "links": list(range(1, 9)), "turning_pairs": [list(tp) for tp in turning_pairs],
            "gear_pairs": [{"gears": [a, b], "ratio": f"e_{a}_{b}", "carrier": c} for a, b, c in circuits]}


EIGHT_LINK = {
    "GKC 8-2-324": _chain_data("GKC 8-2-324",
                               [(1, 2, "a"), (1, 5, "a"), (1, 8, "a"), (1, 6, "b"), (1, 7, "c"), (2, 3, "d"), (2, 4, "d")],
                               [(1, 3, 2), (4, 8, 2), (5, 6, 1), (6, 7, 1), (7, 8, 1)]),
    "GKC 8-2-161": _chain_data("GKC 8-2-161",
                               [(1, 2, "a"), (1, 3, "a"), (1, 5, "a"), (1, 6, "a"), (1, 7, "b"), (2, 8, "c"), (3, 4, "d")],
                               [(1, 4, 3), (2, 7, 1), (3, 8, 2), (5, 7, 1), (6, 8, 2)]),
    "GKC 8-2-667": _chain_data("GKC 8-2-667",
                               [(1, 2, "a"), (1, 7, "a"), (1, 8, "a"), (1, 5, "b"), (1, 6, "c"), (2, 3, "d"), (2, 4, "d")],
                               [(3, 7, 2), (4, 8, 2), (5, 6, 1), (5, 7, 1), (6, 8, 1)]),
}
"""The eight-link chains of exercises 6.10 (GKC 8-2-324), 6.11 (GKC 8-2-161) and 6.12
(GKC 8-2-667), as ``gl.Mechanism.from_dict`` data: the atlas's chains of those names."""


@functools.cache
def eight_link(name: str):
    """The chain *name* of :data:`EIGHT_LINK` as a :class:`~gearlib.Mechanism`."""
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict(EIGHT_LINK[name])


@functools.lru_cache(maxsize=256)
def _constraint(name: str, ground, terminals: tuple):
    from ..synthesis.dgm import terminal_constraint

    return terminal_constraint(eight_link(name), terminals, ground=ground)


def _adjacent(name: str) -> dict:
    from ..synthesis.dgm import adjacency

    return adjacency(eight_link(name))


def _links(xs) -> str:
    xs = sorted(xs)
    return ", ".join(map(str, xs[:-1])) + " and " + str(xs[-1]) if len(xs) > 1 else "".join(map(str, xs))


# ----------------------------------------------------------------------------- 6.10
_DESIGN = "GKC 8-2-324"


class _Assignment(Design):
    """A design whose fields may be a list of links (kind ``"links"``)."""

    def _value(self, key, v):
        if v is None:
            raise Unreadable(f"no answer yet: replace `None` with the {key}")
        if self.fields[key] == "links":
            links = tuple(_link(x) for x in _collection(v, "a list of link ids"))
            if len(links) != 3 or len(set(links)) != 3:
                raise Unreadable(f"{key}: give three different links")
            return tuple(sorted(links, key=str))
        return super()._value(key, v)


def _assignment_conditions(name: str, *, name_redundant: bool = True):
    def known(d, p):
        ids = set(eight_link(name).link_ids)
        return d["ground"] in ids and set(d["terminals"]) <= ids and d["ground"] not in d["terminals"]

    def n2(d, p):
        return known(d, p) and len(_adjacent(name)[d["ground"]]) >= 3

    def c3(d, p):
        return known(d, p) and set(d["terminals"]) <= set(_adjacent(name)[d["ground"]])

    def c3_message(d, p):
        away = [t for t in d["terminals"] if t not in _adjacent(name).get(d["ground"], ())]
        return (f"link{'s' if len(away) > 1 else ''} {_links(away)} {'do' if len(away) > 1 else 'does'} not turn "
                f"about link {d['ground']}: a terminal must be coaxial with the ground (C3)")

    def c1(d, p):
        return known(d, p) and _constraint(name, d["ground"], d["terminals"]).count == 1

    def all_in(d, p):
        return c1(d, p) and not _constraint(name, d["ground"], d["terminals"]).missing_terminals

    def none_redundant(d, p):
        return c1(d, p) and not _constraint(name, d["ground"], d["terminals"]).redundant

    def redundant_message(d, p):
        r = _constraint(name, d["ground"], d["terminals"]).redundant
        which = (f"link{'s' if len(r) > 1 else ''} {_links(r)} {'are' if len(r) > 1 else 'is'}" if name_redundant
                 else "a non-terminal is")
        return (f"{which} redundant: none of the gear ratios of its circuits appears in the constraint (a "
                "non-terminal in one circuit only, N3, always is)")

    return [
        Condition("links of the chain", known, "the ground and the three terminals must be links 1 to 8 of the "
                  "chain, and the ground is not a terminal"),
        Condition("N2", n2, lambda d, p: f"link {d['ground']} is coaxial with "
                  f"{len(_adjacent(name).get(d['ground'], ()))} link(s); a ground of three terminals needs three"),
        Condition("C3", c3, c3_message),
        Condition("one constraint (C1)", c1, lambda d, p: f"these terminal speeds obey "
                  f"{_constraint(name, d['ground'], d['terminals']).count} independent constraints, not one: one "
                  "terminal's speed then fixes the others, and the mechanism cannot share motion between them"),
        Condition("every terminal in it", all_in, lambda d, p: "the coefficient of omega_" + ", omega_".join(
            map(str, _constraint(name, d["ground"], d["terminals"]).missing_terminals)) + " is zero: that terminal "
            "takes no part in the constraint"),
        Condition("no redundant link", none_redundant, redundant_message),
    ]


def _assignment_example(name: str):
    from ..synthesis.dgm import identify

    c = identify(eight_link(name)).admissible[0]
    return {"ground": c.ground, "terminals": list(c.terminals)}


@register(
    "synth_design_dgm", exercise="6.10", title="Design: a ground and terminals for a new differential", stars=3,
    minutes=30, kind="design",
    question=f"Choose a ground and three terminals that make the atlas chain {_DESIGN} an admissible three-terminal "
             "DGM: one constraint among the terminals, every terminal in it, no redundant link. Work from the "
             "turning pairs and the fundamental circuits (N2, C3, N3), then derive the constraint. Give "
             "{'ground': ..., 'terminals': [...]}; any admissible choice passes.",
    answer=_Assignment({"ground": "link", "terminals": "links"}, _assignment_conditions(_DESIGN),
                       example=lambda p: _assignment_example(_DESIGN)),
)
def synth_design_dgm():
    return None


# ----------------------------------------------------------------------------- 6.11
_MISPRINT = "GKC 8-2-161"
_PRINTED = ("(e_2_7 - e_5_7)*(e_3_8 - e_6_7)*omega_4 + e_1_4*e_5_7*(e_3_8 - e_6_8)*omega_5 "
            "+ e_1_4*e_2_7*e_6_8*omega_6")
"""The constraint of exercise 6.11 as the report prints it (ground 3, terminals 4, 5, 6)."""


def _symbols_printed() -> list:
    return sorted({n for n in re.findall(r"e_\d_\d", _PRINTED)})


_WRONG = Choice(_symbols_printed(), synonyms={n: [n.replace("e_", "gamma_"), n[2] + n[4]] for n in _symbols_printed()},
                generic="That gear pair is in the chain: compare each symbol of the printed constraint with the "
                        "chain's fundamental circuits.")


@register(
    "synth_misprint", exercise="6.11", title="Find the misprint in a printed constraint", stars=2, minutes=20,
    kind="mistake",
    question=f"A report on the atlas chain {_MISPRINT} prints, for ground 3 and terminals 4, 5 and 6, the "
             f"constraint {_PRINTED} = 0. One symbol is misprinted, as in CYL's eq. (9). Which symbol is it, and "
             "what is the right constraint (any non-zero multiple)? Give {'symbol': ..., 'constraint': ...}.",
    answer=Parts({
        "symbol": ("the misprinted symbol", _WRONG),
        "constraint": ("the constraint", Constraint(
            (4, 5, 6), ("e_1_4", "e_2_7", "e_3_8", "e_5_7", "e_6_8"), name_extra=False,
            generic="Derive the constraint: with omega_3 = 0, eliminate omega_1, omega_2, omega_7 and omega_8 from "
                    "the five circuit equations (two pairs of them share a carrier and a gear)")),
    }),
)
def synth_misprint():
    real = set(f"e_{a}_{b}" for a, b, _ in _circuits(_MISPRINT))
    (wrong,) = set(_symbols_printed()) - real
    return {"symbol": wrong, "constraint": _constraint(_MISPRINT, 3, (4, 5, 6)).coefficients}


# ----------------------------------------------------------------------------- 6.12
class _Terminals(Spec):
    """Three terminals for a given ground of a chain: any admissible choice passes; a wrong
    one is told which condition it breaks (the conditions of exercise 6.10)."""

    form = "a list of three link ids"

    def __init__(self, name: str, ground):
        self.ground = ground
        self.conditions = _assignment_conditions(name, name_redundant=False)[1:]

    def _read(self, answer) -> tuple:
        links = tuple(_link(x) for x in _collection(answer, self.form))
        if len(links) != 3 or len(set(links)) != 3:
            raise Unreadable("give three different links")
        return tuple(sorted(links, key=str))

    def check_form(self, answer) -> None:
        self._read(answer)

    def prepare(self, reference):
        return frozenset(reference)

    def example(self, reference, params):
        return sorted(reference)

    def judge(self, answer, reference, params) -> Verdict:
        d = {"ground": self.ground, "terminals": self._read(answer)}
        if self.ground in d["terminals"]:
            return Verdict(False, f"Link {self.ground} is the ground; the terminals are three other links")
        for c in self.conditions:
            try:
                ok = bool(c.test(d, params))
            except (ValueError, TypeError, ArithmeticError):
                ok = False
            if not ok:
                message = c.message(d, params) if callable(c.message) else c.message
                return Verdict(False, f"{c.name[:1].upper() + c.name[1:]}: {message}")
        return Verdict(True, "Well done: with these terminals the chain is an admissible DGM", 1.0)


_LEFT_OUT = "GKC 8-2-667"
_LISTED = (1, 4, 7, 8)


@register(
    "synth_left_out", exercise="6.12", title="Find the link a printed list leaves out", stars=2, minutes=20,
    kind="mistake",
    question=f"A report on the atlas chain {_LEFT_OUT} says: 'with link 2 as the ground, the terminals can be "
             "chosen from links " + ", ".join(map(str, _LISTED[:-1])) + f" and {_LISTED[-1]}; none of the four "
             "choices gives an admissible DGM, so link 2 cannot be the ground.' The list leaves out one link, as "
             "CYL's case 6 does. Which link, and which terminals (with ground 2) then make an admissible DGM? Give "
             "{'link': ..., 'terminals': [...]}.",
    answer=Parts({
        "link": ("the link left out", LinkId(links=lambda p: list(range(1, 9)), wrong=lambda p: {
            **{k: "That link is on the printed list." for k in _LISTED},
            2: "Link 2 is the ground itself.",
            **{k: f"Link {k} does not turn about link 2: no path of thin edges with one label joins them."
               for k in range(1, 9) if k not in _adjacent(_LEFT_OUT)[2] and k != 2}},
            generic="Look for the links coaxial with link 2: every path of thin edges with one label, through "
                    "other links too.")),
        "terminals": ("the terminals", _Terminals(_LEFT_OUT, 2)),
    }),
)
def synth_left_out():
    adj = set(_adjacent(_LEFT_OUT)[2])
    (missing,) = adj - set(_LISTED)
    good = [t for t in combinations(sorted(adj), 3) if _constraint(_LEFT_OUT, 2, t).admissible]
    return {"link": missing, "terminals": frozenset(good[0])}
