"""Every widget redraws without a browser: an update returns a PNG of its figure, reports the
right numbers in its text, and two different inputs give two different pictures. The
shared canvas keeps its figure private (pyplot never sees it)."""

import matplotlib
import pytest

import gearlib as gl
from gearlib.davies import efficiency_explorer
from gearlib.mechanism.widgets import Canvas

matplotlib.use("Agg")
PNG = b"\x89PNG"


def test_speed_explorer():
    ex = gl.widgets.speed_explorer(gl.catalog.simple_planetary(sun=24, ring=60), ground=3, inputs={1: 1})
    first = ex.update()
    k = ex.keys()[0]
    second = ex.update(**{k: 30})
    assert first[:4] == second[:4] == PNG and first != second


def test_unit_explorer_names_the_units():
    ex = gl.unit_explorer()
    png = ex.update("liu_chen_transmission")
    assert png[:4] == PNG and "transmission" in ex.text.lower()
    assert ex.update("car_differential") != png


def test_transmission_explorer_gives_the_gear_ratio():
    mech = gl.catalog.load("liu_chen_transmission")
    ex = gl.gains.transmission_explorer(mech, gl.transmission.LIU_CHEN_MODES)
    table = gl.shift_table(mech, gl.transmission.LIU_CHEN_MODES)
    for row in table.rows:
        png = ex.update(mode=row.mode.name)
        assert png[:4] == PNG
        assert str(row.ratio) in ex.text or f"{float(row.ratio):.4f}" in ex.text


def test_cornering_and_dgm_explorers_draw_two_different_frames():
    car = gl.cornering_explorer()
    assert car.update(speed=30, turn="right") != car.update(speed=60, turn="left")
    dgm = gl.dgm_explorer([gl.catalog.load("cyl_gkc_8")])
    assert dgm.update(ground=0, terminals=(1, 2, 3))[:4] == PNG


def test_efficiency_explorer_reports_the_laus_efficiency():
    epi = gl.catalog.load("laus_epicyclic")
    ex = efficiency_explorer(epi, 1, 5, 2, eta={(1, 3): 0.99, (2, 3): 0.99})
    assert ex.update()[:4] == PNG
    assert "0.94621" in ex.text  # Laus (2011), eq. (76) at z = 80, 60, 30, 35


def test_efficiency_explorer_labels_every_slider_differently_by_gear():
    """Link 3 of Laus's epicyclic train carries gears 3 and 4: two tooth sliders must not both
    read N_3, and the mesh of annulus 2 is the mesh of gears 2 and 4 (Laus's eta_42)."""
    import ipywidgets

    epi = gl.catalog.load("laus_epicyclic")
    plain = efficiency_explorer(epi, 1, 5, 2).labels()
    assert len(set(plain.values())) == len(plain) == 6
    assert plain["N_3_in_1_3"] == "N_3 (1-3)" and plain["N_3_in_2_3"] == "N_3 (2-3)"
    named = efficiency_explorer(epi, 1, 5, 2, gears={(2, 3): (2, 4)})
    assert sorted(named.labels().values()) == ["N_1", "N_2", "N_3", "N_4", "η 1-3", "η 2-4"]
    shown = [c.description for row in named.controls(ipywidgets) for c in row.children]
    assert sorted(shown) == sorted(named.labels().values())


@pytest.mark.parametrize("keep", [False, True])
def test_canvas_panels_and_frames(keep):
    import matplotlib.pyplot as plt

    before = plt.get_fignums()
    canvas = Canvas(panels=2, width_ratios=[1, 2], keep_axes=keep)
    a = canvas.png(lambda ax: ax.plot([0, 1], [0, 1]), lambda ax: ax.bar([0], [1]))
    b = canvas.png(lambda ax: ax.plot([0, 1], [1, 0]), lambda ax: ax.bar([0], [1]))
    assert a[:4] == b[:4] == PNG and a != b
    assert len(canvas.axes[0].lines) == 1  # the first frame's line is gone
    assert plt.get_fignums() == before


