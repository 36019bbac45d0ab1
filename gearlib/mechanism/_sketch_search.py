"""How the sketch router searches: a descent, then annealing while crossings remain.

Private to :mod:`gearlib.mechanism.sketch`: the search half of :class:`._sketch_route.Router`
(which scores one drawing). A state is a choice of option for every decision (where each
piece stands and which line it starts from, which units are mirrored) and the order of the
pieces within their lanes; the drawing of a state, and so the search, is deterministic.
"""

from __future__ import annotations

import math
import random

__all__: list = []

DESCENT = 60     # evaluations of the first descent
BUDGET = 4000    # evaluations of the annealing, while crossings remain
POLISH = 60      # evaluations spent shortening a drawing
_ZONES = ("in", "out")


class Search:
    @property
    def riser_of(self) -> dict:
        return self._riser_of

    def _index_ports(self):
        self._riser_of = {p.member: k for k, p in enumerate(self.ports) if p.kind == "riser"}
        self.of_member: dict = {}
        for k, p in enumerate(self.ports):
            if len(self.options[k]) > 1:
                self.of_member.setdefault(p.member, []).append(k)
                if p.other is not None:
                    self.of_member.setdefault(p.other, []).append(k)
        self._arm_ports = [k for k, p in enumerate(self.ports) if p.kind == "arm" and len(self.options[k]) > 1]

    @staticmethod
    def _cost(route):
        return (route.crossings, route.penalty, round(route.length, 6))

    # ------------------------------------------------------------------ search
    def _start(self):
        """Each flexible piece from the line its member needs anyway (a ring's drum, a sun's
        shaft), an arm on the side of its planet that crosses fewest gears."""
        self._index_ports()
        forced = {}
        for p, opts in zip(self.ports, self.options):
            zones = {o[0][1] for o in opts}
            if p.kind == "gear" and len(zones) == 1:
                forced.setdefault(p.member, set()).update(zones)
        choice = []
        for k, (p, opts) in enumerate(zip(self.ports, self.options)):
            if k >= self.n_ports:
                choice.append(0)
            elif p.kind == "riser":
                choice.append(len(opts) // 2)
            else:
                want = forced.get(p.member, {"in"})
                fits = [c for c, o in enumerate(opts) if len(o) == 1 and o[0][1] in want]
                choice.append(fits[0] if fits else 0)
        choice += [0] * (len(self.options) - len(choice))
        return choice, list(range(len(self.ports)))

    def _moves(self, state, route, focus=None):
        """Neighbouring drawings: one decision changed; one member's pieces moved to one of its
        lines; two pieces of a lane swapped. With *focus* (the
        decisions involved in a crossing), only those that touch them."""
        choice, rank = state
        members = self.members if focus is None else sorted(
            {self.ports[k].member for k in focus if k < self.n_ports and self.ports[k].member in self.index}
            | {self.ports[k].other for k in focus if k < self.n_ports and self.ports[k].other in self.index},
            key=self.index.get)
        for k in (range(len(self.options)) if focus is None else sorted(focus)):
            if k < self.n_ports and self.ports[k].kind == "riser" and self.ports[k].member not in route.risers:
                continue   # a riser not drawn: where it would stand changes nothing
            for c in range(len(self.options[k])):
                if c != choice[k]:
                    yield choice[:k] + [c] + choice[k + 1:], rank
        for m in members:
            for zone in _ZONES:
                moved = self._group(choice, m, zone)
                if moved != choice:
                    yield moved, rank
        by_lane: dict = {}
        for k in range(self.n_ports):
            p = self.ports[k]
            if p.kind == "riser" and p.member not in route.risers:
                continue
            for lane, cls, _part, _z0, _z1 in self._pieces[k][choice[k]]:
                if lane is not None:
                    by_lane.setdefault((lane, cls), set()).add(k)
        for ks in by_lane.values():
            if focus is not None and not ks & focus:
                continue
            ks = sorted(ks, key=rank.__getitem__)
            for a, b in zip(ks, ks[1:]):
                new = list(rank)
                new[a], new[b] = rank[b], rank[a]
                yield choice, new

    def _group(self, choice, m, zone):
        """*choice* with every flexible piece of member *m* moved to its *zone* line (same lanes)."""
        trial = list(choice)
        for k in self.of_member.get(m, ()):
            p = self.ports[k]
            if p.kind in ("item", "riser", "gear", "toframe"):
                continue
            cur = self.options[k][choice[k]]
            for c, opt in enumerate(self.options[k]):
                if len(opt) != len(cur) or any(a[0] != b[0] for a, b in zip(opt, cur)):
                    continue
                if p.kind == "clutch":
                    if opt[0][1] == "*" + zone:
                        trial[k] = c
                        break
                    continue
                if all((piece[1] == zone if p.member == m else piece[1] == cur[i][1])
                       for i, piece in enumerate(opt)):
                    trial[k] = c
                    break
        return trial

    def _descend(self, state, route, limit, focused=True):
        """First improvement among the moves (scanned from where the last one was found), until
        none improves or the budget is spent; while crossings remain, the moves that touch them
        first."""
        cost = self._cost(route)
        skip = 0
        while self.evaluations < limit:
            focus = route.culprits if focused and route.crossings else None
            moves = list(self._moves(state, route, focus))
            found = None
            for n in range(len(moves)):
                trial = moves[(skip + n) % len(moves)]
                r = self.evaluate(*trial)
                c = self._cost(r)
                if c < cost:
                    found = (trial, r, c, n)
                    break
                if self.evaluations >= limit:
                    break
            if found is None:
                if focus is not None:   # nothing near the crossings helps: try everything
                    focused = False
                    continue
                break
            state, route, cost, n = found
            skip += n
            focused = True
        return state, route

    def _anneal(self, state, route, limit):
        """Simulated annealing while crossings remain: one decision (half the time one involved in
        a crossing) or the places of two pieces in their lanes changed at random, a worse drawing
        taken with the Metropolis probability at a temperature falling linearly over the budget."""
        rnd = random.Random(7)
        n = len(self.options)

        def energy(r):
            return 4 * r.crossings + 0.3 * r.penalty + r.length / (300 * self.pitch / 0.11)

        best_state, best = state, route
        e = energy(route)
        start, span = self.evaluations, max(limit - self.evaluations, 1)
        while best.crossings and self.evaluations < limit:
            t = 2.0 * (1 - (self.evaluations - start) / span) + 0.1
            choice, rank = state
            if rnd.random() < 0.85:
                culprits = sorted(route.culprits)
                k = rnd.choice(culprits) if culprits and rnd.random() < 0.5 else rnd.randrange(n)
                choice = choice[:k] + [rnd.randrange(len(self.options[k]))] + choice[k + 1:]
            else:
                i, j = rnd.randrange(len(rank)), rnd.randrange(len(rank))
                rank = list(rank)
                rank[i], rank[j] = rank[j], rank[i]
            r = self.evaluate(choice, rank)
            e2 = energy(r)
            if e2 <= e or rnd.random() < math.exp((e - e2) / t):
                state, route, e = (choice, rank), r, e2
                if self._cost(r) < self._cost(best):
                    best_state, best = state, r
        return best_state, best

    def solve(self):
        state = self._start()
        route = self.evaluate(*state)
        state, route = self._descend(state, route, self.evaluations + DESCENT)
        if route.crossings:
            state, route = self._anneal(state, route, self.evaluations + BUDGET)
        state, route = self._descend(state, route, self.evaluations + POLISH, focused=False)
        return route
