"""Overall efficiency of a one-degree-of-freedom gear train by Davies' method (Laus's Algorithm 1).

:func:`efficiency` runs the whole method on any train given as data:

1. build the network (couplings, unit screws from the geometry, ``M_N`` and ``A_N``);
2. solve the motions with the input speed as primary variable (checked against Willis);
3. solve the actions *without* losses and take, for every mesh, the virtual power flow
   relative to its carrier: its sign says which gear drives;
4. turn each mesh's ordinary efficiency ``eta_ij`` (``i`` drives ``j``, carrier held) into a
   signed Coulomb coefficient ``zeta`` through the carrier-relative motions (Laus eqs. 72-75);
5. solve the actions *with* the friction torques (and any bearing and viscous losses);
6. ``eta = -P_out / P_in`` from the port torques alone.

Numbers by default; ``symbolic=True`` keeps the ordinary efficiencies (and, with
``radii="symbols"``, the pitch radii) as symbols and returns a closed-form formula.

>>> import gearlib as gl
>>> res = gl.davies.efficiency(gl.catalog.load("laus_epicyclic"), ground=1, input=5, output=2, eta=0.99)
>>> round(res.value, 9)                                   # Laus section 3.4.1.6
0.94620687
>>> [(m.driver, m.driven) for m in res.meshes]
[(1, 3), (3, 2)]
>>> gl.davies.efficiency(gl.catalog.load("laus_epicyclic"), ground=1, input=5, output=2, symbolic=True).formula
-5*eta_1_3*eta_3_2/(9*eta_1_3*eta_3_2 - 14)
"""

from __future__ import annotations

import html
import json
from dataclasses import dataclass, field

import sympy

from .._common.parse import parse_expr
from ..errors import ConstraintError, InputError
from . import _rational, _ringformula
from ._eta import check_eta, check_number
from .motion import Motions, motions as solve_motions
from .coupling_network import Network, network as make_network
from .power import coupling_powers, mesh_flows, mesh_power_ratio
from .statics import Actions, actions as solve_actions, viscous_torque
from ..mechanism._accept import takes_mechanism

__all__ = ["efficiency", "Efficiency", "MeshResult", "GLOVER", "eta_symbol"]

GLOVER = {"external": 0.98, "internal": 0.99, "bevel": 0.98}
"""Glover's typical ordinary efficiencies, used when none are given."""


def eta_symbol(driver, driven) -> sympy.Symbol:
    """The symbol ``eta_i_j`` of the ordinary efficiency of a mesh in which gear *i* drives *j*."""
    return sympy.Symbol(f"eta_{driver}_{driven}", positive=True)


@dataclass(frozen=True)
class MeshResult:
    """One mesh of an efficiency analysis."""

    coupling: str
    gears: tuple
    carrier: object
    driver: object
    driven: object
    eta: object
    zeta: object
    virtual_power: object
    loss: object

    @property
    def recirculation(self):
        """The lossless carrier-relative power through the mesh per unit input power."""
        return self.virtual_power


