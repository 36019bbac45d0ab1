"""The elements a mechanism is built of: links, turning pairs, gear pairs and bearings.

Each is a frozen dataclass validated when it is made, with ``from_data``/``to_data`` for the
file format (:mod:`gearlib.mechanism.io`); :class:`~gearlib.Mechanism` puts them together and
checks that they fit. Vocabulary of the papers: links are the vertices of the graph, turning
pairs its thin edges ``[link, link, axis_label]``, gear pairs its heavy edges, each with a
carrier (the transfer vertex) that holds both gear axes.

The gear ratio of pair ``(a, b)`` is ``e_{a,b} = omega(b/c) / omega(a/c)`` where ``c`` is the
carrier and ``omega(u/v)`` the angular velocity of ``u`` relative to ``v``: ``-N_a/N_b`` for an
external spur mesh, ``+N_a/N_b`` for an internal one; for bevel gears it is complex (Penaud's
angles) or given with the sign fixed by the chosen axis directions.

>>> import gearlib as gl
>>> gp = gl.GearPair(gears=(1, 2), teeth=(20, 60))
>>> gp.e
-1/3
"""

from __future__ import annotations
import numbers
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property
import sympy
from .._common.parse import (
    shown,
    expr_to_data,
    parse_expr,
    parse_link_id,
    parse_positive,
    parse_real,
    parse_real_expr,
    parse_teeth,
)
from ..errors import CarrierError, DataFormatError, DataWarning, SelfMeshError, UnknownLinkError

__all__ = ['Link', 'Bearing', 'TurningPair', 'GearPair', 'GEAR_KINDS']


GEAR_KINDS = ("external", "internal", "bevel")


def _fmt(ids) -> str:
    return ", ".join(str(i) for i in ids)


def _check_keys(data: Mapping, allowed: Sequence[str], where: str) -> None:
    unknown = [k for k in data if k not in allowed]
    if unknown:
        raise DataFormatError(
            f"{where}: unknown field {unknown[0]!r}; known fields are {', '.join(allowed)}"
        )


def _seq(value, where: str, what: str) -> tuple:
    """A list/tuple field as a tuple (None means empty), or a DataFormatError."""
    if type(value) in (list, tuple):  # the common case first: the ABC checks below are slow
        return tuple(value)
    if value is None:
        return ()
    if isinstance(value, (str, bytes, Mapping)) or not isinstance(value, Sequence):
        raise DataFormatError(f"{where}: `{what}` must be a list, got {value!r}")
    return tuple(value)


def _text(value, where: str, what: str) -> str | None:
    if value is None or isinstance(value, str):
        return value
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return str(value)
    raise DataFormatError(f"{where}: `{what}` must be text, got {value!r}")


def _check_spur_angles(where: str, kind: str, angles) -> None:
    """Warn when the Penaud angles of a spur pair contradict its ``type``: the ratio is
    ``-(N_a/N_b) e^{i(theta_a - theta_b)}``, so an external mesh has equal angles (mod 2 pi),
    an internal one angles that differ by pi, and any other difference means non-parallel axes."""
    turn = float((angles[0] - angles[1]) / sympy.pi) % 2.0  # the difference, in half turns
    made = "external" if min(turn, 2.0 - turn) < 1e-9 else "internal" if abs(turn - 1.0) < 1e-9 else None
    if made == kind:
        return
    a, b = angles
    if made is None:
        what = "a complex ratio (axes that are not parallel): a bevel pair needs `type: bevel`"
    else:
        what = (f"the ratio of an {made} mesh (an internal mesh's angles differ by pi, an external mesh's are "
                "equal); check `type` or the angles")
    warnings.warn(f"{where} is `type: {kind}`, but its angles [{a}, {b}] make {what}. The angles decide the ratio",
                  DataWarning, stacklevel=4)


