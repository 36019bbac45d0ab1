"""Power through couplings, and power flows as seen by an observer on a link.

* The **power of a coupling** (transferable power, Laus's Definition 1) is its action screw
  dotted with its motion screw: positive where power enters the network (the input port),
  negative where it leaves (the output port, and every friction column). By Tellegen's
  theorem the powers of all couplings sum to zero.
* The **power flow** across a coupling (Definition 2) is the power the coupling's action
  delivers to its head link, ``$a . ^i$m_head``, or takes from its tail link, as measured by
  an observer on link ``i``. Actions do not depend on the observer; motions do. Positive
  means the flow runs along the edge (tail to head).
* Measured from the **carrier** of a mesh (the *virtual* power flow, Definition 4) the flow
  says which gear drives the other, and how much power the mesh really handles: it can be
  many times the input power (recirculation). Measured from a link common to the input and
  the output port (the *real* power flow, Definition 3), it never exceeds the input power.

>>> import gearlib as gl
>>> net = gl.davies.network(gl.catalog.load("laus_epicyclic"), ground=1, input=5, output=2)
>>> mo, act = gl.davies.motions(net), gl.davies.actions(net)
>>> [(f.driver, f.driven, f.tail_power) for f in gl.davies.mesh_flows(mo, act)]   # eqs. (69)-(70)
[(1, 3, 14/5), (3, 2, -14/5)]
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..errors import InputError
from . import screws
from .motion import Motions
from .statics import Actions

__all__ = ["coupling_powers", "column_powers", "tellegen", "power_flow", "MeshFlow", "mesh_flows",
           "real_flows", "mesh_power_ratio"]


def _simp(x):
    return sympy.cancel(x) if isinstance(x, sympy.Basic) else x


def coupling_powers(mo: Motions, act: Actions, roles=None) -> dict:
    """``{coupling: $a . $m}``; with *roles*, only the action columns of those roles count
    (``roles=("input",)`` is the source part of an input coupling)."""
    return {c.name: _simp(screws.power(_pad(act.screw(c.name, roles)), _pad(mo.screw(c.name))))
            for c in mo.network.couplings}


def column_powers(mo: Motions, act: Actions) -> dict:
    """``{action variable: power}``: each column's power on its coupling's motion."""
    out = {}
    net = act.network
    for k, i in enumerate(act.columns):
        v = net.action_vars[i]
        m = mo.screw(v.coupling)
        out[v.name] = _simp(act.values[k] * sum(v.screw[r] * m[r] for r in range(net.d)))
    return out


def tellegen(mo: Motions, act: Actions):
    """The sum of all coupling powers, ``tr(A^T M)``: zero for any solution (Tellegen's theorem)."""
    return _simp(sum(coupling_powers(mo, act).values()))


def _pad(s):
    return tuple(s) if len(s) == 3 else (0,) + tuple(s)


def power_flow(mo: Motions, act: Actions, coupling, reference=None) -> tuple:
    """``(P_tail, P_head)``: the power the coupling takes from its tail link and delivers to its
    head link, measured by an observer on *reference* (default: the ground)."""
    net = mo.network
    c = net.coupling(coupling)
    a = _pad(act.screw(c.name))
    ref = net.ground if reference is None else net.mechanism.resolve(reference)
    return (_simp(screws.power(a, _pad(mo.link(c.tail, ref)))), _simp(screws.power(a, _pad(mo.link(c.head, ref)))))


@dataclass(frozen=True)
class MeshFlow:
    """The virtual power flow of one mesh, measured from its carrier.

    ``tail_power`` and ``head_power`` are the power leaving the tail gear and reaching the head
    gear; ``driver`` and ``driven`` follow from their sign; ``efficiency`` is what reaches the
    driven gear over what leaves the driver (the ordinary efficiency)."""

    coupling: str
    gears: tuple
    carrier: object
    tail_power: object
    head_power: object

    @property
    def tail_drives(self) -> bool:
        value = self.tail_power
        try:
            return float(value) > 0
        except TypeError:
            raise InputError(f"the sign of the flow in mesh {self.coupling} depends on symbols: {value}") from None

    @property
    def driver(self):
        return self.gears[0] if self.tail_drives else self.gears[1]

    @property
    def driven(self):
        return self.gears[1] if self.tail_drives else self.gears[0]

    @property
    def efficiency(self):
        if self.tail_drives:
            return _simp(self.head_power / self.tail_power)
        return _simp(self.tail_power / self.head_power)

    @property
    def loss(self):
        return _simp(self.head_power - self.tail_power)


def mesh_flows(mo: Motions, act: Actions) -> tuple:
    """The carrier-relative (virtual) power flow of every mesh (:class:`MeshFlow`)."""
    out = []
    for c in mo.network.meshes:
        pt, ph = power_flow(mo, act, c.name, c.carrier)
        out.append(MeshFlow(c.name, (c.tail, c.head), c.carrier, pt, ph))
    return tuple(out)


def real_flows(mo: Motions, act: Actions, reference=None) -> dict:
    """``{coupling: (P_tail, P_head)}`` measured from *reference* (default: the ground, the link
    common to both ports: the real power flow)."""
    return {c.name: power_flow(mo, act, c.name, reference) for c in mo.network.couplings}


def mesh_power_ratio(mo: Motions, coupling, *, tail_drives: bool, internal: bool = False, simplify: bool = True):
    """The ordinary efficiency of a mesh as a function of its Coulomb coefficient: returns
    ``(eta(zeta), zeta(eta))`` as two callables built from the carrier-relative motions.

    The mesh action is ``U (f + zeta tau)`` (contact force and friction torque), so ``U``
    cancels from the ratio of the powers at the driven and the driving gear. With *internal*,
    ``zeta`` is per unit of the network's friction screw (no square roots in exact work).
    ``simplify=False`` leaves ``zeta(eta)`` uncancelled (for callers that cancel it later)."""
    net = mo.network
    c = net.coupling(coupling)
    fric = next(v for v in net.action_vars if v.coupling == c.name and v.role == "friction")
    force = next(v for v in net.action_vars if v.coupling == c.name and v.name == f"U_{c.name}")
    mt, mh = _pad(mo.link(c.tail, c.carrier)), _pad(mo.link(c.head, c.carrier))
    f, tau = _pad(force.screw), _pad(fric.screw)
    ft, fh = screws.power(f, mt), screws.power(f, mh)
    tt, th = screws.power(tau, mt), screws.power(tau, mh)
    scale = 1 if internal else fric.scale
    if not tail_drives:
        ft, fh, tt, th = fh, ft, th, tt

    def eta_of(zeta):
        z = zeta / scale if scale != 1 else zeta
        return _simp((fh + z * th) / (ft + z * tt))

    def zeta_of(eta):
        z = (eta * ft - fh) / (th - eta * tt)
        z = z * scale if scale != 1 else z
        return _simp(z) if simplify else z

    return eta_of, zeta_of
