"""Mechanisms as validated data: construction, carriers, round trips, and bad input."""

import copy
import json
import math

import pytest
import sympy
import yaml

import gearlib as gl
from conftest import PLANETARY


def test_carriers_are_found_from_the_turning_pairs():
    m = gl.Mechanism.from_dict(PLANETARY)
    assert [gp.carrier for gp in m.gear_pairs] == [4, 4]
    assert m.coaxial(1, 3) == "a" and m.coaxial(1, 2) is None
    assert m.carrier_candidates(1, 2) == [4]


def test_carriers_of_every_catalogue_entry_match_their_sources():
    # carriers stated in the papers (seed notes, reconstructions), found here from axis labels only
    expected = {
        "liu_chen_fig1": {(4, 1): 5, (5, 2): 3, (2, 1): 3},
        "liu_chen_fig3a": {(1, 2): 4, (6, 5): 4, (2, 3): 5},
        "liu_chen_transmission": {(2, 3): 4, (3, 5): 4, (1, 6): 5, (6, 2): 5, (1, 7): 5, (7, 8): 5},
        "cyl_gkc_5_7_2": {(5, 1): 4, (7, 3): 4, (2, 1): 3, (6, 2): 3},
        "cyl_gkc_8": {(5, 0): 2, (6, 3): 2, (4, 1): 2, (7, 4): 5, (7, 6): 5},
        "chen_wrist": {(5, 4): 1, (7, 6): 1, (3, 5): 2, (3, 7): 2},
        "humpage": {(1, 2): 6, (5, 2): 6, (2, 4): 6},
    }
    for name, carriers in expected.items():
        data = gl.catalog.load(name).to_dict()
        for gp in data["gear_pairs"]:
            gp.pop("carrier")  # make the library find them
        m = gl.Mechanism.from_dict(data)
        assert {gp.gears: gp.carrier for gp in m.gear_pairs} == carriers, name


@pytest.mark.parametrize("name", gl.catalog.names())
def test_catalogue_round_trips_through_dict_yaml_and_json(name, tmp_path):
    m = gl.catalog.load(name)
    assert m.source, f"{name} must cite its source"
    assert gl.Mechanism.from_dict(m.to_dict()) == m
    for suffix in (".yaml", ".json"):
        path = tmp_path / f"m{suffix}"
        gl.save(m, path)
        assert gl.load(path) == m
    json.dumps(json.loads(json.dumps({str(k): v for k, v in m.to_dict().items() if k != "links"})))


def test_mechanism_is_immutable_and_replace_revalidates():
    m = gl.Mechanism.from_dict(PLANETARY)
    with pytest.raises(AttributeError):
        m.name = "x"
    m2 = m.with_gear_pair((1, 2), teeth=(30, 15))
    assert m2.gear_pairs[0].teeth == (30, 15) and m.gear_pairs[0].teeth == (24, 18)
    with pytest.raises(gl.ToothNumberError):
        m.with_gear_pair((1, 2), teeth=(0, 15))


def test_ratio_from_teeth_angles_and_symbols():
    ext = gl.GearPair((1, 2), teeth=(20, 60))
    internal = gl.GearPair((1, 2), teeth=(20, 60), kind="internal")
    assert ext.e == sympy.Rational(-1, 3) and internal.e == sympy.Rational(1, 3)
    bevel = gl.GearPair((3, 5), teeth=(14, 10), kind="bevel", angles=("-pi/4", "pi/4"))
    assert sympy.simplify(bevel.e - sympy.Rational(7, 5) * sympy.I) == 0  # e = -T(3,5)/T(5,3) = 1.4 i
    sym = gl.GearPair((5, 1), ratio="e_5_1")
    assert sym.e == sympy.Symbol("e_5_1") and sym.symbol == sympy.Symbol("e_5_1")


def mutate(**changes):
    d = copy.deepcopy(PLANETARY)
    for key, value in changes.items():
        if callable(value):
            value(d)
        else:
            d[key] = value
    return d


