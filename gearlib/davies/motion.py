"""Motion analysis: Kirchhoff's circulation law ``M_N psi = 0`` and what follows from it.

The null space of the network unit motion matrix holds every motion the couplings allow
together. A one-degree-of-freedom train has nullity 1; the input port's speed is the
*primary variable* and fixes the rest (Laus 2011, section 3.4.1.1). The motion screw of a
coupling is its unit screw times its magnitude; the motion of a link relative to another is
the sum of the coupling motions along any path between them (Laus's inspection method), or
``M_i = -M A_i^+`` (eq. 6).

An independent check compares every turning pair's speed with the Willis equations
(:func:`gearlib.speeds`): Davies' equations alone accept a wrongly oriented axis, because
with all axes through one point the circuit equations keep their rank whatever the axis
directions (Laus's Humpage example; the book's :ref:`notes on the sources <sources-humpage>`).

>>> import gearlib as gl
>>> net = gl.davies.network(gl.catalog.load("laus_epicyclic"), ground=1, input=5, output=2)
>>> mo = gl.davies.motions(net)
>>> [mo.magnitude(v) for v in net.motion_names()]          # eq. (58) with r = 40, 60, 15, 35
[1, -5/9, -5/3, -10/9, 8/3]
>>> mo.link(2, relative_to=1)                               # (t, u) of annulus 2 in the frame
(-5/9, 0)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy

from ..errors import ConstraintError, GeometryError, InputError
from . import _solve
from .coupling_network import Network

__all__ = ["Motions", "motions", "check_willis"]


@dataclass(frozen=True)
class Motions:
    """Motion magnitudes of every coupling (see :func:`motions`)."""

    network: Network
    values: tuple
    null_vector: tuple
    speed: object

    def _index(self, name) -> int:
        names = self.network.motion_names()
        if name in names:
            return names.index(name)
        for i, v in enumerate(self.network.motion_vars):
            if v.coupling == name:
                return i
        raise InputError(f"no motion variable {name!r}; they are {', '.join(names)}")

    def magnitude(self, name):
        """Speed of a motion variable (``"t_A"``), or of a coupling's freedom (``"A"``)."""
        i = self._index(name)
        return _clean(self.values[i] * self.network.motion_vars[i].scale)

    def screw(self, coupling) -> tuple:
        """The motion screw of a coupling (zero for a locked one), in the network's coordinates."""
        d = self.network.d
        out = [0] * d
        for i, v in enumerate(self.network.motion_vars):
            if v.coupling == coupling:
                out = [out[r] + v.screw[r] * self.values[i] for r in range(d)]
        return tuple(_clean(x) for x in out)

    def matrix(self):
        """The condensed motion matrix ``[M]_{d x e}``: one motion screw per coupling."""
        cols = [self.screw(c.name) for c in self.network.couplings]
        rows = [[c[r] for c in cols] for r in range(self.network.d)]
        return sympy.Matrix(rows) if self.network.exact else np.array(rows, dtype=float)

    def link(self, link, relative_to=None) -> tuple:
        """Motion screw of *link* relative to *relative_to* (default the ground): the sum of the
        coupling motions along the tree path between them."""
        net = self.network
        ref = net.ground if relative_to is None else net.mechanism.resolve(relative_to)
        link = net.mechanism.resolve(link)
        out = [0] * net.d
        for name, sign in net.graph.tree_path(ref, link):
            s = self.screw(name)
            out = [out[r] + sign * s[r] for r in range(net.d)]
        return tuple(_clean(x) for x in out)

    def absolute(self, reference):
        """``M_i = -M A_i^+`` (Laus eq. 6): motions of all links but *reference* relative to it,
        one column per link in the order of the mechanism's links."""
        pinv = self.network.graph.pseudo_inverse(self.network.mechanism.resolve(reference))
        m = self.matrix()
        if self.network.exact:
            return (-m * pinv).applyfunc(sympy.cancel)
        return -m @ np.array(pinv, dtype=float)

    def speed_of(self, link, relative_to=None):
        """Angular speed of *link* relative to *relative_to* about their common axis (they must be
        coaxial), signed along the axis direction."""
        net = self.network
        ref = net.ground if relative_to is None else net.mechanism.resolve(relative_to)
        link = net.mechanism.resolve(link)
        axis = net.layout.common_axis(link, ref)
        if axis is None:
            raise InputError(f"links {link} and {ref} are not coaxial; compare motion screws with .link()")
        s = self.link(link, ref)
        unit = (axis.direction[1],) if net.d == 2 else tuple(axis.direction)
        val = s[0] if net.d == 2 else s[0] * unit[0] + s[1] * unit[1]
        return _clean(val)


