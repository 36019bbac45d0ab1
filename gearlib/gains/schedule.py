"""The shift table of a transmission given as data: every gear of its schedule, and every
combination of its shift elements.

A transmission file names its brakes and clutches (``shift_elements``) and its gears
(``schedule``, each a set of engaged elements; see :mod:`gearlib.mechanism.shifting`).
:func:`~gearlib.gains.schedule_table` (``gl.shift_table(mech)``) computes, for each gear:

* the exact speed ratio ``omega_out / omega_in`` and the *transmission ratio*
  ``i = omega_in / omega_out`` that makers print, the step ``i_k / i_{k+1}`` to the next forward
  gear, and the spread ``i_first / i_last`` of the forward gears;
* every link's speed and the slip speed of every open element (a brake slips at its link's
  speed, a clutch at the difference of its two links' speeds): which element drags how fast;
* the efficiency by Davies' method (:func:`gearlib.davies.efficiency`), the torque each engaged
  element carries, and the power flow of every mesh: its rolling (carrier-relative) power, which
  fixes its loss, and its real power (contact force times pitch-line speed, in the frame), which
  exceeds the input power where power circulates;

and it classifies every combination of ``k`` elements with exact rank tests on the Willis
equations (fractions, no rounding): a **gear** (one degree of freedom, the input drives the
output), a **tie-up** (the input cannot turn: the elements lock it), **output held** (one degree
of freedom, but the elements hold the output while the input turns idle), **under-constrained**
(more than one degree of freedom: the output is not determined) or **over-constrained** (an
element adds no constraint: it is redundant and carries an undetermined torque).

>>> import gearlib as gl
>>> table = gl.shift_table(gl.catalog.load("zf_8hp70"))
>>> [(g.name, round(float(g.i), 4)) for g in table.gears][:3]
[('1st', 4.6957), ('2nd', 3.1304), ('3rd', 2.1039)]
>>> [(c.label, c.kind) for c in table.combinations if c.kind != "gear"]
[('A+C+E', 'tie-up')]
"""

from __future__ import annotations

from dataclasses import dataclass, field
from itertools import combinations as _subsets

from .._common.linalg import FRACTIONS, Echelon, domain_for
from .._common.parse import to_fraction
from ..errors import ConstraintError, GearlibError, InputError
from ..mechanism.assembly import check_assembly
from ..mechanism.data import Mechanism
from ..mechanism.kinematics import speeds
from ..mechanism._accept import takes_mechanism

__all__ = ["GearResult", "MeshPower", "Combination", "ScheduleTable", "schedule_table", "classify", "KINDS"]

KINDS = ("gear", "tie-up", "output held", "under-constrained", "over-constrained")
"""The classes of a combination of shift elements (see the module documentation)."""


@dataclass(frozen=True)
class MeshPower:
    """The power flow of one mesh in one gear, per unit input power: ``rolling`` (measured from
    the carrier: what the mesh's friction acts on), ``real`` (measured from the frame) and the
    ``loss``; ``circulating`` when the real power exceeds the input power."""

    gears: tuple
    carrier: object
    driver: object
    rolling: float
    real: float
    loss: float

    @property
    def circulating(self) -> bool:
        return abs(self.real) > 1 + 1e-9


@dataclass(frozen=True)
class GearResult:
    """One gear of the schedule (see the module documentation)."""

    name: str
    engaged: tuple
    held: tuple
    joined: tuple
    ratio: object
    step: object
    speeds: dict
    slips: dict
    efficiency: float | None
    element_torques: dict = field(default_factory=dict)
    meshes: tuple = ()
    notes: tuple = ()

    @property
    def i(self):
        """The transmission ratio ``omega_in / omega_out`` (the makers' number, 4.696 for a first gear)."""
        return 1 / self.ratio

    @property
    def circulating(self) -> tuple:
        """The meshes whose real power exceeds the input power."""
        return tuple(m.gears for m in self.meshes if m.circulating)


@dataclass(frozen=True)
class Combination:
    """One combination of engaged elements, classified (:data:`~gearlib.gains.schedule.KINDS`)."""

    elements: tuple
    kind: str
    dof: int
    ratio: object = None
    gear: str | None = None
    note: str = ""

    @property
    def label(self) -> str:
        return "+".join(self.elements) if self.elements else "(none)"


def _field_and_ratios(mech):
    es = [gp.e for gp in mech.gear_pairs]
    fr = [to_fraction(e) for e in es]
    if all(f is not None for f in fr):
        return FRACTIONS, fr
    return domain_for(es)