def gp(i, **kw):
    def f(d):
        d["gear_pairs"][i].update(kw)
    return f


BAD = [
    # (description, data, error class, text the message must contain)
    ("unknown link in a gear pair", mutate(x=gp(0, gears=[1, 9])), gl.UnknownLinkError, "unknown link 9"),
    ("unknown link in a turning pair", mutate(turning_pairs=[[4, 1, "a"], [4, 3, "a"], [4, 7, "b"]]),
     gl.UnknownLinkError, "unknown link 7"),
    ("unknown carrier", mutate(x=gp(0, carrier=8)), gl.UnknownLinkError, "carrier of gear pair (1, 2)"),
    ("wrong carrier", mutate(x=gp(0, carrier=3)), gl.CarrierError, "carrier 3 does not hold both gears"),
    ("gear without a bearing",
     mutate(links=[1, 2, 3, 4, 5], x=lambda d: d["gear_pairs"].append({"gears": [1, 5], "teeth": [20, 30]})),
     gl.CarrierError, "gear 5 has no turning pair"),
    ("coaxial gears cannot mesh", mutate(turning_pairs=[[4, 1, "a"], [4, 3, "a"], [4, 2, "a"]]),
     gl.CarrierError, "gears 1 and 2 are coaxial"),
    ("no carrier at all", mutate(turning_pairs=[[4, 1, "a"], [4, 3, "b"], [3, 2, "c"]]), gl.CarrierError,
     "gear pair (1, 2) has no possible carrier"),
    ("zero teeth", mutate(x=gp(0, teeth=[0, 18])), gl.ToothNumberError, "gear 1"),
    ("negative teeth", mutate(x=gp(1, teeth=[18, -60])), gl.ToothNumberError, "gear 3"),
    ("fractional teeth", mutate(x=gp(0, teeth=[24.5, 18])), gl.ToothNumberError, "24.5"),
    ("teeth as text", mutate(x=gp(0, teeth=["24", 18])), gl.ToothNumberError, "'24'"),
    ("one tooth number only", mutate(x=gp(0, teeth=[24])), gl.DataFormatError, "two values"),
    ("huge tooth number", mutate(x=gp(0, teeth=[10**9, 18])), gl.ToothNumberError, "larger than"),
    ("NaN tooth number", mutate(x=gp(0, teeth=[float("nan"), 18])), gl.ToothNumberError, "nan"),
    ("a gear meshing with itself", mutate(x=gp(0, gears=[2, 2])), gl.SelfMeshError, "gear 2 with itself"),
    ("a turning pair on one link", mutate(turning_pairs=[[4, 4, "a"], [4, 3, "a"], [4, 2, "b"]]),
     gl.SelfMeshError, "link 4 to itself"),
    ("duplicate gear pair", mutate(gear_pairs=PLANETARY["gear_pairs"] + [{"gears": [2, 1], "teeth": [18, 24]}]),
     gl.DuplicateEdgeError, "(2, 1) is given twice"),
    ("duplicate turning pair", mutate(turning_pairs=PLANETARY["turning_pairs"] + [[1, 4, "a"]]),
     gl.DuplicateEdgeError, "(1, 4) is given twice"),
    ("duplicate link", mutate(links=[1, 2, 3, 4, 4]), gl.DuplicateEdgeError, "link 4 is declared twice"),
    ("disconnected graph", mutate(links={1: "sun", 2: "planet", 3: "ring", 4: "carrier", 5: "lost"}),
     gl.DisconnectedError, "{5}"),
    ("unknown field", mutate(gearpairs=[]), gl.DataFormatError, "unknown field 'gearpairs'"),
    ("unknown gear type", mutate(x=gp(0, type="helical")), gl.DataFormatError, "external, internal, bevel"),
    ("bevel without angles or ratio", mutate(x=gp(0, type="bevel")), gl.DataFormatError, "angles"),
    ("ratio disagrees with teeth", mutate(x=gp(0, ratio=2)), gl.DataFormatError, "disagrees with teeth"),
    ("zero ratio", mutate(x=gp(0, ratio=0, teeth=None)), gl.DataFormatError, "must not be zero"),
    ("no teeth and no ratio", mutate(x=gp(0, teeth=None)), gl.DataFormatError, "give `teeth"),
    ("unreadable ratio", mutate(x=gp(0, teeth=None, ratio="e_1_2 +* 3")), gl.DataFormatError, "cannot read"),
    ("code in a ratio", mutate(x=gp(0, teeth=None, ratio="__import__('os')")), gl.DataFormatError, "unexpected"),
    ("links not a list", mutate(links="1 2 3"), gl.DataFormatError, "`links`"),
    ("gear pairs not a list", mutate(gear_pairs={"gears": [1, 2]}), gl.DataFormatError, "`gear_pairs` must be a list"),
    ("mixed-axis loop of turning pairs",
     mutate(turning_pairs=[[4, 1, "a"], [4, 3, "a"], [4, 2, "b"], [1, 3, "c"]], x=gp(0, carrier=4),
            y=gp(1, carrier=4)), gl.AxisError, "more than one axis label"),
    ("locking loop of gears",
     {"links": [0, 1, 2, 3], "turning_pairs": [[0, 1, "a"], [0, 2, "b"], [0, 3, "c"]],
      "gear_pairs": [{"gears": [1, 2], "teeth": [20, 30]}, {"gears": [2, 3], "teeth": [30, 40]},
                     {"gears": [3, 1], "teeth": [40, 20]}]}, gl.OverconstrainedError, "locks its gears"),
    ("ground not a link", mutate(ground=9), gl.UnknownLinkError, "`ground`"),
    ("bad link id", mutate(links=[1, 2, 3, "four legs"]), gl.DataFormatError, "four legs"),
]