def _clean(x):
    if isinstance(x, sympy.Basic):
        return sympy.cancel(sympy.nsimplify(x, rational=True) if x.is_Float else x)
    return x


def motions(net: Network, speed=1, *, check: bool = True) -> Motions:
    """Solve ``M_N psi = 0`` with the input port's speed as primary variable.

    Raises :class:`gearlib.ConstraintError` when the train is locked or has more than one
    degree of freedom, and (with ``check``) :class:`gearlib.GeometryError` when the result
    disagrees with the Willis equations.
    """
    mn = net.M_N()
    basis = _solve.nullspace(mn, net.exact)
    nullity = len(basis) if net.exact else basis.shape[1]
    held = net.options.get("held") or ()
    if nullity == 0:
        raise ConstraintError(f"{net.mechanism.name!r} cannot move with link {net.ground} grounded"
                              + (f" and {list(held)} held" if held else "") + ": check the gear pairs and brakes")
    if nullity > 1:
        raise ConstraintError(
            f"{net.mechanism.name!r} has {nullity} degrees of freedom with link {net.ground} grounded; Davies' "
            "efficiency needs one. Hold links (brakes: held=[...], on the command line --held LINK) or join them "
            "(clutches: joined=[(u, v)], --joined U,V; or a gear of the schedule, --gear NAME), or rate the train at "
            "an operating point (gl.davies.operating_point, or efficiency --speed LINK=W --torque LINK=T)"
        )
    primary = net.motion_names().index(next(v.name for v in net.motion_vars if v.coupling == net.port("input").name))
    if net.exact:
        vec = basis[0]
        if vec[primary] == 0:
            raise InputError(f"the input link {net.input} cannot turn relative to the ground {net.ground}")
        vec = [sympy.cancel(x / vec[primary]) for x in vec]
        speed = sympy.sympify(speed)
        values = tuple(sympy.cancel(x * speed) for x in vec)
    else:
        vec = basis[:, 0]
        if abs(vec[primary]) < 1e-12 * np.abs(vec).max():
            raise InputError(f"the input link {net.input} cannot turn relative to the ground {net.ground}")
        row = np.zeros((1, mn.shape[1]))
        row[0, primary] = 1.0
        rhs = np.zeros(mn.shape[0] + 1)
        rhs[-1] = 1.0
        vec = _solve.solve(np.vstack([mn, row]), rhs, False, "motion analysis")  # refined
        values = tuple(float(x) * float(speed) for x in vec)
    out = Motions(net, values, tuple(vec), speed)
    if check:
        check_willis(out)
    return out


def check_willis(mo: Motions, tol: float = 1e-9) -> None:
    """Compare the speed of every turning pair with the Willis equations (:func:`gearlib.speeds`);
    raise :class:`gearlib.GeometryError` naming the first one that disagrees."""
    from ..mechanism.kinematics import speeds

    net = mo.network
    mech = net.mechanism
    values = net.layout.values
    subs = {k: v for k, v in values.items()}
    try:
        speed = float(sympy.sympify(mo.speed).subs(subs))
    except TypeError:  # a symbolic speed: compare per unit input
        speed = 1.0
        scale = 1 / sympy.sympify(mo.speed)
    else:
        scale = 1
    sol = speeds(mech, net.ground, {net.input: speed}, method="numeric", held=net.options.get("held") or (),
                 joined=net.options.get("joined") or ())
    for c in net.couplings:
        if c.kind == "mesh" or c.locked:
            continue
        davies = complex(sympy.sympify(mo.magnitude(c.name) * scale).subs(subs))
        willis = complex(sol.relative(c.head, c.tail))
        if abs(davies - willis) > tol * max(1.0, abs(willis), speed):
            raise GeometryError(
                f"Davies' motions disagree with the Willis equations at coupling {c.name} (link {c.head} relative to "
                f"{c.tail}: {davies.real:.6g} instead of {willis.real:.6g}): an axis or a pitch point is placed "
                "inconsistently with the gear ratios. Fix the geometry, or pass check=False to study the model as it is"
            )