@dataclass(frozen=True)
class Efficiency:
    """The result of :func:`efficiency`: the overall efficiency and everything behind it."""

    value: object
    network: Network
    motions: Motions
    lossless: Actions
    actions: Actions
    meshes: tuple
    powers: dict
    input_power: object
    output_power: object
    ratio: object
    formula: object = None
    formula_zeta: object = None
    zeta_symbols: dict = field(default_factory=dict)
    notes: tuple = ()

    def __float__(self) -> float:
        return float(self.value)

    def mesh(self, a, b) -> MeshResult:
        """The mesh between gears *a* and *b* (its ``driver`` and ``driven`` are None when it does
        not roll)."""
        for m in self.meshes:
            if set(m.gears) == {a, b}:
                return m
        raise InputError(f"no mesh between {a} and {b}")

    def table(self, digits: int = 6) -> list[tuple]:
        """Rows ``(coupling, gears, carrier, driver -> driven, eta_ij, zeta, virtual power, loss)``."""
        def fmt(x):
            try:
                v = float(x)
            except TypeError:
                return str(x)
            return "0" if abs(v) < 1e-12 else f"{v:.{digits}g}"  # rounding noise of an unloaded mesh
        return [(m.coupling, m.gears, m.carrier, "does not roll" if m.driver is None else f"{m.driver} -> {m.driven}",
                 fmt(m.eta), fmt(m.zeta),
                 fmt(m.virtual_power), fmt(m.loss)) for m in self.meshes]

    def __str__(self) -> str:
        net = self.network
        head = (f"efficiency of {net.mechanism.name!r}, input {net.input}, output {net.output}, ground {net.ground}: "
                f"{_fmt(self.value)}  (speed ratio {_fmt(self.ratio)})")
        lines = [head, "mesh  gears     carrier  driver->driven  eta_ij    zeta       virtual power  loss"]
        for row in self.table():
            c, g, k, d, e, z, v, loss = row
            lines.append(f"{c:<5} {str(g):<9} {str(k):<8} {d:<15} {e:<9} {z:<10} {v:<14} {loss}")
        lines += [f"note: {n}" for n in self.notes]
        return "\n".join(lines)

    __repr__ = __str__

    def _repr_html_(self) -> str:
        from .._common.matview import PAD

        try:
            p_in = float(self.input_power)
        except TypeError:
            p_in = None

        def per_input(x):
            try:
                v = float(x) / p_in
            except (TypeError, ZeroDivisionError):
                return html.escape(str(x))
            return "0" if abs(v) < 1e-12 else f"{v:.6g}"

        def cells(m, row):
            c, g, k, d, e, z, v, _ = row
            return (c, str(g), str(k), d.replace("->", "→"), e, z, v, per_input(m.loss) if m.loss is not None else "")

        rows = "".join("<tr>" + "".join(f"<td style='{PAD}; text-align: center; white-space: nowrap'>{x}</td>"
                                        for x in cells(m, row)) + "</tr>"
                       for m, row in zip(self.meshes, self.table()))
        head = "".join(f"<th style='{PAD}'>{h}</th>" for h in (
            "mesh", "gears", "carrier", "driver → driven", "ordinary η", "ζ (signed)", "virtual power", "loss"))
        key = ("<p style='font-size: 0.85em'>Per mesh: the ordinary efficiency used (the driver's gear "
               "drives, the carrier held); ζ, the signed Coulomb coefficient of the friction torque "
               "T = ζU (a length, in the unit of the radii; its sign follows the coupling's direction); the "
               "virtual power, the lossless power through the mesh seen from its carrier, and the loss, "
               "both per unit input power.</p>")
        notes = "".join(f"<p><i>{html.escape(n)}</i></p>" for n in self.notes)
        return (f"<p><b>η = {_fmt(self.value)}</b> (input {self.network.input}, output {self.network.output}, "
                f"ground {self.network.ground}; speed ratio {_fmt(self.ratio)})</p>"
                f"<table><tr>{head}</tr>{rows}</table>{key}{notes}")

    def to_json(self) -> dict:
        def num(x):
            try:
                return float(x)
            except TypeError:
                return str(x)
        return {
            "efficiency": num(self.value), "ratio": num(self.ratio), "input": str(self.network.input),
            "output": str(self.network.output), "ground": str(self.network.ground),
            "formula": None if self.formula is None else str(self.formula),
            "meshes": [{"coupling": m.coupling, "gears": [str(g) for g in m.gears], "carrier": str(m.carrier),
                        "driver": None if m.driver is None else str(m.driver),
                        "driven": None if m.driven is None else str(m.driven), "eta": num(m.eta), "zeta": num(m.zeta),
                        "virtual_power": num(m.virtual_power), "loss": num(m.loss)} for m in self.meshes],
            "powers": {k: num(v) for k, v in self.powers.items()},
            "notes": list(self.notes),
        }

    def dumps(self) -> str:
        return json.dumps(self.to_json(), indent=2)

    def plot(self, ax=None, **kwargs):
        """The power through every coupling (:func:`gearlib.davies.plot_power_flow`)."""
        from .drawing import plot_power_flow

        return plot_power_flow(self, ax=ax, **kwargs)


def _fmt(x) -> str:
    try:
        return f"{float(x):.6g}"
    except TypeError:
        return str(x)


def _num(x, values):
    if isinstance(x, sympy.Basic):
        return float(x.subs(values)) if x.free_symbols else float(x)
    return float(x)


def _lookup(spec, key_pair, coupling, driver, driven, default):
    if spec is None:
        return default
    if not isinstance(spec, dict):
        return spec
    if (driver, driven) in spec:
        return spec[(driver, driven)]
    for k, v in spec.items():
        if k == coupling or (isinstance(k, (tuple, list)) and set(k) == set(key_pair)):
            return v
    return default