def _pair_of(value, where: str, what: str) -> tuple:
    if type(value) in (list, tuple) and len(value) == 2:  # the common case, fast
        return tuple(value)
    if isinstance(value, (str, bytes)) or not isinstance(value, Sequence) or len(value) != 2:
        raise DataFormatError(f"{where}: `{what}` must be a list of two values, got {value!r}")
    return tuple(value)


@dataclass(frozen=True)
class Link:
    """A link (vertex): an id and an optional name such as ``"sun"`` or ``"carrier"``."""

    id: int | str
    name: str | None = None

    def __post_init__(self):
        object.__setattr__(self, "id", parse_link_id(self.id, "link"))
        if self.name is not None and not isinstance(self.name, str):
            object.__setattr__(self, "name", _text(self.name, f"link {self.id}", "name"))

    @property
    def label(self) -> str:
        """``"3 (planet)"``, or just ``"3"`` without a name."""
        return f"{self.id} ({self.name})" if self.name else str(self.id)


@dataclass(frozen=True)
class Bearing:
    """Geometry of a rolling bearing inside a turning pair (Penaud and Alazard, Fig. 1-2).

    Parameters
    ----------
    pitch_diameter : float
        Mean (pitch) diameter ``D_m`` of the rolling elements' centres.
    ball_diameter : float
        Diameter ``d_b`` of a ball or roller, same unit as ``pitch_diameter``.
    balls : int
        Number ``Z`` of rolling elements.
    contact_angle : expression, optional
        Contact angle ``alpha`` in radians (``"15*deg"`` reads as 15 degrees). Default 0.
    inner : link id, optional
        The link that carries the inner ring; the other link of the pair carries the outer ring.
    name : str, optional
    """

    pitch_diameter: float
    ball_diameter: float
    balls: int
    contact_angle: sympy.Expr = sympy.Integer(0)
    inner: int | str | None = None
    name: str | None = None

    def __post_init__(self):
        where = f"bearing {self.name}" if self.name else "bearing"
        object.__setattr__(self, "pitch_diameter", parse_positive(self.pitch_diameter, where + " pitch_diameter"))
        object.__setattr__(self, "ball_diameter", parse_positive(self.ball_diameter, where + " ball_diameter"))
        if self.ball_diameter >= self.pitch_diameter:
            raise DataFormatError(
                f"{where}: ball_diameter {self.ball_diameter} must be smaller than pitch_diameter "
                f"{self.pitch_diameter}"
            )
        object.__setattr__(self, "balls", parse_teeth(self.balls, where + " balls"))
        angle = parse_real_expr(self.contact_angle, where + " contact_angle")
        if not (0 <= float(angle) < float(sympy.pi / 2)):
            raise DataFormatError(f"{where}: contact_angle must be a number in [0, pi/2) radians, got {angle} "
                                  "(write degrees as 15*deg)")
        object.__setattr__(self, "contact_angle", angle)
        if self.inner is not None:
            object.__setattr__(self, "inner", parse_link_id(self.inner, where + " inner"))
        object.__setattr__(self, "name", _text(self.name, where, "name"))

    @classmethod
    def from_dict(cls, data: Mapping, where: str = "bearing") -> Bearing:
        if not isinstance(data, Mapping):
            raise DataFormatError(f"{where}: a bearing must be a mapping, got {data!r}")
        fields = ("pitch_diameter", "ball_diameter", "balls", "contact_angle", "inner", "name")
        _check_keys(data, fields, where)
        missing = [f for f in fields[:3] if f not in data]
        if missing:
            raise DataFormatError(f"{where}: missing field {missing[0]!r}")
        return cls(**dict(data))

    def to_dict(self) -> dict:
        out = {"pitch_diameter": self.pitch_diameter, "ball_diameter": self.ball_diameter, "balls": self.balls}
        if self.contact_angle != 0:
            out["contact_angle"] = expr_to_data(self.contact_angle)
        if self.inner is not None:
            out["inner"] = self.inner
        if self.name:
            out["name"] = self.name
        return out


