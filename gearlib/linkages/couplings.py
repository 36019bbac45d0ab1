"""A linkage as a Davies network: couplings, their motion and action variables, the matrices.

:func:`~gearlib.linkages.network` turns each joint into one coupling (two for a split pair), each load port into
a *virtual coupling* between the ground and its link (all freedoms, one action: the load),
and names the variables as the thesis does (Laus 2011, Tables 7-10): ``t_A``, ``u_D`` (planar);
``p_A1``, ``q_B`` (spatial rotations and translations); ``T_A``, ``U_B``, ``V_D`` (planar couples
and forces along x and y); ``P_A``, ``Q_A1`` (spatial couples and forces); a friction column
ends in ``F`` (``U_DF``, ``P_AF1``, ``Q_BF``), an actuator in ``A`` (``Q_CA``), a load is
``W_M``. The coupling graph and its circuit and cutset matrices come from chapter 5's
:class:`~gearlib.davies.CouplingGraph`; the unit screws depend on the pose
(:meth:`~gearlib.linkages.LinkageNetwork.unit_screws`), the topology does not.

>>> import gearlib as gl
>>> net = gl.linkages.network(gl.linkages.load("laus_slider_crank"))
>>> net.motion_names()
['t_A', 't_B', 't_C', 'u_D']
>>> net.action_names()                   # the thesis' Table 8, its friction force U_DD written U_DF
['T_A', 'U_A', 'V_A', 'U_B', 'V_B', 'U_C', 'V_C', 'T_D', 'U_D', 'U_DF', 'V_D']
>>> net.B.tolist(), net.Q.tolist()       # eq. (103): one circuit A, B, C, D all the same way round
([[1, 1, 1, 1]], [[1, 0, 0, -1], [0, 1, 0, -1], [0, 0, 1, -1]])
"""

from __future__ import annotations

from dataclasses import dataclass, field
import numpy as np

from ..davies.graph import CouplingGraph, replicate
from . import screws as sc

__all__ = ["Coupling", "Column", "FrictionTerm", "LinkageNetwork", "network"]


@dataclass(frozen=True)
class Coupling:
    """One edge of the coupling graph: ``kind`` is the joint's kind, ``square annulus`` /
    ``round annulus`` (a split spatial pair), ``slider`` (half of a split planar pair) or
    ``virtual`` (a load port)."""

    name: str
    tail: object
    head: object
    kind: str
    joint: str | None = None
    port: str | None = None


@dataclass(frozen=True)
class Column:
    """One motion or action variable: ``kind`` ``rotation``/``translation`` (motions) or
    ``force``/``couple`` (actions); ``role`` ``freedom``, ``constraint``, ``input``,
    ``output`` or ``friction``."""

    name: str
    coupling: str
    kind: str
    role: str
    port: str | None = None
    spec: tuple = field(default=(), compare=False, repr=False)  # how to build its unit screw


@dataclass(frozen=True)
class FrictionTerm:
    """A friction column's constitutive law: ``value = -coef sign(motion) * sum_g m_g |forces_g|``
    (``|.|`` the sum of absolute values or the resultant, by ``norms``)."""

    column: int
    motion: int
    coef: float
    groups: tuple  # ((multiplier, (force column indices...), norm), ...)


def _letters(axis) -> tuple[str, str]:
    """(along, across) letters of a planar prismatic axis: U/V along x/y, F/N otherwise."""
    if axis is None:
        return "F", "N"
    x, y = abs(axis[0]), abs(axis[1])
    if y < 1e-12:
        return "U", "V"
    if x < 1e-12:
        return "V", "U"
    return "F", "N"


