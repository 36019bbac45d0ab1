"""Project hygiene: notebooks stripped and listed in the book, imports without side effects."""

import json
import pathlib
import subprocess
import sys

import yaml

from notebook_tools import ROOT, cells_with_outputs, notebooks


def test_notebooks_are_committed_without_outputs():
    dirty = {str(p.relative_to(ROOT)): cells for p in notebooks() if (cells := cells_with_outputs(p))}
    assert not dirty, f"strip outputs with `make strip`: {dirty}"


def test_every_notebook_is_in_the_table_of_contents_and_every_entry_exists():
    toc = yaml.safe_load((ROOT / "book" / "_toc.yml").read_text())
    files = []

    def walk(node):
        if isinstance(node, dict):
            if "file" in node:
                files.append(node["file"])
            for v in node.values():
                walk(v)
        elif isinstance(node, list):
            for v in node:
                walk(v)

    walk(toc)
    files.append(toc["root"])
    for f in files:
        assert any((ROOT / f).with_suffix(s).exists() for s in (".ipynb", ".md")), f
    listed = {str(pathlib.Path(f)) for f in files}
    for p in notebooks():
        assert str(p.relative_to(ROOT).with_suffix("")) in listed, f"{p} is not in book/_toc.yml"


def test_notebooks_use_the_gl_alias_and_no_path_hacks():
    for p in notebooks():
        nb = json.loads(p.read_text())
        code = "\n".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code")
        assert "sys.path" not in code, p
        assert "pip install" not in code, p
        if "gearlib" in code:
            assert "import gearlib as gl" in code, p


STATE = r"""
import json, random, sys
import numpy as np
import matplotlib
def snapshot():
    return {
        "rc": {k: repr(v) for k, v in matplotlib.rcParams.items()},
        "np_print": repr(np.get_printoptions()),
        "np_random": repr(np.random.get_state()[1][:8].tolist()) + repr(np.random.get_state()[2:]),
        "py_random": repr(random.getstate()[1][:8]),
        "np_err": repr(np.geterr()),
    }
before = snapshot()
import gearlib as gl
gl.check.names()          # loads every check module
gl.catalog.names()
after = snapshot()
diff = [k for k in before if before[k] != after[k]]
print(json.dumps(diff))
"""


def test_importing_gearlib_changes_no_global_state():
    out = subprocess.run([sys.executable, "-c", STATE], capture_output=True, text=True, check=True, cwd=ROOT)
    assert json.loads(out.stdout.strip().splitlines()[-1]) == []


def test_plotting_does_not_change_matplotlib_settings():
    code = (
        "import matplotlib; matplotlib.use('Agg'); import gearlib as gl;"
        "before = dict(matplotlib.rcParams);"
        "gl.draw_graph(gl.catalog.car_differential());"
        "gl.speeds(gl.catalog.simple_planetary(), ground=3, inputs={1: 1}).plot();"
        "print(before == dict(matplotlib.rcParams))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    assert out.stdout.strip() == "True"


def _documented_on_the_api_page() -> set[str]:
    """Every name book/api.md documents: each autodoc target, the members it lists, and the
    public names of a module documented with all its members."""
    import importlib
    import re

    lines = (ROOT / "book" / "api.md").read_text(encoding="utf-8").splitlines()
    names = set()
    for i, line in enumerate(lines):
        m = re.match(r"\.\. auto(\w+):: ([\w.]+)", line.strip())
        if not m:
            continue
        kind, target = m.groups()
        names.add(target.rsplit(".", 1)[-1])
        following = lines[i + 1].strip() if i + 1 < len(lines) else ""
        if following.startswith(":members:"):
            listed = following[len(":members:"):].strip()
            if listed:
                names |= {x.strip() for x in listed.split(",")}
            elif kind == "module":
                names |= set(getattr(importlib.import_module(target), "__all__", ()))
    return names


def test_every_function_a_chapter_calls_is_on_the_api_page():
    """The book's first page promises that the API reference documents every function the
    chapters call (``gl.<name>(...)``)."""
    import re

    documented = _documented_on_the_api_page()
    missing = {}
    for p in sorted((ROOT / "chapters").glob("*.ipynb")):
        for cell in json.loads(p.read_text(encoding="utf-8"))["cells"]:
            if cell["cell_type"] != "code":
                continue
            for m in re.finditer(r"\bgl\.((?:\w+\.)*\w+)\s*\(", "".join(cell["source"])):
                if m.group(1).rsplit(".", 1)[-1] not in documented:
                    missing.setdefault(f"gl.{m.group(1)}", set()).add(p.stem)
    assert not missing, f"called in a chapter, not on book/api.md: {missing}"


def test_every_package_gearlib_imports_is_a_declared_dependency():
    """``pip install .`` brings what the library imports: every third-party module imported
    anywhere in gearlib/ (its pytest configuration, conftest.py, aside) belongs to a
    distribution named in pyproject's dependencies, and each one named is imported."""
    import ast
    import re
    import tomllib
    from importlib.metadata import packages_distributions

    imported = set()
    for path in (ROOT / "gearlib").rglob("*.py"):
        if path.name == "conftest.py":
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                imported |= {a.name.split(".")[0] for a in node.names}
            elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                imported.add(node.module.split(".")[0])
    third = imported - set(sys.stdlib_module_names) - {"gearlib", "__future__"}

    def norm(name):
        return re.sub(r"[-_.]+", "-", name).lower()

    declared = {norm(re.split(r"[<>=!~\[; ]", d)[0])
                for d in tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["dependencies"]}
    owners = packages_distributions()
    needed = {m: {norm(d) for d in owners.get(m, [m])} for m in third}
    missing = sorted(m for m, dists in needed.items() if not dists & declared)
    assert not missing, f"gearlib imports {missing}: add them to pyproject's dependencies"
    unused = declared - {d for dists in needed.values() for d in dists}
    assert not unused, f"pyproject declares {sorted(unused)}, which gearlib never imports"