@pytest.mark.parametrize("description, data, error, text", BAD, ids=[b[0] for b in BAD])
def test_malformed_mechanisms_raise_a_named_error(description, data, error, text):
    with pytest.raises(error) as info:
        gl.Mechanism.from_dict(data)
    message = str(info.value)
    assert text in message, message
    assert isinstance(info.value, gl.GearlibError)
    assert "\n" not in message and "Traceback" not in message


def test_there_are_at_least_twenty_distinct_malformed_cases():
    assert len({b[2] for b in BAD}) >= 9 and len(BAD) >= 20


def test_explicit_carrier_is_needed_when_two_are_possible():
    # thin edges with a coaxial loop offer two transfer vertices for pair (1, 2)
    data = {
        "links": [1, 2, 3, 4],
        "turning_pairs": [[3, 1, "a"], [4, 1, "a"], [3, 4, "a"], [3, 2, "b"], [4, 2, "b"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [20, 30]}],
    }
    with pytest.raises(gl.CarrierError, match=r"more than one possible carrier \(3, 4\)"):
        gl.Mechanism.from_dict(data)


def test_files_that_are_not_mechanisms(tmp_path):
    cases = {"empty.yaml": "", "list.yaml": "- 1\n- 2\n", "bad.yaml": "links: [1, 2\n", "text.json": '"hello"'}
    for name, text in cases.items():
        (tmp_path / name).write_text(text)
        with pytest.raises(gl.FileFormatError) as info:
            gl.load(tmp_path / name)
        assert name in str(info.value)
    with pytest.raises(gl.FileFormatError, match="no such file"):
        gl.load(tmp_path / "missing.yaml")


@pytest.mark.parametrize("bad", ["\n", "a\tb", "x\r\ny"])
def test_control_characters_in_ids_stay_on_one_line(planetary_data, bad):
    # found by the fuzz test in CI: the raw id used to break the message over two lines
    planetary_data["turning_pairs"][0][0] = bad
    with pytest.raises(gl.DataFormatError) as info:
        gl.Mechanism.from_dict(planetary_data)
    text = str(info.value)
    assert "\n" not in text and "\t" not in text and "\r" not in text
    assert text.startswith("turning pair (") and repr(bad)[1:-1] in text


