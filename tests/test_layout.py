"""The layout of gearlib: one subpackage per method of the book, imports that run one way.

Imports are read from the source with `ast` (at module level and inside functions, since a
function-level import is a dependency all the same), together with the lazy export tables
(`EXPORTS`) through which a package loads its modules.
"""

import ast
import importlib
import json
import pathlib
import subprocess
import sys

import networkx as nx
import pytest

import gearlib as gl
from gearlib._common.exports import names_and_modules

ROOT = pathlib.Path(__file__).resolve().parents[1]
PKG = ROOT / "gearlib"
METHODS = ("mechanism", "units", "gains", "adjacency", "davies", "synthesis", "linkages")

# gearlib.__all__ before the subpackages existed: every name must still resolve as gl.<name>
BEFORE = [
    "Mechanism", "Link", "TurningPair", "GearPair", "Bearing", "load", "loads", "save", "catalog", "check",
    "to_networkx", "fundamental_circuits", "FundamentalCircuit", "displacement_graph", "willis_equations",
    "willis_matrix", "WillisEquation", "omega", "ratio_symbols", "dof", "Mobility", "choose_inputs",
    "speeds", "ratio", "Solution", "Constraints", "link_table", "adjacency_matrix", "null_space",
    "speed_ratio_matrix", "plot", "widgets", "draw_graph", "plot_speeds", "number", "random_mechanism",
    "serial_train", "units", "kinematic_units", "Fractionation", "KinematicUnit", "CommonLinkage",
    "fundamental_geared_entities", "ku_catalogue", "plan", "propagation", "unit_plot", "draw_units",
    "draw_fractionation", "draw_ku_catalogue", "unit_widgets", "unit_explorer", "gains", "relation",
    "rules", "transmission", "robots", "propagate", "Propagation", "unit_ratio", "local_gain",
    "derive_rule", "match_rule", "shift_table", "geared_robot", "GearedRobot", "reduced_basis",
    "same_subspace", "constraint_rows", "direction", "show_link_table", "show_matrix", "frequency_table",
    "FrequencyTable", "FrequencyRow", "bearing_frequencies", "BearingFrequencies", "plot_spectrum",
    "load_bearings", "with_bearings", "wheel_speeds", "cornering_explorer", "plot_cornering", "davies",
    "efficiency", "torque_balance_efficiency", "atlas", "synthesis", "terminal_constraint", "identify",
    "plot_dgm", "plot_identification", "dgm_explorer", "GearlibError", "MechanismError", "DataFormatError",
    "UnknownLinkError", "DuplicateEdgeError", "SelfMeshError", "ToothNumberError", "CarrierError",
    "AxisError", "DisconnectedError", "OverconstrainedError", "ConstraintError", "InputError",
    "FileFormatError", "GeometryError",
]


def _modules() -> dict:
    out = {}
    for p in sorted(PKG.rglob("*.py")):
        parts = p.relative_to(ROOT).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        out[name] = p
    return out


MODULES = _modules()


