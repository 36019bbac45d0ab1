"""How motion propagates through the kinematic units of a mechanism, from inputs to output.

Each kinematic unit has one degree of freedom relative to its carrier, so once the speeds of
two of its links are known (a *local input*: the relative displacement of two of its links),
every other link of the unit follows. Liu, Chen and Chang (2004, Sec. 4) trace this from the
output back to the inputs through the common linkages: a **2-link chain** passes one unit's
local output to the next unit as its local input; a **coaxial triangle** adds two units'
outputs into the local input of a third (eq. 10).

:func:`plan` works this out for any mechanism, any ground, inputs (absolute or relative),
held links (brakes) and joined links (clutches): it *fires* each unit as soon as two of its
links are known, in order, which is linear in the number of gear pairs. When no unit has two
known links (the third gear of Liu and Chen's transmission, where the input link 4 and the
ground 1 lie in different units) it does what the paper does in eqs. (25)-(28): it takes the
displacement across a common linkage as an unknown (a *tear*), fires the unit with it, and
closes the loop with the consistency equation of the unit that holds the input. The plan is
structure only; :mod:`gearlib.gains` evaluates it with numbers, symbols or local gains.
Derived in chapters 2 and 3.

>>> import gearlib as gl
>>> p = gl.plan(gl.catalog.load("liu_chen_fig1"), ground=5, inputs=[4], output=3)
>>> for step in p.steps:
...     print(step)
KU1 (K3-1) fired by theta_4,5 (input)
KU2 (K4-1S) fired by theta_1,5 (2-link chain from KU1)
>>> sorted(p.graph().edges())
[('KU1', 'KU2'), ('KU2', 'theta_3,5'), ('theta_4,5', 'KU1')]
"""

from __future__ import annotations

from collections import defaultdict, deque
from collections.abc import Mapping
from dataclasses import dataclass, field, replace

from .._common.nogc import no_gc
from ..errors import ConstraintError, InputError
from ..mechanism.data import Mechanism
from ..units.unit import KinematicUnit
from ..units.fractionation import kinematic_units
from ..mechanism._accept import takes_mechanism

__all__ = ["Step", "Plan", "plan", "parse_relative"]


def theta(u, v) -> str:
    """``"theta_u,v"``: the relative displacement (or speed) of *u* with respect to *v*."""
    return f"theta_{u},{v}"


@dataclass(frozen=True)
class Step:
    """One unit fired: its local input ``input = (x, w)`` (the displacement of x relative to w),
    the *anchor* (a known link the other speeds are measured from), the links it makes known and
    the known links it only checks (consistency equations).

    ``source`` says where the local input comes from: ``"input"``, ``"2-link chain"``,
    ``"coaxial triangle"``, ``"known links"`` or ``"tear"`` (an unknown, found at the end);
    ``feeds`` are the indices of the units it comes from.
    """

    index: int
    unit: KinematicUnit
    input: tuple
    anchor: object
    source: str
    feeds: tuple = ()
    outputs: tuple = ()
    checks: tuple = ()
    tear: int | None = None
    order: int = 0
    chain: int | None = None  # index of an earlier step whose unit holds both input links

    def __str__(self) -> str:
        x, w = self.input
        src = self.source
        if self.feeds and self.source != "tear":
            src += " from " + ", ".join(f"KU{i}" for i in self.feeds)
        text = f"{self.unit.name} ({self.unit.label}) fired by {theta(x, w)} ({src})"
        if self.checks:
            text += f"; closes on {', '.join(map(str, self.checks))}"
        return text


