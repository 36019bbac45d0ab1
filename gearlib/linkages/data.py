"""Linkages as validated, immutable data: :class:`Linkage`.

A linkage is links, joints between them (:class:`~gearlib.linkages.Joint`: revolute,
prismatic, universal, spherical, cylindrical, with their geometry in the reference pose and
their friction), ports where power enters or leaves
(:class:`~gearlib.linkages.Port`), and optionally named tasks
(:class:`~gearlib.linkages.Task`). It is *planar* when its points have two coordinates
(motions and actions are then screws of order 3, ``{t; u, v}`` and ``{T; U, V}``) and
*spatial* with three (order 6). A file may define ``parameters`` (names for numbers, such as
the thesis' ``r_b`` and ``l_B``) and use them in expressions.

Every check runs when the object is built: unknown links, duplicated names, a joint on one
link, a graph in pieces, ports and tasks that name nothing, a number of motion inputs that
does not match the degrees of freedom.

>>> import gearlib as gl
>>> crank = gl.linkages.load("laus_slider_crank")
>>> crank.space, crank.dof, [j.name for j in crank.joints]
('planar', 1, ['A', 'B', 'C', 'D'])
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property

from .._common.parse import parse_link_id
from .._common.topology import components
from ..errors import DataFormatError, DisconnectedError, DuplicateEdgeError, InputError, SelfMeshError, UnknownLinkError
from .elements import Friction, Joint, Port
from .tasks import Task, expression

__all__ = ["Linkage"]

_FIELDS = ("name", "description", "source", "space", "parameters", "links", "ground", "joints", "ports", "tasks",
           "layout")


@dataclass(frozen=True)
class Linkage:
    """A linkage (see the module documentation). Build it with :meth:`from_dict` or
    :func:`gearlib.linkages.load`; change it with :meth:`replace` (validated again)."""

    links: tuple
    ground: object
    joints: tuple
    ports: tuple = ()
    tasks: tuple = ()
    name: str = "linkage"
    description: str | None = None
    source: str | None = None
    parameters: tuple = ()
    layout: tuple | None = field(default=None, compare=False)

    def __post_init__(self):
        names = {}
        for lk in self.links:
            if lk[0] in names:
                raise DuplicateEdgeError(f"link {lk[0]} is declared twice")
            names[lk[0]] = lk[1]
        if self.ground not in names:
            raise UnknownLinkError(f"the ground {self.ground!r} is not a link; links are {_ids(names)}")
        if not self.joints:
            raise DataFormatError(f"linkage {self.name!r}: no joints")
        dims = {len(j.point) for j in self.joints}
        if len(dims) > 1:
            raise DataFormatError(f"linkage {self.name!r}: mixes planar (2 coordinates) and spatial (3) joints")
        seen: dict = {}
        for j in self.joints:
            for link in j.links:
                if link not in names:
                    raise UnknownLinkError(f"joint {j.name} joins unknown link {link!r}; links are {_ids(names)}. Add "
                                           f"it to `links` or fix the id")
            if j.tail == j.head:
                raise SelfMeshError(f"joint {j.name} joins link {j.tail} to itself; a joint joins two links")
            for c in (j.name, *j.couplings):
                if c in seen and seen[c] != j.name:
                    raise DuplicateEdgeError(f"the name {c} is used by joints {seen[c]} and {j.name}; names are unique")
                seen[c] = j.name
            if len([x for x in self.joints if x.name == j.name]) > 1:
                raise DuplicateEdgeError(f"two joints are called {j.name}")
            if j.fixed_in is not None and any(x not in names for x in j.fixed_in):
                raise UnknownLinkError(f"joint {j.name}: `fixed_in` names a link that is not one of its two links")
        comps = components(list(names), [j.links for j in self.joints])
        if len(comps) > 1:
            apart = [c for c in comps if self.ground not in c][0]
            raise DisconnectedError(f"linkage {self.name!r} falls apart: links {_ids(dict.fromkeys(apart))} are not "
                                    f"joined to the ground {self.ground} through joints")
        self._check_ports(names, seen, dims.pop())
        self._check_tasks()

    def _check_ports(self, names, seen, dim):
        joints = {j.name: j for j in self.joints}
        for p in self.ports:
            if [q.name for q in self.ports].count(p.name) > 1:
                raise DuplicateEdgeError(f"two ports are called {p.name}")
            if p.joint is not None and p.joint not in joints:
                raise UnknownLinkError(f"port {p.name} is on joint {p.joint!r}, which is not a joint; joints are "
                                       f"{', '.join(joints)}")
            if p.name in seen and p.name != p.joint:
                raise DuplicateEdgeError(f"port {p.name}: the name is already a joint or a coupling (a port on a joint "
                                         "may take its joint's name)")
            if p.joint is not None:
                j = joints[p.joint]
                if j.kind not in ("revolute", "prismatic", "cylindrical"):
                    raise DataFormatError(f"port {p.name}: a {j.kind} joint has no single freedom to drive; put the "
                                          "port on a revolute, prismatic or cylindrical joint")
            else:
                if p.link not in names:
                    raise UnknownLinkError(f"port {p.name} loads unknown link {p.link!r}; links are {_ids(names)}")
                if p.link == self.ground:
                    raise DataFormatError(f"port {p.name} loads the ground {p.link}; a load acts on a moving link")
                if len(p.point) != dim:
                    raise DataFormatError(f"port {p.name}: its point has {len(p.point)} coordinates, the joints {dim}")

    def _check_tasks(self):
        for task in self.tasks:
            self.check_task(task)

    def check_task(self, task) -> None:
        """Raise a clear error when *task* does not fit this linkage: unknown joints or ports,
        a wrong number of coordinates, or not one motion input per degree of freedom."""
        joints = {j.name: j for j in self.joints}
        ports = {p.name: p for p in self.ports}
        where = f"task {task.name}"
        sampled = task.samples[1] if task.samples is not None else {}
        for name, exprs in task.motion:
            if name in ports and ports[name].kind == "load":
                need = len(ports[name].point)
                what = f"the position of port {name}'s point"
            elif name in joints or (name in ports and ports[name].joint in joints):
                j = joints.get(name) or joints[ports[name].joint]
                if j.kind not in ("revolute", "prismatic"):
                    raise DataFormatError(f"{where}: joint {j.name} ({j.kind}) has no single coordinate; drive a "
                                          "revolute or prismatic joint, or a load port's point")
                need, what = 1, f"joint {j.name}'s {'angle' if j.kind == 'revolute' else 'displacement'}"
            else:
                raise UnknownLinkError(f"{where}: motion {name!r} is neither a joint nor a load port")
            got = len(exprs) if name not in sampled else sampled[name][0].shape[1]
            if got != need:
                raise DataFormatError(f"{where}: {what} has {need} coordinate(s), got {got}")
        for name, _ in task.actions:
            if name not in ports:
                raise UnknownLinkError(f"{where}: action {name!r} is not a port; ports are "
                                       f"{', '.join(ports) or 'none'}")
        for name, _ in task.roles:
            if name not in ports:
                raise UnknownLinkError(f"{where}: a role for {name!r}, which is not a port")
        given = sum(len(ports[n].point) if n in ports and ports[n].kind == "load" else 1 for n, _ in task.motion)
        if given != self.dof:
            raise InputError(f"{where}: the linkage has {self.dof} degree(s) of freedom, the task gives {given} "
                             f"motion input(s)")

    # ------------------------------------------------------------------ building
    @classmethod
    def from_dict(cls, data: Mapping) -> Linkage:
        """Build a linkage from plain data (as read from YAML or JSON)."""
        if not isinstance(data, Mapping):
            raise DataFormatError(f"a linkage is a mapping with `links`, `joints`, ...; got {type(data).__name__}")
        unknown = sorted(str(k) for k in data if k not in _FIELDS)
        if unknown:
            raise DataFormatError(f"linkage: unknown field {unknown[0]!r}; fields are {', '.join(_FIELDS)}")
        for key in ("links", "joints", "ground"):
            if key not in data:
                raise DataFormatError(f"linkage: missing `{key}`")
        params = _parameters(data.get("parameters") or {})
        space = data.get("space")
        links = data["links"]
        if isinstance(links, Mapping):
            links = tuple((parse_link_id(k, "links"), str(v)) for k, v in links.items())
        elif isinstance(links, Sequence) and not isinstance(links, str):
            links = tuple((parse_link_id(k, "links"), str(k)) for k in links)
        else:
            raise DataFormatError("linkage: `links` is a list of ids or a mapping id: name")
        joints = tuple(_joint(j, params, k) for k, j in enumerate(_list(data["joints"], "joints")))
        dim = len(joints[0].point) if joints else 0
        if space is not None and space not in ("planar", "spatial"):
            raise DataFormatError(f"linkage: space must be 'planar' or 'spatial', got {space!r}")
        if space is not None and {"planar": 2, "spatial": 3}[space] != dim:
            raise DataFormatError(f"linkage: space is {space} but the joints' points have {dim} coordinates")
        ports = tuple(_port(p, params, k) for k, p in enumerate(_list(data.get("ports") or [], "ports")))
        tasks_data = data.get("tasks") or {}
        if not isinstance(tasks_data, Mapping):
            raise DataFormatError("linkage: `tasks` is a mapping from a task's name to the task")
        tasks = tuple(Task.from_dict(str(k), v, params) for k, v in tasks_data.items())
        layout = data.get("layout")
        if layout is not None:
            layout = tuple((parse_link_id(k, "layout"), tuple(map(float, v))) for k, v in dict(layout).items())
        return cls(links=links, ground=parse_link_id(data["ground"], "ground"), joints=joints, ports=ports,
                   tasks=tasks, name=str(data.get("name") or "linkage"), description=data.get("description"),
                   source=data.get("source"), parameters=tuple((k, float(v)) for k, v in params.items()),
                   layout=layout)

    def to_dict(self) -> dict:
        """Plain data that :meth:`from_dict` reads back to an equal linkage (numbers, not the
        parameters' expressions)."""
        out: dict = {"name": self.name}
        for key in ("description", "source"):
            if getattr(self, key):
                out[key] = getattr(self, key)
        out["space"] = self.space
        out["links"] = {k: v for k, v in self.links}
        out["ground"] = self.ground
        out["joints"] = [j.to_data() for j in self.joints]
        if self.ports:
            out["ports"] = [p.to_data() for p in self.ports]
        if self.tasks:
            out["tasks"] = {t.name: t.to_data() for t in self.tasks}
        if self.layout:
            out["layout"] = {k: list(v) for k, v in self.layout}
        return out

    def replace(self, **changes) -> Linkage:
        """A copy with some fields changed, validated again."""
        return dataclasses.replace(self, **changes)

    # ------------------------------------------------------------------ lookups
    @property
    def space(self) -> str:
        return "planar" if len(self.joints[0].point) == 2 else "spatial"

    @property
    def planar(self) -> bool:
        return self.space == "planar"

    @property
    def link_ids(self) -> tuple:
        return tuple(k for k, _ in self.links)

    def joint(self, name) -> Joint:
        for j in self.joints:
            if j.name == name:
                return j
        raise UnknownLinkError(f"no joint {name!r}; joints are {', '.join(j.name for j in self.joints)}")

    def port(self, name) -> Port:
        for p in self.ports:
            if p.name == name:
                return p
        raise UnknownLinkError(f"no port {name!r}; ports are {', '.join(p.name for p in self.ports) or 'none'}")

    def task(self, name) -> Task:
        for t in self.tasks:
            if t.name == name:
                return t
        raise UnknownLinkError(f"no task {name!r} in {self.name!r}; tasks are "
                               f"{', '.join(t.name for t in self.tasks) or 'none'}")

    @cached_property
    def dof(self) -> int:
        """Degrees of freedom: the links' pose coordinates minus the rank of the joints'
        constraints at the reference pose (:func:`gearlib.linkages.mobility`)."""
        from .pose import mobility

        return mobility(self)

    def with_friction(self, mu=None, **changes) -> Linkage:
        """Every joint's friction with ``mu`` (and other :class:`~gearlib.linkages.Friction` fields) changed; a
        joint without friction gets it."""
        joints = []
        for j in self.joints:
            f = j.friction or Friction()
            kw = dict(changes)
            if mu is not None:
                kw["mu"] = mu
            if j.kind == "spherical":
                joints.append(j)
                continue
            joints.append(dataclasses.replace(j, friction=dataclasses.replace(f, **kw)))
        return self.replace(joints=tuple(joints))

    def __repr__(self) -> str:
        return (f"<Linkage {self.name!r}: {self.space}, {len(self.links)} links, {len(self.joints)} joints, "
                f"{len(self.ports)} ports, {self.dof} dof>")


def _ids(names) -> str:
    return ", ".join(str(k) for k in names)


def _list(value, where):
    if not isinstance(value, Sequence) or isinstance(value, (str, bytes)):
        raise DataFormatError(f"linkage: `{where}` must be a list")
    return value


def _parameters(data) -> dict:
    if not isinstance(data, Mapping):
        raise DataFormatError("linkage: `parameters` is a mapping from names to numbers")
    out: dict = {}
    for k, v in data.items():
        if not isinstance(k, str) or not k.isidentifier() or k in ("t", "pi", "I", "E", "deg"):
            raise DataFormatError(f"parameters: {k!r} is not a usable name (letters, digits, _; not t or pi)")
        out[k] = expression(v, out, f"parameters: {k}")
    return out


def _numbers(value, params, where):
    if not isinstance(value, (list, tuple)):
        raise DataFormatError(f"{where}: expected a list of coordinates, got {value!r}")
    return tuple(float(expression(v, params, where)) for v in value)


def _joint(data, params, k) -> Joint:
    if not isinstance(data, Mapping):
        raise DataFormatError(f"joints[{k}]: a joint is a mapping with name, kind, links, point, ...")
    name = str(data.get("name", f"J{k + 1}"))
    where = f"joint {name}"
    allowed = {"name", "kind", "links", "point", "axis", "axes", "fixed_in", "normal", "split", "split_names", "split_in",
               "friction"}
    extra = sorted(str(x) for x in data if x not in allowed)
    if extra:
        raise DataFormatError(f"{where}: unknown field {extra[0]!r}; a joint has {', '.join(sorted(allowed))}")
    for key in ("kind", "links", "point"):
        if key not in data:
            raise DataFormatError(f"{where}: missing `{key}`")
    links = data["links"]
    if not isinstance(links, (list, tuple)) or len(links) != 2:
        raise DataFormatError(f"{where}: `links` is [tail, head], two link ids")
    kw = {}
    for key in ("axis", "normal"):
        if data.get(key) is not None:
            kw[key] = _numbers(data[key], params, f"{where}: {key}")
    if data.get("axes") is not None:
        kw["axes"] = tuple(_numbers(a, params, f"{where}: axes") for a in _list(data["axes"], "axes"))
    if data.get("split") is not None:
        kw["split"] = tuple(_numbers(p, params, f"{where}: split") for p in _list(data["split"], "split"))
    for key in ("fixed_in", "split_in"):
        if data.get(key) is not None:
            kw[key] = tuple(parse_link_id(x, f"{where}: {key}") for x in _list(data[key], key))
    if data.get("split_names") is not None:
        kw["split_names"] = tuple(str(x) for x in data["split_names"])
    if data.get("friction") is not None:
        f = data["friction"]
        if not isinstance(f, Mapping):
            raise DataFormatError(f"{where}: friction is a mapping such as {{mu: 0.1}}")
        fields = {"mu", "radius", "law", "multiplier", "thrust", "norm"}
        bad = sorted(str(x) for x in f if x not in fields)
        if bad:
            raise DataFormatError(f"{where}: unknown friction field {bad[0]!r}; fields are {', '.join(sorted(fields))}")
        fk = {x: float(expression(f[x], params, f"{where}: friction {x}")) for x in ("mu", "radius", "multiplier",
                                                                                    "thrust") if f.get(x) is not None}
        for x in ("law", "norm"):
            if f.get(x) is not None:
                fk[x] = str(f[x])
        try:
            kw["friction"] = Friction(**fk)
        except DataFormatError as err:
            raise DataFormatError(f"{where}: {err}") from None
    return Joint(name, str(data["kind"]), tuple(parse_link_id(x, f"{where}: links") for x in links),
                 _numbers(data["point"], params, f"{where}: point"), **kw)


def _port(data, params, k) -> Port:
    if not isinstance(data, Mapping):
        raise DataFormatError(f"ports[{k}]: a port is a mapping with name, role and joint (or link and point)")
    allowed = {"name", "role", "joint", "link", "point", "force", "torque"}
    name = str(data.get("name", data.get("joint", f"P{k + 1}")))
    extra = sorted(str(x) for x in data if x not in allowed)
    if extra:
        raise DataFormatError(f"port {name}: unknown field {extra[0]!r}; a port has {', '.join(sorted(allowed))}")
    kw = {}
    for key in ("point", "force", "torque"):
        if data.get(key) is not None:
            value = data[key] if isinstance(data[key], (list, tuple)) else [data[key]]
            kw[key] = _numbers(value, params, f"port {name}: {key}")
    link = data.get("link")
    return Port(name, str(data.get("role", "")), joint=None if data.get("joint") is None else str(data["joint"]),
                link=None if link is None else parse_link_id(link, f"port {name}: link"), **kw)
