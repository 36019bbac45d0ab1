"""Laus's own models, for reproducing the thesis and its errata.

:func:`laus_humpage_geometry` returns the axis and pitch-point overrides of Laus's Humpage
model (thesis eqs. 80 and 138-141; the book's :ref:`notes on the sources <sources-humpage>`):
the pitch points C, D, E of eq. (138) and the planet axis either as printed in eq. (80) --
inconsistent with the pitch cones, the cautionary case -- or along the bisector of OC and OD, which is what the rest of the geometry implies.
Pass them to :func:`gearlib.davies.efficiency` (``check=False`` for the printed axis, whose
carrier speed contradicts the Willis equations).

>>> import gearlib as gl
>>> opts = gl.davies.laus_humpage_geometry(printed_axis=True)
>>> res = gl.davies.efficiency(gl.catalog.humpage(), 5, 1, 4, eta=0.98, check=False, **opts)
>>> round(res.value, 6)                      # the thesis's 42.5 %
0.424979
"""

from __future__ import annotations

import sympy

from ..mechanism.data import Mechanism

__all__ = ["laus_humpage_geometry", "humpage_radii"]


def humpage_radii(mech: Mechanism | None = None) -> dict:
    """``{"r1": .., "r2": .., "r3": .., "r4": .., "r5": ..}``: Laus's names for the pitch radii of a
    Humpage train built like the catalogue entry (gears 1-2, 5-2 and 3-4 on the planet 2)."""
    from .. import catalog

    mech = mech or catalog.humpage()
    r = {}
    for gp in mech.gear_pairs:
        radii = [sympy.nsimplify(x, rational=True) for x in (gp.radii or tuple(t / 2 for t in gp.teeth))]
        if gp.gears == (1, 2):
            r["r1"], r["r2"] = radii
        elif gp.gears == (5, 2):
            r["r5"] = radii[0]
        elif gp.gears == (2, 4):
            r["r3"], r["r4"] = radii
    return r


def laus_humpage_geometry(mech: Mechanism | None = None, *, printed_axis: bool = True) -> dict:
    """``{"axes": ..., "pitch_points": ...}`` of Laus's Humpage model (see the module docs)."""
    r = humpage_radii(mech)
    r1, r2, r3, r4, r5 = (r[k] for k in ("r1", "r2", "r3", "r4", "r5"))
    b = 4 * r2 ** 2 - (r5 - r1) ** 2
    d = 2 * r2 ** 2 - r5 * (r5 - r1)
    e = 2 * r2 ** 2 + r1 * (r5 - r1)
    f = 2 * r2 * r3 - r4 * (r5 - r1)
    sb = sympy.sqrt(b)
    points = {(1, 2): (r1, -e / sb), (5, 2): (r5, d / sb), (2, 4): (r4, f / sb)}
    if printed_axis:  # eq. (80): (0, -(r5 - r1), sqrt(b)) / (2 r2)
        direction = (-(r5 - r1) / (2 * r2), sb / (2 * r2))
    else:  # the bisector of OC and OD, pointing away from the main axis
        direction = (sb / (2 * r2), -(r5 - r1) / (2 * r2))
    return {"axes": {"p": {"point": (0, 0), "direction": direction}}, "pitch_points": points}