@takes_mechanism
def efficiency(mech, ground=None, input=None, output=None, *, eta=None, zeta=None, bearings=None, viscous=None,
               torque=1, speed=1, symbolic=False, held=(), joined=(), check: bool = True, radii=None,
               mode: str = "auto", axes=None, pitch_points=None, chords=None, layout=None,
               drivers=None) -> Efficiency:
    """Overall efficiency ``-P_out/P_in`` of *mech* driven at *input* and loaded at *output*.

    Parameters
    ----------
    eta : ordinary efficiencies. A number for every mesh, or ``{(a, b): value}`` per gear pair
        (the value applies whichever gear drives; give both ``(a, b)`` and ``(b, a)`` for
        different values in the two directions). Default: Glover's 0.98 (external and bevel)
        and 0.99 (internal), or symbols ``eta_i_j`` when ``symbolic``.
    zeta : ``{(a, b) or coupling: zeta}`` signed Coulomb coefficients of meshes, used instead of
        their ordinary efficiency.
    bearings : ``{coupling or (u, v): zeta}``: Coulomb bearing friction ``-zeta |U| sign(t)``.
    viscous : ``{coupling or (u, v): b or (b, law)}``: viscous torque ``-b g(t)``, law
        ``"linear"`` (default), ``"quadratic"`` or ``"cubic"``.
    torque, speed : the input torque and speed (they matter only with viscous losses).
    symbolic : ``True`` for a formula in symbols, ``"exact"`` for exact numbers.
    held, joined : brakes and clutches. ``check`` compares the motions with Willis.
    radii, mode, axes, pitch_points, chords, layout : passed to :func:`gearlib.davies.network`.
    drivers : ``{(a, b) or coupling: driving gear}`` to impose the power-flow direction of some
        meshes instead of taking it from the lossless analysis (to write the formula of another
        case of the turning conditions).
    """
    exact = bool(symbolic) or radii is not None
    torque, speed = check_number(torque, "torque", exact=exact), check_number(speed, "speed", exact=exact)
    net = make_network(mech, ground, input, output, held=held, joined=joined, bearings=list(bearings or {}),
                       viscous=list(viscous or {}), chords=chords, layout=layout, mode=mode, exact=exact,
                       radii=radii, axes=axes, pitch_points=pitch_points)
    values = dict(net.layout.values)
    check_eta(mech, eta, symbolic=symbolic is True, names=[c.name for c in net.meshes])
    if exact:
        torque, speed = sympy.sympify(torque), sympy.sympify(speed)
    if _num(torque * speed, values) <= 0:
        raise InputError("the input must deliver power: give the input torque and speed the same sign")
    mo = solve_motions(net, speed, check=check)
    lossless = solve_actions(net, torque=torque)
    flows0 = mesh_flows(mo, lossless)
    p_in0 = _port_power(mo, lossless, "input")
    tail = {f.coupling: _num(f.tail_power, values) > 0 for f in flows0}
    for key, drv in (drivers or {}).items():
        c = net.coupling(key) if isinstance(key, str) else net.mesh_coupling(*key)
        drv = net.mechanism.resolve(drv)
        if drv not in (c.tail, c.head):
            raise InputError(f"drivers: gear {drv} is not in mesh {c.name} {c.mesh.gears}")
        tail[c.name] = drv == c.tail
    bearing_z = _bearing_spec(net, bearings)
    visc = _viscous_values(net, mo, viscous)
    notes = list(net.notes)
    zeta_given = _zeta_spec(net, zeta)
    for _ in range(6):
        zetas, used, zsyms = _mesh_zetas(net, mo, tail, eta, zeta_given, symbolic, exact)
        bsigns = _bearing_signs(net, mo, lossless, bearing_z, values)
        act = solve_actions(net, lossless=False, zeta=zsyms if exact else zetas, torque=torque, internal=exact,
                            bearings={k: (z, bsigns[k]) for k, z in bearing_z.items()}, viscous=visc)
        if exact or drivers:
            break
        if -_port_power(mo, act, "output") / _port_power(mo, act, "input") <= 0:
            notes.append("the train self-locks: with these losses the output cannot be driven from this input "
                         "(efficiency <= 0)")
            break
        flows = mesh_flows(mo, act)
        new_tail = {f.coupling: f.tail_power > 0 if abs(f.tail_power) > 1e-15 else tail[f.coupling] for f in flows}
        if new_tail == tail:
            break
        changed = [c for c in tail if tail[c] != new_tail[c]]
        notes.append(f"losses reverse the power flow in mesh {', '.join(changed)}; recomputed with the new drivers")
        tail = new_tail
        lossless = act
    else:
        raise ConstraintError("the power flow directions do not settle: the train is near self-locking")
    (k_in, s_in), (k_out, s_out) = _port_column(mo, act, "input"), _port_column(mo, act, "output")
    p_in, p_out = act.values[k_in] * s_in, act.values[k_out] * s_out
    formula = formula_zeta = None
    if exact:
        subs = {zsyms[c]: zetas[c] for c in zsyms}
        fast = _ringformula.formula(act.values, k_out, k_in, -s_out / s_in, subs)
        if fast is not None:
            formula_zeta, value = fast
        else:
            formula_zeta = _rational.factored(-p_out / p_in)
            value = _rational.substitute(formula_zeta, subs)
        if value.free_symbols:
            formula = value
        zphys = {c: _physical_zeta(zetas[c], _scale(net, c)) for c in zetas}
    else:
        value = -p_out / p_in
        zphys = zetas
    powers = {} if (exact and formula is not None) else coupling_powers(mo, act)
    meshes = []
    still = [c.name for c in net.meshes if not _rolls(mo, c)]
    for f0 in flows0:
        c = f0.coupling
        drv, dvn = (f0.gears if tail[c] else f0.gears[::-1])
        vp = f0.tail_power / p_in0 if tail[c] else f0.head_power / p_in0
        loss = None
        if not (exact and formula is not None):
            loss = powers[c] if not exact else sympy.nsimplify(powers[c], rational=True)
        if c in still:  # rounding noise of a mesh that does not roll: exactly nothing
            drv = dvn = None
            vp, loss = (0, 0) if exact else (0.0, 0.0 if loss is not None else None)
        meshes.append(MeshResult(c, f0.gears, f0.carrier, drv, dvn, used[c], zphys.get(c),
                                 sympy.cancel(vp) if exact else vp, loss))
    if still:
        notes.append(f"mesh{'es' * (len(still) > 1)} {', '.join(still)} do{'es' * (len(still) == 1)} not roll "
                     "(no motion relative to the carrier): no driver and no loss")
        if len(still) == len(net.meshes) and not bearing_z and not visc:
            value = sympy.Integer(1) if exact else 1.0  # a direct drive: nothing dissipates, exactly 1
    ratio = _port_speed(mo, "output") / _port_speed(mo, "input")
    if exact:
        ratio = sympy.cancel(ratio)
        if formula is not None and not (set(formula.free_symbols) - set(values)):
            formula = formula  # numeric radii only enter through the values
    return Efficiency(value, net, mo, lossless, act, tuple(meshes), powers, p_in, p_out, ratio, formula,
                      formula_zeta, zsyms if exact else {}, tuple(notes))