class _Kinematics:
    """The Willis rows of a mechanism with its ground, reduced once; a combination of elements
    adds its rows to a copy."""

    def __init__(self, mech: Mechanism, ground, input, output):
        self.mech = mech
        self.ix = mech.index
        self.n = len(mech.link_ids)
        self.field, ratios = _field_and_ratios(mech)
        f = self.field
        self.base = Echelon(f)
        for gp, e in zip(mech.gear_pairs, ratios):
            a, b = (self.ix[g] for g in gp.gears)
            c = self.ix[gp.carrier]
            row = {b: f.convert(1)}
            row[a] = row.get(a, f.zero) - e
            row[c] = row.get(c, f.zero) + (e - f.convert(1))
            self.base.add(row, 0, ("gear", gp.gears))
        self.ground, self.input, self.output = (self.ix[x] for x in (ground, input, output))
        self.base.add({self.ground: 1}, 0, ("ground",))

    def _copy(self) -> Echelon:
        e = Echelon(self.field)
        e.pivots = dict(self.base.pivots)
        e.order = list(self.base.order)
        e.tags = list(self.base.tags)
        return e

    def rows(self, element):
        if element.kind == "brake":
            return {self.ix[element.links[0]]: 1}
        u, v = (self.ix[x] for x in element.links)
        return {u: 1, v: -1}

    def classify(self, elements) -> Combination:
        ech = self._copy()
        redundant = [el.name for el in elements if not ech.add(self.rows(el), 0, el.name)]
        dof = self.n - ech.rank
        names = tuple(el.name for el in elements)
        locked = not ech.reduce({self.input: 1}, 0)[0]
        if locked:
            return Combination(names, "tie-up", dof, note="the input cannot turn")
        if redundant:
            return Combination(names, "over-constrained", dof,
                               note=f"{', '.join(redundant)} adds no constraint (an undetermined torque)")
        if dof > 1:
            return Combination(names, "under-constrained", dof, note=f"{dof} degrees of freedom: the output is free")
        ech.add({self.input: 1}, 1, ("input",))
        w = ech.solve(self.n)
        ratio = w[self.output]
        if self.field.is_zero(ratio):
            return Combination(names, "output held", dof, note="the input turns idle, the output is held")
        if self.field is not FRACTIONS:
            ratio = self.field.to_sympy(ratio)
        return Combination(names, "gear", dof, ratio)


def classify(mech: Mechanism, k=None, *, ground=None, input=None, output=None) -> tuple:
    """Every combination of *k* shift elements of *mech*, classified (:class:`Combination`).
    *k* is a number, a list of numbers, or None for the number of elements the schedule's gears
    engage."""
    ground, input, output = _ports(mech, ground, input, output)
    kin = _Kinematics(mech, ground, input, output)
    elements = mech.shift_elements
    if not elements:
        raise InputError(f"{mech.name!r} has no shift_elements to combine; declare its brakes and clutches")
    if k is None:
        k = sorted({len(g.engaged) for g in mech.schedule}) or [1]
    ks = [k] if isinstance(k, int) and not isinstance(k, bool) else list(k)
    for n in ks:
        if isinstance(n, bool) or not isinstance(n, int) or not 0 <= n <= len(elements):
            raise InputError(f"k = {n!r}: choose a number of engaged elements from 0 to {len(elements)}")
    gears = {frozenset(g.engaged): g.name for g in mech.schedule}
    out = []
    for n in ks:
        for combo in _subsets(elements, n):
            c = kin.classify(combo)
            name = gears.get(frozenset(c.elements))
            if name is not None:
                c = Combination(c.elements, c.kind, c.dof, c.ratio, name, c.note)
            out.append(c)
    return tuple(out)


def _ports(mech, ground, input, output):
    ground = mech.ground if ground is None else ground
    if ground is None:
        raise InputError(f"{mech.name!r} has no ground: give ground= (the housing)")
    if input is None:
        if not mech.inputs:
            raise InputError(f"{mech.name!r} has no input: give input= or `inputs` in the file")
        input = mech.inputs[0]
    output = mech.output if output is None else output
    if output is None:
        raise InputError(f"{mech.name!r} has no output: give output= or `output` in the file (the output shaft)")
    return (mech.resolve(ground, "ground"), mech.resolve(input, "input"), mech.resolve(output, "output"))


def _gear(mech, state, ground, input, output, eta, efficiency: bool):
    cons = state.constraints(mech.shift_elements)
    held, joined = tuple(cons["held"]), tuple(tuple(p) for p in cons["joined"])
    try:
        sol = speeds(mech, ground, {input: 1}, held=held, joined=joined)
    except GearlibError as err:
        raise ConstraintError(f"gear {state.name!r} ({'+'.join(state.engaged)}) is not a gear: {err}") from None
    ratio = sol.relative(output, ground)
    if ratio == 0:
        raise ConstraintError(f"gear {state.name!r} ({'+'.join(state.engaged)}) holds the output; check the schedule")
    w = dict(sol.items())
    slips = {}
    for el in mech.shift_elements:
        if el.name in state.engaged:
            continue
        slips[el.name] = w[el.links[0]] if el.kind == "brake" else w[el.links[0]] - w[el.links[1]]
    value, torques, meshes, notes = None, {}, (), ()
    if efficiency:
        value, torques, meshes, notes = _rate(mech, ground, input, output, held, joined, eta)
    return GearResult(state.name, state.engaged, held, joined, ratio, None, w, slips, value, torques, meshes, notes)


