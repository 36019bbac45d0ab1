"""Geared mechanisms as validated, immutable data: :class:`Mechanism`.

A mechanism is described in the vocabulary of the papers (Freudenstein, Tsai, Liu and
Chen, Penaud and Alazard):

* **links** are the vertices of the graph; an id is an integer or a short name;
* **turning pairs** (thin edges) ``[link, link, axis_label]``: links joined by a revolute
  joint; two links are *coaxial* when a path of turning pairs with one axis label joins them;
* **gear pairs** (heavy edges) with tooth numbers or a gear ratio, and a **carrier** (the
  transfer vertex): the link that holds both gear axes. When the carrier is left out it is
  found from the turning pairs (:meth:`Mechanism.carrier_candidates`).

The gear ratio of pair ``(a, b)`` is ``e_{a,b} = omega(b/c) / omega(a/c)`` where ``c`` is the
carrier and ``omega(u/v)`` the angular velocity of ``u`` relative to ``v``: ``-N_a/N_b`` for an
external spur mesh, ``+N_a/N_b`` for an internal one; for bevel gears it is complex (Penaud's
angles) or given with the sign fixed by the chosen axis directions.

Every check runs when the object is built, so a :class:`Mechanism` that exists is valid.

>>> import gearlib as gl
>>> m = gl.Mechanism.from_dict({
...     "name": "simple planetary",
...     "links": {1: "sun", 2: "planet", 3: "ring", 4: "carrier", 5: "frame"},
...     "turning_pairs": [[5, 1, "a"], [5, 3, "a"], [5, 4, "a"], [4, 2, "b"]],
...     "gear_pairs": [{"gears": [1, 2], "teeth": [24, 18]},
...                    {"gears": [2, 3], "teeth": [18, 60], "type": "internal"}]})
>>> [p.carrier for p in m.gear_pairs]
[4, 4]
>>> m.gear_pairs[1].e
3/10
"""

from __future__ import annotations
import dataclasses
import functools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
import sympy
from .._common.parse import hashable as _hashable, iterable as _iterable, parse_link_id, parse_real, parse_teeth
from .._common.parse import shown as _short
from .._common.topology import CoaxialGroups, UnionFind, components
from ..errors import (
    AxisError,
    CarrierError,
    DataFormatError,
    DisconnectedError,
    DuplicateEdgeError,
    OverconstrainedError,
    UnknownLinkError,
)
from .elements import GearPair, Link, TurningPair, _check_keys, _fmt, _pair_of, _seq, _text
from ._axes import infer_axes
from .shifting import validate as validate_shifting

__all__ = ['Mechanism']


_MECH_FIELDS = ("name", "description", "source", "links", "turning_pairs", "gear_pairs", "ground", "inputs", "layout",
                "output", "planets", "shift_elements", "schedule")


