"""From measured mesh losses back to ordinary efficiencies (the inverse problem).

Nelson and Cipra report the power lost in each mesh of a Humpage reducer; Laus turns those
losses into friction coefficients and ordinary efficiencies (thesis eq. 96, section 3.5.1.2).
:func:`efficiencies_from_losses` does the same for any train: it finds the Coulomb coefficients
whose mesh losses, per unit input power, equal the given ones (a small nonlinear system,
solved by Newton's method from the lossless state) and converts each to the ordinary
efficiency of its mesh.

>>> import gearlib as gl
>>> fit = gl.davies.efficiencies_from_losses(gl.catalog.humpage(), 5, 1, 4,
...                                          losses={(1, 2): 0.014, (5, 2): 0.047, (2, 4): 0.114})
>>> round(fit.efficiency, 6), [round(v, 6) for v in fit.eta.values()]
(0.825, [0.982316, 0.995993, 0.989697])
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ConstraintError, InputError
from .motion import motions as solve_motions
from .coupling_network import network as make_network
from .power import column_powers, coupling_powers, mesh_flows, mesh_power_ratio
from .statics import actions as solve_actions
from ..mechanism._accept import takes_mechanism

__all__ = ["LossFit", "efficiencies_from_losses"]


@dataclass(frozen=True)
class LossFit:
    """``eta``: ``{gear pair: ordinary efficiency}`` (in the direction of the power flow),
    ``zeta``: ``{gear pair: signed Coulomb coefficient}``, ``drivers``: ``{gear pair: driver}``,
    and the overall ``efficiency``."""

    eta: dict
    zeta: dict
    drivers: dict
    efficiency: float


@takes_mechanism
def efficiencies_from_losses(mech, ground=None, input=None, output=None, *, losses: dict, check: bool = True,
                             **options) -> LossFit:
    """Ordinary efficiencies of the meshes whose losses (power per unit input power, positive
    numbers, ``{(a, b): loss}``) are given; the other meshes are taken as lossless."""
    net = make_network(mech, ground, input, output, exact=False, **options)
    mo = solve_motions(net, check=check)
    lossless = solve_actions(net)
    tail = {f.coupling: f.tail_power > 0 for f in mesh_flows(mo, lossless)}
    target = {}
    for key, value in losses.items():
        c = net.mesh_coupling(*key)
        if not (0 <= value < 1):
            raise InputError(f"loss of mesh {key} must be a fraction of the input power in [0, 1), got {value}")
        target[c.name] = float(value)
    names = list(target)
    fric = {c: next(v.name for v in net.action_vars if v.coupling == c and v.role == "friction") for c in names}

    def residual(z):
        act = solve_actions(net, lossless=False, zeta=dict(zip(names, z)))
        pin = coupling_powers(mo, act, roles=("input",))[net.port("input").name]
        cols = column_powers(mo, act)
        return np.array([-cols[fric[c]] / pin - target[c] for c in names]), act, pin

    z = np.zeros(len(names))
    for _ in range(50):
        r, _, _ = residual(z)
        if np.abs(r).max() < 1e-13:
            break
        jac = np.empty((len(names), len(names)))
        for j in range(len(names)):
            step = np.zeros(len(names))
            step[j] = 1e-7 * max(1.0, abs(z[j]))
            jac[:, j] = (residual(z + step)[0] - r) / step[j]
        z = z - np.linalg.solve(jac, r)
    else:
        raise ConstraintError("the losses could not be matched; are they physically possible?")
    _, act, pin = residual(z)
    pout = coupling_powers(mo, act, roles=("output",))[net.port("output").name]
    eta, zeta, drivers = {}, {}, {}
    for c, value in zip(names, z):
        coupling = net.coupling(c)
        eta_of, _ = mesh_power_ratio(mo, c, tail_drives=tail[c])
        key = coupling.mesh.gears
        eta[key] = float(eta_of(value))
        zeta[key] = float(value)
        drivers[key] = coupling.tail if tail[c] else coupling.head
    return LossFit(eta, zeta, drivers, float(-pout / pin))