# --------------------------------------------------------------------------- transmissions as data
SIMPSON = yaml.safe_load(gl.catalog.path("simpson").read_text())


def with_shifting(**extra):
    d = copy.deepcopy(SIMPSON)
    d.update(extra)
    return d


ELEMENTS = [{"name": "B1", "type": "brake", "link": 4}, {"name": "C1", "type": "clutch", "links": [1, 2]}]


def test_shift_elements_and_schedule_round_trip_and_give_each_gear_its_constraints():
    m = gl.Mechanism.from_dict(with_shifting(
        shift_elements=ELEMENTS, schedule=[{"gear": "1st", "engaged": ["B1"]}, {"gear": "3rd", "engaged": ["C1"]}],
        output=3, planets={5: 3, 6: 4}))
    assert [e.name for e in m.shift_elements] == ["B1", "C1"]
    assert m.gear_constraints("1st") == {"held": [4], "joined": []}
    assert m.gear_constraints("3rd") == {"held": [], "joined": [(1, 2)]}
    assert m.planet_count(5) == 3 and m.planet_count(6) == 4 and m.planet_count(1) == 1
    assert gl.Mechanism.from_dict(m.to_dict()) == m
    # first gear, rear carrier 4 braked, input front ring 2, from the two Willis equations:
    # rear set (carrier 4 held): w1 = -(72/30) w3; front set (carrier 3): w1 - w3 = -(72/30)(w2 - w3)
    k = sympy.Rational(72, 30)
    w2, w3 = sympy.symbols("w2 w3")
    w1 = -k * w3
    sol = sympy.solve([sympy.Eq(w1 - w3, -k * (w2 - w3)), sympy.Eq(w2, 1)], [w2, w3])
    sp = gl.speeds(m, 0, {2: 1}, **m.gear_constraints("1st"))
    assert sp[3] == sol[w3]


BAD_SHIFTING = [
    ("brake on an unknown link", dict(shift_elements=[{"name": "B", "type": "brake", "link": 9}]),
     gl.UnknownLinkError, "unknown link 9"),
    ("clutch on one link", dict(shift_elements=[{"name": "C", "type": "clutch", "links": [2, 2]}]),
     gl.DataFormatError, "joins link 2 to itself"),
    ("clutch with three links", dict(shift_elements=[{"name": "C", "type": "clutch", "links": [1, 2, 3]}]),
     gl.DataFormatError, "got 3 link(s)"),
    ("unknown element type", dict(shift_elements=[{"name": "F", "type": "freewheel", "link": 2}]),
     gl.DataFormatError, "brake or clutch"),
    ("element without a name", dict(shift_elements=[{"type": "brake", "link": 2}]), gl.DataFormatError, "name"),
    ("two elements with one name", dict(shift_elements=[ELEMENTS[0], {"name": "B1", "type": "brake", "link": 2}]),
     gl.DuplicateEdgeError, "declared twice"),
    ("brake on the frame", dict(shift_elements=[{"name": "B", "type": "brake", "link": 0}]),
     gl.DataFormatError, "to itself"),
    ("clutch to the frame", dict(shift_elements=[{"name": "C", "type": "clutch", "links": [0, 2]}]),
     gl.DataFormatError, "that is a brake"),
    ("gear engages an unknown element",
     dict(shift_elements=ELEMENTS, schedule=[{"gear": "1st", "engaged": ["B2"]}]),
     gl.UnknownLinkError, "unknown shift element 'B2'"),
    ("gear listed twice",
     dict(shift_elements=ELEMENTS, schedule=[{"gear": "1st", "engaged": ["B1"]}, {"gear": "1st", "engaged": ["C1"]}]),
     gl.DuplicateEdgeError, "listed twice"),
    ("gear engages an element twice", dict(shift_elements=ELEMENTS, schedule=[{"gear": "1st", "engaged": ["B1", "B1"]}]),
     gl.DataFormatError, "twice"),
    ("schedule entry without a name", dict(shift_elements=ELEMENTS, schedule=[{"engaged": ["B1"]}]),
     gl.DataFormatError, "gear:"),
    ("planets on a link that is no gear", dict(planets={4: 3}), gl.DataFormatError, "not a gear"),
    ("a fractional planet count", dict(planets={5: 2.5}), gl.DataFormatError, "whole number"),
    ("a planet count of True", dict(planets={5: True}), gl.DataFormatError, "whole number"),
    ("planets as a list", dict(planets=[5, 3]), gl.DataFormatError, "mapping"),
    ("output not a link", dict(output=12), gl.UnknownLinkError, "`output`"),
    ("type and kind disagree",
     dict(gear_pairs=[dict(SIMPSON["gear_pairs"][0], type="external", kind="internal")] + SIMPSON["gear_pairs"][1:]),
     gl.DataFormatError, "disagree"),
    ("module and normal module", dict(gear_pairs=[dict(SIMPSON["gear_pairs"][0], module=2, normal_module=2)]
                                     + SIMPSON["gear_pairs"][1:]), gl.DataFormatError, "not both"),
    ("helix angle without a normal module",
     dict(gear_pairs=[dict(SIMPSON["gear_pairs"][0], helix_angle="20*deg")] + SIMPSON["gear_pairs"][1:]),
     gl.DataFormatError, "normal_module"),
]


