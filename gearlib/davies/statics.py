"""Action analysis: Kirchhoff's cutset law ``A_N Psi = 0`` with constitutive equations.

Without losses the network unit action matrix of a one-degree-of-freedom train has nullity
1 and the input torque is the primary variable. Friction adds a torque column in parallel
with a coupling and one *constitutive equation* per column (Laus 2011, section 3.2):

* Coulomb friction of a mesh, written with a *signed* coefficient (eqs. 63-64):
  ``T_f = zeta U`` (``U`` the contact force); the sign of ``zeta`` absorbs the directions,
  which a lossless analysis fixes in advance;
* Coulomb friction of a bearing, ``T* = -zeta |U| sign(t)``: linear once the signs of the
  radial force ``U`` and of the speed ``t`` are known (eqs. 38-41);
* viscous friction, a *dependent source* ``T = -b g(t)`` whose value the motion analysis
  already fixes, so it goes to the right-hand side (eqs. 50-53, in the dissipative form).

The rows are appended to ``A_N`` to form ``D_A`` and the system ``D_A Psi = [0; nu]`` is solved
with the input torque fixed.

>>> import gearlib as gl
>>> net = gl.davies.network(gl.catalog.load("laus_simple_pair"), ground=0, input=1, output=2)
>>> act = gl.davies.actions(net)                  # lossless, T_A = 1
>>> [act.magnitude(n) for n in net.action_names(lossless=True)]
[1, -1, 2, 1, -1]
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import sympy

from ..errors import ConstraintError, InputError
from . import _solve
from .coupling_network import Network

__all__ = ["Actions", "actions", "VISCOUS_LAWS", "viscous_torque"]

VISCOUS_LAWS = ("linear", "quadratic", "cubic", "printed")


def viscous_torque(b, speed, law: str = "linear"):
    """A dissipative viscous torque: ``-b t``, ``-b t |t|`` or ``-b t^3`` (the book's repair of
    Laus's Table 2: every form must oppose the motion for both signs of ``t``). The law
    ``"printed"`` is Laus's eq. (50) as printed, ``-b t sign(t) = -b |t|``: it *injects* power
    whenever ``t < 0`` and is kept only to show that error.

    >>> import gearlib as gl
    >>> gl.davies.viscous_torque(0.5, -2.0, "quadratic")
    2.0
    """
    if law == "linear":
        return -b * speed
    if law == "quadratic":
        return -b * speed * abs(speed)
    if law == "cubic":
        return -b * speed ** 3
    if law == "printed":
        return -b * abs(speed)
    raise InputError(f"viscous law must be one of {', '.join(VISCOUS_LAWS)}, got {law!r}")


@dataclass(frozen=True)
class Actions:
    """Action magnitudes of the columns used (see :func:`actions`)."""

    network: Network
    columns: tuple
    values: tuple
    lossless: bool
    torque: object
    zeta: dict = field(default_factory=dict)

    def _col(self, name) -> int:
        for k, i in enumerate(self.columns):
            if self.network.action_vars[i].name == name:
                return k
        raise InputError(f"no action variable {name!r} in this analysis; they are "
                         f"{', '.join(self.network.action_vars[i].name for i in self.columns)}")

    def magnitude(self, name):
        """Magnitude of an action variable (``"T_A"``, ``"U_C"``), in physical units."""
        k = self._col(name)
        return _clean(self.values[k] * self.network.action_vars[self.columns[k]].scale)

    def raw(self, name):
        """Magnitude per unit of the network's screw, not simplified (fast for symbolic work)."""
        return self.values[self._col(name)]

    def screw(self, coupling, roles=None) -> tuple:
        """The action screw of a coupling (applied to its head link): the sum of its columns,
        or only of the columns whose role is in *roles* (e.g. ``("input",)``)."""
        d = self.network.d
        out = [0] * d
        for k, i in enumerate(self.columns):
            v = self.network.action_vars[i]
            if v.coupling == coupling and (roles is None or v.role in roles):
                out = [out[r] + v.screw[r] * self.values[k] for r in range(d)]
        return tuple(_clean(x) for x in out)

    def matrix(self):
        """The condensed action matrix ``[A]_{d x e}``: one action screw per coupling."""
        cols = [self.screw(c.name) for c in self.network.couplings]
        rows = [[c[r] for c in cols] for r in range(self.network.d)]
        return sympy.Matrix(rows) if self.network.exact else np.array(rows, dtype=float)

    def items(self):
        """``(name, magnitude)`` for every column."""
        return [(self.network.action_vars[i].name, self.magnitude(self.network.action_vars[i].name))
                for i in self.columns]


def _clean(x):
    if isinstance(x, sympy.Basic):
        return sympy.cancel(x)
    return x


def actions(net: Network, *, lossless: bool | None = None, zeta=None, bearings=None, viscous=None,
            torque=1, internal: bool = False, torques=None) -> Actions:
    """Solve the cutset equations with the input torque *torque* as primary variable.

    Parameters
    ----------
    lossless : leave out every friction column (default: True unless friction is given).
    zeta : ``{mesh coupling name: zeta}``, signed Coulomb coefficients ``T_f = zeta U``
        (physical units: length); meshes not listed have no friction.
    bearings : ``{coupling name: (zeta, sign)}``: the bearing friction torque is
        ``T* = sign * zeta * U``, with ``sign = -sign(U) sign(t)`` from a previous analysis.
    viscous : ``{variable name: torque}``: known values of the viscous (dependent-source) columns.
    internal : *zeta* is per unit of the network's (possibly unnormalised) friction screw, as
        :func:`gearlib.davies.mesh_power_ratio` gives it with ``internal=True``; this keeps
        symbolic work free of square roots.
    torques : ``{port torque variable: value}`` fixed instead of the input torque (a train with
        more than one degree of freedom needs one torque per port beyond its freedoms).
    """
    if lossless is None:
        lossless = not (zeta or bearings or viscous)
    cols = net.columns(lossless)
    vars_ = [net.action_vars[i] for i in cols]
    index = {v.name: k for k, v in enumerate(vars_)}
    an = net.A_N(lossless)
    exact = net.exact
    rows, rhs = [], []

    def row(entries, value=0):
        r = [0] * len(cols)
        for k, coef in entries:
            r[k] = r[k] + coef
        rows.append(r)
        rhs.append(value)

    if not lossless:
        zeta = dict(zeta or {})
        bearings = dict(bearings or {})
        viscous = dict(viscous or {})
        for k, v in enumerate(vars_):
            force = index.get(f"U_{v.coupling}")
            if v.role == "friction":
                z = zeta.get(v.coupling, 0)
                z = z / v.scale if (v.scale != 1 and not internal) else z
                row([(k, 1)] + ([(force, -z)] if force is not None and z != 0 else []))
            elif v.role == "bearing":
                if v.coupling not in bearings:
                    raise InputError(f"bearing friction of coupling {v.coupling} needs (zeta, sign)")
                z, sign = bearings[v.coupling]
                row([(k, 1), (force, -sign * z)])
            elif v.role == "viscous":
                if v.name not in viscous:
                    raise InputError(f"viscous column {v.name} needs its torque value")
                row([(k, 1)], viscous[v.name] / v.scale if v.scale != 1 else viscous[v.name])
    if torques is None:
        primary = next(k for k, v in enumerate(vars_) if v.role == "input")
        row([(primary, 1)], torque)
    else:
        for name, value in torques.items():
            row([(index[name], 1)], value)
    if exact:
        a = an.col_join(sympy.Matrix(rows)) if an.rows else sympy.Matrix(rows)
        b = sympy.Matrix([0] * an.rows + list(rhs))
    else:
        a = np.vstack([an, np.array(rows, dtype=float)]) if an.size else np.array(rows, dtype=float)
        b = np.concatenate([np.zeros(an.shape[0]), np.array(rhs, dtype=float)])
    try:
        x = _solve.solve(a, b, exact, "action analysis")
    except ValueError as err:
        raise ConstraintError(
            f"{err}: the statics of {net.mechanism.name!r} is not determined by one input torque. A duplicate "
            "planet or a loop of bearings shares load in an undetermined way: model one planet (the efficiency "
            "does not change), or check the ports"
        ) from None
    values = x if exact else tuple(float(v) for v in x)  # exact: read lazily (_solve.ExactSolution)
    return Actions(net, tuple(cols), values, lossless, torque, dict(zeta or {}))
