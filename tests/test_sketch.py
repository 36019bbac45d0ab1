"""Kinematic sketches (gl.sketch_layout, gl.draw_sketch): geometry checked, not pixels.

Every property is computed here from the drawn polygons and lines and from the mechanism's own
data (teeth, turning pairs), independently of how the layout was found: coaxial links share
one axis line and every gear sits at its pitch radius from it; meshing gears' blocks touch;
unrelated blocks never overlap; each link is labelled once. The mechanisms: the whole
catalogue, an eight-speed transmission of four simple sets with five shift elements, and 200
random coaxial trains from a generator written here.
"""

import math

import matplotlib
import numpy as np
import pytest

import gearlib as gl

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

EPS = 1e-7


# ----------------------------------------------------------------------------- geometry helpers
def _area(poly):
    return 0.5 * abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1])))


def _oriented(poly):
    a = sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]))
    return list(poly) if a > 0 else list(poly)[::-1]


def _inside(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= -1e-12


def _cut(a, b, p, q):
    dx, dy = q[0] - p[0], q[1] - p[1]
    den = (b[0] - a[0]) * dy - (b[1] - a[1]) * dx
    t = ((b[0] - a[0]) * (a[1] - p[1]) - (b[1] - a[1]) * (a[0] - p[0])) / den
    return (p[0] + t * dx, p[1] + t * dy)


def _clip(subject, clipper):
    """Sutherland-Hodgman: the intersection of two convex polygons."""
    out = _oriented(subject)
    clip = _oriented(clipper)
    for a, b in zip(clip, clip[1:] + clip[:1]):
        pts, out = out, []
        for i, p in enumerate(pts):
            q = pts[(i + 1) % len(pts)]
            if _inside(a, b, q):
                if not _inside(a, b, p):
                    out.append(_cut(a, b, p, q))
                out.append(q)
            elif _inside(a, b, p):
                out.append(_cut(a, b, p, q))
        if not out:
            return []
    return out


def _overlap_area(a, b):
    pts = _clip(a, b)
    return _area(pts) if len(pts) >= 3 else 0.0


def _shared_edge(a, b, tol):
    """Length of boundary the two polygons share (collinear, overlapping edges)."""
    total = 0.0
    for (p0, p1) in zip(a, a[1:] + a[:1]):
        for (q0, q1) in zip(b, b[1:] + b[:1]):
            d = np.subtract(p1, p0)
            n = np.hypot(*d)
            if n < tol:
                continue
            u = d / n
            # both ends of q on the line of p?
            off = [abs(_cross(u, np.subtract(q, p0))) for q in (q0, q1)]
            if max(off) > tol:
                continue
            s = sorted([0.0, n])
            t = sorted(float(np.dot(u, np.subtract(q, p0))) for q in (q0, q1))
            total += max(0.0, min(s[1], t[1]) - max(s[0], t[0]))
    return total


def _cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def _distance_to_line(p, line):
    (x0, y0), (x1, y1) = line.start, line.end
    d = np.array([x1 - x0, y1 - y0])
    return abs(_cross(d / np.hypot(*d), np.subtract(p, (x0, y0))))


def _meshing(mech):
    return {frozenset(gp.gears) for gp in mech.gear_pairs}


# ----------------------------------------------------------------------------- the properties
def check_sketch(mech, sk, *, consistent=True):
    ids = list(mech.link_ids)
    tol = 1e-6 * sk.scale
    # every link appears once, with its label
    assert sorted(map(str, (lb.link for lb in sk.labels))) == sorted(map(str, ids))
    for lb in sk.labels:
        assert lb.text.split(" ")[0] == str(lb.link)
    # coaxial links share one axis line; each gear sits on it at its pitch radius
    lines = {}
    for a in sk.axes:
        for link in a.links:
            lines.setdefault((link, a.label), []).append(a)
    for u in ids:
        for v in ids:
            label = mech.coaxial(u, v)
            if u != v and label is not None:
                assert len(lines[u, label]) == 1 and lines[u, label] == lines[v, label], (u, v, label)
    for b in sk.blocks:
        (line,) = lines[b.link, b.axis] if (b.link, b.axis) in lines else [
            a for a in sk.axes if b.axis == a.label]
        d = [_distance_to_line(p, line) for p in b.polygon]
        if b.kind == "bevel":   # its pitch point is a corner (the body lies inside or outside its cone)
            assert min(abs(x - b.radius) for x in d) < tol, (mech.name, b.link, d, b.radius)
            continue
        edge = min(d) if b.kind == "ring" else max(d)   # a ring's teeth face inwards
        assert abs(edge - b.radius) < tol, (mech.name, b.link, b.kind, edge, b.radius)
    # meshing gears' blocks touch (when the data's radii close every centre distance)
    blocks = [b for b in sk.blocks]
    if consistent:
        for gp in mech.gear_pairs:
            a, c = gp.gears
            pa = [p for p in blocks if p.link == a]
            qc = [q for q in blocks if q.link == c]
            touching = [(p, q) for p in pa for q in qc
                        if _shared_edge(list(p.polygon), list(q.polygon), tol) > tol
                        and _overlap_area(p.polygon, q.polygon) < tol * sk.scale]
            if touching:
                continue
            # two pinions of a double-pinion set stand at different angles about the main axis: in
            # the section their axes are closer than their centre distance, and their blocks overlap
            p, q = pa[0], qc[0]
            ya, yc = (np.mean([y for _, y in b.polygon]) for b in (p, q))
            assert p.kind == q.kind == "planet" and abs(ya - yc) < p.radius + q.radius - tol, (mech.name, gp.label)
            assert _overlap_area(p.polygon, q.polygon) > 0, (mech.name, gp.label)
    # no two unrelated blocks overlap
    mesh = _meshing(mech)
    for i, p in enumerate(blocks):
        for q in blocks[i + 1:]:
            if p.link == q.link or frozenset((p.link, q.link)) in mesh:
                continue
            assert _overlap_area(p.polygon, q.polygon) < tol * sk.scale, (mech.name, p.link, q.link)


CATALOGUE = gl.catalog.names()


@pytest.mark.parametrize("name", CATALOGUE)
def test_every_catalogue_mechanism_is_sketched_and_drawn(name):
    mech = gl.catalog.load(name)
    sk = gl.sketch_layout(mech)
    check_sketch(mech, sk, consistent=not sk.notes)
    ax = gl.draw_sketch(mech)
    texts = [t.get_text() for t in ax.texts]
    for link in mech.link_ids:   # drawn once each, as the graph names it
        assert sum(1 for t in texts if t.split(" ")[0] == str(link)) == 1, (name, link)
    assert ax.get_title() == mech.name
    plt.close(ax.figure)


def test_the_catalogue_radii_close_and_nothing_crosses():
    """Every catalogue train's teeth close its centre distances (no notes), and the members'
    lines are routed without a spoke crossing another member's line."""
    for name in CATALOGUE:
        sk = gl.sketch_layout(gl.catalog.load(name))
        assert sk.notes == (), name
        assert sk.crossings == 0, name


def test_a_planet_sits_at_sun_plus_planet_radius_from_the_axis():
    """Simple planetary 24/18/60 with teeth as sizes: the planet's axis line is at (24 + 18)/2
    above the main axis, the ring's inner edge at 60/2."""
    sk = gl.sketch_layout(gl.catalog.simple_planetary(sun=24, ring=60))
    planet_axis = next(a for a in sk.axes if a.label == "b")
    assert planet_axis.start[1] == pytest.approx((24 + 18) / 2) == planet_axis.end[1]
    ring = next(b for b in sk.blocks if b.kind == "ring")
    assert min(y for _, y in ring.polygon) == pytest.approx(30)
    sun = next(b for b in sk.blocks if b.kind == "sun")
    assert max(y for _, y in sun.polygon) == pytest.approx(12)
    planet = next(b for b in sk.blocks if b.kind == "planet")
    assert (min(y for _, y in planet.polygon), max(y for _, y in planet.polygon)) == pytest.approx((12, 30))


def test_radii_from_module_and_a_module_mix():
    """Laus's two annuli: modules 1 and 2 mm; the drawn radii are the data's radii (mm)."""
    sk = gl.sketch_layout(gl.catalog.load("laus_epicyclic"))
    radii = sorted((b.link, round(b.radius, 9)) for b in sk.blocks)
    assert radii == [(1, 40.0), (2, 60.0), (3, 15.0), (3, 35.0)]
    assert sum(1 for b in sk.blocks if b.link == 3) == 2   # a stepped planet: two blocks on one pin


def test_bevel_planet_axis_follows_from_the_pitch_radii():
    """Humpage (Laus D5.6): the planet axis makes cos(beta) = (r5 - r1)/(2 r2) with the main
    axis (60 degrees for 20, 56, 76); the differential's planets stand at 90 degrees."""
    sk = gl.sketch_layout(gl.catalog.humpage())
    p = next(a for a in sk.axes if a.label == "p")
    angle = math.degrees(math.atan2(p.end[1] - p.start[1], p.end[0] - p.start[0]))
    assert min(angle, 180 - angle) == pytest.approx(math.degrees(math.acos((76 - 20) / (2 * 56))))
    sk = gl.sketch_layout(gl.catalog.car_differential())
    c = next(a for a in sk.axes if a.label == "c")
    assert c.start[0] == pytest.approx(c.end[0])   # vertical
    assert sk.mode == "full"                       # the second planet is drawn below the axis
    (low,) = [b for b in sk.blocks if b.link == 6]
    assert max(y for _, y in low.polygon) < 0 < min(y for b in sk.blocks if b.link == 5 for _, y in b.polygon)


def test_fixed_axes_are_laid_out_by_centre_distance():
    """A compound train 20/60, 15/45 on fixed axes: axes at 0, (20+60)/2 and that + (15+45)/2."""
    sk = gl.sketch_layout(gl.catalog.load("compound_train"))
    assert sk.mode == "fixed"
    ys = sorted(a.start[1] for a in sk.axes)
    assert ys == pytest.approx([0, 40, 70])
    assert sum(1 for s in sk.symbols if s.kind == "bearing") == 6   # each shaft in two bearings


# ----------------------------------------------------------------------------- transmissions
def eight_speed():
    """Four simple sets (sun/ring 48/96, 48/96, 69/111, 23/85), brakes A and B, clutches C, D, E,
    in the structure of an eight-speed automatic (ring 3 and sun 4 one shaft)."""
    return gl.Mechanism.from_dict({
        "name": "eight-speed, four simple sets",
        "links": {0: "housing", 1: "input", 2: "suns 1, 2", 3: "ring 1", 4: "carrier 1, ring 4",
                  5: "ring 2, sun 3", 6: "ring 3, sun 4", 7: "carrier 3", 8: "output",
                  11: "planet 1", 12: "planet 2", 13: "planet 3", 14: "planet 4"},
        "turning_pairs": [[0, k, "a"] for k in range(1, 9)] + [[4, 11, "b"], [1, 12, "c"], [7, 13, "d"],
                                                             [8, 14, "e"]],
        "gear_pairs": [{"gears": [2, 11], "teeth": [48, 24]}, {"gears": [11, 3], "teeth": [24, 96], "type": "internal"},
                       {"gears": [2, 12], "teeth": [48, 24]}, {"gears": [12, 5], "teeth": [24, 96], "type": "internal"},
                       {"gears": [5, 13], "teeth": [69, 21]}, {"gears": [13, 6], "teeth": [21, 111], "type": "internal"},
                       {"gears": [6, 14], "teeth": [23, 31]}, {"gears": [14, 4], "teeth": [31, 85], "type": "internal"}],
        "ground": 0, "inputs": [1], "output": 8, "planets": {11: 4, 12: 4, 13: 4, 14: 4},
        "shift_elements": [{"name": "A", "type": "brake", "link": 2}, {"name": "B", "type": "brake", "link": 3},
                           {"name": "C", "type": "clutch", "links": [1, 6]}, {"name": "D", "type": "clutch", "links": [7, 8]},
                           {"name": "E", "type": "clutch", "links": [5, 7]}],
        "schedule": [{"gear": g, "engaged": list(e)} for g, e in (
            ("1st", "ABC"), ("2nd", "ABE"), ("3rd", "BCE"), ("4th", "BDE"), ("5th", "BCD"), ("6th", "CDE"),
            ("7th", "ACD"), ("8th", "ADE"), ("R", "ABD"))],
    })


def test_the_eight_speed_structure_gives_its_published_ratios():
    """The test transmission is a real one: its nine gears give the published 4.696 ... 0.667, -3.297."""
    mech = eight_speed()
    published = [4.696, 3.130, 2.104, 1.667, 1.285, 1.000, 0.839, 0.667, -3.297]
    got = [1 / float(gl.ratio(mech, output=8, input=1, **mech.gear_constraints(g.name))) for g in mech.schedule]
    assert got == pytest.approx(published, abs=6e-4)


def test_a_transmission_shows_every_brake_and_clutch():
    mech = eight_speed()
    sk = gl.sketch_layout(mech)
    check_sketch(mech, sk)
    shown = {s.name: (s.kind, set(s.links)) for s in sk.symbols if s.kind in ("brake", "clutch") and not s.copy}
    assert shown == {e.name: (e.kind, set(e.links)) for e in mech.shift_elements}
    # a brake's plates hang from the hatched housing at the top; a clutch's plates sit between its two
    # members' lines, each member's spoke reaching its own plate
    top = max(ln.start[1] for ln in sk.lines if ln.kind == "housing")
    for s in sk.symbols:
        if s.kind == "brake":
            assert max(y for seg in s.segments for _, y in seg) == pytest.approx(top)
        if s.kind == "clutch":
            (x0, ya), (_, _) = s.segments[0]
            plates = sorted(seg[0][1] for seg in s.segments)
            spokes = [ln for ln in sk.lines if ln.kind == "spoke" and ln.link in s.links
                      and min(ln.start[0], ln.end[0]) > x0 - 1e-9 and max(ln.start[0], ln.end[0]) < x0 + 2 * sk.scale]
            ends = {round(y, 9) for ln in spokes for y in (ln.start[1], ln.end[1])}
            assert {round(plates[0], 9), round(plates[-1], 9)} <= ends, s.name
    plt.close(gl.draw_sketch(mech).figure)


def test_members_joined_by_a_turning_pair_are_nested_next_to_each_other():
    """The data say the carrier is journalled on the output shaft and the output in the input: their
    shafts are drawn side by side, in that order from the axis."""
    data = eight_speed().to_dict()
    data["turning_pairs"] = [[0, 1, "a"], [1, 8, "a"], [8, 7, "a"], [0, 2, "a"], [0, 3, "a"], [0, 4, "a"],
                             [0, 5, "a"], [0, 6, "a"], [4, 11, "b"], [1, 12, "c"], [7, 13, "d"], [8, 14, "e"]]
    mech = gl.Mechanism.from_dict(data)
    sk = gl.sketch_layout(mech)
    shafts = sorted((ln.start[1], ln.link) for ln in sk.lines if ln.kind == "shaft" and not ln.copy)
    order = [link for _, link in shafts]
    for inner, outer in ((1, 8), (8, 7)):
        if inner in order and outer in order:
            assert abs(order.index(inner) - order.index(outer)) == 1, order


# ----------------------------------------------------------------------------- random coaxial trains
def random_coaxial(seed):
    """A random valid coaxial train: 1 to 4 planetary sets (some double-pinion) on one main axis,
    members of later sets sometimes joined to earlier ones, with brakes and clutches."""
    rng = np.random.default_rng(seed)
    for _ in range(20):
        n_sets = int(rng.integers(1, 5))
        links, tps, gps, planets = {0: "frame"}, [], [], {}
        members = []
        for s in range(n_sets):
            zs, zp = int(rng.integers(12, 40)), int(rng.integers(10, 30))
            double = rng.random() < 0.25
            zq = int(rng.integers(8, 16)) if double else 0
            zr = zs + 2 * zp + 2 * zq
            roles = {}
            for role in ("sun", "carrier", "ring"):
                free = [m for m in members if m not in roles.values()]
                if free and rng.random() < 0.35:
                    roles[role] = free[int(rng.integers(len(free)))]
                else:
                    roles[role] = len(links)
                    links[len(links)] = role
                    members.append(roles[role])
            p = len(links)
            links[p] = "planet"
            tps.append([roles["carrier"], p, f"p{s}"])
            gps.append({"gears": [roles["sun"], p], "teeth": [zs, zp]})
            last = p
            if double:
                q = len(links)
                links[q] = "outer planet"
                tps.append([roles["carrier"], q, f"q{s}"])
                gps.append({"gears": [p, q], "teeth": [zp, zq]})
                last, zp = q, zq
            gps.append({"gears": [last, roles["ring"]], "teeth": [zp, zr], "type": "internal"})
            if rng.random() < 0.5:
                planets[p] = int(rng.integers(3, 6))
        tps += [[0, m, "a"] for m in members]
        elements = [{"name": f"B{i}", "type": "brake", "link": m} for i, m in enumerate(members) if rng.random() < 0.3]
        for i in range(int(rng.integers(0, 3))):
            u, v = (int(x) for x in rng.choice(members, 2, replace=False))
            elements.append({"name": f"C{i}", "type": "clutch", "links": [u, v]})
        data = {"name": f"random coaxial train {seed}", "links": links, "turning_pairs": tps, "gear_pairs": gps,
                "ground": 0, "inputs": [members[0]], "output": members[-1], "planets": planets,
                "shift_elements": elements}
        try:
            return gl.Mechanism.from_dict(data)
        except gl.GearlibError:   # two sets joined into a locked loop: draw again
            continue
    raise AssertionError("no valid random train")  # pragma: no cover


@pytest.mark.parametrize("block", range(4))
def test_two_hundred_random_coaxial_trains(block):
    """Each train's sketch has the properties above; and the router's count of crossings is the
    drawing's: on every fourth train, some of which it cannot draw without a crossing, the
    recount on the drawn lines equals ``Sketch.crossings`` (each block of 50 meets such a train)."""
    counted = []
    for seed in range(50 * block, 50 * block + 50):
        mech = random_coaxial(seed)
        sk = gl.sketch_layout(mech)
        assert sk.mode in ("half", "full")
        check_sketch(mech, sk)
        if seed % 4 == 0:
            drawn = len(_crossings_drawn(sk)) + len(_pins_through_gears(sk))
            assert drawn == sk.crossings, seed
            counted.append(drawn)
        if seed % 25 == 0:
            plt.close(gl.draw_sketch(mech).figure)
    assert max(counted) > 0   # the recount met trains that need crossings


def test_random_mechanisms_draw_or_say_why():
    """gl.random_mechanism's trees of axes: every spur one draws; a bevel one draws or raises a
    GeometryError (a spatial train), never anything else."""
    for seed in range(60):
        n = 3 + seed % 9
        mech = gl.random_mechanism(n, dof=1, rng=seed, bevel=0.3 if seed % 2 else 0.0)
        try:
            sk = gl.sketch_layout(mech)
        except gl.GeometryError as err:
            assert seed % 2, (seed, err)
            assert "axis" in str(err) or "bevel" in str(err)
            continue
        assert sorted(map(str, (lb.link for lb in sk.labels))) == sorted(map(str, mech.link_ids))


# ----------------------------------------------------------------------------- what cannot be drawn
def test_a_spatial_train_is_refused_with_its_reason():
    """An axis held by a link that turns about an inclined (bevel) axis may leave the plane."""
    data = gl.catalog.load("penaud_example_1").to_dict()
    data["links"][5] = "arm on the planet"
    data["links"][6] = "gear on the arm"
    data["turning_pairs"] += [[3, 5, "e"], [5, 6, "f"]]
    data["gear_pairs"].append({"gears": [6, 3], "teeth": [12, 10], "carrier": 5})
    mech = gl.Mechanism.from_dict({k: v for k, v in data.items() if k != "layout"})
    with pytest.raises(gl.GeometryError, match="inclined axis 'b'.*spatial train"):
        gl.sketch_layout(mech)


def test_bevel_gears_that_cannot_meet_are_refused():
    """A bevel planet of pitch radius 5 between central gears of radii 3 and 20 (they differ by more
    than its diameter): no cone apex fits."""
    mech = gl.Mechanism.from_dict({
        "links": [1, 2, 3, 4],
        "turning_pairs": [[4, 1, "a"], [4, 2, "a"], [4, 3, "b"]],
        "gear_pairs": [{"gears": [1, 3], "teeth": [6, 10], "type": "bevel", "ratio": "-3/5"},
                       {"gears": [2, 3], "teeth": [40, 10], "type": "bevel", "ratio": 4}]})
    with pytest.raises(gl.GeometryError, match="cannot mesh both 1 and 2"):
        gl.sketch_layout(mech)


def test_three_identical_planets_are_refused_with_the_fix():
    data = gl.catalog.simple_planetary().to_dict()
    data["links"].update({5: "planet", 6: "planet"})
    data["turning_pairs"] += [[4, 5, "c"], [4, 6, "d"]]
    data["gear_pairs"] += [{"gears": [1, 5], "teeth": [24, 18]}, {"gears": [5, 3], "teeth": [18, 60], "type": "internal"},
                           {"gears": [1, 6], "teeth": [24, 18]}, {"gears": [6, 3], "teeth": [18, 60], "type": "internal"}]
    data.pop("layout", None)
    with pytest.raises(gl.GeometryError, match="planets: "):
        gl.sketch_layout(gl.Mechanism.from_dict(data))
    data["gear_pairs"] = data["gear_pairs"][:4]   # two identical planets: both shown, one below
    data["links"].pop(6)
    data["turning_pairs"].pop()
    sk = gl.sketch_layout(gl.Mechanism.from_dict(data))
    assert sk.mode == "full"


def test_not_a_mechanism():
    with pytest.raises(gl.DataFormatError, match="gl.Mechanism"):
        gl.sketch_layout({"links": [1, 2]})


def test_drawing_takes_an_axes_and_returns_it():
    fig, ax = plt.subplots()
    assert gl.draw_sketch(gl.catalog.simpson(), ax=ax, names=True) is ax
    assert any("common sun" in t.get_text() for t in ax.texts)
    assert fig.get_facecolor()[:3] == (1.0, 1.0, 1.0) and ax.get_facecolor()[:3] == (1.0, 1.0, 1.0)
    plt.close(fig)


# ----------------------------------------------------------------------------- command line
def test_the_sketch_command_writes_svg_png_and_levers(tmp_path):
    from cli_tools import run

    out = tmp_path / "simpson.svg"
    r = run("sketch", "simpson", "--output", str(out))
    assert r.returncode == 0, r.stderr
    assert out.read_text().lstrip().startswith(("<?xml", "<svg")) and "</svg>" in out.read_text()
    path = tmp_path / "eight.yaml"
    gl.save(eight_speed(), path)
    png = tmp_path / "eight.png"
    r = run("sketch", str(path), "-o", str(png), "--names")
    assert r.returncode == 0 and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    r = run("sketch", str(path), "-o", str(tmp_path / "levers.pdf"), "--lever", "--gear", "3rd")
    assert r.returncode == 0 and (tmp_path / "levers.pdf").read_bytes()[:4] == b"%PDF"
    assert "lever diagram (4 levers)" in r.stdout


@pytest.mark.parametrize("args, message", [
    (["simpson", "-o", "x.txt"], "give a file ending in .svg"),
    (["simpson", "-o", "x.png", "--gear", "1st"], "add --lever"),
    (["compound_train", "-o", "x.png", "--lever"], "no planetary set"),
    (["EIGHT", "-o", "x.png", "--lever", "--gear", "ninth"], "no gear 'ninth'"),
    (["SPATIAL", "-o", "x.png"], "spatial train"),
])
def test_the_sketch_command_says_what_is_wrong_in_one_line(tmp_path, args, message):
    from cli_tools import run

    gl.save(eight_speed(), tmp_path / "eight.yaml")
    data = gl.catalog.load("penaud_example_1").to_dict()
    data.pop("layout")
    data["links"][5] = "arm"
    data["turning_pairs"].append([3, 5, "e"])
    gl.save(gl.Mechanism.from_dict(data), tmp_path / "spatial.yaml")
    args = [str(tmp_path / "eight.yaml") if a == "EIGHT" else str(tmp_path / "spatial.yaml") if a == "SPATIAL"
            else str(tmp_path / a) if a.startswith("x.") else a for a in args]
    r = run("sketch", *args)
    assert r.returncode == 2
    assert len(r.stderr.strip().splitlines()) == 1 and message in r.stderr and "Traceback" not in r.stderr


# ----------------------------------------------------------------------------- profile shift
def _inv(a):
    return math.tan(a) - a


def _working_distance(z1, z2, x1, x2, internal=False, degrees=20.0, module=1.0):
    """The working centre distance of a profile-shifted spur pair, from the involute function:
    inv(alpha_w) = inv(alpha) + 2 tan(alpha) (x1 + x2) / (z1 + z2) (for an internal pair the
    differences, ring minus pinion), a_w = a cos(alpha) / cos(alpha_w), solved here by bisection."""
    alpha = math.radians(degrees)
    zs, xs = ((z2 - z1), (x2 - x1)) if internal else ((z1 + z2), (x1 + x2))
    target = _inv(alpha) + 2 * math.tan(alpha) * xs / zs
    lo, hi = 1e-6, math.radians(60)
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if _inv(mid) < target else (lo, mid)
    return module * zs / 2 * math.cos(alpha) / math.cos((lo + hi) / 2)


def test_a_profile_shifted_pair_is_drawn_at_its_working_centre_distance():
    """Gears of 12 and 30 teeth, module 2, shifted +0.5 and +0.1: their axes are drawn a_w apart
    (not (12 + 30) module / 2 = 42), and their blocks touch."""
    mech = gl.Mechanism.from_dict({
        "name": "shifted pair", "links": {0: "frame", 1: "pinion", 2: "wheel"},
        "turning_pairs": [[0, 1, "a"], [0, 2, "b"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [12, 30], "module": 2, "profile_shift": [0.5, 0.1]}],
        "ground": 0, "inputs": [1], "output": 2})
    sk = gl.sketch_layout(mech)
    assert sk.notes == ()
    ys = sorted(a.start[1] for a in sk.axes)
    a_w = _working_distance(12, 30, 0.5, 0.1, module=2)
    assert a_w > 42 + 0.5   # the shift opens the centre distance
    assert ys[1] - ys[0] == pytest.approx(a_w, rel=1e-9)
    check_sketch(mech, sk)


def test_the_6hp26_long_pinion_runs_at_its_working_centre_distance():
    """ZF 6HP26: the long pinion 10 (23 teeth, x = 0.25) meshes the large sun 5 (38, x = 0.2793) and
    the ring 7 (85, x = 0.25, internal): both working centre distances are 31 modules to the data's
    rounding, not the 30.5 the reference radii give the sun pair; the pinion's axis is drawn there,
    and the sketch notes nothing."""
    mech = gl.catalog.load("zf_6hp26")
    sk = gl.sketch_layout(mech)
    assert sk.notes == ()
    sun = _working_distance(23, 38, 0.25, 0.2793)
    ring = _working_distance(23, 85, 0.25, 0.25, internal=True)
    assert sun == pytest.approx(ring, abs=1e-3) and abs(sun - 30.5) > 0.4
    module = next(b.radius for b in sk.blocks if b.link == 4) / (31 / 2)   # the unshifted small sun
    label = mech.coaxial(10, 6)
    (axis,) = [a for a in sk.axes if a.label == label]
    assert axis.start[1] == pytest.approx(sun * module, rel=1e-9)
    check_sketch(mech, sk)


# ----------------------------------------------------------------------------- double pinions
@pytest.mark.parametrize("name, short, long", [("ravigneaux", 5, 6), ("zf_6hp26", 9, 10)])
def test_the_pinions_of_a_ravigneaux_set_stand_side_by_side(name, short, long):
    """The short and the long pinion stand at different angles about the axis: drawn in two planes
    side by side, touching along their common height, never one over the other."""
    sk = gl.sketch_layout(gl.catalog.load(name))
    (a,), (b,) = ([x for x in sk.blocks if x.link == link] for link in (short, long))
    assert _overlap_area(a.polygon, b.polygon) < 1e-9 * sk.scale
    ya = sorted(y for _, y in a.polygon)
    yb = sorted(y for _, y in b.polygon)
    common = min(ya[-1], yb[-1]) - max(ya[0], yb[0])
    assert _shared_edge(list(a.polygon), list(b.polygon), 1e-9 * sk.scale) == pytest.approx(common)


# ----------------------------------------------------------------------------- labels on the page
def _segments_in_points(ax, sk):
    """Every drawn line piece in display points with its half width, and the link it belongs to
    for the edges of the gear blocks (from the layout: the blocks are drawn in its order); the
    dotted leaders from a label to its link are left out."""
    out = []
    for coll in ax.collections:
        gid = coll.get_gid()
        if gid == "leaders":
            continue
        widths = list(coll.get_linewidths()) or [1.0]
        if gid == "blocks":
            pieces = [np.array(b.polygon + (b.polygon[0],)) for b in sk.blocks]
            owners = [b.link for b in sk.blocks]
        elif hasattr(coll, "get_segments"):
            pieces = coll.get_segments()
            owners = [None] * len(pieces)
        else:   # the hatched frame: its outlines
            pieces = [p.vertices for p in coll.get_paths()]
            owners = [None] * len(pieces)
        for i, (seg, owner) in enumerate(zip(pieces, owners)):
            pts = ax.transData.transform(np.asarray(seg, dtype=float)[:, :2])
            half = widths[i % len(widths)] / 2 * ax.figure.dpi / 72
            out += [(pts[j], pts[j + 1], half, owner) for j in range(len(pts) - 1)]
    return out


def _box_meets_segment(box, p, q, half):
    x0, y0, x1, y1 = box.x0 - half, box.y0 - half, box.x1 + half, box.y1 + half
    if max(p[0], q[0]) <= x0 or min(p[0], q[0]) >= x1 or max(p[1], q[1]) <= y0 or min(p[1], q[1]) >= y1:
        return False
    d = q - p
    sides = [d[0] * (cy - p[1]) - d[1] * (cx - p[0]) for cx, cy in ((x0, y0), (x1, y0), (x0, y1), (x1, y1))]
    return not (all(s > 0 for s in sides) or all(s < 0 for s in sides))


def _label_boxes(ax):
    """(text, box of its white patch in display points) of every label drawn."""
    fig = ax.figure
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    return [(t.get_text(), (t.get_bbox_patch() or t).get_window_extent(renderer)) for t in ax.texts]


@pytest.mark.parametrize("name", CATALOGUE)
def test_labels_overlap_no_line_and_no_other_label(name):
    """On the rendered figure (text extents from the renderer, not from the layout): no two labels'
    boxes (link ids, brake and clutch names) overlap, and none meets a drawn line, another link's
    gear block or the hatched frame (a link's id may sit on its own block, over its outline)."""
    mech = gl.catalog.load(name)
    sk = gl.sketch_layout(mech)
    ax = gl.draw_sketch(mech)
    tol = 0.5 * ax.figure.dpi / 72   # half a point: boxes that only touch do not overlap
    labels = _label_boxes(ax)
    for i, (ta, a) in enumerate(labels):
        for tb, b in labels[i + 1:]:
            overlap = min(a.x1, b.x1) - max(a.x0, b.x0), min(a.y1, b.y1) - max(a.y0, b.y0)
            assert min(overlap) <= tol, (name, ta, tb)
    segments = _segments_in_points(ax, sk)
    ids = {str(link) for link in mech.link_ids}
    for text, box in labels:
        own = text.split(" ")[0] if text.split(" ")[0] in ids else None
        inner = box.padded(-tol)
        hits = [(p, q) for p, q, half, owner in segments
                if str(owner) != own and _box_meets_segment(inner, p, q, half)]
        assert not hits, (name, text, hits[:2])
    plt.close(ax.figure)


# ----------------------------------------------------------------------------- crossings, recounted
def _crossings_drawn(sk):
    """Every point where a horizontal piece of one link (shaft, drum, pin) and a vertical piece of
    another (spoke, arm, riser) cross, counted on the drawn lines themselves, not by the router."""
    tol = 1e-7 * sk.scale
    flat, upright = [], []
    for ln in sk.lines:
        (x0, y0), (x1, y1) = ln.start, ln.end
        if abs(y0 - y1) < tol < abs(x0 - x1):
            flat.append((min(x0, x1), max(x0, x1), y0, ln))
        elif abs(x0 - x1) < tol < abs(y0 - y1):
            upright.append((x0, min(y0, y1), max(y0, y1), {ln.link}, ln.kind))
    for sym in sk.symbols:   # a clutch: its two spokes and the gap between its plates are one piece
        if sym.kind != "clutch":
            continue
        x = (sym.segments[0][0][0] + sym.segments[0][1][0]) / 2
        parts = [u for u in upright if abs(u[0] - x) < tol and u[3] <= set(sym.links) and u[4] == "spoke"]
        if len(parts) == 2:
            upright = [u for u in upright if u not in parts]
            upright.append((x, min(u[1] for u in parts), max(u[2] for u in parts), set(sym.links), "clutch"))
    return [(h.kind, h.link, kind, tuple(links)) for x0, x1, y, h in flat for x, ya, yb, links, kind in upright
            if h.link not in links and x0 + tol < x < x1 - tol and ya + tol < y < yb - tol]


def _pins_through_gears(sk):
    """Visible pin pieces that run through a gear block of another axis (a pin may pass behind the
    other pinion of its set, drawn as a hidden, dashed, piece)."""
    tol = 1e-7 * sk.scale
    out = []
    for ln in sk.lines:
        if ln.kind != "pin" or abs(ln.start[1] - ln.end[1]) > tol:
            continue
        y = ln.start[1]
        x0, x1 = sorted((ln.start[0], ln.end[0]))
        for b in sk.blocks:
            xs, ys = [p[0] for p in b.polygon], [p[1] for p in b.polygon]
            centred = abs((min(ys) + max(ys)) / 2 - y) < tol   # a planet on this pin
            if not centred and min(ys) + tol < y < max(ys) - tol and min(x1, max(xs)) - max(x0, min(xs)) > tol:
                out.append((ln.link, b.link))
    return out


@pytest.mark.parametrize("name", CATALOGUE)
def test_no_drawn_line_crosses_another(name):
    """Recounted on the geometry: no piece of one link crosses a line of another, and no visible
    pin runs through another axis's gear, in any catalogue sketch."""
    sk = gl.sketch_layout(gl.catalog.load(name))
    assert _crossings_drawn(sk) == []
    assert _pins_through_gears(sk) == []