@pytest.mark.parametrize("description, extra, error, text", BAD_SHIFTING, ids=[b[0] for b in BAD_SHIFTING])
def test_malformed_shift_data_raise_a_named_error(description, extra, error, text):
    with pytest.raises(error) as info:
        gl.Mechanism.from_dict(with_shifting(**extra))
    assert text in str(info.value), str(info.value)
    assert "\n" not in str(info.value)


def test_pitch_radii_from_the_module_or_the_normal_module_and_helix_angle():
    spur = gl.GearPair((1, 2), teeth=(20, 44), module=2.5)
    assert spur.pitch_radii == (25.0, 55.0)  # r = m z / 2
    helical = gl.GearPair((1, 2), teeth=(20, 44), normal_module=2, helix_angle="30*deg")
    m_t = 2 / math.cos(math.radians(30))  # transverse module of a helical gear
    assert helical.pitch_radii == pytest.approx((m_t * 10, m_t * 22), rel=1e-12)
    assert gl.GearPair((1, 2), teeth=(20, 44)).pitch_radii is None
    assert gl.GearPair((1, 2), teeth=(20, 44), radii=(25, 55), module=2.5).pitch_radii == (25.0, 55.0)
    with pytest.raises(gl.DataFormatError, match="disagree with module"):
        gl.GearPair((1, 2), teeth=(20, 44), radii=(25, 56), module=2.5)


# ------------------------------------------------------------------ axis labels left out (issue 25)
def _without_labels(mech):
    data = mech.to_dict()
    data["turning_pairs"] = [tp[:2] if isinstance(tp, list) else {k: v for k, v in tp.items() if k != "axis"}
                             for tp in data["turning_pairs"]]
    return data


@pytest.mark.parametrize("name", gl.catalog.names())
def test_axis_labels_follow_from_the_carriers(name):
    """Penaud's tables mark a turning pair with a bare "p": with every carrier given, the labels
    are inferred, and the mechanism turns exactly as the labelled one (Willis needs the carriers
    only). Coaxialities that no gear pair implies (a sun and a ring on one carrier) are not."""
    mech = gl.catalog.load(name)
    bare = gl.Mechanism.from_dict(_without_labels(mech))
    assert [gp.carrier for gp in bare.gear_pairs] == [gp.carrier for gp in mech.gear_pairs]
    for gp in mech.gear_pairs:  # each gear on its carrier, the two on different axes
        la, lb = (bare.coaxial(g, gp.carrier) for g in gp.gears)
        assert la and lb and la != lb
        assert mech.coaxial(*gp.gears) is None and bare.coaxial(*gp.gears) is None
    ground = mech.ground if mech.ground is not None else mech.link_ids[0]
    assert int(gl.dof(bare, ground)) == int(gl.dof(mech, ground))
    if not mech.is_symbolic:
        assert gl.same_subspace(gl.null_space(gl.adjacency_matrix(bare)), gl.null_space(gl.adjacency_matrix(mech)))
    assert gl.Mechanism.from_dict(bare.to_dict()) == bare  # the inferred labels are written out