class LinkageNetwork:
    """The Davies network of a linkage (see the module documentation)."""

    def __init__(self, linkage):
        self.linkage = linkage
        self.planar = linkage.planar
        self.d = 3 if self.planar else 6
        self.coordinates = ("t", "u", "v") if self.planar else sc.MOTION_COORDS
        self.action_coordinates = ("T", "U", "V") if self.planar else sc.ACTION_COORDS
        ports_on = {}
        for p in linkage.ports:
            if p.joint is not None:
                ports_on.setdefault(p.joint, []).append(p)
        couplings, mcols, acols = [], [], []
        for j in linkage.joints:
            for c, m, a in self._joint(j, ports_on.get(j.name, [])):
                couplings.append(c)
                mcols += m
                acols += a
        for p in linkage.ports:
            if p.kind == "load":
                c, m, a = self._virtual(p)
                couplings.append(c)
                mcols += m
                acols += a
        self.couplings = tuple(couplings)
        self.motion_cols = tuple(mcols)
        self.action_cols = tuple(acols)
        self.graph = CouplingGraph(tuple(linkage.link_ids), tuple((c.name, c.tail, c.head) for c in couplings))
        self.B = self.graph.circuit_matrix()
        self.Q = self.graph.cutset_matrix()
        names = [c.name for c in couplings]
        self.B_M = replicate(self.B, [sum(1 for m in mcols if m.coupling == n) for n in names])
        self.Q_A = replicate(self.Q, [sum(1 for a in acols if a.coupling == n) for n in names])
        self._coupling_of_m = np.array([names.index(m.coupling) for m in mcols])
        self._coupling_of_a = np.array([names.index(a.coupling) for a in acols])
        self.friction = tuple(self._friction_terms())

    # ------------------------------------------------------------------ building the columns
    def _joint(self, j, ports):
        f = j.friction
        planar = self.planar
        if j.split is not None:
            names = j.split_names
            kinds = ("slider", "slider") if planar else (("square annulus", "round annulus") if j.kind == "prismatic"
                                                         else ("round annulus", "round annulus"))
            out = []
            for k, (name, kind) in enumerate(zip(names, kinds)):
                on = j.split_in[k]
                geo = ("split", j.name, k, on)
                c = Coupling(name, j.tail, j.head, kind, joint=j.name)
                out.append((c, *self._columns(c, j, geo, f, ports if k == 1 else [])))
            return out
        c = Coupling(j.name, j.tail, j.head, j.kind, joint=j.name)
        return [(c, *self._columns(c, j, ("joint", j.name), f, ports))]

    def _columns(self, c, j, geo, f, ports):
        n, kind, planar = c.name, c.kind, self.planar
        M = []  # motions: (name, kind, spec)
        A = []  # actions: (name, kind, role, spec, port)
        mu = f.mu if f is not None else 0.0
        radius = f.radius if f is not None else None
        if planar:
            along, across = _letters(j.axis)
            q = {"U": "u", "V": "v"}.get(along, "q")
            if kind == "revolute":
                M.append((f"t_{n}", "rotation", ("rot", geo, "z")))
                A += [(f"T_{n}", "couple", p.role, ("couple", geo, "z"), p.name) for p in ports]
                A += [(f"U_{n}", "force", "constraint", ("force", geo, "x"), None),
                      (f"V_{n}", "force", "constraint", ("force", geo, "y"), None)]
                if mu > 0 and radius:
                    A.append((f"T_{n}F", "couple", "friction", ("couple", geo, "z"), None))
            else:  # prismatic, or one half of a split planar pair
                M.append((f"{q}_{n}", "translation", ("tra", geo, "axis")))
                if kind == "slider":
                    M.append((f"t_{n}", "rotation", ("rot", geo, "z")))
                else:
                    A.append((f"T_{n}", "couple", "constraint", ("couple", geo, "z"), None))
                A += [(f"{along}_{n}", "force", p.role, ("force", geo, "axis"), p.name) for p in ports]
                if mu > 0:
                    A.append((f"{along}_{n}F", "force", "friction", ("force", geo, "axis"), None))
                A.append((f"{across}_{n}", "force", "constraint", ("force", geo, "normal"), None))
        else:
            self._spatial(n, kind, geo, mu, radius, ports, M, A)
        mcols = [Column(name, n, k, "freedom", spec=s) for name, k, s in M]
        acols = [Column(name, n, k, role, port, spec=s) for name, k, role, s, port in A]
        return mcols, acols

    @staticmethod
    def _spatial(n, kind, geo, mu, radius, ports, M, A):
        def drive(sym, k, spec):
            A.extend((f"{sym}_{n}A" if len(ports) == 1 else f"{sym}_{n}A{i + 1}", k, p.role, spec, p.name)
                     for i, p in enumerate(ports))

        pin = mu > 0 and radius is not None
        if kind == "revolute":
            M.append((f"p_{n}", "rotation", ("rot", geo, "a")))
            A += [(f"Q_{n}{i + 1}", "force", "constraint", ("force", geo, e), None) for i, e in enumerate("auw")]
            A += [(f"P_{n}{i + 1}", "couple", "constraint", ("couple", geo, e), None) for i, e in enumerate("uw")]
            drive("P", "couple", ("couple", geo, "a"))
            if pin:
                A.append((f"P_{n}F", "couple", "friction", ("couple", geo, "a"), None))
        elif kind == "universal":
            M += [(f"p_{n}1", "rotation", ("rot", geo, "d1")), (f"p_{n}2", "rotation", ("rot", geo, "d2"))]
            A.append((f"P_{n}", "couple", "constraint", ("couple", geo, "d3"), None))
            if pin:
                A += [(f"P_{n}F1", "couple", "friction", ("couple", geo, "d1"), None),
                      (f"P_{n}F2", "couple", "friction", ("couple", geo, "d2"), None)]
            A += [(f"Q_{n}{i + 1}", "force", "constraint", ("force", geo, e), None) for i, e in enumerate(("d1", "d2", "d3"))]
        elif kind == "spherical":
            M += [(f"p_{n}{i + 1}", "rotation", ("rot", geo, e)) for i, e in enumerate("xyz")]
            A += [(f"Q_{n}{i + 1}", "force", "constraint", ("force", geo, e), None) for i, e in enumerate("xyz")]
        elif kind in ("prismatic", "square annulus", "round annulus", "cylindrical"):
            M.append((f"q_{n}", "translation", ("tra", geo, "a")))
            if kind == "square annulus":
                M += [(f"p_{n}1", "rotation", ("rot", geo, "u")), (f"p_{n}2", "rotation", ("rot", geo, "w"))]
                A.append((f"P_{n}", "couple", "constraint", ("couple", geo, "a"), None))
            elif kind == "round annulus":
                M += [(f"p_{n}{i + 1}", "rotation", ("rot", geo, e)) for i, e in enumerate("auw")]
            elif kind == "cylindrical":
                M.append((f"p_{n}", "rotation", ("rot", geo, "a")))
            A += [(f"Q_{n}{i + 1}", "force", "constraint", ("force", geo, e), None) for i, e in enumerate("uw")]
            if kind == "prismatic":
                A += [(f"P_{n}{i + 1}", "couple", "constraint", ("couple", geo, e), None) for i, e in enumerate("auw")]
            elif kind == "cylindrical":
                A += [(f"P_{n}{i + 1}", "couple", "constraint", ("couple", geo, e), None) for i, e in enumerate("uw")]
            drive("Q", "force", ("force", geo, "a"))
            if mu > 0:
                A.append((f"Q_{n}F", "force", "friction", ("force", geo, "a"), None))
            if kind == "cylindrical" and pin:
                A.append((f"P_{n}F", "couple", "friction", ("couple", geo, "a"), None))

    def _virtual(self, p):
        n = p.name
        c = Coupling(n, self.linkage.ground, p.link, "virtual", port=n)
        geo = ("port", n)
        if self.planar:
            M = [(f"t_{n}", "rotation", ("rot", geo, "z")), (f"u_{n}", "translation", ("tra", geo, "x")),
                 (f"v_{n}", "translation", ("tra", geo, "y"))]
        else:
            M = [(f"{a}_{n}", "rotation", ("rot", geo, e)) for a, e in zip("rst", "xyz")]
            M += [(f"{a}_{n}", "translation", ("tra", geo, e)) for a, e in zip("uvw", "xyz")]
        kind = "force" if p.force is not None else "couple"
        A = [(f"W_{n}", kind, p.role, (kind, geo, "load"), n)]
        mcols = [Column(name, n, k, "freedom", spec=s) for name, k, s in M]
        return c, mcols, [Column(name, n, k, role, port, spec=s) for name, k, role, s, port in A]

    def _friction_terms(self):
        joints = {j.name: j for j in self.linkage.joints}
        kinds = {c.name: c.kind for c in self.couplings}
        for i, col in enumerate(self.action_cols):
            if col.role != "friction":
                continue
            name, axis = col.coupling, col.spec[2]
            f = joints[next(c.joint for c in self.couplings if c.name == name)].friction
            forces = [k for k, a in enumerate(self.action_cols)
                      if a.coupling == name and a.role == "constraint" and a.kind == "force"]
            if col.kind == "force":  # a slider: mu times the normal forces, against the translation
                motion = next(k for k, m in enumerate(self.motion_cols) if m.coupling == name and m.kind == "translation")
                yield FrictionTerm(i, motion, f.mu, ((1.0, tuple(forces), f.norm or "sum"),))
                continue
            # a pin: mu r times the forces on its faces, against the rotation about the same axis
            motion = next(k for k, m in enumerate(self.motion_cols)
                          if m.coupling == name and m.kind == "rotation" and m.spec[2] == axis)
            along = tuple(k for k in forces if self.action_cols[k].spec[2] == axis)
            across = tuple(k for k in forces if k not in along)
            norm = f.norm or ("sum" if kinds[name] == "universal" else "resultant")
            groups = ((f.across, across, norm),) + (((f.thrust, along, "sum"),) if along else ())
            yield FrictionTerm(i, motion, f.mu * f.radius, groups)

    # ------------------------------------------------------------------ lookups
    def motion_names(self) -> list[str]:
        return [m.name for m in self.motion_cols]

    def action_names(self) -> list[str]:
        return [a.name for a in self.action_cols]

    def coupling(self, name) -> Coupling:
        for c in self.couplings:
            if c.name == name:
                return c
        raise KeyError(name)

    # ------------------------------------------------------------------ geometry at a pose
    @property
    def _plan(self):
        plan = self.__dict__.get("_geo_plan")
        if plan is None:
            from ._geometry import geometry_plan

            plan = self.__dict__["_geo_plan"] = geometry_plan(self)
        return plan

    def geometry(self, pose) -> tuple[np.ndarray, np.ndarray]:
        """``(points, directions)`` of every coupling at *pose*, in the order of the plan."""
        from .pose import _cross

        plan = self._plan
        R, P = pose.R, pose.P
        pts = np.einsum("kab,kb->ka", R[plan["pt_link"]], plan["pt_ref"]) + P[plan["pt_link"]]
        dirs = np.empty((plan["n"], 3))
        dirs[plan["world"]] = plan["world_v"]
        if len(plan["link"]):
            dirs[plan["link"]] = np.einsum("kab,kb->ka", R[plan["link_l"]], plan["link_v"])
        if len(plan["cross"]):
            i, j = plan["cross_ij"][:, 0], plan["cross_ij"][:, 1]
            c = _cross(dirs[i], dirs[j])
            dirs[plan["cross"]] = c / np.linalg.norm(c, axis=1)[:, None]
        return pts, dirs

    def frames_at(self, pose) -> dict:
        """``{coupling geometry key: (point, {direction name: unit vector})}`` at *pose*."""
        pts, dirs = self.geometry(pose)
        plan = self._plan
        out = {key: (pts[i], {}) for i, key in enumerate(plan["keys"])}
        for (key, name), i in plan["where"].items():
            out[key][1][name] = dirs[i]
        return out

    def unit_screws(self, pose) -> tuple[np.ndarray, np.ndarray]:
        """``(M_D, A_D)`` at *pose*: one unit motion screw and one unit action screw per column
        (``d`` rows: 3 planar, 6 spatial)."""
        from .pose import _cross

        points, dirs = self.geometry(pose)
        plan = self._plan

        def build(point, direction, moment, angular):
            s, p = dirs[direction], points[point]
            m = _cross(p, s) * moment
            # a rotation (s; p x s) or a couple (s; 0); a translation (0; s) or a force (p x s; s)
            return np.hstack([np.where(angular, s, m), np.where(angular, m, s)]).T

        md, ad = build(*plan["motion"]), build(*plan["action"])
        if self.planar:
            md, ad = md[sc.PLANAR], ad[sc.PLANAR]
        return md, ad

    def M_N(self, md) -> np.ndarray:
        """Network unit motion matrix ``[M_N]_{dl x F}`` (Laus eq. 56): circuit by circuit."""
        return (self.B_M[:, None, :] * md[None, :, :]).reshape(-1, md.shape[1])

    def A_N(self, ad) -> np.ndarray:
        """Network unit action matrix ``[A_N]_{dk x C}`` (Laus eq. 19): cutset by cutset."""
        return (self.Q_A[:, None, :] * ad[None, :, :]).reshape(-1, ad.shape[1])

    def __repr__(self) -> str:
        return (f"<Davies network of {self.linkage.name!r}: {self.graph.n} links, {self.graph.e} couplings, "
                f"d = {self.d}, F = {len(self.motion_cols)}, C = {len(self.action_cols)}>")


def network(linkage) -> LinkageNetwork:
    """The Davies network of *linkage* (kept with the linkage: the topology does not change
    with the pose)."""
    cached = linkage.__dict__.get("_network")
    if cached is None:
        cached = linkage.__dict__["_network"] = LinkageNetwork(linkage)
    return cached
