"""The lines of a fault table, family by family (used by :func:`gearlib.fault_table`).

Every function here takes the speeds in Hz relative to the ground (``w``: link -> complex)
and appends :class:`~gearlib.FaultLine` rows through an :class:`_Emitter`, which adds the
harmonics and the sidebands of each fundamental line.
"""

from __future__ import annotations

from .bearings import bearing_frequencies
from .planetary import tooth_factors

FAMILIES = ("shaft", "mesh", "planet pass", "sun fault", "central gear fault", "ring fault", "planet fault",
            "hunting tooth", "assembly phase", "outer race", "inner race", "rolling element", "cage")
"""The families of lines, in the order of the table and of the spectrum map's lanes."""


def name_of(mech, link) -> str:
    """``sun (input shaft)`` for a named link, else ``link 3``."""
    name = mech.link(link).name
    return name if name else f"link {link}"


class _Emitter:
    """Collects lines: each fundamental with its harmonics 1..H and, around every harmonic,
    the sidebands +/- k x spacing (k = 1..K) of each modulation it carries."""

    def __init__(self, line_type, f_ref: float, harmonics: int, sidebands: int):
        self.Line, self.f_ref, self.H, self.K = line_type, f_ref, harmonics, sidebands
        self.lines: list = []

    def add(self, family, kind, name, label, f, *, links=(), bearing=None, modulation=(), note="",
            harmonics=True, centre_note=None, carries=()):
        """A fundamental at *f* Hz (skipped when it is zero), its harmonics and sidebands.

        *modulation* is ``((name, label, spacing), ...)``: sidebands +/- k x spacing around every
        harmonic. *centre_note*, a function of the harmonic number, may mark a harmonic.
        """
        if not f > 1e-12:
            return
        for m in range(1, (self.H if harmonics else 1) + 1):
            fm = m * f
            extra = centre_note(m) if centre_note else ""
            self.lines.append(self.Line(family, kind, harmonic_name(name, m), (f"{m}" if m > 1 else "") + label, fm,
                                        fm / self.f_ref, m, 0, None, None,
                                        tuple(modulation_names(modulation)) + (tuple(carries) if m == 1 else ()),
                                        tuple(links), bearing, "; ".join(x for x in (note, extra) if x)))
            for mod_name, mod_label, spacing in modulation:
                self.sidebands(family, harmonic_name(name, m), (f"{m}" if m > 1 else "") + label, fm, m, mod_name, mod_label,
                               spacing, links, bearing)

    def sidebands(self, family, centre, centre_label, fc, m, mod_name, mod_label, spacing, links, bearing,
                  offsets=None, note=""):
        if not spacing > 1e-12:
            return
        for k in (offsets if offsets is not None else [j for j in range(-self.K, self.K + 1) if j]):
            f = fc + k * spacing
            if f <= 1e-9:
                continue  # a sideband below zero frequency is left out
            sign = "+" if k > 0 else "-"
            self.lines.append(self.Line(
                family, "sideband", f"{centre} {sign} {abs(k)} x {mod_name}", f"{centre_label}{sign}{abs(k)}{mod_label}",
                f, f / self.f_ref, m, k, spacing, centre, (), tuple(links), bearing, note))


def harmonic_name(name: str, m: int) -> str:
    """``2x sun`` for the second harmonic of ``1x sun``, else ``2 x GMF 1-2``."""
    if m == 1:
        return name
    return f"{m}x {name[3:]}" if name.startswith("1x ") else f"{m} x {name}"


def modulation_names(modulation):
    return [(name, spacing) for name, _, spacing in modulation]


# ----------------------------------------------------------------------------- shafts
def shaft_lines(em, mech, w, ground, sets):
    planets = {p for s in sets for p, _ in s.planets}
    for x in mech.link_ids:
        if x == ground:
            continue
        f = abs(w[x] - w[ground])
        what = "planet spin relative to the housing" if x in planets else "shaft speed"
        em.add("shaft", "1x", f"1x {name_of(mech, x)}", f"1x{x}", f, links=(x,), note=what)