# ------------------------------------------------------------------------------ helpers
def _scale(net, coupling):
    v = next(v for v in net.action_vars if v.coupling == coupling and v.role == "friction")
    return v.scale


def _linear(expr):
    """``(x, a, b)`` when *expr* is ``a x + b`` in one symbol with rational a, b; else None."""
    symbols = expr.free_symbols
    if len(symbols) > 1:
        return None
    x = next(iter(symbols), None)
    terms = expr.as_coefficients_dict()
    if any(k not in (x, sympy.S.One) or not v.is_Rational for k, v in terms.items()):
        return None
    return x, terms.get(x, sympy.S.Zero), terms.get(sympy.S.One, sympy.S.Zero)


def _physical_zeta(z, scale):
    """``cancel(z * scale)`` for a mesh's ``zeta(eta) = (a eta + b) / (c eta + d)``: integer
    coefficients without a common factor, the denominator's leading one positive, the scale
    (a length, possibly a square root) in front. Other forms go to :func:`sympy.cancel`."""
    num, den = z.as_numer_denom()
    n, d = _linear(num), _linear(den)
    if n is None or d is None or (n[0] is not None and d[0] is not None and n[0] != d[0]):
        return sympy.cancel(z * scale)
    x = n[0] if n[0] is not None else d[0]
    if x is None:  # a number (exact efficiencies given)
        return sympy.cancel(z * scale)
    coefs = [n[1], n[2], d[1], d[2]]
    lcm = sympy.ilcm(*[q.q for q in coefs])
    ints = [int(q * lcm) for q in coefs]
    g = sympy.igcd(*ints) or 1
    sign = -1 if (ints[2] < 0 or (ints[2] == 0 and ints[3] < 0)) else 1
    a, b, c, e = (sign * k // g for k in ints)
    return scale * (a * x + b) / (c * x + e)


def _port_column(mo, act, role):
    """``(position of the port's torque among the actions, its screw dotted with the port's
    motion)``: the port's power is the torque times that number."""
    net = mo.network
    c = net.port(role)
    var = next(v for v in net.action_vars if v.coupling == c.name and v.role == role)
    m = mo.screw(c.name)
    return act._col(var.name), sum(var.screw[r] * m[r] for r in range(net.d))


def _port_power(mo, act, role):
    k, s = _port_column(mo, act, role)
    return act.values[k] * s


def _port_speed(mo, role):
    c = mo.network.port(role)
    return mo.magnitude(c.name)


def _mesh_zetas(net, mo, tail, eta, zeta_given, symbolic, exact):
    zetas, used, zsyms = {}, {}, {}
    for c in net.meshes:
        gp = c.source
        drv, dvn = (c.tail, c.head) if tail[c.name] else (c.head, c.tail)
        if exact:
            zsyms[c.name] = sympy.Symbol(f"zeta_{c.name}")
        if not _rolls(mo, c):
            # no motion relative to the carrier: the mesh transmits torque like a locked joint and
            # dissipates nothing, whatever its ordinary efficiency (a direct drive)
            zetas[c.name] = sympy.Integer(0) if exact else 0.0
            used[c.name] = _lookup(eta, gp.gears, c.name, drv, dvn, None if symbolic is True else GLOVER[gp.kind])
            continue
        if c.name in zeta_given:
            z = zeta_given[c.name]
            zetas[c.name] = z / _scale(net, c.name) if exact else z
            eta_of, _ = mesh_power_ratio(mo, c.name, tail_drives=tail[c.name])
            used[c.name] = eta_of(z)
            continue
        default = eta_symbol(drv, dvn) if symbolic is True else GLOVER[gp.kind]
        value = _lookup(eta, gp.gears, c.name, drv, dvn, default)
        if isinstance(value, str):
            value = parse_expr(value, f"ordinary efficiency of mesh {c.name} (gears {gp.gears})")
        if exact:
            value = sympy.nsimplify(value, rational=True) if isinstance(value, float) else sympy.sympify(value)
        elif isinstance(value, sympy.Basic):
            if value.free_symbols:
                raise InputError(f"mesh {c.name}: a symbolic ordinary efficiency {value} needs symbolic=True")
            value = float(value)
        if not exact and not (0 < value <= 1):
            raise InputError(f"mesh {c.name} (gears {gp.gears}): ordinary efficiency {value} must be in (0, 1]")
        # zeta(eta) is linear over linear in eta: cancelled later, once, with its physical scale
        # (_physical_zeta); with radii as symbols too, the general route needs it reduced now
        _, zeta_of = mesh_power_ratio(mo, c.name, tail_drives=tail[c.name], internal=exact, simplify=False)
        z = zeta_of(value)
        zetas[c.name] = sympy.cancel(z) if len(getattr(z, "free_symbols", ())) > 1 else z
        used[c.name] = value
    return zetas, used, zsyms


def _rolls(mo, coupling) -> bool:
    """Whether the gears of a mesh turn relative to its carrier (a mesh that does not roll
    passes torque without loss)."""
    values = mo.network.layout.values
    for x in mo.link(coupling.tail, coupling.carrier):
        try:
            if abs(_num(x, values)) > 1e-12:
                return True
        except TypeError:  # a symbolic motion: assume it rolls
            return True
    return False


def _zeta_spec(net, zeta):
    out = {}
    for key, value in (zeta or {}).items():
        c = net.coupling(key) if isinstance(key, str) else net.mesh_coupling(*key)
        out[c.name] = value
    return out


def _bearing_spec(net, bearings):
    out = {}
    for key, value in (bearings or {}).items():
        name = key if isinstance(key, str) else next(
            c.name for c in net.couplings if {c.tail, c.head} == {net.mechanism.resolve(x) for x in key})
        out[name] = value
    return out


def _bearing_signs(net, mo, lossless, bearing_z, values):
    signs = {}
    for name in bearing_z:
        u = _num(lossless.magnitude(f"U_{name}"), values)
        t = _num(mo.magnitude(name), values)
        s = -(1 if u > 0 else -1 if u < 0 else 1) * (1 if t > 0 else -1 if t < 0 else 1)
        signs[name] = s
    return signs


def _viscous_values(net, mo, viscous):
    out = {}
    for key, spec in (viscous or {}).items():
        if isinstance(key, str):
            c = net.coupling(key)
        else:
            pair = {net.mechanism.resolve(x) for x in key}
            c = next(c for c in net.couplings if {c.tail, c.head} == pair)
        b, law = (spec, "linear") if not isinstance(spec, (tuple, list)) else spec
        var = next(v for v in net.action_vars if v.coupling == c.name and v.role == "viscous")
        out[var.name] = viscous_torque(b, mo.magnitude(c.name), law)
    return out