@dataclass(frozen=True)
class TurningPair:
    """A turning pair (thin edge) joining two links about the axis with the given label.

    The label may be left out (``None``, or ``[a, b]`` in a file, as Penaud's tables mark a
    turning pair with a bare "p") when every gear pair of the mechanism names its carrier:
    :class:`~gearlib.Mechanism` then infers it."""

    links: tuple
    axis: str | None = None
    bearings: tuple[Bearing, ...] = ()

    def __post_init__(self):
        a, b = _pair_of(self.links, "turning pair", "links")
        where = f"turning pair ({a}, {b})"
        a, b = parse_link_id(a, where), parse_link_id(b, where)
        object.__setattr__(self, "links", (a, b))
        if a == b:
            raise SelfMeshError(f"{where} joins link {a} to itself; a turning pair joins two different links")
        if (type(self.axis) is str and self.axis) or self.axis is None:
            pass  # the common case, fast; None: inferred by the mechanism from its carriers
        elif isinstance(self.axis, bool) or not isinstance(self.axis, (str, numbers.Integral)) or str(self.axis) == "":
            raise DataFormatError(f"{where}: axis label must be a short text such as 'a', got {self.axis!r}")
        if self.axis is not None:
            object.__setattr__(self, "axis", str(self.axis))
        bearings = () if self.bearings == () else tuple(
            b if isinstance(b, Bearing) else Bearing.from_dict(b, f"{where} bearing {i + 1}")
            for i, b in enumerate(_seq(self.bearings, where, "bearings"))
        )
        for brg in bearings:
            if brg.inner is not None and brg.inner not in (a, b):
                raise UnknownLinkError(f"{where}: bearing inner ring on link {brg.inner}, which is not {a} or {b}")
        object.__setattr__(self, "bearings", bearings)

    @classmethod
    def from_data(cls, data, where: str = "turning pair") -> TurningPair:
        """From ``[a, b, label]`` or ``{"links": [a, b], "axis": label, "bearings": [...]}``."""
        if type(data) in (list, tuple) and len(data) == 3:  # the common case, fast
            return cls((data[0], data[1]), data[2])
        if type(data) in (list, tuple) and len(data) == 2:  # no label: inferred from the carriers
            return cls((data[0], data[1]), None)
        if isinstance(data, TurningPair):
            return data
        if isinstance(data, Mapping):
            _check_keys(data, ("links", "axis", "bearings"), where)
            if "links" not in data:
                raise DataFormatError(f"{where}: needs `links: [a, b]` (and `axis`)")
            return cls(data["links"], data.get("axis"), _seq(data.get("bearings"), where, "bearings"))
        if isinstance(data, Sequence) and not isinstance(data, (str, bytes)) and len(data) in (2, 3):
            return cls((data[0], data[1]), data[2] if len(data) == 3 else None)
        raise DataFormatError(f"{where}: expected [link, link, axis_label] (or [link, link] when every gear pair "
                              f"names its carrier), got {shown(data)}")

    def to_data(self):
        if self.bearings:
            return {"links": list(self.links), "axis": self.axis, "bearings": [b.to_dict() for b in self.bearings]}
        return [self.links[0], self.links[1], self.axis]


