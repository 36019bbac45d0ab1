"""Checks for the exercises of chapter 2, kinematic units (``exercises/02_kinematic_units.ipynb``)."""

from __future__ import annotations

from collections.abc import Iterable, Mapping

from .. import catalog
from ..units.fractionation import kinematic_units
from ._core import register, register_custom


def _link_sets(answer):
    """A list of units, each a collection of link ids, as a set of frozensets (or None)."""
    if isinstance(answer, (str, bytes, Mapping)) or not isinstance(answer, Iterable):
        return None
    out = []
    for unit in answer:
        if isinstance(unit, (str, bytes, Mapping)) or not isinstance(unit, Iterable):
            return None
        links = set()
        for x in unit:
            if isinstance(x, bool) or not isinstance(x, (int, str)):
                return None
            links.add(int(x) if isinstance(x, str) and x.isdigit() else x)
        out.append(frozenset(links))
    return out


def _accept_units(name: str, what: str):
    def accept(answer):
        if answer is None:
            return False, "No answer yet: replace `None` with a list of units, each a set of link ids."
        got = _link_sets(answer)
        if got is None:
            return False, "Give a list of units, each a set of link ids such as {1, 2, 3}."
        units = kinematic_units(catalog.load(name)).units
        expected = {frozenset(u.links) for u in units}
        if set(got) == expected and len(got) == len(expected):
            return True, "Well done."
        if len(got) != len(expected):
            return False, (f"{what} has a different number of units: one unit per carrier (per connected piece of "
                           "the gear pairs on that carrier).")
        gears_only = {frozenset(u.gears) for u in units}
        if set(got) == gears_only:
            return False, "Each unit also contains its carrier (step 3 adds the carrier vertex)."
        return False, ("Not these links: a unit is a carrier with every gear that meshes on it; a link can belong to "
                       "two units (a common link).")

    return accept


register_custom("units_simpson", _accept_units("simpson", "The Simpson gear set"), chapter="02",
                question="The kinematic units of the Simpson gear set, each as a set of links.")


def _normalise(text) -> str:
    return "".join(str(text).upper().split()).replace("–", "-").replace("_", "-")


def _accept_type(answer):
    if answer is None:
        return False, "No answer yet: replace `None` with a catalogue name such as 'K5-2'."
    if not isinstance(answer, str):
        return False, "Give the type as text, for example 'K5-2' or 'K5-2S'."
    got = _normalise(answer)
    unit = kinematic_units(catalog.load("simpson")).units[1]
    if got == _normalise(unit.type):
        return True, "Well done."
    if got == _normalise(unit.base_type):
        return False, ("The structure is right, but look at the common links: two of them are gears of this unit "
                       "on one axis, so step 4 joins them by a g-g thin edge.")
    if got.startswith("K4"):
        return False, "Right size. Which of the unit's gears share an axis on the carrier?"
    if got.startswith("K"):
        return False, "Count the unit's links: the carrier and every gear on it."
    return False, "Give a catalogue name of the form Kn-#, with S or D for g-g thin edges."


register_custom("unit_type_simpson", _accept_type, chapter="02",
                question="The catalogue type of the Simpson set's unit with carrier 4.")

_KINDS = {"2-LINKCHAIN": "2-link chain", "TWO-LINKCHAIN": "2-link chain", "COAXIALTRIANGLE": "coaxial triangle"}


def _accept_linkage(answer):
    if answer is None:
        return False, "No answer yet: replace `None` with '2-link chain' or 'coaxial triangle'."
    if not isinstance(answer, str):
        return False, "Give the kind of common linkage as text."
    got = _KINDS.get(_normalise(answer).replace("-", "").replace("2LINK", "2-LINK"))
    if got is None:
        return False, "The two kinds are '2-link chain' and 'coaxial triangle'."
    kinds = {c.kind for c in kinematic_units(catalog.load("chen_wrist")).linkages}
    if got in kinds:
        return True, "Well done."
    return False, "Count the units that share links, and how many links each two of them share."


register_custom("linkage_wrist", _accept_linkage, chapter="02",
                question="The kind of common linkage between the units of Chen's wrist.")


@register(
    "atlas_single_unit_chains",
    chapter="02",
    question="How many of the non-isomorphic one-dof five-link geared chains are a single kinematic unit?",
    generic_hint="Fractionate every chain of gl.atlas.geared_chains(5, 1) and count those with one unit.",
    standard_hints=False,
)
def atlas_single_unit_chains():
    from ..synthesis import atlas

    return sum(1 for m in atlas.geared_chains(5, 1) if len(kinematic_units(m).units) == 1)