def _rate(mech, ground, input, output, held, joined, eta):
    from ..davies.overall import efficiency
    from ..davies.power import power_flow

    try:
        res = efficiency(mech, ground, input, output, eta=eta, held=held, joined=joined)
    except GearlibError as err:
        return None, {}, (), (f"efficiency not rated: {err}",)
    net, mo, act = res.network, res.motions, res.actions
    p_in = float(res.input_power)
    meshes = []
    for m, c in zip(res.meshes, net.meshes):
        tail, head = power_flow(mo, act, c.name, ground)
        real = max(float(tail), float(head), key=abs) / p_in
        meshes.append(MeshPower(m.gears, m.carrier, m.driver, abs(float(m.virtual_power)),
                                real, 0.0 - float(m.loss) / p_in))
    torques = {}
    t_in = float(act.magnitude(next(v.name for v in net.action_vars if v.role == "input")))
    for el in mech.shift_elements:
        c = _element_coupling(net, el)
        if c is None:
            continue
        var = next((v for v in net.action_vars if v.coupling == c.name and v.role == "reaction"), None)
        if var is not None:
            torques[el.name] = abs(float(act.magnitude(var.name))) / abs(t_in)
    notes = tuple(n for n in res.notes if "not roll" not in n)  # the mesh rows say so
    return float(res.value), torques, tuple(meshes), notes


def _element_coupling(net, el):
    links = set(el.links) | ({net.ground} if el.kind == "brake" else set())
    for c in net.couplings:
        if c.locked and {c.tail, c.head} == links:
            return c
    return None


@dataclass(frozen=True, eq=False)
class ScheduleTable:
    """The shift table of a transmission (see the module documentation): ``gears`` in schedule
    order, the ``spread``, and the classified ``combinations``."""

    mechanism: Mechanism
    ground: object
    input: object
    output: object
    gears: tuple
    combinations: tuple
    eta: object
    spread: object = None
    rated: bool = True

    @property
    def eta_text(self) -> str:
        """The ordinary efficiencies used, in words (the defaults are stated, never silent)."""
        from ..davies.overall import GLOVER

        if not self.rated:
            return "no efficiencies (kinematics only)"
        if self.eta is None:
            return (f"Glover's defaults: {GLOVER['external']} per external mesh, {GLOVER['internal']} per internal "
                    "mesh")
        if isinstance(self.eta, dict):
            return "per mesh: " + ", ".join(f"{k}: {v}" for k, v in self.eta.items())
        return f"{self.eta} per mesh"

    def gear(self, name) -> GearResult:
        for g in self.gears:
            if g.name == str(name):
                return g
        raise InputError(f"no gear {name!r}; gears are {', '.join(g.name for g in self.gears)}")

    def to_json(self) -> dict:
        from ._schedule_format import to_json

        return to_json(self)

    def to_csv(self, table: str = "gears") -> str:
        from ._schedule_format import to_csv

        return to_csv(self, table)

    def __str__(self) -> str:
        from ._schedule_format import to_text

        return to_text(self)

    def _repr_html_(self) -> str:
        from ._schedule_format import to_html

        return to_html(self)

    def plot(self, ax=None, **kwargs):
        """The slip of every open element in every gear (:func:`gearlib.gains.plot_shift_table`)."""
        from .drawing import plot_shift_table

        return plot_shift_table(self, ax=ax, **kwargs)


@takes_mechanism
def schedule_table(mech: Mechanism, *, eta=None, k=None, efficiency: bool = True, ground=None, input=None,
                   output=None) -> ScheduleTable:
    """The shift table of *mech*'s schedule (see the module documentation).

    Parameters
    ----------
    eta : ordinary efficiencies for :func:`gearlib.davies.efficiency`: one number, or
        ``{(a, b): value}`` per gear pair; default Glover's 0.98 (external) and 0.99 (internal).
    k : the number(s) of engaged elements to classify; default the schedule's.
    efficiency : False to skip the efficiencies (kinematics only).
    ground, input, output : default the file's ``ground``, first ``inputs`` entry and ``output``.
    """
    if not mech.schedule:
        raise InputError(f"{mech.name!r} has no schedule: declare `shift_elements` and `schedule`, "
                         "or give operating modes (gl.shift_table(mech, modes))")
    check_assembly(mech, stacklevel=3)
    ground, input, output = _ports(mech, ground, input, output)
    gears = [_gear(mech, g, ground, input, output, eta, efficiency) for g in mech.schedule]
    forward = [g for g in gears if _positive(g.ratio)]
    steps = {a.name: a.i / b.i for a, b in zip(forward, forward[1:])}
    gears = [GearResult(g.name, g.engaged, g.held, g.joined, g.ratio, steps.get(g.name), g.speeds, g.slips,
                        g.efficiency, g.element_torques, g.meshes, g.notes) for g in gears]
    spread = None
    if len(forward) > 1:
        i = [g.i for g in forward]
        spread = max(i) / min(i)
    combos = classify(mech, k, ground=ground, input=input, output=output)
    return ScheduleTable(mech, ground, input, output, tuple(gears), combos, eta, spread, efficiency)


def _positive(x) -> bool:
    try:
        return float(x) > 0
    except TypeError:
        return False