def _target(module: str, is_package: bool, node: ast.ImportFrom) -> str:
    if node.level == 0:
        return node.module or ""
    base = module.split(".") if is_package else module.split(".")[:-1]
    base = base[: len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def import_graph() -> nx.DiGraph:
    """Module -> the gearlib modules it imports (anywhere in its source) or loads lazily."""
    g = nx.DiGraph()
    for name, path in MODULES.items():
        g.add_node(name)
        is_package = path.name == "__init__.py"
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            if isinstance(node, ast.ImportFrom):
                target = _target(name, is_package, node)
                for a in node.names:
                    full = f"{target}.{a.name}"
                    dep = full if full in MODULES else target
                    if dep in MODULES and dep != name:
                        g.add_edge(name, dep)
            elif isinstance(node, ast.Import):
                for a in node.names:
                    if a.name in MODULES and a.name != name:
                        g.add_edge(name, a.name)
        if is_package:
            exports = getattr(importlib.import_module(name), "EXPORTS", {})
            for module in names_and_modules(exports)[1].values():
                g.add_edge(name, f"{name}.{module}")
    return g


def test_the_import_graph_is_read_whole():
    g = import_graph()
    # known edges: one top-level import, one inside a function, one lazy export
    assert g.has_edge("gearlib.mechanism.data", "gearlib._common.topology")
    assert g.has_edge("gearlib.mechanism.kinematics", "gearlib.mechanism.plot")  # inside Solution.plot
    assert g.has_edge("gearlib.units", "gearlib.units.fractionation")
    assert len(g) == len(MODULES) > 90


def test_no_import_cycles():
    cycles = list(nx.simple_cycles(import_graph()))
    assert not cycles, "import cycles: " + "; ".join(" -> ".join(c + c[:1]) for c in cycles[:5])


# A module may import its own subpackage's modules and the layers below its own. The one
# exception: chapter 1's solver gl.speeds(method="nullspace") solves with chapter 4's
# matrix module, which stands on the mechanism data alone (checked below).
LAYER = {"errors": 0, "_common": 1, "mechanism": 2, "catalog": 3, "units": 4, "gains": 5, "adjacency": 4,
         "davies": 4, "synthesis": 4, "linkages": 5, "check": 6, "cli": 6, "__main__": 7, "conftest": 9}
UPWARD = {("gearlib.mechanism.kinematics", "gearlib.adjacency.matrix")}


def _layer(module: str) -> tuple:
    parts = module.split(".")
    return (parts[1] if len(parts) > 1 else "", LAYER[parts[1]] if len(parts) > 1 else 8)


def test_imports_run_one_way_from_data_to_methods_to_command_line():
    g = import_graph()
    wrong = []
    for a, b in g.edges:
        (pa, la), (pb, lb) = _layer(a), _layer(b)
        if pa != pb and lb >= la and (a, b) not in UPWARD and a != "gearlib":
            wrong.append(f"{a} -> {b}")
    assert not wrong, wrong
    for a, b in UPWARD:
        assert g.has_edge(a, b)
        assert {_layer(d)[1] for d in g.successors(b)} <= {0, 1, 2}, f"{b} must stand on the data alone"
        assert not {d for d in g.successors(b) if d.startswith("gearlib.mechanism.")} - {
            "gearlib.mechanism.data", "gearlib.mechanism.elements"}, f"{b} must stand on the data alone"


def test_the_top_level_holds_at_most_sixteen_entries():
    entries = sorted(p.name for p in PKG.iterdir() if p.name != "__pycache__")
    assert len(entries) <= 16, entries
    for method in METHODS:
        assert (PKG / method / "__init__.py").exists(), method


@pytest.mark.parametrize("method", METHODS)
def test_each_method_says_which_chapter_and_paper(method):
    pkg = importlib.import_module(f"gearlib.{method}")
    first = pkg.__doc__.split("\n\n")[0]
    assert "chapter" in first, first
    assert any(author in pkg.__doc__ for author in ("Liu", "Penaud", "Laus", "Chen", "Freudenstein", "Tsai"))


@pytest.mark.parametrize("method", METHODS)
def test_export_tables_match_the_modules(method):
    pkg = importlib.import_module(f"gearlib.{method}")
    where, modules = names_and_modules(pkg.EXPORTS)
    for module in set(modules.values()):
        assert (PKG / method / f"{module}.py").exists(), module
    submodules = {p.stem for p in (PKG / method).glob("*.py")}
    for name, module in where.items():
        mod = importlib.import_module(f"gearlib.{method}.{module}")
        assert name in mod.__all__, f"{name} is not in gearlib.{method}.{module}.__all__"
        # a name equal to a submodule's would be hidden by the module once it is imported
        assert name not in submodules, name
        assert getattr(pkg, name) is getattr(mod, name)
    for module in {m for m in modules.values()}:
        mod = importlib.import_module(f"gearlib.{method}.{module}")
        missing = [n for n in getattr(mod, "__all__", ()) if n not in where and n not in modules
                   and getattr(mod, n).__module__ == mod.__name__ if hasattr(getattr(mod, n), "__module__")]
        assert not missing, f"gearlib.{method}.{module} defines {missing} but {method}.EXPORTS leaves them out"
    assert set(pkg.TOP) <= set(where) | set(modules)


def test_every_name_gearlib_offered_before_still_resolves():
    for name in BEFORE:
        assert getattr(gl, name) is not None, name
    assert set(BEFORE) <= set(gl.__all__)
    assert len(gl.__all__) == len(set(gl.__all__))
    # module names are the modules they were, in their new homes
    assert gl.plot.draw_graph is gl.draw_graph
    assert gl.units.kinematic_units is gl.kinematic_units
    assert gl.unit_plot.draw_units is gl.draw_units
    assert gl.relation.propagate is gl.propagate
    assert gl.atlas.geared_chains is gl.synthesis.geared_chains
    assert gl.scaling.scaling.__module__ == "gearlib.gains.scaling"
    assert gl.davies.network.__module__ == "gearlib.davies.coupling_network"


def test_import_gearlib_loads_no_method():
    code = ("import sys, time; t = time.perf_counter(); import gearlib; t = time.perf_counter() - t; "
            "import json; print(json.dumps(sorted(m for m in sys.modules if m.split('.')[0] in "
            "('gearlib', 'numpy', 'sympy', 'matplotlib', 'networkx', 'yaml'))))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    loaded = json.loads(out.stdout)
    assert loaded == ["gearlib", "gearlib.errors"], loaded
