"""The dense null-space baseline of chapter 3's timing comparison, and the curve helpers.
Timings themselves are never asserted (they belong to `make bench`)."""

from fractions import Fraction

import matplotlib
import pytest

import gearlib as gl
from gearlib.gains.scaling import ScalingCurve, dense_nullspace_ratio

matplotlib.use("Agg")


@pytest.mark.parametrize("n", [1, 2, 5, 12])
def test_dense_baseline_gives_the_serial_train_ratio(n):
    assert dense_nullspace_ratio(gl.serial_train(n), output=n + 1, input=1, ground=0) == pytest.approx(
        float(Fraction(-1, 2) ** n), rel=1e-9)


@pytest.mark.parametrize("seed", range(6))
def test_dense_baseline_agrees_with_the_exact_solver_on_random_trains(seed):
    m = gl.random_mechanism(8, dof=1, rng=seed)
    exact = gl.ratio(m, output=m.link_ids[-1], input=1, ground=0)
    assert dense_nullspace_ratio(m, output=m.link_ids[-1], input=1, ground=0) == pytest.approx(float(exact),
                                                                                               rel=1e-8)


def test_dense_baseline_refuses_bad_input():
    m = gl.serial_train(3)
    with pytest.raises(gl.InputError, match="output link 9"):
        dense_nullspace_ratio(m, output=9, input=1, ground=0)
    two_dof = gl.catalog.load("ravigneaux")
    with pytest.raises(gl.InputError, match="one degree of freedom; this mechanism has 2"):
        dense_nullspace_ratio(two_dof, output=2, input=1, ground=0)


def test_curve_exponent_and_extrapolation_on_known_power_laws():
    sizes = (100, 200, 400, 800)
    cubic = ScalingCurve("dense null space", sizes, tuple(2e-9 * n**3 for n in sizes))
    linear = ScalingCurve("propagation", sizes, tuple(3e-5 * n for n in sizes))
    assert cubic.exponent() == pytest.approx(3.0)
    assert linear.exponent() == pytest.approx(1.0)
    assert cubic.extrapolate(1600) == pytest.approx(2e-9 * 1600**3)
    assert linear.per_pair == pytest.approx((3e-5,) * 4)


def test_scaling_checks_its_arguments_and_plots():
    with pytest.raises(gl.InputError, match="unknown method 'qr'"):
        gl.scaling.scaling("qr", (10,))
    with pytest.raises(gl.InputError, match="positive"):
        gl.scaling.scaling("propagation", (0,))
    curve = gl.scaling.scaling("propagation", (5, 10), repeat=1)
    assert curve.sizes == (5, 10) and all(t > 0 for t in curve.seconds)
    ax = gl.scaling.plot_scaling(curve)
    assert ax.get_xscale() == "log" and "propagation" in ax.get_legend().get_texts()[0].get_text()


def test_propagation_leaves_the_garbage_collector_as_it_found_it():
    """plan() and the evaluation pause the cyclic collector (gearlib._common.nogc); the state comes
    back as it was, also when the call raises, and a collector the caller disabled stays off."""
    import gc

    m = gl.serial_train(4)
    assert gc.isenabled()
    assert gl.unit_ratio(m, output=5, input=1, ground=0) == Fraction(1, 16)
    assert gc.isenabled()
    with pytest.raises(gl.errors.GearlibError):
        gl.unit_ratio(m, output=99, input=1, ground=0)
    assert gc.isenabled()
    gc.disable()
    try:
        gl.unit_ratio(gl.serial_train(3), output=4, input=1, ground=0)
        assert not gc.isenabled()
    finally:
        gc.enable()


def test_uncached_copies_keep_nothing_an_earlier_run_computed():
    """The scaling curves time propagation on copies of one train (gearlib.gains.scaling._uncached):
    a copy must carry none of the caches a run leaves behind, and give the same ratio."""
    import dataclasses

    from gearlib.gains.scaling import _uncached

    train = gl.serial_train(6)
    fresh_keys = set(train.__dict__)
    assert gl.unit_ratio(train, output=7, input=1, ground=0) == Fraction(1, 64)
    assert set(train.__dict__) > fresh_keys  # the run cached something on the mechanism
    copy = _uncached(train)
    assert set(copy.__dict__) == fresh_keys and copy == train
    for gp in copy.gear_pairs:
        assert set(gp.__dict__) == {f.name for f in dataclasses.fields(gp)}
    assert gl.unit_ratio(copy, output=7, input=1, ground=0) == Fraction(1, 64)
