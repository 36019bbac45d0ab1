"""Tooth numbers a reader changes (chapters 0 and 1): one number per gear, planetary sets that
stay buildable, and speed plots that show only angular velocities. Expected values are worked
out here from the Willis equations by hand (fractions), not taken from the library."""

from fractions import Fraction

import matplotlib
import numpy as np
import pytest

import gearlib as gl
from gearlib.mechanism import followers, gears, set_teeth, tilted_links

matplotlib.use("Agg")


def _teeth(mech):
    return {g.key: g.teeth for g in gears(mech)}


def test_a_planet_meshing_sun_and_ring_is_one_gear_and_a_stepped_planet_two():
    assert _teeth(gl.catalog.simple_planetary(24, 60)) == {"N_1": 24, "N_2": 18, "N_3": 60}
    humpage = _teeth(gl.catalog.humpage())  # the compound planet 2: 56 teeth to gears 1 and 5, 24 to gear 4
    assert humpage["N_2_in_1_2"] == 56 and humpage["N_2_in_2_4"] == 24 and "N_2" not in humpage


@pytest.mark.parametrize("change, expected", [
    ({"N_3": 72}, (24, 24, 72)),   # ring changed: planet (72 - 24)/2
    ({"N_1": 30}, (30, 15, 60)),   # sun changed: planet (60 - 30)/2
    ({"N_2": 20}, (24, 20, 64)),   # planet changed: ring 24 + 2*20
    ({"N_1": 20, "N_2": 10}, (20, 10, 40)),
])
def test_set_teeth_keeps_the_planet_between_sun_and_ring(change, expected):
    mech = set_teeth(gl.catalog.simple_planetary(24, 60), change)
    t = _teeth(mech)
    assert (t["N_1"], t["N_2"], t["N_3"]) == expected
    assert all(c.ok for c in gl.assembly_conditions(mech))
    # every pair agrees on the planet's teeth
    assert {gp.teeth[gp.gears.index(2)] for gp in mech.gear_pairs} == {expected[1]}


@pytest.mark.parametrize("change", [{"N_3": 61}, {"N_3": 20}, {"N_1": 20, "N_2": 10, "N_3": 44}, {"N_9": 3}])
def test_set_teeth_refuses_what_cannot_be_built_and_names_it(change):
    with pytest.raises(gl.GearlibError) as err:
        set_teeth(gl.catalog.simple_planetary(24, 60), change)
    assert "N_" in str(err.value) or "planet" in str(err.value)


def test_the_speed_explorer_has_one_slider_per_planet_and_the_ring_follows():
    ex = gl.widgets.speed_explorer(gl.catalog.simple_planetary(24, 60), ground=3, inputs={1: 1})
    assert ex.keys() == ["N_1", "N_2"] and followers(ex.mechanism) == {"N_3": ("N_1", "N_2")}
    ex.update(N_2=20)
    assert "= 64" in ex.text
    ex.update(N_1=30, N_2=18)  # the sun moves: the ring follows, the planet keeps its teeth
    assert "= 66" in ex.text
    mech = ex.mechanism_for(N_2=20)
    # ring held, sun 24, ring 64: carrier/sun = 24/(24 + 64) by the textbook formula
    assert gl.ratio(mech, output=4, input=1, ground=3) == Fraction(24, 88)


def test_the_speed_explorer_names_teeth_that_cannot_be_built():
    ex = gl.widgets.speed_explorer(gl.catalog.simple_planetary(24, 60), ground=3, inputs={1: 1}, pairs=[(2, 3)])
    assert ex.keys() == ["N_2", "N_3"]  # the sun is not among the pairs: no follower
    before = ex.update()
    after = ex.update(N_2=19, N_3=61)  # both moved: the planet cannot fit
    assert after == before and "planet" in ex.text


def _line(ax, label):
    line = next(x for x in ax.get_lines() if x.get_label() == label)
    return np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float)


def test_the_static_twin_sweeps_buildable_planetaries_and_the_planet_slows_down():
    ax = gl.widgets.plot_speed_sweep(gl.catalog.simple_planetary(24, 60), ground=3, inputs={1: 1}, gear=3,
                                     values=range(40, 101, 4))
    rings, planet = _line(ax, "2 planet")
    _, carrier = _line(ax, "4 carrier")
    for nr, w2, w4 in zip(rings, planet, carrier):
        ns, np_ = 24, (nr - 24) / 2
        c = ns / (ns + nr)                    # carrier, ring held
        p = c + (-ns / np_) * (1 - c)         # Willis for (1, 2) on carrier 4
        assert w4 == pytest.approx(c) and w2 == pytest.approx(p)
    assert np.all(np.diff(np.abs(planet)) < 0), "a consistent planet turns slower as the ring grows"
    import matplotlib.pyplot as plt

    plt.close("all")


def test_bevel_planets_are_tilted_and_shown_by_their_spin():
    assert tilted_links(gl.catalog.humpage()) == {2: 6}
    assert tilted_links(gl.catalog.car_differential()) == {5: 7, 6: 7}
    assert tilted_links(gl.catalog.simple_planetary()) == {}
    assert tilted_links(gl.catalog.compound_train()) == {}
    sol = gl.speeds(gl.catalog.humpage(), ground=5, inputs={1: 1})
    ax = sol.plot()
    heights = sorted(round(b.get_height(), 9) for b in ax.patches)
    # carrier r1/(r1 + r5) = 20/96; planet spin relative to it e_12 (1 - 5/24) = (5/14)(19/24)
    spin = float(Fraction(5, 14) * (1 - Fraction(5, 24)))
    assert round(spin, 9) in heights and round(float(Fraction(5, 24)), 9) in heights
    assert round(55 / 112, 9) not in heights, "the planet's Willis value is no angular velocity"
    assert "2/6" in " ".join(t.get_text() for t in ax.get_xticklabels())
    assert "tilted" in str(sol)
    import matplotlib.pyplot as plt

    plt.close("all")


def test_the_sweep_of_one_gear_of_a_stepped_planet_needs_its_pair():
    with pytest.raises(gl.GearlibError, match="pair"):
        gl.widgets.plot_speed_sweep(gl.catalog.humpage(), ground=5, inputs={1: 1}, gear=2, values=[20, 22])


def test_the_differential_counts_agree_without_the_redundancies():
    mob = gl.dof(gl.catalog.car_differential())
    # 7 links; 8 turning pairs of which 2 close loops; 5 gear pairs of which 1 repeats: 3*6 - 2*6 - 4 = 2
    assert (mob.planar, mob.count, mob.rank) == (-3, 3, 2)
    assert mob.explanation[-1] == "Without them both counts give 2, the rank."
    assert not any("bevel" in text for text in mob.explanation)


def test_formulas_print_ratio_symbols_with_a_comma():
    import sympy

    e = sympy.Symbol("e_1_12") * sympy.Symbol("e_12_3")
    tex = gl.formula(e)._repr_latex_()
    assert "e_{1,12}" in tex and "e_{12,3}" in tex and " 12}" not in tex
    eq = gl.willis_equations(gl.catalog.simple_planetary())[0]
    assert eq._repr_latex_() == r"$\omega_{2} - \omega_{4} = e_{1,2} \left(\omega_{1} - \omega_{4}\right)$"
