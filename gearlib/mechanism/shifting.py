"""Shift elements and the shift schedule of a transmission, as data.

An automatic transmission makes each of its gears by engaging a few **shift elements**:

* a **brake** holds one link to the frame (the mechanism's ``ground``);
* a **clutch** joins two links so that they turn together.

Each is named as the maker names it (``A``, ``B``, ``C1``, ``K1``...). The **schedule** lists
the gears, each as the set of elements it engages. In a mechanism file::

    ground: 1
    inputs: [2]
    output: 8
    shift_elements:
      - {name: B1, type: brake, link: 4}
      - {name: C1, type: clutch, links: [2, 5]}
    schedule:
      - {gear: 1st, engaged: [B1, C1]}

The analyses of a gear (:func:`gearlib.shift_table`, ``held=``/``joined=`` of
:func:`gearlib.speeds`) read these through :meth:`gearlib.mechanism.GearState.constraints`.

>>> import gearlib as gl
>>> b = gl.mechanism.ShiftElement("B1", "brake", (4,))
>>> b.links, b.kind
((4,), 'brake')
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from .._common.parse import parse_link_id
from ..errors import DataFormatError, DuplicateEdgeError, UnknownLinkError
from .elements import _check_keys, _fmt, _seq, _text

__all__ = ["ShiftElement", "GearState", "SHIFT_KINDS"]

SHIFT_KINDS = ("brake", "clutch")


@dataclass(frozen=True)
class ShiftElement:
    """A brake (``links = (link,)``, held to the frame) or a clutch (``links = (u, v)``,
    joined), with the name the maker gives it."""

    name: str
    kind: str
    links: tuple

    def __post_init__(self):
        name = _text(self.name, "shift element", "name")
        if not name:
            raise DataFormatError("shift element: give it a `name` (as the maker names it, e.g. C1 or B)")
        object.__setattr__(self, "name", name)
        where = f"shift element {name!r}"
        if not isinstance(self.kind, str) or self.kind not in SHIFT_KINDS:
            raise DataFormatError(f"{where}: `type` must be brake or clutch, got {self.kind!r}")
        links = self.links
        if isinstance(links, (str, int)) and not isinstance(links, bool):
            links = (links,)
        links = tuple(parse_link_id(x, where) for x in _seq(links, where, "links"))
        want = 1 if self.kind == "brake" else 2
        if len(links) != want:
            raise DataFormatError(
                f"{where}: a brake holds one link to the frame (`link: 4`), a clutch joins two (`links: [2, 5]`); "
                f"got {len(links)} link(s)"
            )
        if self.kind == "clutch" and links[0] == links[1]:
            raise DataFormatError(f"{where} joins link {links[0]} to itself; a clutch joins two different links")
        object.__setattr__(self, "links", links)

    @classmethod
    def from_data(cls, data, where: str = "shift element") -> ShiftElement:
        if isinstance(data, ShiftElement):
            return data
        if not isinstance(data, Mapping):
            raise DataFormatError(
                f"{where}: expected a mapping such as {{name: C1, type: clutch, links: [2, 5]}}, got {data!r}")
        _check_keys(data, ("name", "type", "kind", "link", "links"), where)
        if "type" in data and "kind" in data and data["type"] != data["kind"]:
            raise DataFormatError(f"{where}: `type: {data['type']}` and `kind: {data['kind']}` disagree; give one")
        kind = data.get("type", data.get("kind"))
        if kind is None:
            raise DataFormatError(f"{where}: give `type: brake` or `type: clutch`")
        if ("link" in data) == ("links" in data):
            raise DataFormatError(f"{where}: give `link: L` for a brake or `links: [U, V]` for a clutch (one of them)")
        return cls(data.get("name"), kind, data["link"] if "link" in data else data["links"])

    def to_data(self) -> dict:
        if self.kind == "brake":
            return {"name": self.name, "type": "brake", "link": self.links[0]}
        return {"name": self.name, "type": "clutch", "links": list(self.links)}


@dataclass(frozen=True)
class GearState:
    """One gear of a transmission: its name (``"1st"``, ``"R"``) and the shift elements it
    engages, by name."""

    name: str
    engaged: tuple

    def __post_init__(self):
        name = _text(self.name, "schedule", "gear")
        if not name:
            raise DataFormatError("schedule: every entry needs a `gear:` name such as 1st or R")
        object.__setattr__(self, "name", name)
        engaged = self.engaged
        if isinstance(engaged, str):
            engaged = (engaged,)
        names = tuple(_text(x, f"gear {name!r}", "engaged") for x in _seq(engaged, f"gear {name!r}", "engaged"))
        if len(set(names)) != len(names):
            raise DataFormatError(f"gear {name!r} engages an element twice: {', '.join(names)}")
        object.__setattr__(self, "engaged", names)

    def constraints(self, elements: Sequence[ShiftElement]) -> dict:
        """``{"held": [...], "joined": [(u, v), ...]}`` for :func:`gearlib.speeds` and friends."""
        by_name = {e.name: e for e in elements}
        held, joined = [], []
        for n in self.engaged:
            e = by_name[n]
            if e.kind == "brake":
                held.append(e.links[0])
            else:
                joined.append(e.links)
        return {"held": held, "joined": joined}

    @classmethod
    def from_data(cls, data, where: str = "schedule entry") -> GearState:
        if isinstance(data, GearState):
            return data
        if not isinstance(data, Mapping):
            raise DataFormatError(f"{where}: expected a mapping such as {{gear: 1st, engaged: [B1, C1]}}, got {data!r}")
        _check_keys(data, ("gear", "engaged"), where)
        if "gear" not in data:
            raise DataFormatError(f"{where}: missing `gear:` (its name, e.g. 1st)")
        return cls(data["gear"], data.get("engaged", ()))

    def to_data(self) -> dict:
        return {"gear": self.name, "engaged": list(self.engaged)}


def validate(elements, schedule, link_ids, ground) -> tuple[tuple, tuple]:
    """The shift elements and schedule of a mechanism, checked against its links."""
    elements = tuple(ShiftElement.from_data(e, f"shift element {i + 1}")
                     for i, e in enumerate(_seq(elements, "mechanism", "shift_elements")))
    known = set(link_ids)
    names: dict = {}
    for e in elements:
        if e.name in names:
            raise DuplicateEdgeError(f"shift element {e.name!r} is declared twice; names must be unique")
        names[e.name] = e
        for x in e.links:
            if x not in known:
                raise UnknownLinkError(f"shift element {e.name!r} refers to unknown link {x}; links are {_fmt(link_ids)}")
        if e.kind == "brake":
            if ground is None:
                raise DataFormatError(f"brake {e.name!r} holds link {e.links[0]} to the frame: give the frame as `ground`")
            if e.links[0] == ground:
                raise DataFormatError(f"brake {e.name!r} holds the frame {ground} to itself; name the link it brakes")
        elif ground in e.links:
            raise DataFormatError(
                f"clutch {e.name!r} joins link {e.links[0 if e.links[1] == ground else 1]} to the frame {ground}: "
                "that is a brake (`type: brake, link: ...`)")
    gears = tuple(GearState.from_data(g, f"schedule entry {i + 1}") for i, g in enumerate(_seq(schedule, "mechanism", "schedule")))
    seen = set()
    for g in gears:
        if g.name in seen:
            raise DuplicateEdgeError(f"gear {g.name!r} is listed twice in `schedule`")
        seen.add(g.name)
        for n in g.engaged:
            if n not in names:
                known_names = ", ".join(names) or "none declared"
                raise UnknownLinkError(f"gear {g.name!r} engages unknown shift element {n!r}; elements are {known_names}")
    return elements, gears