# ----------------------------------------------------------------------------- gear meshes
def mesh_lines(em, mech, w, ground, sets):
    in_set = {gp.gears: s for s in sets for gp in s.pairs}
    for gp in mech.gear_pairs:
        if gp.teeth is None:
            continue
        a, b = gp.gears
        k = gp.carrier
        fa, fb = abs(w[a] - w[k]), abs(w[b] - w[k])
        fm = gp.teeth[0] * fa
        if not fm > 1e-12:
            continue
        pair = f"{a}-{b}"
        mods = [(f"1x {name_of(mech, a)}", f"{a}", fa), (f"1x {name_of(mech, b)}", f"{b}", fb)]
        s = in_set.get(gp.gears)
        note, centre_note = f"gear mesh of pair ({a}, {b}) relative to carrier {k}", None
        if s is not None:
            fpp = s.passing * abs(w[k] - w[ground])
            comb = _mcfadden_smith(mech, w, ground, s)
            if comb is None and fpp > 1e-12 and s.passing > 1:
                mods.append(("planet pass", "PP", fpp))
            elif comb is not None:
                ring_teeth, n = comb
                centre_note = (lambda m, z=ring_teeth, n=n: "" if (m * z) % n == 0 else
                               f"cancels at a sensor on the fixed ring (McFadden and Smith 1985: {m} x {z} teeth is not "
                               f"a multiple of {n} planets); the nearest multiple of the planet pass dominates")
        em.add("mesh", "GMF", f"GMF {pair}", f"GMF{pair}", fm, links=gp.gears, modulation=mods, note=note,
               centre_note=centre_note)
        if s is not None:
            _planet_pass_comb(em, mech, w, ground, s, gp, fm, pair)
        n_a, lcm = tooth_factors(*gp.teeth)
        em.add("hunting tooth", "hunting tooth", f"hunting tooth {pair}", f"HT{pair}", fm / lcm, links=gp.gears,
               note=f"the same two teeth meet again every {lcm} meshes (teeth {gp.teeth[0]} and {gp.teeth[1]}, "
                    f"common factor {n_a})")
        if n_a > 1:
            em.add("assembly phase", "assembly phase", f"assembly phase {pair}", f"AP{pair}", fm / n_a, links=gp.gears,
                   note=f"{n_a} assembly phases: a tooth meets every {_ordinal(n_a)} tooth of the other gear")


def _ordinal(n: int) -> str:
    """``2nd``, ``3rd``, ``4th``, ``11th``, ``21st``."""
    suffix = "th" if 10 <= n % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return f"{n}{suffix}"


def _mcfadden_smith(mech, w, ground, s):
    """``(ring teeth, N)`` when the set's ring is fixed to the housing and N >= 2 planets
    turn with the carrier: McFadden and Smith's case. Else None."""
    ring = s.ring
    if ring is None or s.passing < 2 or abs(w[ring] - w[ground]) > 1e-9 * (1 + abs(w[s.carrier])):
        return None
    if abs(w[s.carrier] - w[ground]) <= 1e-12:
        return None
    z = s.teeth_of(ring)
    return None if z is None else (z, s.passing)


def _planet_pass_comb(em, mech, w, ground, s, gp, fm, pair):
    """Sidebands of the mesh harmonics spaced by the planet pass. With the ring fixed, only
    multiples of the planet-pass frequency survive at a sensor on the ring (McFadden and
    Smith 1985): the comb sits at q x f_pp around m x GMF, not at m x GMF + k x f_pp."""
    comb = _mcfadden_smith(mech, w, ground, s)
    if comb is None or s.ring not in gp.gears:
        return  # one comb per set: the planet-ring mesh carries it
    z, n = comb
    fpp = n * abs(w[s.carrier] - w[ground])
    for m in range(1, em.H + 1):
        q0 = (2 * m * z + n) // (2 * n)  # the multiple of N nearest m x Z_ring
        pre = "" if m == 1 else f"{m} x "
        offsets = [j for j in range(-em.K, em.K + 1) if j or (m * z) % n]
        for j in offsets:
            q = q0 + j
            f = q * fpp
            if f <= 1e-9:
                continue
            shift = q * n - m * z  # in carrier orders, from the mesh harmonic
            where = f"{pre}GMF {pair} {'+' if shift >= 0 else '-'} {abs(shift)} x carrier"
            em.lines.append(em.Line(
                "planet pass", "sideband", f"{q} x planet pass ({where})", f"{q}PP", f, f / em.f_ref, m, j, fpp,
                f"{pre}GMF {pair}", (), (s.carrier, s.ring), None,
                "McFadden and Smith 1985: with the ring fixed only multiples of the planet-pass frequency survive"))


# ----------------------------------------------------------------------------- planetary sets
def planetary_lines(em, mech, w, ground, sets):
    for s in sets:
        k = s.carrier
        fc = abs(w[k] - w[ground])
        if s.passing > 1:
            em.add("planet pass", "planet pass", f"planet pass, carrier {k}", f"PP{k}", s.passing * fc, links=(k,),
                   note=f"{s.passing} planets pass a point of the housing per turn of carrier {k}")
        for c, role in s.roles:
            f = s.contacts_of(c) * abs(w[c] - w[k])
            tag = f"{role[0].upper()}{c}"
            _local_fault(em, mech, w, s, c, f"{role} fault", f"{role} {c} local fault", tag, f,
                         f"a tooth of {name_of(mech, c)} meets {s.contacts_of(c)} planet(s) per turn relative to "
                         f"carrier {k}")
        for p, _ in s.planets:
            fp = abs(w[p] - w[k])
            _local_fault(em, mech, w, s, p, "planet fault", f"planet {p} local fault, one flank", f"P{p}", fp,
                         f"a defect on one flank of a tooth of {name_of(mech, p)} meets one mating gear per turn "
                         f"relative to carrier {k}")
            mates = s.contacts_of(p)
            if mates > 1:
                both = "both flanks" if mates == 2 else f"all {mates} meshes"
                _local_fault(em, mech, w, s, p, "planet fault", f"planet {p} local fault, {both}", f"P{p}x{mates}",
                             mates * fp, f"a defect through the tooth meets the {mates} gears planet {p} meshes with "
                                         "(the sun on one flank, the ring on the other)")


