"""Random corruptions of valid mechanism files: every one is either still valid or raises a
gearlib error with a one-line message. Nothing else may escape (no numpy, sympy, yaml or
Python errors)."""

import copy
import math

import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import gearlib as gl

SOURCES = ["simple_planetary", "car_differential", "liu_chen_transmission", "cyl_gkc_8", "humpage"]
JUNK = st.one_of(
    st.none(), st.booleans(), st.integers(-10**30, 10**30), st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=12), st.lists(st.integers(-3, 12), max_size=4), st.dictionaries(st.text(max_size=4),
                                                                                       st.integers(), max_size=2),
    st.sampled_from(["pi/4", "e_1_2", "1/0", "x**", "__class__", "nan", "-1", "0", "1e400", "sqrt(-1)", "a"]),
)


def paths(node, prefix=()):
    """Every path to a value inside nested dicts/lists."""
    yield prefix
    if isinstance(node, dict):
        for k, v in node.items():
            yield from paths(v, prefix + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from paths(v, prefix + (i,))


def replace_at(node, path, value):
    if not path:
        return value
    node = copy.deepcopy(node)
    cur = node
    for key in path[:-1]:
        cur = cur[key]
    cur[path[-1]] = value
    return node


def delete_at(node, path):
    if not path:
        return None
    node = copy.deepcopy(node)
    cur = node
    for key in path[:-1]:
        cur = cur[key]
    del cur[path[-1]]
    return node


def assert_clean(data):
    try:
        m = gl.Mechanism.from_dict(data) if isinstance(data, dict) else gl.loads(yaml.safe_dump(data))
    except gl.GearlibError as err:
        text = str(err)
        assert text and "\n" not in text and "Traceback" not in text
        return
    # still valid: it must analyse without surprises
    gl.dof(m)
    gl.to_networkx(m)


@settings(max_examples=250, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(SOURCES), st.data())
def test_replacing_any_value_by_junk(name, data):
    base = gl.catalog.load(name).to_dict()
    all_paths = list(paths(base))
    path = data.draw(st.sampled_from(all_paths))
    junk = data.draw(JUNK)
    assert_clean(replace_at(base, path, junk))


@settings(max_examples=150, deadline=None)
@given(st.sampled_from(SOURCES), st.data())
def test_deleting_any_element(name, data):
    base = gl.catalog.load(name).to_dict()
    path = data.draw(st.sampled_from([p for p in paths(base) if p]))
    assert_clean(delete_at(base, path))


@settings(max_examples=150, deadline=None)
@given(st.sampled_from(SOURCES), st.integers(0, 10**6), st.text(max_size=3))
def test_truncated_or_garbled_text(name, cut, insert):
    text = gl.catalog.path(name).read_text()
    cut = cut % max(1, len(text))
    for broken in (text[:cut], text[:cut] + insert + text[cut:]):
        try:
            gl.loads(broken)
        except gl.GearlibError as err:
            assert "\n" not in str(err)


def test_nan_and_infinity_everywhere_numbers_go():
    base = gl.catalog.load("simple_planetary").to_dict()
    for bad in (math.nan, math.inf, -math.inf):
        for path in [("gear_pairs", 0, "teeth", 0), ("gear_pairs", 1, "teeth", 1)]:
            data = replace_at(base, path, bad)
            try:
                gl.Mechanism.from_dict(data)
            except gl.ToothNumberError as err:
                assert "tooth number" in str(err)
            else:
                raise AssertionError(f"{bad} accepted at {path}")


# ------------------------------------------------------------------ issue 25: corruptions of the text
SPECIAL = st.sampled_from([
    "9^9^9^9", "1e400", "exp(1000)", "2^-5000", "9" * 5000, "'" + "(" * 80 + "1" + ")" * 80 + "'", ".inf", ".nan",
    "[" * 200 + "]" * 200, "{a: " * 100 + "1" + "}" * 100, "&x [1, 2]", "*x", "*nowhere", "!!python/object:os.system",
    "\x00", "\ufeff", "~", "- - - - -", "? a", "<<: {a: 1}", "{}", "[]", "'", '"',
])


def _corrupt(text: str, how: int, at: int, value: str) -> str:
    lines = text.splitlines(keepends=True)
    i = at % max(1, len(lines))
    if how == 0:  # a line given twice: duplicate keys
        return "".join(lines[: i + 1] + lines[i:])
    if how == 1:  # a value replaced by something special
        line = lines[i]
        if ":" in line:
            key = line.split(":", 1)[0]
            lines[i] = f"{key}: {value}\n"
        return "".join(lines)
    if how == 2:  # a number replaced, wherever it is
        import re

        return re.sub(r"\b\d+\b", value if value.strip("9") == "" or value[0].isdigit() else "1e400", text, count=1 + at % 5)
    if how == 3:  # an anchor and an alias bomb in front
        return "".join(f"b{k}: &b{k} [" + ", ".join([f"*b{k - 1}"] * 9 if k else ["x"] * 9) + "]\n"
                       for k in range(at % 12)) + text
    return text + "\n" + value + "\n"  # something appended


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(SOURCES), st.integers(0, 4), st.integers(0, 10**6), SPECIAL)
def test_corrupted_files_load_or_fail_in_one_line(name, how, at, value):
    """Any corruption of a valid file either still loads (and analyses) or raises a gearlib
    error of one line naming the text: never a yaml, Python or numpy error, never a hang."""
    text = _corrupt(gl.catalog.path(name).read_text(), how, at, value)
    try:
        m = gl.loads(text)
    except gl.GearlibError as err:
        assert "\n" not in str(err) and str(err).startswith("<text>") and len(str(err)) < 2000
        return
    gl.dof(m)
