"""Lever diagrams (Benford and Leising): node spacing from the teeth, speeds on straight lines.

The spacing rule and the straight-line property are computed here from the teeth and from
gl.speeds, not from the lever code: a simple set's carrier lies between sun and ring with
sun-carrier : carrier-ring = Z_r : Z_s; a double-pinion set's ring lies between sun and
carrier with sun-ring : ring-carrier = (Z_r - Z_s) : Z_s; in any state the arrow tips of a
lever's members lie on one line, which is the drawn velocity line.
"""

from fractions import Fraction

import matplotlib
import pytest

import gearlib as gl

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from test_sketch import eight_speed, random_coaxial  # noqa: E402


def _collinear(points, tol=1e-9):
    (x0, y0), (x1, y1) = points[0], points[-1]
    return all(abs((x1 - x0) * (y - y0) - (y1 - y0) * (x - x0)) < tol * max(1.0, abs(x1 - x0) + abs(y1 - y0))
               for x, y in points)


def _simple_sets(mech):
    """(sun, carrier, ring, Z_s, Z_r) of each simple set, read from the data directly."""
    out = []
    for gp in mech.gear_pairs:
        if gp.kind != "internal":
            continue
        planet, ring = gp.gears if gp.teeth[1] > gp.teeth[0] else gp.gears[::-1]
        zr = max(gp.teeth)
        for other in mech.gear_pairs:
            if other is not gp and planet in other.gears and other.carrier == gp.carrier and other.kind == "external":
                sun = other.gears[0] if other.gears[1] == planet else other.gears[1]
                if mech.coaxial(sun, gp.carrier) is not None:
                    zs = other.teeth[other.gears.index(sun)]
                    out.append((sun, gp.carrier, ring, zs, zr))
    return out


@pytest.mark.parametrize("make", [lambda: gl.catalog.simple_planetary(sun=24, ring=60), eight_speed,
                                  lambda: gl.catalog.load("liu_chen_fig1")])
def test_a_simple_set_is_spaced_by_its_teeth(make):
    mech = make()
    lev = gl.lever_diagram(mech)
    sets = _simple_sets(mech)
    assert sets
    for sun, carrier, ring, zs, zr in sets:
        lever = next(lv for lv in lev.levers if {sun, carrier, ring} <= {n.link for n in lv.nodes})
        xs, xc, xr = (lever.node(k).position for k in (sun, carrier, ring))
        assert min(xs, xr) < xc < max(xs, xr)                  # the carrier between
        assert abs(xs - xc) / abs(xc - xr) == Fraction(zr, zs)  # sun-carrier : carrier-ring = Z_r : Z_s
        assert abs(xs - xc) == zr and abs(xc - xr) == zs        # in tooth units


def test_a_double_pinion_set_puts_the_ring_between():
    mech = gl.Mechanism.from_dict({
        "links": {0: "frame", 1: "sun", 2: "inner pinion", 3: "outer pinion", 4: "ring", 5: "carrier"},
        "turning_pairs": [[0, 1, "a"], [0, 4, "a"], [0, 5, "a"], [5, 2, "b"], [5, 3, "c"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [30, 15]}, {"gears": [2, 3], "teeth": [15, 14]},
                       {"gears": [3, 4], "teeth": [14, 88], "type": "internal"}], "ground": 0})
    lev = gl.lever_diagram(mech)
    (lever,) = lev.levers
    xs, xc, xr = (lever.node(k).position for k in (1, 5, 4))
    assert min(xs, xc) < xr < max(xs, xc)
    assert abs(xs - xr) / abs(xr - xc) == Fraction(88 - 30, 30)
    sol = gl.speeds(mech, 0, {1: 1, 4: Fraction(1, 3)})
    pts = [(float(sol[k]), float(lever.node(k).position)) for k in (1, 4, 5)]
    assert _collinear(pts)


def test_sets_that_share_two_members_make_one_lever():
    """Simpson: common sun, front carrier = rear ring: four members on one lever, in the classic
    order ring 2, carrier/ring 3, carrier 4, sun 1; Ravigneaux: four members on one lever."""
    lev = gl.lever_diagram(gl.catalog.simpson())
    (lever,) = lev.levers
    assert [n.link for n in lever.nodes] == [2, 3, 4, 1]
    assert lever.node(3).role == "C/R"
    (lever,) = gl.lever_diagram(gl.catalog.ravigneaux()).levers
    assert {n.link for n in lever.nodes} == {1, 2, 3, 4}


