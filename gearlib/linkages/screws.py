"""Screws in Davies' coordinates: motions ``{r, s, t; u, v, w}``, actions ``{R, S, T; U, V, W}``.

A *motion* (twist) is an angular velocity and the velocity of the body point at the origin;
an *action* (wrench) is a moment about the origin and a force. Their power is the plain dot
product (Laus 2011, eq. 5). For a rotation about the line through ``p`` along ``s`` the unit
motion is ``(s; p x s)``; a translation along ``s`` is ``(0; s)``; a force along ``s`` through
``p`` is ``(p x s; s)``; a couple about ``s`` is ``(s; 0)``.

In the plane ``z = 0`` only ``{t; u, v}`` and ``{T; U, V}`` are ever non-zero: planar linkages
keep those three coordinates (``PLANAR``), the screws of order 3 of the thesis' slider-crank.
Chapter 5's gear trains, whose axes lie in the plane ``x = 0``, keep ``{s, t; u}`` instead
(:mod:`gearlib.davies.screws`).

>>> import numpy as np
>>> from gearlib.linkages import screws
>>> screws.rotation([1.0, 2.0, 0.0], [0, 0, 1.0])[screws.PLANAR]      # (t; u, v) = (1; y, -x)
array([ 1.,  2., -1.])
>>> screws.force([1.0, 2.0, 0.0], [1.0, 0, 0])[screws.PLANAR]         # (T; U, V) = (-y; 1, 0)
array([-2.,  1.,  0.])
>>> float(screws.power(screws.force([0, 0, 0], [0, 0, 1.0]), screws.translation([0, 0, 2.0])))
2.0
"""

from __future__ import annotations

import numpy as np

__all__ = ["MOTION_COORDS", "ACTION_COORDS", "PLANAR", "rotation", "translation", "force", "couple", "power",
           "perpendicular"]

MOTION_COORDS = ("r", "s", "t", "u", "v", "w")
ACTION_COORDS = ("R", "S", "T", "U", "V", "W")
PLANAR = [2, 3, 4]
"""The coordinates a planar screw keeps: ``t, u, v`` (motions) and ``T, U, V`` (actions)."""


def _cross(a, b) -> list:
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def rotation(point, direction) -> np.ndarray:
    """Unit motion of a rotation about the line through *point* along *direction*."""
    return np.array([*direction, *_cross(point, direction)], dtype=float)


def translation(direction) -> np.ndarray:
    """Unit motion of a translation along *direction*."""
    return np.array([0.0, 0.0, 0.0, *direction], dtype=float)


def force(point, direction) -> np.ndarray:
    """Unit action of a force along *direction* through *point*."""
    return np.array([*_cross(point, direction), *direction], dtype=float)


def couple(direction) -> np.ndarray:
    """Unit action of a couple (a pure torque) about *direction*."""
    return np.array([*direction, 0.0, 0.0, 0.0], dtype=float)


def power(action, motion):
    """The power of an action on a motion: ``rR + sS + tT + uU + vV + wW``."""
    return np.dot(action, motion)


def perpendicular(direction, hint=None) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors ``(u, w)`` with ``(direction, u, w)`` right-handed and orthonormal; ``u``
    is *hint* made perpendicular when one is given."""
    a = np.asarray(direction, dtype=float)
    a = a / np.linalg.norm(a)
    if hint is None:
        hint = np.eye(3)[int(np.argmin(np.abs(a)))]
    u = np.asarray(hint, dtype=float) - np.dot(hint, a) * a
    u = u / np.linalg.norm(u)
    return u, np.cross(a, u)
