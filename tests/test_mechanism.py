"""Mechanisms as validated data: construction, carriers, round trips, and bad input."""

import copy
import json

import pytest
import sympy

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