def test_penauds_example_1_as_its_table_gives_it():
    """Penaud and Alazard's Table 1 for example 1: "p" between the carrier 4 and links 1, 2, 3."""
    table = gl.Mechanism.from_dict({
        "links": [1, 2, 3, 4], "turning_pairs": [[4, 1], [4, 2], [4, 3]],
        "gear_pairs": [{"gears": [1, 3], "teeth": [15, 10], "type": "bevel", "angles": ["pi/4", "-pi/12"],
                        "carrier": 4},
                       {"gears": [2, 3], "teeth": [25, 10], "type": "bevel", "angles": ["-7*pi/12", "pi/12"],
                        "carrier": 4}]})
    ex1 = gl.catalog.load("penaud_example_1")
    assert gl.speeds(table, ground=1, inputs={2: 1}).values == gl.speeds(ex1, ground=1, inputs={2: 1}).values
    assert table.coaxial(1, 4) and table.coaxial(3, 4) != table.coaxial(1, 4)


def test_axis_labels_in_a_loop_of_bearings_are_one():
    # the car differential: side gears on the frame and in the cage (coaxial bearing loops)
    car = gl.catalog.car_differential()
    bare = gl.Mechanism.from_dict(_without_labels(car))
    assert {tp.links: tp.axis for tp in bare.turning_pairs}[(7, 3)] == {tp.links: tp.axis for tp in
                                                                          bare.turning_pairs}[(1, 3)]
    assert len(bare.redundant_turning_pairs) == len(car.redundant_turning_pairs)


def test_spur_pairs_whose_angles_contradict_their_type_warn():
    base = {"links": [1, 2, 3], "turning_pairs": [[3, 1, "a"], [3, 2, "b"]]}

    def pair(kind, angles):
        return gl.Mechanism.from_dict({**base, "gear_pairs": [{"gears": [1, 2], "teeth": [20, 40], "type": kind,
                                                               "angles": angles}]})

    with pytest.warns(gl.DataWarning, match="internal.*ratio of an external mesh"):
        m = pair("internal", [0, 0])
    assert m.gear_pairs[0].e == sympy.Rational(-1, 2)  # the angles decide
    with pytest.warns(gl.DataWarning, match="complex ratio"):
        pair("external", ["pi/2", 0])
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error", gl.DataWarning)
        assert pair("internal", ["pi", 0]).gear_pairs[0].e == sympy.Rational(1, 2)
        assert pair("external", ["pi/3", "pi/3"]).gear_pairs[0].e == sympy.Rational(-1, 2)


def test_stored_layouts_are_the_kamada_kawai_layouts():
    """The catalogue's graph layouts stored for widgets (gearlib/mechanism/layouts.json) are what
    the optimisation gives now; a networkx that lays them out differently fails here."""
    from gearlib.mechanism.plot import _compute_kamada_kawai, _edges, _layout_key, _stored_layouts

    stored = _stored_layouts()
    assert stored
    for name in gl.catalog.names():
        mech = gl.catalog.load(name)
        key = _layout_key(tuple(mech.link_ids), _edges(mech))
        if mech.layout or key not in stored:
            continue
        fresh = [xy for _, xy in _compute_kamada_kawai(tuple(mech.link_ids), _edges(mech))]
        assert max(abs(a - b) for p, q in zip(stored[key], fresh) for a, b in zip(p, q)) < 1e-3, name