@dataclass(frozen=True, eq=False)
class Plan:
    """The propagation plan of a mechanism for given ground, inputs and output.

    ``known_by[link]`` says how each link's speed is found: ``("ground",)``, ``("held",)``,
    ``("edge", k, other, sign)`` (input *k*, or a clutch when k is None, from link *other*),
    ``("step", s)`` (fired by step *s*) or ``("tear", j)``. ``equations`` are the consistency
    equations ``("check", s, link)``, ``("edge", k, u, v)`` that fix the tears.
    """

    mechanism: Mechanism
    ground: object
    inputs: tuple
    output: tuple | None
    held: tuple
    joined: tuple
    steps: tuple
    known_by: dict
    order: dict
    equations: tuple
    n_tears: int
    free: tuple = ()
    units: tuple = field(default=(), repr=False)

    def step_of(self, link):
        how = self.known_by.get(link)
        return self.steps[how[1]] if how and how[0] == "step" else None

    def graph(self):
        """The propagation structure as a networkx DiGraph: input nodes ``theta_u,v``, unit nodes
        ``KU<i>`` and the output node, from inputs to output. Edges carry ``signal`` (the local
        input they pass) and ``kind`` (``"input"``, ``"2-link chain"``, ``"coaxial triangle"``,
        ``"tear"``, ``"output"``); a coaxial triangle's edges also carry ``sign``, -1 where the
        receiving unit takes the feeding unit's output reversed (``theta_2,5 = theta_2,4 - theta_5,4``,
        eq. (10)) and +1 otherwise."""
        import networkx as nx

        g = nx.DiGraph()
        for k, (u, v) in enumerate(self.inputs):
            g.add_node(theta(u, v), kind="input", index=k)
        for s in self.steps:
            g.add_node(s.unit.name, kind="unit", label=s.unit.label)
        for s in self.steps:
            sig = theta(*s.input)
            kind = s.source if s.source in ("2-link chain", "coaxial triangle") else "input"
            if s.source == "tear":
                continue
            for src in self._sources(s):
                if src[0] == "input":
                    g.add_edge(theta(*self.inputs[src[1]]), s.unit.name, signal=sig, kind="input")
                else:
                    t = self.steps[src[1]]
                    if t.source == "tear" and s.checks:
                        g.add_edge(s.unit.name, t.unit.name, signal=theta(*t.input), kind="tear")
                    elif kind == "coaxial triangle":  # each feeding unit passes its own link (eq. 10)
                        z = next((z for z in s.input if self.known_by.get(z) == ("step", t.index)), s.input[0])
                        # theta_{x,w} = theta_{x,a} - theta_{w,a}: the feed of w arrives reversed
                        sign = -1 if z == s.input[1] else 1
                        g.add_edge(t.unit.name, s.unit.name, signal=theta(z, t.anchor), kind=kind, sign=sign)
                    else:
                        g.add_edge(t.unit.name, s.unit.name, signal=sig, kind=kind)
            for link in s.checks:
                for src in self._link_sources(link):
                    if src[0] == "input":
                        g.add_edge(theta(*self.inputs[src[1]]), s.unit.name, signal=theta(link, s.anchor),
                                   kind="input")
        if self.output is not None:
            o, r = self.output
            name = theta(o, r)
            g.add_node(name, kind="output")
            for s in self.steps:
                if o in s.unit and r in s.unit and (o in s.outputs or r in s.outputs or s.source == "tear"):
                    g.add_edge(s.unit.name, name, signal=name, kind="output")
                    break
            else:
                for link in (o, r):
                    for src in self._link_sources(link):
                        a = theta(*self.inputs[src[1]]) if src[0] == "input" else self.steps[src[1]].unit.name
                        g.add_edge(a, name, signal=name, kind="output")
        return g

    def _link_sources(self, link, seen=None):
        """Where a known link's speed comes from: ``("input", k)`` or ``("step", s)`` items."""
        out, stack, seen = [], [link], set()
        while stack:
            x = stack.pop()
            if x in seen:
                continue
            seen.add(x)
            how = self.known_by.get(x, ("free",))
            if how[0] == "step":
                out.append(("step", how[1]))
            elif how[0] == "edge":
                if how[1] is not None:
                    out.append(("input", how[1]))
                stack.append(how[2])
        return out

    def _sources(self, s: Step):
        if s.chain is not None:
            return [("step", s.chain)]
        out = []
        for link in dict.fromkeys((*s.input, s.anchor)):
            for src in self._link_sources(link):
                if src not in out:
                    out.append(src)
        return out


def parse_relative(mech: Mechanism, x, ref, what: str = "link"):
    """A link id or a relative pair (``(u, v)`` or ``"u/v"``) as a resolved pair ``(u, v)``."""
    if isinstance(x, str) and "/" in x:
        x = tuple(x.split("/", 1))
    if isinstance(x, (tuple, list)) and len(x) == 2:
        return mech.resolve(x[0], what), mech.resolve(x[1], what)
    return mech.resolve(x, what), ref