def _local_fault(em, mech, w, s, gear, family, name, tag, f, note):
    """A local fault line with its harmonics, and the sidebands +/- k x f it puts around the
    harmonics of the meshes of *gear* (one comb per distinct mesh frequency)."""
    meshes, seen = [], set()
    for gp in s.pairs:
        if gp.teeth is None or gear not in gp.gears:
            continue
        fm = gp.teeth[0] * abs(w[gp.gears[0]] - w[s.carrier])
        key = round(fm, 9)
        if fm > 1e-12 and key not in seen:
            seen.add(key)
            meshes.append((f"GMF {gp.gears[0]}-{gp.gears[1]}", fm, gp.gears))
    carries = tuple((f"around {m}", f) for m, _, _ in meshes)
    em.add(family, family, name, tag, f, links=(gear, s.carrier), note=note, carries=carries)
    if not f > 1e-12:
        return
    for mesh, fm, gears in meshes:
        for m in range(1, em.H + 1):
            centre = mesh if m == 1 else f"{m} x {mesh}"
            em.sidebands(family, centre, ("" if m == 1 else f"{m}") + mesh.replace(" ", ""), m * fm, m,
                         name.replace(" local fault", ""), tag, f, gears, None)


# ----------------------------------------------------------------------------- bearings
def _load_reference(mech, tp, ground):
    """The link of the turning pair fixed to the load: the carrier of the other link's gears
    (a planet's pin), else the ground (a shaft in the housing), else None."""
    u, v = tp.links
    if ground in tp.links:
        return ground
    for a, b in ((u, v), (v, u)):
        if any(gp.carrier == a and b in gp.gears for gp in mech.gear_pairs):
            return a
    return None


def bearing_lines(em, mech, w_hz, ground, convention):
    for tp in mech.turning_pairs:
        for i, brg in enumerate(tp.bearings, start=1):
            u, v = tp.links
            inner = brg.inner if brg.inner is not None else u
            outer = v if inner == u else u
            name = brg.name or f"bearing {i} in ({u}, {v})"
            f = bearing_frequencies(brg, w_hz[inner], w_hz[outer])
            load = _load_reference(mech, tp, ground)
            fr = f.relative_speed
            cage_to_load = None if load is None else (f.cage if load == outer else f.cage_inner)
            mod_inner = [("1x shaft", "R", fr)] if load is not None and load == outer else []
            mod_outer = [("1x shaft", "R", fr)] if load is not None and load == inner else []
            links = (inner, outer)
            em.add("outer race", "BPFO", f"BPFO {name}", f"BPFO {name}", f.outer_ring, links=links, bearing=name,
                   modulation=mod_outer, note=f"outer-race defect, Z/2 (1 - g) f_r, f_r = {fr:.6g} Hz")
            em.add("inner race", "BPFI", f"BPFI {name}", f"BPFI {name}", f.inner_ring, links=links, bearing=name,
                   modulation=mod_inner, note="inner-race defect, Z/2 (1 + g) f_r")
            cage_mod = [("cage", "C", cage_to_load)] if cage_to_load else []
            if convention == "paper":
                em.add("rolling element", "ball (paper)", f"ball {name}", f"ball {name}", f.paper_ball, links=links,
                       bearing=name, modulation=cage_mod,
                       note="Penaud and Alazard's Table A: (D_m / (d_b cos a)) (1 - g^2) f_r (erratum PA-E4)")
            else:
                em.add("rolling element", "BSF", f"BSF {name}", f"BSF {name}", f.ball_spin, links=links, bearing=name,
                       harmonics=False, note="ball spin, (D_m / 2 d_b) (1 - g^2) f_r; MATLAB's bearingFaultBands Fb")
                em.add("rolling element", "2xBSF", f"ball defect {name}", f"2BSF {name}", f.ball_defect, links=links,
                       bearing=name, modulation=cage_mod,
                       note="rolling-element defect: it strikes both races once per spin (the bearing rigs' "
                            "'rolling element' multiplier)")
            em.add("cage", "FTF", f"FTF {name}", f"FTF {name}", f.cage, links=links, bearing=name,
                   note="cage relative to the outer race, (1 - g) f_r / 2")

