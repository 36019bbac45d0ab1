"""Trains with more than one degree of freedom, rated at an operating point.

A differential (power in at the carrier, out at two side gears) or a power-split device (an
engine and a motor in, the wheels out) has two degrees of freedom: its efficiency depends on
how it is run. An **operating point** fixes it: the speeds of as many ports as the train has
freedoms, and the torques of the other ports (one, for a two-dof train with three ports).
:func:`~gearlib.davies.operating_point` then runs Davies' method as :func:`gearlib.davies.efficiency` does for
one freedom: the motions from the given speeds, the lossless actions from the given torques,
each mesh's driver from its carrier-relative power, its ordinary efficiency turned into a
Coulomb coefficient, and the actions again with friction. It returns the power at every port
(positive where power enters), the loss in every mesh, and the efficiency

    eta = (power out, summed over the ports where it leaves) / (power in, summed where it enters).

Torques are those the outside applies to each port link, about its axis (the sign of the
link's speed); a torque that opposes the port's speed takes power out.

>>> import gearlib as gl
>>> diff = gl.catalog.load("cyl_standard_differential")   # pinion 1, side gears 2 and 3, housing 0
>>> op = gl.davies.operating_point(diff, 0, speeds={2: 26, 3: 30}, torques={1: -10}, eta=0.98)
>>> [(p.link, round(p.power, 3)) for p in op.ports]       # the pinion's 1400 in, out at both wheels
[(2, -649.867), (3, -720.153), (1, 1400.0)]
>>> round(op.efficiency, 6)
0.978586
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ConstraintError, GeometryError, InputError
from . import _solve
from .coupling_network import network as make_network
from .motion import Motions
from ._eta import check_eta
from .overall import GLOVER, _mesh_zetas, _zeta_spec
from .power import column_powers, coupling_powers, mesh_flows
from .statics import actions as solve_actions
from ..mechanism._accept import takes_mechanism

__all__ = ["operating_point", "OperatingPoint", "PortResult", "MeshLoss"]


@dataclass(frozen=True)
class PortResult:
    """One port at the operating point: link, speed (relative to the ground), the torque the
    outside applies, the power (positive: in), and what was given (``"speed"``, ``"torque"``,
    ``"speed and torque"`` or ``""``)."""

    link: object
    speed: float
    torque: float
    power: float
    given: str


@dataclass(frozen=True)
class MeshLoss:
    """One mesh at the operating point: driver and driven gear (carrier-relative), the ordinary
    efficiency used, the rolling (carrier-relative) power and the power lost."""

    coupling: str
    gears: tuple
    carrier: object
    driver: object
    driven: object
    eta: float
    rolling: float
    loss: float


@dataclass(frozen=True)
class OperatingPoint:
    """The result of :func:`~gearlib.davies.operating_point`."""

    network: object
    motions: object
    actions: object
    ports: tuple
    meshes: tuple
    input_power: float
    output_power: float
    efficiency: float
    notes: tuple = ()

    @property
    def loss(self) -> float:
        """The power lost in the meshes (input power minus output power)."""
        return self.input_power - self.output_power

    def port(self, link) -> PortResult:
        link = self.network.mechanism.resolve(link)
        for p in self.ports:
            if p.link == link:
                return p
        raise InputError(f"link {link} is not a port; ports are {', '.join(str(p.link) for p in self.ports)}")

    def to_json(self) -> dict:
        return {"mechanism": self.network.mechanism.name, "ground": str(self.network.ground),
                "efficiency": self.efficiency, "input_power": self.input_power, "output_power": self.output_power,
                "loss": self.loss,
                "ports": [{"link": str(p.link), "speed": p.speed, "torque": p.torque, "power": p.power,
                           "given": p.given} for p in self.ports],
                "meshes": [{"coupling": m.coupling, "gears": [str(g) for g in m.gears], "carrier": str(m.carrier),
                            "driver": str(m.driver), "driven": str(m.driven), "eta": m.eta,
                            "rolling_power": m.rolling, "loss": m.loss} for m in self.meshes],
                "notes": list(self.notes)}

    def __str__(self) -> str:
        net = self.network
        lines = [f"operating point of {net.mechanism.name!r} (ground {net.ground}): efficiency {self.efficiency:.6g} "
                 f"= {self.output_power:.6g} out / {self.input_power:.6g} in",
                 "port  speed       torque      power       given"]
        for p in self.ports:
            lines.append(f"{str(p.link):<5} {p.speed:<11.6g} {p.torque:<11.6g} {p.power:<11.6g} {p.given}")
        lines.append("mesh  gears     carrier  driver->driven  eta_ij    rolling power  loss")
        for m in self.meshes:
            lines.append(f"{m.coupling:<5} {str(m.gears):<9} {str(m.carrier):<8} {f'{m.driver} -> {m.driven}':<15} "
                         f"{m.eta:<9.6g} {m.rolling:<14.6g} {m.loss:.6g}")
        lines += [f"note: {n}" for n in self.notes]
        return "\n".join(lines)

    __repr__ = __str__

    def _repr_html_(self) -> str:
        from .._common.matview import PAD

        def row(cells):
            return "<tr>" + "".join(f"<td style='{PAD}; text-align: center'>{c}</td>" for c in cells) + "</tr>"

        def head(names):
            return "<tr>" + "".join(f"<th style='{PAD}'>{n}</th>" for n in names) + "</tr>"

        rows = "".join(row((p.link, f"{p.speed:.6g}", f"{p.torque:.6g}", f"{p.power:.6g}", p.given))
                       for p in self.ports)
        mrows = "".join(row((m.gears, f"{m.driver} → {m.driven}", f"{m.eta:.6g}", f"{m.rolling:.6g}",
                             f"{m.loss:.6g}")) for m in self.meshes)
        return (f"<p><b>η = {self.efficiency:.6g}</b> ({self.output_power:.6g} out of {self.input_power:.6g} in)</p>"
                f"<table>{head(('port', 'speed', 'torque', 'power', 'given'))}{rows}</table>"
                f"<table>{head(('mesh', 'driver → driven', 'ordinary η', 'rolling power', 'loss'))}{mrows}</table>")


def _values(mech, spec, what) -> dict:
    if not isinstance(spec, dict):
        raise InputError(f"{what} must be a mapping {{link: value}}, got {spec!r}")
    out = {}
    for k, v in spec.items():
        link = mech.resolve(k, what)
        try:
            out[link] = float(v)
        except (TypeError, ValueError):
            raise InputError(f"{what}: the value for link {link} must be a number, got {v!r}") from None
        if not np.isfinite(out[link]):
            raise InputError(f"{what}: the value for link {link} must be finite, got {v!r}")
    return out


@takes_mechanism
def operating_point(mech, ground=None, *, speeds, torques, ports=(), eta=None, zeta=None, held=(), joined=(),
                    check: bool = True, mode: str = "auto", radii=None) -> OperatingPoint:
    """Rate *mech* at an operating point (see the module documentation).

    Parameters
    ----------
    speeds : ``{port link: speed}`` relative to the ground, one per degree of freedom.
    torques : ``{port link: torque}``, the torques the outside applies, one per port beyond the
        degrees of freedom.
    ports : further port links with neither speed nor torque given (their torque follows).
    eta, zeta : ordinary efficiencies (default Glover's 0.98 external, 0.99 internal) or Coulomb
        coefficients of the meshes, as for :func:`gearlib.davies.efficiency`.
    held, joined : brakes and clutches. ``check`` compares the motions with the Willis equations.
    """
    ground = mech.resolve(mech.ground if ground is None else ground, "ground")
    speeds, torques = _values(mech, speeds, "speeds"), _values(mech, torques, "torques")
    order = []
    for link in (*speeds, *torques, *(mech.resolve(p, "port") for p in ports)):
        if link not in order:
            order.append(link)
    if ground in order:
        raise InputError(f"the ground {ground} cannot be a port; a port joins the ground to another link")
    if len(order) < 2:
        raise InputError("an operating point needs two ports or more: give speeds and torques on the shafts")
    net = make_network(mech, ground, order[0], order[1], ports=order[2:], held=held, joined=joined, exact=False,
                       mode=mode, radii=radii)
    check_eta(mech, eta, names=[c.name for c in net.meshes])
    couplings = {c.head: c for c in net.couplings if c.role in ("input", "output", "port")}
    mo = _motions(net, couplings, speeds)
    if check:
        _check(mo, speeds, held, joined)
    tvars = {}
    for link, value in torques.items():
        var = next(v for v in net.action_vars if v.coupling == couplings[link].name and v.role in
                   ("input", "output", "port"))
        tvars[var.name] = value
    if len(tvars) != len(order) - len(speeds):
        raise InputError(f"{len(order)} ports with {len(speeds)} speeds given need {len(order) - len(speeds)} "
                         f"torque(s); got {len(tvars)}")
    try:
        lossless = solve_actions(net, torques=tvars)
    except ConstraintError:
        raise InputError("the torques given do not determine the others: give the torque of another port") from None
    tail = {f.coupling: f.tail_power > 0 for f in mesh_flows(mo, lossless)}
    zeta_given, notes = _zeta_spec(net, zeta), list(net.notes)
    for _ in range(6):
        zetas, used, _ = _mesh_zetas(net, mo, tail, eta, zeta_given, False, False)
        act = solve_actions(net, lossless=False, zeta=zetas, torques=tvars)
        flows = mesh_flows(mo, act)
        new = {f.coupling: f.tail_power > 0 if abs(f.tail_power) > 1e-12 else tail[f.coupling] for f in flows}
        if new == tail:
            break
        notes.append("losses reverse the power flow in mesh "
                     f"{', '.join(c for c in tail if tail[c] != new[c])}; recomputed with the new drivers")
        tail = new
    else:
        raise ConstraintError("the power flow directions do not settle: the train is near self-locking here")
    cpow = column_powers(mo, act)
    results = []
    for link in order:
        c = couplings[link]
        var = next(v for v in net.action_vars if v.coupling == c.name and v.role in ("input", "output", "port"))
        given = " and ".join(w for w, d in (("speed", speeds), ("torque", torques)) if link in d)
        results.append(PortResult(link, float(mo.magnitude(c.name)), float(act.magnitude(var.name)),
                                  float(cpow[var.name]), given))
    powers = coupling_powers(mo, act)
    meshes = []
    for f0, c in zip(mesh_flows(mo, lossless), net.meshes):
        drv, dvn = (c.tail, c.head) if tail[c.name] else (c.head, c.tail)
        rolling = abs(float(f0.tail_power if tail[c.name] else f0.head_power))
        meshes.append(MeshLoss(c.name, c.mesh.gears, c.carrier, drv, dvn, float(used[c.name] if used[c.name]
                               is not None else GLOVER[c.source.kind]), rolling, -float(powers[c.name])))
    p_in = sum(p.power for p in results if p.power > 0)
    p_out = -sum(p.power for p in results if p.power < 0)
    if p_in <= 0:
        raise InputError("no port delivers power at this operating point: check the signs of the torques")
    return OperatingPoint(net, mo, act, tuple(results), tuple(meshes), p_in, p_out, p_out / p_in, tuple(notes))


def _motions(net, couplings, speeds) -> Motions:
    mn = np.array(net.M_N(), dtype=float)
    names = net.motion_names()
    rows, rhs = [], []
    for link, value in speeds.items():
        if link not in couplings:
            raise InputError(f"a speed is given for link {link}, which is not a port")
        row = np.zeros(len(names))
        row[names.index(next(v.name for v in net.motion_vars if v.coupling == couplings[link].name))] = 1
        rows.append(row)
        rhs.append(value)
    free = len(names) - _solve.rank(mn, False)
    if free != len(speeds):
        raise InputError(f"{net.mechanism.name!r} has {free} degree(s) of freedom with link {net.ground} grounded"
                         + (" and the brakes and clutches given" if net.options.get("held") or
                            net.options.get("joined") else "")
                         + f": give {free} port speed(s), got {len(speeds)}")
    a = np.vstack([mn, np.array(rows)])
    b = np.concatenate([np.zeros(mn.shape[0]), np.array(rhs)])
    try:
        values = _solve.solve(a, b, False, "motion analysis")
    except ValueError:
        raise InputError("the port speeds given are not independent: give the speed of another port") from None
    vals = tuple(float(x) for x in values)
    return Motions(net, vals, vals, 1.0)


def _check(mo, speeds, held, joined) -> None:
    from ..mechanism.kinematics import speeds as willis_speeds

    net = mo.network
    sol = willis_speeds(net.mechanism, net.ground, dict(speeds), method="numeric", held=held, joined=joined)
    scale = max(1.0, *(abs(v) for v in speeds.values()))
    for c in net.couplings:
        if c.kind == "mesh" or c.locked:
            continue
        davies, willis = float(mo.magnitude(c.name)), complex(sol.relative(c.head, c.tail)).real
        if abs(davies - willis) > 1e-9 * max(scale, abs(willis)):
            raise GeometryError(
                f"Davies' motions disagree with the Willis equations at coupling {c.name} (link {c.head} relative to "
                f"{c.tail}: {davies:.6g} instead of {willis:.6g}): an axis is placed inconsistently with the gear "
                "ratios; fix the geometry, or pass check=False")