@no_gc
@takes_mechanism
def plan(mech: Mechanism, ground=None, inputs=(), output=None, *, held=(), joined=()) -> Plan:
    """The propagation plan (see the module documentation).

    Parameters
    ----------
    mech : Mechanism
    ground : link id (default ``mech.ground``)
    inputs : links, pairs ``(u, v)`` or text ``"u/v"``: the driven displacements
    output : link or pair, optional
    held, joined : brakes (links held like the ground) and clutches (pairs of links joined)
    """
    if ground is None:
        ground = mech.ground
    if ground is None:
        raise InputError(f"choose a ground link for {mech.name!r} (ground=...); links are {list(mech.link_ids)}")
    ground = mech.resolve(ground, "ground")
    if inputs is None:
        inputs = mech.inputs
    if isinstance(inputs, (int, str)):
        inputs = [inputs]
    elif isinstance(inputs, Mapping):
        inputs = list(inputs)  # {link: speed}: the links (propagation finds ratios, not speeds)
    ins = tuple(parse_relative(mech, x, ground, "input") for x in inputs)
    for u, v in ins:
        if u == v == ground:
            raise InputError(f"input link {u} is the ground; drive another link")
        if u == v:
            raise InputError(f"input {u}/{v} drives a link relative to itself; choose two different links")
    out = None if output is None else parse_relative(mech, output, ground, "output")
    held = mech.resolve_links(held, "held link")
    joined = mech.resolve_pairs(joined, "joined link")
    frac = kinematic_units(mech)
    units = frac.units
    units_of = defaultdict(list)
    for i, u in enumerate(units):
        for x in u.links:
            units_of[x].append(i)

    edges = defaultdict(list)  # link -> [(edge id, other, sign)]; omega_link = omega_other + sign*theta_k
    edge_info = []
    for k, (u, v) in enumerate(ins):
        edge_info.append((k, u, v))
    for u, v in joined:
        edge_info.append((None, u, v))
    for e, (_k, u, v) in enumerate(edge_info):
        edges[u].append((e, v, 1))
        edges[v].append((e, u, -1))
    used_edge = [False] * len(edge_info)

    known_by: dict = {}
    order: dict = {}
    counter = [0]
    count = [0] * len(units)
    fired = [False] * len(units)
    queue: deque = deque()
    equations: list = []
    steps: list = []
    n_tears = [0]

    gen: dict = {}  # links made known together (by one step) share a generation

    def make_known(link, how, generation=None, more=()):
        """Make *link* known (and *more* seeds with it), then every link an input or clutch ties
        to them; an input or clutch whose two links are both known already is an equation."""
        pending = deque([(link, how, None), *more])
        while pending:
            x, h, via = pending.popleft()
            if x in known_by:
                if via is not None:  # reached twice: the second edge closes a loop
                    equations.append(("edge", via))
                continue
            known_by[x] = h
            order[x] = counter[0]
            gen[x] = counter[0] if generation is None else generation
            counter[0] += 1
            for i in units_of.get(x, ()):
                count[i] += 1
                if count[i] == 2 and not fired[i]:
                    queue.append(i)
            for e, other, sign in edges.get(x, ()):
                if used_edge[e]:
                    continue
                used_edge[e] = True
                k = edge_info[e][0]
                if other in known_by:
                    equations.append(("edge", e))
                else:
                    pending.append((other, ("edge", k, x, -sign), e))

    for h in held:
        if h == ground:
            raise ConstraintError(f"link {h} is the ground and also held; the ground is already fixed")
    # the ground and the brakes first, together: an input between two of them is an equation
    make_known(ground, ("ground",), more=[(h, ("held",), None) for h in dict.fromkeys(held)])
    from .unit_tree import _tree

    def degenerate(i, a, b):
        """True when links a and b of unit i always turn together (exact ratios only)."""
        tree = _tree(units[i])
        ca, cb = tree.speed(a, "exact"), tree.speed(b, "exact")
        if getattr(ca, "free_symbols", None) or getattr(cb, "free_symbols", None):
            return False
        diff = ca - cb
        return diff == 0 if not hasattr(diff, "is_zero") else bool(diff.is_zero)

    def in_step(a, b):
        """The earliest fired step whose unit holds both a and b."""
        best = None
        for i in units_of.get(a, ()):
            if fired[i] and b in units[i]:
                s = step_index[i]
                if best is None or s < best:
                    best = s
        return best

    step_index: dict = {}

    def orient(i, a, b, chain):
        unit = units[i]
        for w in (ground, unit.carrier, steps[chain].unit.carrier if chain is not None else None):
            if w is not None and w in (a, b):
                return (b, a) if w == a else (a, b)
        return (a, b) if order[a] >= order[b] else (b, a)

    def fire(i):
        unit = units[i]
        known = sorted((x for x in unit.links if x in known_by), key=lambda x: order[x])
        best = None
        for ia in range(len(known)):
            for ib in range(ia + 1, len(known)):
                a, b = known[ia], known[ib]
                if degenerate(i, a, b):
                    continue
                chain = in_step(a, b) if "step" in (known_by[a][0], known_by[b][0]) else None
                score = (chain is None, ground not in (a, b), unit.carrier not in (a, b), order[a] + order[b])
                if best is None or score < best[0]:
                    best = (score, a, b, chain)
            if len(known) > 40 and best is not None:
                break
        if best is None:  # every known pair moves together: use one known link as the anchor of a tear
            return tear(i)
        _, a, b, chain = best
        x, w = orient(i, a, b, chain)
        anchor = min((x, w), key=lambda z: (gen[z], z != x))
        if chain is not None:
            source, feeds = "2-link chain", (steps[chain].unit.index,)
        else:
            srcs = []
            for z in (x, w):
                h = known_by[z]
                if h[0] == "step":
                    srcs.append(steps[h[1]].unit.index)
            feeds = tuple(dict.fromkeys(srcs))
            if len(feeds) == 2:
                source = "coaxial triangle"
            elif feeds:
                source = "known links"
            else:
                source = "input"
        checks = tuple(z for z in known if z not in (x, w))
        outputs = tuple(z for z in unit.links if z not in known_by)
        add_step(i, Step(len(steps), unit, (x, w), anchor, source, feeds, outputs, checks, None, counter[0], chain))

    def tear(i):
        unit = units[i]
        known = sorted((x for x in unit.links if x in known_by), key=lambda x: order[x])
        anchor = known[0]
        pair = None
        for j, other in enumerate(units):
            if j == i or fired[j]:
                continue
            common = [x for x in unit.links if x in other]
            if len(common) == 2 and unit.coaxial(*common):
                score = (count[j] == 0, j)
                if pair is None or score < pair[0]:
                    pair = (score, common)
        if pair is not None:
            a, b = pair[1]
            x, w = (b, a) if a == unit.carrier else (a, b)
        else:
            shared = [z for z in unit.links if z != anchor and len(units_of[z]) > 1 and z not in known_by]
            cand = shared or [z for z in unit.links if z != anchor and z not in known_by] or \
                [z for z in unit.links if z != anchor]
            x, w = cand[0], anchor
        j = n_tears[0]
        n_tears[0] += 1
        checks = tuple(z for z in known if z != anchor)
        outputs = tuple(z for z in unit.links if z not in known_by)
        add_step(i, Step(len(steps), unit, (x, w), anchor, "tear", (), outputs, checks, j, counter[0], None))

    def add_step(i, s):
        """Record unit i's step: its consistency checks, and the links it makes known."""
        counter[0] += 1
        fired[i] = True
        step_index[i] = s.index
        steps.append(s)
        for z in s.checks:
            equations.append(("check", s.index, z))
        late = []
        for z in s.outputs:
            if z in known_by:  # made known meanwhile through an input or clutch from another output
                late.append(z)
                equations.append(("check", s.index, z))
            else:
                make_known(z, ("step", s.index), s.order)
        if late:
            steps[-1] = replace(s, outputs=tuple(z for z in s.outputs if z not in late), checks=s.checks + tuple(late))

    out_units = set(units_of.get(out[0], ())) | set(units_of.get(out[1], ())) if out else set()
    while True:
        while queue:
            i = queue.popleft()
            if not fired[i]:
                fire(i)
        left = [i for i in range(len(units)) if not fired[i]]
        if not left:
            pending = [e for e, (k, u, v) in enumerate(edge_info) if not used_edge[e]]
            if not pending:
                break
            _, u, v = edge_info[pending[0]]
            make_known(v, ("tear", n_tears[0]))
            n_tears[0] += 1
            continue
        with_known = [i for i in left if count[i] >= 1]
        if with_known:
            i = min(with_known, key=lambda i: (i not in out_units, -count[i], i))
            tear(i)
        else:
            pending = [e for e, (k, u, v) in enumerate(edge_info) if not used_edge[e]]
            if pending:
                link = edge_info[pending[0]][2]
            else:
                i = min(left, key=lambda i: (i not in out_units, i))
                link = units[i].carrier
            make_known(link, ("tear", n_tears[0]))
            n_tears[0] += 1
    free = tuple(x for x in mech.link_ids if x not in known_by)
    if free:
        x = next((x for x in out or () if x in free), free[0])
        raise InputError(
            f"link {x} of {mech.name!r} turns freely: no gear pair, input, brake or clutch fixes its speed; "
            f"give it as an input (or hold it)"
        )
    return Plan(mech, ground, ins, out, held, joined, tuple(steps), known_by, order, tuple(equations),
                n_tears[0], free, units)

