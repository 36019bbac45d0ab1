"""Screws of a gear train whose axes all lie in one plane.

Davies' method works with screws: a *motion* (twist) ``{r, s, t; u, v, w}`` is an angular
velocity and the velocity of the body point at the origin; an *action* (wrench)
``{R, S, T; U, V, W}`` is a moment about the origin and a force. Power is their plain dot
product, ``rR + sS + tT + uU + vV + wW`` (Laus 2011, eq. 5).

Every train this package handles is drawn at the instant when all its axes lie in the plane
``x = 0`` (Laus's simplifying assumptions: thin gears, zero pressure angle, contacts in that
plane). Then only three coordinates are ever non-zero, and a screw is stored as a 3-vector:

* motions ``(s, t, u)``: angular velocity in the plane, and the ``x``-velocity of the origin;
* actions ``(S, T, U)``: moment parallel to the plane, and a force along ``x``.

``r, v, w`` and ``R, V, W`` are identically zero. Points and directions in the plane are
pairs ``(y, z)``. For parallel axes (spur trains) ``s`` and ``S`` vanish too and the screws
reduce to Laus's 2-system ``{t; u}`` / ``{T; U}``; for bevel trains whose axes meet at the
origin ``u = 0`` and the motions span ``{s, t}``, padded with ``u = 0`` as in the thesis.

>>> from gearlib.davies import screws
>>> screws.revolute((2, 0), (0, 1))        # rotation about z through y = 2: (s, t, u)
(0, 1, 2)
>>> screws.x_force((2, 0))                 # an x-force through y = 2: (S, T, U)
(0, -2, 1)
>>> screws.power(screws.x_force((2, 0)), screws.revolute((2, 0), (0, 1)))
0
"""

from __future__ import annotations

__all__ = [
    "MOTION_COORDS", "ACTION_COORDS", "revolute", "torque", "x_force", "power", "perpendicular",
    "cross2", "dot2", "is_parallel",
]

MOTION_COORDS = ("s", "t", "u")
ACTION_COORDS = ("S", "T", "U")


def revolute(point, direction) -> tuple:
    """Unit motion screw of a rotation about the line through *point* along *direction*
    (both in the plane ``x = 0``): ``(s, t, u) = (d_y, d_z, y d_z - z d_y)``."""
    (y, z), (dy, dz) = point, direction
    return (dy, dz, y * dz - z * dy)


def torque(direction) -> tuple:
    """Unit action screw of a pure torque along *direction*: ``(S, T, U) = (d_y, d_z, 0)``."""
    dy, dz = direction
    return (dy, dz, 0 * dy)


def x_force(point) -> tuple:
    """Unit action screw of a force along ``x`` through *point*: moment ``(0, z, -y)``, force 1."""
    y, z = point
    return (z, -y, 1 + 0 * y)


def power(action, motion):
    """The power ``sS + tT + uU`` of an action on a motion (3-vectors as above)."""
    return action[0] * motion[0] + action[1] * motion[1] + action[2] * motion[2]


def perpendicular(direction) -> tuple:
    """The in-plane direction at a right angle to *direction* (turned by -90 degrees): for
    ``z = (0, 1)`` it is ``y = (1, 0)``. Revolutes transmit a torque about it."""
    dy, dz = direction
    return (dz, -dy)


def cross2(a, b):
    """The scalar cross product ``a_y b_z - a_z b_y`` of two in-plane vectors."""
    return a[0] * b[1] - a[1] * b[0]


def dot2(a, b):
    return a[0] * b[0] + a[1] * b[1]


def is_parallel(a, b, tol=1e-12) -> bool:
    """True when two in-plane directions are parallel (exactly, or within *tol* for floats)."""
    c = cross2(a, b)
    try:
        return abs(float(c)) <= tol
    except TypeError:  # symbolic
        import sympy

        return sympy.simplify(c) == 0