@dataclass(frozen=True)
class Mechanism:
    """A geared mechanism: links, turning pairs and gear pairs, validated on construction.

    Build it from data with :meth:`from_dict` or :func:`gearlib.load`, or directly; lists
    of tuples such as ``[(1, 2, "a")]`` are accepted for the pairs. Change one with
    :meth:`replace` or :meth:`with_gear_pair`: the result is a new, re-validated object.

    Attributes
    ----------
    links, turning_pairs, gear_pairs : tuple
    name, description, source : str
        ``source`` cites where the mechanism comes from.
    ground : link id, optional
        The link usually held fixed (a default for analyses and drawings).
    inputs : tuple of link ids, optional
        The usual input links (a default for drawings and the command line).
    layout : tuple of (link id, (x, y)), optional
        Positions for drawing the graph as the source draws it.
    output : link id, optional
        The usual output link (a transmission's output shaft).
    planets : tuple of (link id, count), optional
        Planets that stand for ``count`` identical, equally spaced planets on their carrier
        (``planets: {3: 4}`` in a file); kinematics needs one, assembly conditions and fault
        frequencies need the count (:meth:`planet_count`).
    shift_elements, schedule : tuple
        A transmission's brakes and clutches (:class:`~gearlib.mechanism.ShiftElement`) and
        its gears, each the set of elements it engages (:class:`~gearlib.mechanism.GearState`);
        see :mod:`gearlib.mechanism.shifting`.
    """

    links: tuple
    turning_pairs: tuple = ()
    gear_pairs: tuple = ()
    name: str = "mechanism"
    description: str | None = None
    source: str | None = None
    ground: int | str | None = None
    inputs: tuple = ()
    layout: tuple | None = field(default=None, compare=False)
    output: int | str | None = None
    planets: tuple = ()
    shift_elements: tuple = ()
    schedule: tuple = ()

    # ------------------------------------------------------------------ validation
    def __post_init__(self):
        links = self._coerce_links(self.links)
        ids = [lk.id for lk in links]
        known = set(ids)
        tps = tuple(TurningPair.from_data(t, f"turning pair {i + 1}")
                    for i, t in enumerate(_seq(self.turning_pairs, "mechanism", "turning_pairs")))
        gps = tuple(GearPair.from_data(g, f"gear pair {i + 1}")
                    for i, g in enumerate(_seq(self.gear_pairs, "mechanism", "gear_pairs")))
        for attr in ("description", "source"):
            object.__setattr__(self, attr, _text(getattr(self, attr), "mechanism", attr))
        if not isinstance(self.name, str):
            object.__setattr__(self, "name", _text(self.name, "mechanism", "name") or "mechanism")

        def need(link, where):
            if link not in known:
                raise UnknownLinkError(
                    f"{where} refers to unknown link {link}; declared links are {_fmt(ids)}. "
                    f"Add {link} to `links` or fix the id."
                )

        seen = {}
        for tp in tps:
            for x in tp.links:
                if x not in known:
                    need(x, f"turning pair {tp.links}")
            key = frozenset(tp.links)
            if key in seen:
                raise DuplicateEdgeError(f"turning pair {tp.links} is given twice; remove one")
            seen[key] = tp
        seen_g = {}
        for gp in gps:
            for x in gp.gears:
                if x not in known:
                    need(x, f"gear pair {gp.label}")
            if gp.carrier is not None and gp.carrier not in known:
                need(gp.carrier, f"carrier of gear pair {gp.label}")
            key = frozenset(gp.gears)
            if key in seen_g:
                raise DuplicateEdgeError(f"gear pair {gp.label} is given twice; remove one")
            seen_g[key] = gp
        if any(tp.axis is None for tp in tps):  # labels left out: inferred from the carriers
            tps = infer_axes(ids, tps, gps, lambda tp, label: dataclasses.replace(tp, axis=label))
        object.__setattr__(self, "links", links)
        object.__setattr__(self, "turning_pairs", tps)

        comps = components(ids, [tp.links for tp in tps] + [gp.gears for gp in gps])
        if len(comps) > 1:
            pieces = "; ".join("{" + _fmt(c[:10]) + (", ..." if len(c) > 10 else "") + "}" for c in comps[:5])
            pieces += "; ..." if len(comps) > 5 else ""
            raise DisconnectedError(
                f"mechanism {self.name!r} falls apart into {len(comps)} pieces: {pieces}. "
                "Join them with a turning pair or a gear pair, or describe them separately."
            )
        groups = CoaxialGroups([(tp.links[0], tp.links[1], tp.axis) for tp in tps])
        object.__setattr__(self, "gear_pairs", tuple(self._resolve_carrier(gp, groups) for gp in gps))
        self._check_gear_loops()
        loop = groups.mixed_loop()
        if loop is not None:
            raise AxisError(
                f"turning pairs among links {_fmt(loop)} close a loop with more than one axis label; "
                "such a loop would be rigid. Only coaxial bearings (one label) may form loops: "
                "check the axis labels or remove a turning pair."
            )
        for attr in ("ground", "output"):
            value = getattr(self, attr)
            if value is not None:
                value = parse_link_id(value, attr)
                need(value, f"`{attr}`")
                object.__setattr__(self, attr, value)
        raw_inputs = self.inputs if self.inputs is not None else ()
        if isinstance(raw_inputs, (str, int)) and not isinstance(raw_inputs, bool):
            raw_inputs = (raw_inputs,)
        if isinstance(raw_inputs, (bytes, Mapping)) or not isinstance(raw_inputs, Sequence):
            raise DataFormatError(f"`inputs` must be a list of link ids, got {raw_inputs!r}")
        inputs = tuple(parse_link_id(x, "inputs") for x in raw_inputs)
        for x in inputs:
            need(x, "`inputs`")
        object.__setattr__(self, "inputs", inputs)
        object.__setattr__(self, "planets", self._coerce_planets(self.planets, gps, need))
        elements, schedule = validate_shifting(self.shift_elements, self.schedule, ids, self.ground)
        object.__setattr__(self, "shift_elements", elements)
        object.__setattr__(self, "schedule", schedule)
        if self.layout is not None:
            object.__setattr__(self, "layout", self._coerce_layout(self.layout, known))
        object.__setattr__(self, "_groups", groups)

    @staticmethod
    def _coerce_links(links) -> tuple:
        if isinstance(links, Mapping):
            items = [Link(k, v) for k, v in links.items()]
        elif isinstance(links, (str, bytes)) or not isinstance(links, Sequence):
            raise DataFormatError(f"`links` must be a list of ids or a mapping id -> name, got {links!r}")
        else:
            items = []
            for i, x in enumerate(links):
                if isinstance(x, Link):
                    items.append(x)
                elif isinstance(x, Mapping):
                    _check_keys(x, ("id", "name"), f"link {i + 1}")
                    if "id" not in x:
                        raise DataFormatError(f"link {i + 1}: missing `id`")
                    items.append(Link(x["id"], x.get("name")))
                else:
                    items.append(Link(x))
        if not items:
            raise DataFormatError("`links` is empty; a mechanism needs at least two links")
        seen = set()
        for lk in items:
            if lk.id in seen:
                raise DuplicateEdgeError(f"link {lk.id} is declared twice in `links`")
            seen.add(lk.id)
        return tuple(items)

    @staticmethod
    def _coerce_planets(planets, gear_pairs, need) -> tuple:
        if isinstance(planets, Mapping):
            items = list(planets.items())
        elif isinstance(planets, tuple) and all(isinstance(i, tuple) and len(i) == 2 for i in planets):
            items = list(planets)  # the stored form, from replace()
        else:
            raise DataFormatError(f"`planets` must be a mapping planet link -> number of planets, got {planets!r}")
        gears = {g for gp in gear_pairs for g in gp.gears}
        out = []
        for k, n in items:
            k = parse_link_id(k, "planets")
            need(k, "`planets`")
            if k not in gears:
                raise DataFormatError(f"`planets` counts copies of link {k}, which is not a gear of any gear pair")
            if isinstance(n, bool) or not isinstance(n, int) or n < 1:
                raise DataFormatError(f"`planets`: link {k} needs a whole number of planets (1 or more), got {n!r}")
            out.append((k, n))
        return tuple(out)

    @staticmethod
    def _coerce_layout(layout, known) -> tuple:
        if isinstance(layout, Mapping):
            items = list(layout.items())
        elif isinstance(layout, tuple) and all(isinstance(i, tuple) and len(i) == 2 for i in layout):
            items = list(layout)  # the stored form, from replace()
        else:
            raise DataFormatError(f"`layout` must be a mapping link -> [x, y], got {type(layout).__name__}")
        out = []
        for k, xy in items:
            k = parse_link_id(k, "layout")
            if k not in known:
                raise UnknownLinkError(f"`layout` places unknown link {k}")
            x, y = _pair_of(xy, f"layout of link {k}", "position")
            out.append((k, (parse_real(x, f"layout of link {k}"), parse_real(y, f"layout of link {k}"))))
        return tuple(out)

    def _resolve_carrier(self, gp: GearPair, groups: CoaxialGroups) -> GearPair:
        a, b = gp.gears
        label = groups.coaxial_label(a, b)
        if label is not None:
            raise CarrierError(
                f"gear pair {gp.label}: gears {a} and {b} are coaxial (axis {label!r}) and cannot mesh; "
                "check the axis labels of their turning pairs"
            )
        cands = groups.carrier_candidates(a, b)
        carriers = sorted({c for c, _, _ in cands}, key=str)
        if gp.carrier is not None:
            if gp.carrier in carriers:
                return gp
            hint = f"the turning pairs make {_fmt(carriers)} the carrier" if carriers else self._why_no_carrier(gp, groups)
            raise CarrierError(
                f"gear pair {gp.label}: carrier {gp.carrier} does not hold both gears "
                f"(each gear must be joined to its carrier by turning pairs on one axis, the two gears on "
                f"different axes); {hint}"
            )
        if len(carriers) == 1:
            return dataclasses.replace(gp, carrier=carriers[0])
        if not carriers:
            raise CarrierError(f"gear pair {gp.label} has no possible carrier: {self._why_no_carrier(gp, groups)}")
        raise CarrierError(
            f"gear pair {gp.label} has more than one possible carrier ({_fmt(carriers)}); "
            "give `carrier:` explicitly or check the axis labels"
        )

    def _check_gear_loops(self) -> None:
        """Gear pairs on one carrier must form a tree, or close loops whose ratios multiply to 1
        (a duplicate planet); otherwise the loop locks its gears."""
        trees: dict = {}
        for gp in self.gear_pairs:
            uf, adj = trees.setdefault(gp.carrier, (UnionFind(), {}))
            a, b = gp.gears
            uf.add(a)
            uf.add(b)
            if not uf.union(a, b):
                path = self._tree_path(adj, b, a)  # b -> ... -> a, then the new pair a -> b
                product = gp.e
                for _x, _y, e in path:
                    product = product * e
                if sympy.simplify(product - 1) != 0:
                    loop = " -> ".join(str(x) for x, _, _ in path) + f" -> {a}"
                    raise OverconstrainedError(
                        f"gear pair {gp.label} closes a loop of gears on carrier {gp.carrier} ({loop} -> {b}) whose "
                        f"ratios multiply to {sympy.nsimplify(product)}, not 1: the loop locks its gears. "
                        "Remove one pair of the loop or fix the tooth numbers"
                    )
            adj.setdefault(a, []).append((b, gp, False))
            adj.setdefault(b, []).append((a, gp, True))  # the inverse ratio, computed only on a loop

    @staticmethod
    def _tree_path(adj, start, goal):
        """Edges ``(x, y, e_xy)`` of the path from *start* to *goal* in a forest given as adjacency."""
        prev = {start: None}
        queue = [start]
        while queue:
            x = queue.pop()
            if x == goal:
                break
            for y, gp, inverse in adj.get(x, ()):
                if y not in prev:
                    prev[y] = (x, 1 / gp.e if inverse else gp.e)
                    queue.append(y)
        path = []
        y = goal
        while prev[y] is not None:
            x, e = prev[y]
            path.append((x, y, e))
            y = x
        return path[::-1]

    @staticmethod
    def _why_no_carrier(gp, groups) -> str:
        for g in gp.gears:
            if g not in groups.membership:
                return f"gear {g} has no turning pair; give it a bearing (turning pair) on its carrier"
        a, b = gp.gears
        return (
            f"no link is joined by turning pairs to gear {a} on one axis and to gear {b} on another. "
            "Add the turning pairs that hold both gears on one link (the carrier), or fix the axis labels"
        )

    # ------------------------------------------------------------------ conversions
    @classmethod
    def from_dict(cls, data: Mapping) -> Mechanism:
        """Build a mechanism from plain data (as read from YAML or JSON)."""
        if not isinstance(data, Mapping):
            raise DataFormatError(f"a mechanism must be a mapping with `links`, `gear_pairs`, ...; got {type(data).__name__}")
        _check_keys(data, _MECH_FIELDS, "mechanism")
        if "links" not in data:
            raise DataFormatError("mechanism: missing `links`")
        for key in ("turning_pairs", "gear_pairs"):
            value = data.get(key)
            if value is not None and (isinstance(value, (str, bytes, Mapping)) or not isinstance(value, Sequence)):
                raise DataFormatError(f"mechanism: `{key}` must be a list, got {type(value).__name__}")
        inputs = data.get("inputs")
        if isinstance(inputs, list):
            inputs = tuple(inputs)
        return cls(
            links=data["links"],
            turning_pairs=tuple(data.get("turning_pairs") or ()),
            gear_pairs=tuple(data.get("gear_pairs") or ()),
            name=_text(data.get("name"), "mechanism", "name") or "mechanism",
            description=data.get("description"),
            source=data.get("source"),
            ground=data.get("ground"),
            inputs=inputs,
            layout=data.get("layout"),
            output=data.get("output"),
            planets=data.get("planets") or {},
            shift_elements=data.get("shift_elements") or (),
            schedule=data.get("schedule") or (),
        )

    def to_dict(self) -> dict:
        """Plain data that :meth:`from_dict` reads back to an equal mechanism."""
        out: dict = {"name": self.name}
        if self.description:
            out["description"] = self.description
        if self.source:
            out["source"] = self.source
        out["links"] = {lk.id: lk.name for lk in self.links}
        out["turning_pairs"] = [tp.to_data() for tp in self.turning_pairs]
        out["gear_pairs"] = [gp.to_data() for gp in self.gear_pairs]
        if self.ground is not None:
            out["ground"] = self.ground
        if self.inputs:
            out["inputs"] = list(self.inputs)
        if self.layout is not None:
            out["layout"] = {k: list(xy) for k, xy in self.layout}
        if self.output is not None:
            out["output"] = self.output
        if self.planets:
            out["planets"] = dict(self.planets)
        if self.shift_elements:
            out["shift_elements"] = [e.to_data() for e in self.shift_elements]
        if self.schedule:
            out["schedule"] = [g.to_data() for g in self.schedule]
        return out

    def replace(self, **changes) -> Mechanism:
        """A copy with some fields changed, validated again."""
        return dataclasses.replace(self, **changes)

    def with_gear_pair(self, gears, **changes) -> Mechanism:
        """A copy in which the gear pair between ``gears`` has some fields changed,
        e.g. ``m.with_gear_pair((1, 2), teeth=(30, 15))``."""
        gp, _ = self.gear_pair(*gears)
        if "teeth" in changes and "ratio" not in changes and gp.ratio is not None and not gp.ratio.free_symbols:
            if gp.kind == "bevel" and gp.angles is None:  # keep the sign, take the size from the teeth
                na, nb = changes["teeth"]
                changes["ratio"] = sympy.sign(gp.ratio) * sympy.Rational(parse_teeth(na, "teeth"), parse_teeth(nb, "teeth"))
            else:
                changes["ratio"] = None
        pairs = tuple(dataclasses.replace(p, **changes) if p is gp else p for p in self.gear_pairs)
        return self.replace(gear_pairs=pairs)

    # ------------------------------------------------------------------ lookups
    @cached_property
    def link_ids(self) -> tuple:
        """Link ids in declaration order (the column order of every matrix)."""
        return tuple(lk.id for lk in self.links)

    @cached_property
    def index(self) -> dict:
        """Column index of each link id."""
        return {x: i for i, x in enumerate(self.link_ids)}

    def link(self, link_id) -> Link:
        """The :class:`Link` with this id (``"3"`` finds link 3)."""
        key = self.resolve(link_id)
        return self.links[self.index[key]]

    def resolve(self, link_id, what: str = "link"):
        """Normalise a link id given by a user; raise :class:`UnknownLinkError` if there is none,
        and :class:`DataFormatError` for something that is not one id (a list, True, a mapping)."""
        if type(link_id) in (int, str) and link_id in self.index:  # the common case, fast
            return link_id
        if isinstance(link_id, float) and link_id.is_integer():
            link_id = int(link_id)  # 3.0 from a computation is link 3
        if isinstance(link_id, bool) or not _hashable(link_id) or isinstance(link_id, float):
            kind = "True/False" if isinstance(link_id, bool) else f"a {type(link_id).__name__}"
            raise DataFormatError(
                f"{what}: expected one link id such as {self.link_ids[0]!r}, got {kind} ({_short(link_id)}); "
                f"links are {_fmt(self.link_ids[:20])}{', ...' if len(self.links) > 20 else ''}")
        try:
            key = parse_link_id(link_id, what)
        except DataFormatError:
            key = link_id
        if key in self.index:
            return key
        for lk in self.links:  # a link may also be named by its name
            if lk.name is not None and lk.name == link_id:
                return lk.id
        more = ", ..." if len(self.links) > 20 else ""
        raise UnknownLinkError(
            f"{what} {_short(link_id)} is not a link of {self.name!r}; links are {_fmt(self.link_ids[:20])}{more}")

    def resolve_links(self, links, what: str = "link") -> tuple:
        """Links given by a user as one id or a list of ids (``held=4`` and ``held=[4]`` alike;
        text is one id, so ``held="14"`` is link 14, never links 1 and 4)."""
        if links is None:
            return ()
        if isinstance(links, (str, int, float)) or not _iterable(links):
            return (self.resolve(links, what),)
        if isinstance(links, Mapping):
            raise DataFormatError(f"{what}: expected a list of links such as [1, 4], got a mapping ({_short(links)})")
        return tuple(self.resolve(x, what) for x in links)

    def resolve_pairs(self, pairs, what: str = "joined links") -> tuple:
        """Pairs of links given by a user: ``[(2, 5), (1, 3)]``, or one pair ``(2, 5)``."""
        if pairs is None:
            return ()
        if isinstance(pairs, (str, bytes, Mapping)) or not _iterable(pairs):
            raise DataFormatError(f"{what}: expected pairs of links such as [(2, 5)], got {_short(pairs)}")
        pairs = list(pairs)
        if len(pairs) == 2 and not any(_iterable(x) and not isinstance(x, str) for x in pairs):
            pairs = [pairs]  # one pair (u, v)
        out = []
        for pair in pairs:
            if isinstance(pair, (str, bytes, Mapping)) or not _iterable(pair) or len(list(pair)) != 2:
                raise DataFormatError(f"{what}: expected a pair of links (u, v), got {_short(pair)}")
            u, v = (self.resolve(x, what) for x in pair)
            out.append((u, v))
        return tuple(out)

    def gear_pair(self, a, b) -> tuple[GearPair, int]:
        """The gear pair between gears *a* and *b*, and +1 or -1 for its orientation."""
        a, b = self.resolve(a, "gear"), self.resolve(b, "gear")
        for gp in self.gear_pairs:
            if gp.gears == (a, b):
                return gp, 1
            if gp.gears == (b, a):
                return gp, -1
        raise UnknownLinkError(f"{self.name!r} has no gear pair between {a} and {b}")

    def coaxial(self, u, v) -> str | None:
        """The axis label on which links *u* and *v* are coaxial, or None."""
        u, v = self.resolve(u), self.resolve(v)
        if u == v:
            return "self"
        return self._groups.coaxial_label(u, v)

    def carrier_candidates(self, a, b) -> list:
        """Every link that could carry a gear pair between *a* and *b* (Tsai's transfer vertex)."""
        a, b = self.resolve(a), self.resolve(b)
        return sorted({c for c, _, _ in self._groups.carrier_candidates(a, b)}, key=str)

    def axis_of(self, gear, carrier) -> str | None:
        """The axis label of *gear* on *carrier* (their coaxial label), or None."""
        return self._groups.coaxial_label(self.resolve(gear), self.resolve(carrier))

    def planet_count(self, link) -> int:
        """How many identical, equally spaced planets *link* stands for (1 unless ``planets`` says)."""
        return dict(self.planets).get(self.resolve(link), 1)

    def shift_element(self, name):
        """The brake or clutch called *name*."""
        for e in self.shift_elements:
            if e.name == name:
                return e
        names = ", ".join(e.name for e in self.shift_elements) or "none declared"
        raise UnknownLinkError(f"{self.name!r} has no shift element {name!r}; its elements are {names}")

    def gear_state(self, name):
        """The gear of the schedule called *name* (``"1st"``, ``"R"``)."""
        for g in self.schedule:
            if g.name == str(name):
                return g
        names = ", ".join(g.name for g in self.schedule) or "no schedule given"
        raise UnknownLinkError(f"{self.name!r} has no gear {name!r} in its schedule; its gears are {names}")

    def gear_constraints(self, name) -> dict:
        """``{"held": [...], "joined": [...]}`` for the gear called *name*, ready for
        ``gl.speeds(mech, **mech.gear_constraints("2nd"), ...)``."""
        return self.gear_state(name).constraints(self.shift_elements)

    @property
    def redundant_turning_pairs(self) -> tuple[TurningPair, ...]:
        """Turning pairs that close a loop of coaxial bearings (kinematically redundant)."""
        return tuple(self.turning_pairs[i] for i in self._groups.redundant)

    @property
    def is_symbolic(self) -> bool:
        """True when some gear ratio is a symbolic expression."""
        return any(gp.e.free_symbols for gp in self.gear_pairs)

    @property
    def is_planar(self) -> bool:
        """True when every gear pair is a spur pair (parallel axes)."""
        return all(gp.kind != "bevel" for gp in self.gear_pairs)

    def __repr__(self) -> str:
        return (
            f"<Mechanism {self.name!r}: {len(self.links)} links, {len(self.turning_pairs)} turning pairs, "
            f"{len(self.gear_pairs)} gear pairs>"
        )


def not_a_mechanism(obj, what: str = "mech") -> DataFormatError:
    """The error for an argument that should have been a :class:`Mechanism`."""
    if isinstance(obj, str):
        hint = f" (for a catalogue entry: gl.catalog.load({_short(obj)}); for a file: gl.load(path))"
    elif isinstance(obj, Mapping):
        hint = " (build it with gl.Mechanism.from_dict(data))"
    else:
        hint = ""
    got = _short(obj) if obj is None or isinstance(obj, (bool, int, float, str)) else f"a {type(obj).__name__}"
    return DataFormatError(
        f"{what}: expected a Mechanism (gl.load('file.yaml'), gl.catalog.load('name')) or a catalogue name; "
        f"got {got}{hint}")


def requires_mechanism(fn):
    """Decorator: the function's first parameter must be a :class:`Mechanism` (for the modules
    below the file reader; the others accept a catalogue name too, see ``mechanism._accept``)."""
    name = fn.__code__.co_varnames[0]

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        obj = args[0] if args else kwargs.get(name)
        if not isinstance(obj, Mechanism):
            raise not_a_mechanism(obj, name)
        return fn(*args, **kwargs)

    return wrapper
