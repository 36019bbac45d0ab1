"""An independent check: efficiency by a conventional torque balance.

This is the classical route (Willis speeds plus a torque balance with each mesh's ordinary
efficiency applied in the direction of its carrier-relative power flow), written with none
of Davies' machinery: no screws, no coupling graph, no geometry.

Unknowns are one torque per mesh and the output torque. Every link other than the ground
is in equilibrium in Tsai's generalised coordinates (the link speeds ``omega_x`` of
:func:`gearlib.speeds`): the generalised force of mesh ``(a, b)`` on carrier ``c`` is
``tau_a`` on ``a``, ``tau_b`` on ``b`` and ``-(tau_a + tau_b)`` on ``c``, so that its power in
any frame equals its power relative to the carrier, ``tau_a omega_{a/c} + tau_b omega_{b/c}``.
Relative to the carrier the pair is an ordinary gear pair: the driven gear receives ``eta``
times what the driver gives, ``tau_b omega_{b/c} = -eta tau_a omega_{a/c}`` when ``a``
drives. The driver is found from the lossless solution, as in Davies' method.

>>> import gearlib as gl
>>> m = gl.catalog.load("laus_epicyclic")
>>> round(gl.davies.torque_balance_efficiency(m, ground=1, input=5, output=2, eta=0.99).value, 9)
0.94620687
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy

from ..errors import ConstraintError, InputError
from ..mechanism.kinematics import speeds
from ..mechanism._accept import takes_mechanism
from ._eta import check_eta

__all__ = ["torque_balance_efficiency", "TorqueBalance"]


@dataclass(frozen=True)
class TorqueBalance:
    """Result of :func:`torque_balance_efficiency`."""

    value: object
    drivers: dict
    mesh_torques: dict
    output_torque: object


def _solve(rows, rhs, exact):
    if exact:
        sol = sympy.Matrix(rows).LUsolve(sympy.Matrix(rhs))
        return [sympy.cancel(x) for x in sol]
    import numpy as np

    a = np.array(rows, dtype=float)
    return list(np.linalg.solve(a, np.array(rhs, dtype=float)))


@takes_mechanism
def torque_balance_efficiency(mech, ground=None, input=None, output=None, *, eta=0.98, held=(),
                              symbolic: bool = False) -> TorqueBalance:
    """Efficiency of *mech* (input and output relative to *ground*) by a torque balance.

    ``eta`` is a number for every mesh, or ``{(a, b): value}`` per gear pair (the value applies
    whichever gear drives; give both orders for direction-dependent values); with
    ``symbolic`` the values may be symbols (default symbols ``eta_i_j``, ``i`` driving).
    """
    ground = mech.resolve(mech.ground if ground is None else ground, "ground")
    input, output = mech.resolve(input, "input"), mech.resolve(output, "output")
    held = mech.resolve_links(held, "held link")
    check_eta(mech, eta, symbolic=symbolic)
    sol = speeds(mech, ground, {input: 1}, method="exact", held=held)
    w = {x: sympy.sympify(sol[x]) for x in mech.link_ids}
    for v in w.values():
        if not v.is_real:
            raise InputError("the torque balance needs real gear ratios (give bevel pairs a signed `ratio`)")
    pairs = mech.gear_pairs
    free = [x for x in mech.link_ids if x != ground and x not in held]
    nvar = len(pairs) + 1  # tau_a of each mesh, then the output torque
    if len(free) != nvar:
        raise ConstraintError(f"the torque balance needs a one-degree-of-freedom train; {mech.name!r} has "
                              f"{len(free)} free links for {len(pairs)} gear pairs")

    def system(k_of):
        rows, rhs = [], []
        for x in free:
            row = [0] * nvar
            for i, gp in enumerate(pairs):
                a, b = gp.gears
                k = k_of(i)
                if x == a:
                    row[i] += 1
                if x == b:
                    row[i] += k
                if x == gp.carrier:
                    row[i] -= 1 + k
            if x == output:
                row[-1] += 1
            rows.append(row)
            rhs.append(-1 if x == input else 0)  # unit input torque on the input link
        return rows, rhs

    def rel(x, c):
        return w[x] - w[c]

    # lossless: tau_b = -tau_a * w_{a/c} / w_{b/c}
    ratios = []
    for gp in pairs:
        a, b = gp.gears
        if rel(b, gp.carrier) == 0 or rel(a, gp.carrier) == 0:
            raise ConstraintError(f"gear pair {gp.label} does not turn relative to its carrier; drop it")
        ratios.append(-rel(a, gp.carrier) / rel(b, gp.carrier))
    x0 = _solve(*system(lambda i: ratios[i]), exact=True)
    drivers, ks = {}, []
    for i, gp in enumerate(pairs):
        a, b = gp.gears
        a_gives = -x0[i] * rel(a, gp.carrier)  # power gear a gives to the mesh, carrier frame
        drv, dvn = (a, b) if a_gives > 0 else (b, a)
        drivers[gp.gears] = (drv, dvn)
        value = _eta(eta, gp.gears, drv, dvn, symbolic)
        ks.append(ratios[i] * (value if drv == a else 1 / value))
    x = _solve(*system(lambda i: ks[i]), exact=symbolic)
    t_out = x[-1]
    value = -t_out * w[output] / (1 * w[input])
    value = sympy.factor(sympy.cancel(value)) if symbolic else float(value)
    return TorqueBalance(value, drivers, {gp.gears: x[i] for i, gp in enumerate(pairs)}, t_out)


def _eta(spec, pair, drv, dvn, symbolic):
    if isinstance(spec, dict):
        if (drv, dvn) in spec:
            return spec[(drv, dvn)]
        for k, v in spec.items():
            if set(k) == set(pair):
                return v
        spec = None
    if spec is None:
        return sympy.Symbol(f"eta_{drv}_{dvn}", positive=True) if symbolic else 0.98
    return spec