def _controls(view):
    import ipywidgets as w

    stack, found = [view], []
    while stack:
        x = stack.pop(0)
        if isinstance(x, (w.IntSlider, w.FloatSlider, w.FloatLogSlider, w.Dropdown, w.ToggleButtons)):
            found.append(x)
        stack.extend(getattr(x, "children", ()))
    return found


def _explorers():
    mech = gl.catalog.load("liu_chen_transmission")
    return [
        gl.widgets.speed_explorer(gl.catalog.simple_planetary(), ground=3, inputs={1: 1}),
        gl.unit_explorer(),
        gl.gains.transmission_explorer(mech, gl.transmission.LIU_CHEN_MODES),
        gl.cornering_explorer(),
        efficiency_explorer(gl.catalog.load("laus_epicyclic"), 1, 5, 2),
    ]


@pytest.mark.parametrize("index", range(5))
def test_moving_the_first_control_redraws_the_view(index):
    """What a reader's first slider move does in JupyterLab, without the browser."""
    import ipywidgets as w

    ex = _explorers()[index]
    view = ex.widget
    image = next(x for x in view.children if isinstance(x, w.Image))
    before = image.value
    control = _controls(view)[0]
    if isinstance(control, (w.Dropdown, w.ToggleButtons)):
        options = [o[1] if isinstance(o, tuple) else o for o in control.options]
        control.value = options[(options.index(control.value) + 1) % len(options)]
    else:
        control.value = control.max if control.value != control.max else control.min
    assert image.value[:4] == PNG and image.value != before


def _pixels(png):
    import io

    import numpy as np
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(png)).convert("RGBA"))


def test_encode_png_is_read_back_by_pillow():
    import numpy as np

    from gearlib.mechanism.widgets import encode_png

    rgba = np.random.default_rng(5).integers(0, 256, size=(37, 53, 4), dtype=np.uint8)
    assert (_pixels(encode_png(rgba)) == rgba).all()


def _sweeps():
    """Each widget with a sequence of states that moves limits, titles, tick labels and legends."""
    k = "N_1"
    laus = gl.catalog.load("laus_epicyclic")
    gears = gl.gains.transmission_explorer(gl.catalog.load("liu_chen_transmission"),
                                                  gl.transmission.LIU_CHEN_MODES)
    return {
        "speed": (gl.widgets.speed_explorer(gl.catalog.simple_planetary(), ground=3, inputs={1: 1}),
                  [{k: t} for t in (20, 21, 60, 22, 120, 5, 30)]),
        "unit": (gl.unit_explorer(), [{"name": n} for n in ("liu_chen_transmission", "car_differential", "simpson")]),
        "transmission": (gears, [{"mode": m} for m in list(gears.modes)[:4]]),
        "cornering": (gl.cornering_explorer(), [{"speed": v, "turn": t} for v, t in
                                                ((30, "right"), (31, "right"), (90, "left"), (5, "straight"),
                                                 (6, "straight"), (130, "right"))]),
        "dgm": (gl.dgm_explorer([gl.catalog.load("cyl_gkc_8")]),
                [{"ground": 0, "terminals": t} for t in ((1, 2, 3), (1, 2, 4), (2, 3, 5))] + [{"ground": 2}]),
        "efficiency": (efficiency_explorer(laus, 1, 5, 2), [{"eta_1_3": e} for e in (0.95, 0.96, 0.9, 0.999)]
                       + [{"N_1_in_1_3": 40}, {"N_1_in_1_3": 80}]),
    }


@pytest.mark.parametrize("name", ["speed", "unit", "transmission", "cornering", "dgm", "efficiency"])
def test_kept_background_gives_the_pixels_of_a_full_redraw(name):
    """A frame drawn on the kept background must equal the same figure drawn from scratch:
    if the background key missed a change (limits, ticks, legend), the pixels would differ."""
    ex, states = _sweeps()[name]
    kept = 0
    for state in states:
        frame = ex.update(**state)
        canvas = ex._canvas
        before = canvas.backgrounds_drawn
        canvas._key = None  # forget the background: the next render draws everything
        full = canvas._render()
        assert canvas.backgrounds_drawn == before + 1
        assert (_pixels(frame) == _pixels(full)).all(), state
        kept += 1
    assert kept == len(states)