@dataclass(frozen=True)
class GearPair:
    """A gear pair (heavy edge) between the gears on links ``gears[0]`` and ``gears[1]``.

    Give ``teeth`` (and ``kind``), or a ``ratio`` ``e_{a,b}`` (a number or an expression),
    or both when they agree. Bevel pairs need Penaud's ``angles`` ``(theta_a, theta_b)``
    with their teeth, or a signed ``ratio``. ``radii`` are pitch radii; or give the
    ``module`` (transverse, in the unit of the radii), or the ``normal_module`` of a helical
    pair with its ``helix_angle`` (transverse module = normal module / cos(helix angle)), and
    the pitch radii follow from the teeth (:attr:`pitch_radii`). ``profile_shift`` gives the
    profile-shift coefficients ``(x_a, x_b)`` (in modules) and ``pressure_angle`` the standard
    (normal) pressure angle, 20 degrees unless given; only the assembly conditions of planetary
    sets read them (:func:`gearlib.assembly_conditions`). ``carrier`` is filled in by
    :class:`Mechanism` when left out.
    """

    gears: tuple
    teeth: tuple[int, int] | None = None
    ratio: sympy.Expr | None = None
    carrier: int | str | None = None
    kind: str = "external"
    angles: tuple | None = None
    radii: tuple[float, float] | None = None
    name: str | None = None
    module: float | None = None
    normal_module: float | None = None
    helix_angle: sympy.Expr | None = None
    profile_shift: tuple[float, float] | None = None
    pressure_angle: sympy.Expr | None = None

    def __post_init__(self):
        a, b = _pair_of(self.gears, "gear pair", "gears")
        where = f"gear pair ({a}, {b})"
        a, b = parse_link_id(a, where), parse_link_id(b, where)
        object.__setattr__(self, "gears", (a, b))
        if a == b:
            raise SelfMeshError(f"{where} meshes gear {a} with itself; a gear pair needs two different links")
        if not isinstance(self.kind, str) or self.kind not in GEAR_KINDS:
            raise DataFormatError(f"{where}: type must be one of {', '.join(GEAR_KINDS)}, got {self.kind!r}")
        if self.teeth is not None:
            ta, tb = _pair_of(self.teeth, where, "teeth")
            object.__setattr__(
                self, "teeth", (parse_teeth(ta, f"{where}, gear {a}"), parse_teeth(tb, f"{where}, gear {b}"))
            )
        if self.ratio is not None:
            r = parse_expr(self.ratio, f"{where} ratio")
            if r == 0:
                raise DataFormatError(f"{where}: ratio must not be zero")
            object.__setattr__(self, "ratio", r)
        if self.angles is not None:
            th = _pair_of(self.angles, where, "angles")
            fresh = not all(isinstance(t, sympy.Basic) for t in th)  # not yet read (a copy warns no more)
            th = tuple(parse_real_expr(t, f"{where} angle") for t in th)
            object.__setattr__(self, "angles", th)
            if self.teeth is None:
                raise DataFormatError(f"{where}: `angles` (Penaud's complex weights) need `teeth` as well")
            if self.kind != "bevel" and fresh:
                _check_spur_angles(where, self.kind, th)
        if self.radii is not None:
            ra, rb = _pair_of(self.radii, where, "radii")
            object.__setattr__(
                self, "radii", (parse_positive(ra, f"{where} radius of {a}"), parse_positive(rb, f"{where} radius of {b}"))
            )
        object.__setattr__(self, "name", _text(self.name, where, "name"))
        if self.carrier is not None:
            c = parse_link_id(self.carrier, where)
            object.__setattr__(self, "carrier", c)
            if c in (a, b):
                raise CarrierError(f"{where}: the carrier must be a third link, not gear {c} itself")
        if self.teeth is None and self.ratio is None:
            raise DataFormatError(f"{where}: give `teeth: [N_{a}, N_{b}]` or a gear `ratio`")
        self._check_module(where)
        if self.kind == "bevel" and self.ratio is None and self.angles is None:
            raise DataFormatError(
                f"{where}: a bevel pair needs Penaud's `angles: [theta_{a}, theta_{b}]` or a signed `ratio`; "
                "the sign of a bevel ratio depends on the chosen axis directions"
            )
        self._check_ratio_agrees(where)

    def _check_module(self, where):
        if self.module is not None and self.normal_module is not None:
            raise DataFormatError(f"{where}: give `module` (transverse) or `normal_module` with `helix_angle`, not both")
        if self.helix_angle is not None and self.normal_module is None:
            raise DataFormatError(f"{where}: a `helix_angle` goes with the `normal_module` of a helical pair")
        for attr in ("module", "normal_module"):
            if getattr(self, attr) is not None:
                object.__setattr__(self, attr, parse_positive(getattr(self, attr), f"{where} {attr}"))
        if self.helix_angle is not None:
            beta = parse_real_expr(self.helix_angle, f"{where} helix_angle")
            if not 0 <= float(beta) < float(sympy.pi / 2):
                raise DataFormatError(
                    f"{where}: helix_angle {self.helix_angle!r} must be at least 0 and under 90 degrees; "
                    "write degrees as 20*deg")
            object.__setattr__(self, "helix_angle", beta)
        if self.profile_shift is not None:
            xa, xb = _pair_of(self.profile_shift, where, "profile_shift")
            shifts = tuple(parse_real(x, f"{where} profile_shift") for x in (xa, xb))
            if any(abs(x) > 2 for x in shifts):
                raise DataFormatError(f"{where}: profile_shift {list(shifts)} are coefficients in modules "
                                      "(typically between -1 and 1); each must lie within [-2, 2]")
            if self.teeth is None:
                raise DataFormatError(f"{where}: a profile_shift needs `teeth`")
            object.__setattr__(self, "profile_shift", shifts)
        if self.pressure_angle is not None:
            alpha = parse_real_expr(self.pressure_angle, f"{where} pressure_angle")
            if not 0 < float(alpha) < float(sympy.pi / 4):
                raise DataFormatError(f"{where}: pressure_angle {self.pressure_angle!r} must be between 0 and 45 "
                                      "degrees; write degrees as 20*deg")
            object.__setattr__(self, "pressure_angle", alpha)
        if (self.module is not None or self.normal_module is not None) and self.teeth is None:
            raise DataFormatError(f"{where}: a module gives pitch radii only with `teeth`")
        if self.radii is not None and self.transverse_module is not None:
            from_module = tuple(self.transverse_module * n / 2 for n in self.teeth)
            if any(abs(r - m) > 1e-9 * max(r, m) for r, m in zip(self.radii, from_module)):
                raise DataFormatError(
                    f"{where}: radii {list(self.radii)} disagree with module and teeth, which give "
                    f"{[round(r, 6) for r in from_module]}; give one of them")

    @property
    def transverse_module(self) -> float | None:
        """The transverse module: ``module``, or ``normal_module / cos(helix_angle)``; None if neither."""
        if self.module is not None:
            return self.module
        if self.normal_module is not None:
            beta = 0.0 if self.helix_angle is None else float(self.helix_angle)
            return self.normal_module / float(sympy.cos(beta))
        return None

    @property
    def pitch_radii(self) -> tuple[float, float] | None:
        """Pitch radii: ``radii``, or the transverse module times the teeth over 2; None when
        the data give neither."""
        if self.radii is not None:
            return self.radii
        m = self.transverse_module
        if m is None:
            return None
        return (m * self.teeth[0] / 2, m * self.teeth[1] / 2)

    def _teeth_ratio(self):
        a_n, b_n = self.teeth
        if self.angles is not None:
            ta, tb = self.angles
            return sympy.nsimplify(-sympy.Rational(a_n, b_n) * sympy.exp(sympy.I * (ta - tb)))
        sign = -1 if self.kind == "external" else 1
        return sympy.Rational(sign * a_n, b_n)

    def _check_ratio_agrees(self, where):
        if self.teeth is None or self.ratio is None or self.ratio.free_symbols:
            return
        if self.kind == "bevel" and self.angles is None:
            ok = sympy.simplify(abs(self.ratio) - sympy.Rational(*self.teeth)) == 0
        else:
            ok = sympy.simplify(self.ratio - self._teeth_ratio()) == 0
        if not ok:
            raise DataFormatError(
                f"{where}: ratio {self.ratio} disagrees with teeth {list(self.teeth)} ({self.kind}); "
                "give one of them, or make them agree"
            )

    @cached_property
    def e(self) -> sympy.Expr:
        """The gear ratio ``e_{a,b} = omega(b/c) / omega(a/c)``, exact (or symbolic)."""
        if self.ratio is not None:
            return self.ratio
        return self._teeth_ratio()

    @cached_property
    def e_value(self) -> complex:
        """The gear ratio as a (complex) floating-point number, for numeric solvers."""
        if self.ratio is None and self.angles is None:
            na, nb = self.teeth
            return complex((-na if self.kind == "external" else na) / nb)
        if self.e.free_symbols:
            raise DataFormatError(f"gear pair {self.label} has a symbolic ratio {self.e}; substitute numbers")
        return complex(sympy.N(self.e, 20))

    @property
    def symbol(self) -> sympy.Symbol:
        """The symbol ``e_a_b`` that stands for this pair's ratio in symbolic analyses."""
        return sympy.Symbol(f"e_{self.gears[0]}_{self.gears[1]}")

    @cached_property
    def weights(self) -> tuple[sympy.Expr, sympy.Expr]:
        """Penaud's table entries ``(T(a, b), T(b, a))``, with ``e = -T(a,b)/T(b,a)``."""
        if self.teeth is not None and (self.ratio is None or self.ratio.free_symbols == set()):
            na, nb = self.teeth
            if self.angles is not None:
                ta, tb = self.angles
                return (na * sympy.exp(sympy.I * ta), nb * sympy.exp(sympy.I * tb))
            if self.kind == "bevel":  # teeth with a signed ratio: keep the magnitudes, carry the sign
                return (sympy.Integer(na), sympy.nsimplify(-na / self.e))
            return (sympy.Integer(na), sympy.Integer(nb if self.kind == "external" else -nb))
        return (-self.e, sympy.Integer(1))

    @property
    def label(self) -> str:
        a, b = self.gears
        return f"({a}, {b})"

    @classmethod
    def from_data(cls, data, where: str = "gear pair") -> GearPair:
        if isinstance(data, GearPair):
            return data
        if type(data) is not dict and not isinstance(data, Mapping):
            raise DataFormatError(f"{where}: expected a mapping such as {{gears: [1, 2], teeth: [20, 40]}}, got {data!r}")
        fields = ("gears", "teeth", "ratio", "carrier", "type", "kind", "angles", "radii", "name", "module",
                  "normal_module", "helix_angle", "profile_shift", "pressure_angle")
        _check_keys(data, fields, where)
        if "gears" not in data:
            raise DataFormatError(f"{where}: missing `gears: [a, b]`")
        kw = {k: v for k, v in data.items() if k not in ("type", "kind")}
        if "type" in data and "kind" in data and data["type"] != data["kind"]:
            raise DataFormatError(f"{where}: `type: {data['type']}` and `kind: {data['kind']}` disagree; give one")
        kind = data.get("type", data.get("kind", "external"))
        return cls(kind=kind, **kw)

    def to_data(self) -> dict:
        out: dict = {"gears": list(self.gears)}
        if self.teeth is not None:
            out["teeth"] = list(self.teeth)
        if self.ratio is not None:
            out["ratio"] = expr_to_data(self.ratio)
        if self.kind != "external":
            out["type"] = self.kind
        if self.angles is not None:
            out["angles"] = [expr_to_data(t) for t in self.angles]
        if self.radii is not None:
            out["radii"] = list(self.radii)
        if self.carrier is not None:
            out["carrier"] = self.carrier
        if self.name:
            out["name"] = self.name
        if self.module is not None:
            out["module"] = self.module
        if self.normal_module is not None:
            out["normal_module"] = self.normal_module
        if self.helix_angle is not None:
            out["helix_angle"] = expr_to_data(self.helix_angle)
        if self.profile_shift is not None:
            out["profile_shift"] = list(self.profile_shift)
        if self.pressure_angle is not None:
            out["pressure_angle"] = expr_to_data(self.pressure_angle)
        return out