def _check_lines(mech, state):
    lev = gl.lever_diagram(mech)
    geo = gl.gains.lever_geometry(lev, state)
    sol = lev.speeds(state)
    for i, lever in enumerate(lev.levers):
        tips = [(x, y) for j, link, x, y in geo["tips"] if j == i]
        assert _collinear(tips), (mech.name, state, i)
        (line,) = [(a, b) for j, a, b in geo["lines"] if j == i]
        assert _collinear([line[0], *tips, line[1]])
        # the same from gl.speeds and the node positions alone: speed is affine in position
        pts = [(float(sol[n.link]), float(n.position)) for n in lever.nodes]
        assert _collinear(pts), (mech.name, state, i, pts)
        for s in lever.sets:   # every set's three (or more) nodes too
            assert _collinear([(float(sol[k]), float(lever.node(k).position)) for k in (s.carrier, *s.gears)])


@pytest.mark.parametrize("gear", [g.name for g in eight_speed().schedule])
def test_each_gear_of_a_transmission_draws_straight_velocity_lines(gear):
    mech = eight_speed()
    _check_lines(mech, gear)
    ax = gl.draw_levers(mech, state=gear)
    assert gear in ax.get_title()
    plt.close(ax.figure)


def test_random_trains_draw_straight_velocity_lines():
    for seed in range(40):
        mech = random_coaxial(seed)
        dof = gl.dof(mech).rank
        free = [m for m in mech.link_ids if m != 0 and mech.coaxial(m, 0) is not None][:dof]
        try:
            state = {"ground": 0, "inputs": {m: i + 1 for i, m in enumerate(free)}}
            gl.speeds(mech, **state)
        except gl.InputError:
            continue
        _check_lines(mech, state)


def test_the_speeds_are_gl_speeds():
    mech = eight_speed()
    lev = gl.lever_diagram(mech)
    want = gl.speeds(mech, 0, {1: 1}, **mech.gear_constraints("3rd"))
    assert lev.speeds("3rd") == dict(want.items())
    assert lev.speeds(want) == dict(want.items())


def test_what_has_no_lever_says_why():
    with pytest.raises(gl.MechanismError, match="no planetary set"):
        gl.lever_diagram(gl.catalog.load("compound_train"))
    with pytest.raises(gl.MechanismError, match="symbolic"):
        gl.lever_diagram(gl.catalog.load("cyl_gkc_5_7_2"))
    with pytest.raises(gl.MechanismError, match="unknown key"):
        gl.lever_diagram(gl.catalog.simpson()).speeds({"grond": 0})
    with pytest.raises(gl.UnknownLinkError, match="no gear 'ninth'"):
        gl.lever_diagram(eight_speed()).speeds("ninth")


def test_the_differential_is_a_lever_with_the_case_in_the_middle():
    """Bevel planets: the basic ratio of one side gear to the other is -1 (their complex ratios
    multiply out), so the case sits halfway: it turns at the mean of the wheels."""
    (lever,) = gl.lever_diagram(gl.catalog.car_differential()).levers
    x3, x7, x4 = (lever.node(k).position for k in (3, 7, 4))
    assert x7 - x4 == x3 - x7 != 0


def test_drawing_takes_an_axes():
    fig, ax = plt.subplots()
    assert gl.draw_levers(gl.catalog.simpson(), ax=ax) is ax
    plt.close(fig)


def test_the_housing_is_marked_held_without_a_state():
    """The frame is held in every state: a lever member that is the mechanism's ground carries
    a ground mark even when no state is drawn (Liu-Chen's transmission: the carrier 5 of KU2
    is the housing)."""
    mech = gl.catalog.load("liu_chen_transmission")
    geo = gl.gains.lever_geometry(gl.lever_diagram(mech))
    marks = [e for e in geo["elements"] if e[1] == "brake"]
    assert [e[2] for e in marks] == [(mech.ground,)]
    assert not geo["speeds"]
