"""Answers that are a mechanism: :class:`Model`, checked by kinematic equivalence.

The reader models a mechanism from a sketch or a description into data (a
:class:`~gearlib.Mechanism`, the dict of :meth:`~gearlib.Mechanism.from_dict`, or YAML text),
naming the links by the roles the exercise gives (``"sun"``, ``"carrier"``, ...) either as
link names or with a separate ``{role: link id}`` map. The check drives the model and the
reference in each :class:`Scenario` (a role held, roles driven) and compares the speed of
every role: link ids, their order and the order of the pairs are the reader's choice.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from ._choice import normalise
from ._compare import numeric
from ._spec import Spec, Verdict
from ._read import Unreadable

__all__ = ["Model", "Scenario"]

MAX_TEXT = 20_000
MAX_NODES = 5_000


@dataclass(frozen=True)
class Scenario:
    """One way to drive the mechanism: the role held and ``{role: speed}`` of the inputs."""

    ground: str
    inputs: Mapping = field(default_factory=dict)


def _bounded_data(data, budget=None, seen=None):
    """Refuse data with shared parts (YAML aliases) or too many nodes."""
    budget = budget if budget is not None else [MAX_NODES]
    seen = seen if seen is not None else set()
    if isinstance(data, (dict, list, tuple)):
        if id(data) in seen:
            raise Unreadable("the data repeat a part by reference (a YAML alias): write each element out")
        seen.add(id(data))
        items = list(data.items()) if isinstance(data, dict) else list(enumerate(data))
        budget[0] -= len(items) + 1
        if budget[0] < 0:
            raise Unreadable("the data are far larger than this mechanism needs")
        for k, v in items:
            _bounded_data(k, budget, seen)
            _bounded_data(v, budget, seen)
    return data


def _mechanism(data):
    from ..errors import GearlibError
    from ..mechanism.data import Mechanism
    from ..mechanism.io import loads

    roles = None
    if isinstance(data, tuple) and len(data) == 2 and isinstance(data[1], Mapping):
        data, roles = data
    try:
        if isinstance(data, Mechanism):
            mech = data
        elif isinstance(data, str):
            if len(data) > MAX_TEXT:
                raise Unreadable("the text is far longer than this mechanism needs")
            from .._common.files import parse_text

            try:
                parsed = parse_text(data, "your data")
            except GearlibError:
                parsed = None  # loads() below says what is wrong
            if isinstance(parsed, dict):
                _bounded_data(parsed)
            mech = loads(data, where="your data")
        elif isinstance(data, Mapping):
            data = dict(_bounded_data(dict(data)))
            if roles is None and isinstance(data.get("roles"), Mapping):
                roles = data.pop("roles")
            mech = Mechanism.from_dict(data)
        elif data is None:
            raise Unreadable("no answer yet: replace `None` with your mechanism (a dict as in gl.Mechanism.from_dict)")
        else:
            raise Unreadable("give a mechanism: a gl.Mechanism, the dict of gl.Mechanism.from_dict, or YAML text")
    except GearlibError as err:
        raise Unreadable(f"your data: {err}") from None
    return mech, roles


class Model(Spec):
    """A mechanism modelled by the reader, compared with the reference one by its speeds.

    ``roles``: the names the exercise gives the links; ``scenarios``: how to drive both
    (:class:`Scenario`); ``compare``: the roles whose speeds must agree (all by default). The
    reference function returns a :class:`~gearlib.Mechanism` whose links are named by the
    roles (or ``(mechanism, {role: link id})``).
    """

    def __init__(self, roles, scenarios, *, compare=None, max_links: int = 40):
        self.roles = tuple(roles)
        self.scenarios = tuple(scenarios)
        self.compare = tuple(compare or roles)
        self.max_links = max_links
        self.form = ("a gl.Mechanism (or its dict, or YAML text) whose links are named " +
                     ", ".join(repr(r) for r in self.roles) + ", or (mechanism, {role: link id})")

    def _roles(self, mech, roles) -> dict:
        if roles is not None:
            out = {}
            for k, v in roles.items():
                key = next((r for r in self.roles if normalise(r) == normalise(str(k))), None)
                if key is None:
                    raise Unreadable(f"{k!r} is not a role of this exercise; the roles are {', '.join(self.roles)}")
                try:
                    out[key] = mech.resolve(v)
                except Exception:
                    raise Unreadable(f"the role {key!r} names link {v!r}, which your mechanism does not have") from None
        else:
            out = {}
            for link in mech.links:
                if link.name is None:
                    continue
                key = next((r for r in self.roles if normalise(r) == normalise(link.name)), None)
                if key is not None:
                    if key in out:
                        raise Unreadable(f"two links are named {key!r}; name each role once")
                    out[key] = link.id
        missing = [r for r in self.roles if r not in out]
        if missing:
            raise Unreadable("name the links by their roles (as link names, or with a {role: link} map); missing: "
                             + ", ".join(missing))
        return out

    def _speeds(self, mech, roles, scenario):
        from ..mechanism.kinematics import speeds
        from ..mechanism.mobility import dof

        ground = roles[scenario.ground]
        f = dof(mech, ground).rank
        sol = speeds(mech, ground=ground, inputs={roles[r]: v for r, v in scenario.inputs.items()})
        return f, {r: numeric(sol[roles[r]]) for r in self.compare}

    def check_form(self, answer) -> None:
        mech, roles = _mechanism(answer)
        if len(mech.links) > self.max_links:
            raise Unreadable(f"your mechanism has {len(mech.links)} links, far more than this one needs")
        self._roles(mech, roles)

    def prepare(self, reference):
        mech, roles = reference if isinstance(reference, tuple) else (reference, None)
        roles = self._roles(mech, roles)
        return {"mech": mech, "roles": roles, "runs": [self._speeds(mech, roles, s) for s in self.scenarios]}

    def example(self, reference, params):
        return (reference["mech"], dict(reference["roles"]))

    def judge(self, answer, reference, params) -> Verdict:
        from ..errors import GearlibError

        mech, roles = _mechanism(answer)
        if len(mech.links) > self.max_links:
            raise Unreadable(f"your mechanism has {len(mech.links)} links, far more than this one needs")
        roles = self._roles(mech, roles)
        for scenario, (f_ref, ref) in zip(self.scenarios, reference["runs"]):
            held = f"the {scenario.ground} held"
            try:
                f, got = self._speeds(mech, roles, scenario)
            except GearlibError as err:
                from ..mechanism.mobility import dof

                try:
                    f = dof(mech, roles[scenario.ground]).rank
                except GearlibError:
                    f = None
                if f is not None and f != f_ref:
                    return Verdict(False, _dof_message(held, f))
                return Verdict(False, f"With {held}, your model cannot be driven as the exercise says: {err}")
            if f != f_ref:
                return Verdict(False, _dof_message(held, f))
            for role in self.compare:
                a, e = got[role], ref[role]
                if abs(a - e) <= 1e-9 * max(1.0, abs(e)):
                    continue
                drive = " and ".join(scenario.inputs)
                if abs(a + e) <= 1e-9 * max(1.0, abs(e)):
                    return Verdict(False, f"With {held} and the {drive} driven, the {role} turns the wrong way: check "
                                   "the type (internal or external) of each gear pair on its path")
                if e and abs(a * e - 1) <= 1e-9 or (a and abs(1 / a - e) <= 1e-9 * max(1.0, abs(e))):
                    return Verdict(False, f"With {held}, the {role} turns at the reciprocal speed: check the order "
                                   "of the teeth in each gear pair (teeth follow the order of the gears)")
                return Verdict(False, f"With {held} and the {drive} driven, the {role} turns at another speed than "
                               "in the mechanism described: check the gear pairs on its path, their teeth, and which "
                               "link carries each planet (turning pairs and axis labels)")
        return Verdict(True, "Well done: your model moves like the mechanism described", 1.0)


def _dof_message(held: str, f) -> str:
    return (f"With {held} your model has {f} degree{'s' if f != 1 else ''} of freedom, not the number of the "
            "mechanism described: look for a gear pair or a turning pair that is missing, extra, or on the wrong "
            "link")
