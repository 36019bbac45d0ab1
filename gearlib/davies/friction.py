"""Friction models of Laus's thesis: tooth friction of an involute pair, bearings and pivots.

* :func:`involute_efficiency` averages the instantaneous efficiency of an involute spur pair
  over the path of contact (Laus 2011, appendix A, eq. 136); :func:`buckingham_efficiency` is
  Buckingham's "more exact" formula for comparison, and :func:`equivalent_zeta` the Coulomb
  coefficient of the equivalent average friction torque (App. A.5, with the book's repair of its final formula).
* :func:`bearing_multiplier` scales a Coulomb coefficient for a cylindrical journal
  (Table 16, after Baranov) and :func:`pivot_friction_torque` gives the friction torque of an
  annular pivot (eqs. 142-146, with the standard uniform-wear law).

Mesh friction inside a network is handled by :func:`gearlib.davies.efficiency` through the
ordinary efficiencies; :func:`gearlib.davies.mesh_power_ratio` gives the relation between a
mesh's ordinary efficiency and its Coulomb coefficient.

>>> import math, gearlib as gl
>>> rho_a, rho_r = 1.072029882, 0.8844028695           # Laus App. A.4 (inches)
>>> round(gl.davies.involute_efficiency(3, 8, math.radians(14.5), 0.0272, rho_a, rho_r), 10)
0.9936745104
"""

from __future__ import annotations

import math

from ..errors import InputError

__all__ = ["involute_efficiency", "buckingham_efficiency", "contact_path", "equivalent_zeta",
           "bearing_multiplier", "pivot_friction_torque"]


def _kappas(r1, alpha, mu):
    k1 = -r1 * (math.sin(alpha) + math.cos(alpha) / mu)
    k2 = -r1 * (math.sin(alpha) - math.cos(alpha) / mu)
    return k1, k2


def _check(mu, alpha, *lengths):
    if not (mu > 0) or not (0 <= alpha < math.pi / 2) or any(not (x > 0) for x in lengths):
        raise InputError("need mu > 0, 0 <= alpha < pi/2 and positive radii and path lengths")


def contact_path(r1, r2, module, alpha) -> tuple[float, float]:
    """``(rho_a, rho_r)``: approach and recess lengths of the path of contact of an involute pair
    with addendum equal to the module, gear 1 driving (Laus eqs. 134-135)."""
    _check(1.0, alpha, r1, r2, module)
    rho_r = -r1 * math.sin(alpha) + math.sqrt((r1 + module) ** 2 - (r1 * math.cos(alpha)) ** 2)
    rho_a = -r2 * math.sin(alpha) + math.sqrt((r2 + module) ** 2 - (r2 * math.cos(alpha)) ** 2)
    return rho_a, rho_r


def involute_efficiency(r1, r2, alpha, mu, rho_a, rho_r) -> float:
    """Mesh-cycle average efficiency of an involute spur pair, gear 1 (pitch radius *r1*) driving
    gear 2, pressure angle *alpha* (radians), Coulomb coefficient *mu* (Laus eq. 136)."""
    _check(mu, alpha, r1, r2, rho_a, rho_r)
    k1, k2 = _kappas(r1, alpha, mu)
    big_l = k2 * math.log(1 + rho_a / k2) - k1 * math.log(1 - rho_r / k1)
    return (r1 / r2 + 1) * big_l / (rho_a + rho_r) - r1 / r2


def equivalent_zeta(r1, r2, alpha, mu, rho_a, rho_r) -> float:
    """Coulomb coefficient (a length) of the average friction torque equivalent to the tooth
    friction of :func:`involute_efficiency`: ``r1 (rho_a + rho_r)/L - r1`` (App. A.5, repaired)."""
    _check(mu, alpha, r1, r2, rho_a, rho_r)
    k1, k2 = _kappas(r1, alpha, mu)
    big_l = k2 * math.log(1 + rho_a / k2) - k1 * math.log(1 - rho_r / k1)
    return r1 * (rho_a + rho_r) / big_l - r1


def buckingham_efficiency(r1, r2, alpha, mu, beta_a, beta_r) -> float:
    """Buckingham's "more exact" average efficiency from the approach and recess angles of gear 1."""
    _check(mu, alpha, r1, r2, beta_a, beta_r)
    s = beta_a + beta_r - mu * math.tan(alpha) * (beta_a - beta_r)
    q = beta_a ** 2 + beta_r ** 2
    return (s - mu * r1 / (2 * r2) * q) / (s + mu / 2 * q)


def bearing_multiplier(beta=math.pi / 2, law: str = "constant") -> float:
    """Factor on the planar Coulomb coefficient of a cylindrical journal with contact angle
    ``2 beta`` (Laus Table 16): ``beta/sin(beta)`` for a constant normal pressure (new pairs),
    ``4 sin(beta)/(2 beta + sin(2 beta))`` for a cosine law (worn-in pairs)."""
    if not (0 < beta <= math.pi / 2):
        raise InputError(f"beta must be in (0, pi/2], got {beta}")
    if law == "constant":
        return beta / math.sin(beta)
    if law == "cosine":
        return 4 * math.sin(beta) / (2 * beta + math.sin(2 * beta))
    raise InputError(f"law must be 'constant' or 'cosine', got {law!r}")


def pivot_friction_torque(mu, r_inner, r_outer, load, *, worn: bool = False) -> float:
    """Friction torque of an annular pivot: uniform pressure (new, eq. 145)
    ``2 mu (r1^2 + r1 r2 + r2^2) Q / (3 (r1 + r2))``, or uniform wear (``worn``)
    ``mu Q (r1 + r2)/2`` -- half of Laus's eq. (146), whose pressure law integrates to ``2 Q``."""
    if not (0 <= r_inner < r_outer) or mu < 0:
        raise InputError("need 0 <= r_inner < r_outer and mu >= 0")
    if worn:
        return mu * load * (r_inner + r_outer) / 2
    return 2 * mu * (r_inner ** 2 + r_inner * r_outer + r_outer ** 2) * load / (3 * (r_inner + r_outer))
