"""Where the axes and pitch points of a gear train are, derived from its radii and topology.

Davies' unit screws need geometry: the line of every axis and the pitch point of every
mesh. A :class:`gearlib.Mechanism` holds only topology, tooth numbers and (optionally) pitch
radii, so :func:`gearlib.davies.layout` builds the geometry at the instant when every axis lies in the plane
``x = 0`` (points and directions are ``(y, z)`` pairs):

* the ground's first axis is the ``z``-axis;
* a spur pair puts the other gear's axis parallel, at the centre distance ``r_a + r_b``
  (external) or ``|r_a - r_b|`` (internal), on the side that closes every loop of centre
  distances (a planetary's sun and ring share an axis, so ``r_ring = r_sun + 2 r_planet``);
* a bevel pair puts the other axis through the apex, at the angle that puts a gear meshing
  two others on a single pitch cone (Humpage's planet: ``cos(phi) = (r1 - r5)/(2 r2)``), or at
  a right angle when nothing fixes it;
* the pitch line of each mesh is the axis of the relative rotation ``e u_b - u_a`` (bevel) or
  the line dividing the centre distance in the ratio ``r_a : r_b`` (spur).

``mode`` chooses how strict this is: ``"physical"`` (the default for numbers) enforces every
centre distance and cone; ``"right-angle"`` keeps bevel axes at 90 degrees to their parent
(exact and symbolic work, no square roots); ``"kinematic"`` also lets loops of centre
distances stay open (a Ravigneaux set cannot be drawn with all axes in one plane). The
efficiency, the speed of every link and every power flow do not depend on the mode; the
sizes of forces, mesh speeds and Coulomb coefficients do. ``"auto"`` tries ``physical`` and
falls back, saying so in ``Layout.notes``.

>>> import gearlib as gl
>>> lay = gl.davies.layout(gl.catalog.load("laus_epicyclic"))
>>> [(m.gears, m.pitch_point) for m in lay.meshes]
[((1, 3), (40, 0)), ((2, 3), (60, 0))]
>>> lay.axis_of(3, "b").point      # the planet axis, r1 - r3 = r2 - r4 from the sun axis
(25, 0)
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field, replace

import sympy

from .._common.topology import CoaxialGroups
from ..errors import DataFormatError, GeometryError, UnknownLinkError
from ..mechanism.data import Mechanism
from ._placement import Axis, Builder, MeshGeometry, intersection
from .screws import cross2

__all__ = ["Axis", "MeshGeometry", "Layout", "layout", "radius_symbols", "MODES"]

MODES = ("auto", "physical", "right-angle", "kinematic")


@dataclass(frozen=True)
class Layout:
    """Axes and pitch points of a mechanism (see :func:`layout`)."""

    mechanism: Mechanism
    axes: tuple
    meshes: tuple
    mode: str
    planar: bool
    membership: dict = field(repr=False, compare=False)
    relations: dict = field(default_factory=dict)
    notes: tuple = ()
    values: dict = field(default_factory=dict, compare=False)

    def axis(self, group: int) -> Axis:
        return self.axes[group]

    def axis_of(self, link, label) -> Axis:
        """The axis of *link* with the given axis label."""
        link = self.mechanism.resolve(link)
        try:
            return self.axes[self.membership[link][str(label)]]
        except KeyError:
            raise UnknownLinkError(f"link {link} has no turning pair with axis label {label!r}") from None

    def common_axis(self, u, v) -> Axis | None:
        """The axis on which links *u* and *v* are coaxial, or None."""
        mu, mv = self.membership.get(u, {}), self.membership.get(v, {})
        for label, g in mu.items():
            if mv.get(label) == g:
                return self.axes[g]
        return None

    def mesh(self, a, b) -> MeshGeometry:
        for m in self.meshes:
            if set(m.gears) == {a, b}:
                return m
        raise UnknownLinkError(f"no gear pair between {a} and {b}")


# ------------------------------------------------------------------------------ numbers
def _exact(value):
    if isinstance(value, sympy.Basic):
        return value
    if isinstance(value, float):
        return _rational(value)
    return sympy.sympify(value)


@functools.lru_cache(maxsize=1024)
def _rational(value: float):
    """The decimal a float was typed as (``0.1`` -> ``1/10``); cached, since ``nsimplify`` is
    slow and a widget meets the same radii on every frame."""
    return sympy.nsimplify(value, rational=True)


def _num(x) -> float:
    return float(x)


def _sign(x) -> int:
    v = _num(x)
    return (v > 0) - (v < 0)


def radius_symbols(mech: Mechanism) -> dict:
    """Default symbols for the pitch radii: ``{(a, b): (r_a, r_b)}`` per gear pair, with one
    symbol per gear (a link and a radius): ``r1`` for a link with one gear, ``r2a``, ``r2b``,
    ... for a link that carries several."""
    values: dict = {}
    for gp in mech.gear_pairs:
        for link, r in zip(gp.gears, _pair_radii(gp)):
            values.setdefault(link, [])
            if r not in values[link]:
                values[link].append(r)
    names = {}
    for link, rs in values.items():
        for k, r in enumerate(rs):
            name = f"r{link}" if len(rs) == 1 else f"r{link}{'abcdefghij'[k]}"
            names[(link, r)] = sympy.Symbol(name, positive=True)
    return {gp.gears: tuple(names[(link, r)] for link, r in zip(gp.gears, _pair_radii(gp))) for gp in mech.gear_pairs}


def _pair_radii(gp) -> tuple:
    if gp.radii is not None:
        return tuple(_exact(r) for r in gp.radii)
    if gp.teeth is not None and (gp.module is not None or gp.normal_module is not None):
        # pitch radii from the (transverse) module, m z / 2; a helical pair's m_n / cos(beta) is
        # taken as a rational number, as radii given as decimals are
        m = _exact(float(gp.transverse_module))
        return tuple(m * sympy.Rational(t, 2) for t in gp.teeth)
    if gp.teeth is not None:
        return tuple(sympy.Rational(t, 2) for t in gp.teeth)  # module 1
    e = gp.e
    if e.free_symbols or not e.is_real:
        raise DataFormatError(f"gear pair {gp.label}: give `teeth` or `radii`; Davies' method needs the pitch radii")
    return (sympy.Integer(1), 1 / abs(e))


def _pair_ratio(gp, radii):
    """The real gear ratio e_{a,b} along the axis directions, and the check that |e| = r_a/r_b."""
    e = gp.e
    if e.free_symbols:
        raise DataFormatError(f"gear pair {gp.label} has a symbolic ratio {e}; give tooth numbers or radii")
    if not e.is_real:
        raise DataFormatError(
            f"gear pair {gp.label} has Penaud's complex weights (ratio {e}); Davies' method needs the signed real "
            "ratio along chosen axis directions: give `ratio:` with its sign instead of `angles:`"
        )
    ra, rb = radii
    if gp.kind != "bevel" and abs(_num(e) - 1) < 1e-12:
        raise GeometryError(f"gear pair {gp.label}: an internal pair needs a ring larger than its pinion "
                            f"(both have {'teeth ' + str(gp.teeth[0]) if gp.teeth else 'the same radius'})")
    if abs(_num(abs(e)) - _num(ra / rb)) > 1e-9 * max(1.0, _num(abs(e))):
        raise GeometryError(
            f"gear pair {gp.label}: pitch radii {_num(ra):g} and {_num(rb):g} give the ratio {_num(ra / rb):.6g}, "
            f"but the teeth give {_num(abs(e)):.6g}; make the radii proportional to the tooth numbers"
        )
    return e


# ------------------------------------------------------------------------------ the layout
@dataclass
class _Pair:
    index: int
    gp: object
    ga: int
    gb: int
    radii: tuple
    e: object
    spur: bool


def _pairs(mech, groups, membership):
    out = []
    for i, gp in enumerate(mech.gear_pairs):
        a, b = gp.gears
        cands = [(la, lb) for c, la, lb in groups.carrier_candidates(a, b) if c == gp.carrier]
        la, lb = cands[0]
        radii = _pair_radii(gp)
        e = _pair_ratio(gp, radii)
        out.append(_Pair(i, gp, membership[a][la], membership[b][lb], radii, e, gp.kind != "bevel"))
    return out


def layout(mech: Mechanism, *, mode: str = "auto", exact: bool = True, radii=None, axes=None,
           pitch_points=None) -> Layout:
    """Axes and pitch points of *mech* in the plane ``x = 0`` (see the module documentation).

    Parameters
    ----------
    mode : ``"auto"``, ``"physical"``, ``"right-angle"`` or ``"kinematic"``.
    exact : keep exact numbers (sympy) where the mode allows; ``False`` gives floats.
    radii : ``"symbols"`` or ``{(a, b): (r_a, r_b)}`` with symbols (or numbers) to use in place of
        the pitch radii of the gear pairs; the layout's signs and sides still come from the
        numeric radii, and loops of centre distances become ``Layout.relations``.
    axes : ``{(link, label) or label: {"point": (y, z), "direction": (y, z)}}`` overrides, e.g.
        to reproduce a published (even an inconsistent) model.
    pitch_points : ``{(a, b): (y, z)}`` overrides of pitch points.
    """
    if mode not in MODES:
        raise DataFormatError(f"layout mode must be one of {', '.join(MODES)}, got {mode!r}")
    tps = [(tp.links[0], tp.links[1], tp.axis) for tp in mech.turning_pairs]
    groups = CoaxialGroups(tps)
    membership = {k: dict(v) for k, v in groups.membership.items()}
    pairs = _pairs(mech, groups, membership)
    symbols = None
    if radii is not None:
        symbols = radius_symbols(mech) if radii == "symbols" else {tuple(k): tuple(map(_exact, v))
                                                                    for k, v in dict(radii).items()}
        exact = True
    notes = []
    has_bevel = any(not p.spur for p in pairs)
    want = mode
    if mode == "auto":
        want = "physical" if not (exact and has_bevel) else "right-angle"
        if exact and has_bevel:
            notes.append("bevel axes drawn at right angles to their parent axis (exact arithmetic); "
                         "the efficiency and all power flows do not depend on this")
    try:
        geo = Builder(mech, groups, pairs, want, exact).run()
    except GeometryError as err:
        if mode != "auto":
            raise
        notes.append(f"{err}; the loop is left open (mode 'kinematic'): speeds, power flows and the efficiency "
                     "are unaffected, forces are not to scale. If the train should close (a planetary set), "
                     "check the data: a ring gear needs `type: internal` in its gear pair")
        geo = Builder(mech, groups, pairs, "kinematic" if want == "physical" else want, exact).run()
        want = "kinematic"
    relations, values = {}, {}
    if symbols is not None:
        for p in pairs:
            for sym, r in zip(symbols[p.gp.gears], p.radii):
                if isinstance(sym, sympy.Symbol):
                    values[sym] = r
        geo, relations = Builder(mech, groups, pairs, want, True, symbols=symbols, decisions=geo).run_symbolic()
    axes_out, meshes = geo.axes_out(), geo.meshes_out()
    if axes or pitch_points:
        axes_out, meshes = _override(mech, membership, groups, axes_out, meshes, axes or {}, pitch_points or {},
                                     exact)
        want = "given"
    planar = all(abs(_num(cross2(ax.direction, axes_out[0].direction))) < 1e-12 for ax in axes_out)
    return Layout(mech, tuple(axes_out), tuple(meshes), want, planar, membership, relations, tuple(notes), values)


def _override(mech, membership, groups, axes_out, meshes, axes, pitch_points, exact):
    conv = _exact if exact else (lambda x: float(sympy.sympify(x)))
    axes_out = list(axes_out)
    for key, spec in axes.items():
        if isinstance(key, str):
            gids = [g for g, lab in enumerate(groups.labels) if lab == key]
            if len(gids) != 1:
                raise UnknownLinkError(f"axis label {key!r} names {len(gids)} axes; use (link, label)")
            g = gids[0]
        else:
            link, label = key
            g = membership.get(mech.resolve(link), {}).get(str(label))
            if g is None:
                raise UnknownLinkError(f"link {link} has no axis {label!r}")
        ax = axes_out[g]
        point = tuple(map(conv, spec.get("point", ax.point)))
        direction = tuple(map(conv, spec.get("direction", ax.direction)))
        axes_out[g] = replace(ax, point=point, direction=direction)
    out = []
    for m in meshes:
        ua, ub = axes_out[m.axes[0]].direction, axes_out[m.axes[1]].direction
        pa, pb = axes_out[m.axes[0]].point, axes_out[m.axes[1]].point
        pitch = m.pitch_point
        for key, value in pitch_points.items():
            if set(key) == set(m.gears):
                pitch = tuple(map(conv, value))
        if m.kind == "bevel":
            apex = intersection(pa, ua, pb, ub)
            vec = tuple(pitch[i] - apex[i] for i in range(2))
            if exact:
                out.append(replace(m, apex=apex, pitch_point=pitch, direction=vec,
                                   scale=sympy.sqrt(vec[0] ** 2 + vec[1] ** 2)))
            else:
                norm = math.hypot(*vec)
                out.append(replace(m, apex=apex, pitch_point=pitch, direction=(vec[0] / norm, vec[1] / norm),
                                   scale=1.0))
        else:
            out.append(replace(m, pitch_point=pitch, direction=ua))
    return axes_out, out
