"""The course kit's parts on their own (quick; the kit as a whole is tests/test_course.py):
reading the exercise and solution pages, a class list, nbgitpuller links, the course's table
of contents, the hub's start page, and binder/ against the project's pins."""

from __future__ import annotations

import os
import pathlib
import re
import runpy
from urllib.parse import parse_qs, urlsplit

import pytest
import yaml

import gearlib as gl
from course.assignments import source_notebook
from course.exercises import CourseError, check_calls, pages
from course.html_book import course_toc
from course.links import pull_link, target_name
from course.students import read_class
from notebook_tools import ROOT


def test_check_calls_are_found_with_their_argument_and_statement():
    code = 'answer = None  # a fraction\ngl.check.intro_gear_ratio(answer)\nx = gl.check.graph_idler.predict(\n    "a")'
    calls = check_calls(code)
    assert [(c.name, c.predict, c.argument, c.statement) for c in calls] == [
        ("intro_gear_ratio", False, "answer", (1, 1)), ("graph_idler", True, '"a"', (2, 3))]
    assert not calls[0].has_variant
    assert check_calls("gl.check.names()") == [] and check_calls("not python (") == []


def test_every_exercise_page_is_read_with_its_checks_and_solutions():
    found = {e.check: e for page in pages() for e in page.exercises}
    assert sorted(n for n in found if n) == gl.check.names()
    for name, exercise in found.items():
        check = gl.check.get(name)
        assert (exercise.number, exercise.title, exercise.stars, exercise.minutes) == (
            check.exercise, check.title, check.stars, check.minutes)
        assert f"gl.check.{name}" in exercise.solution, f"{name}: no worked solution read"
        assert ":::" not in exercise.body and not exercise.body.startswith(":label:")


def test_a_predict_exercise_gets_its_guess_and_its_answer_from_the_solution():
    checks = {n: gl.check.get(n) for n in gl.check.names()}
    predicts = [n for n, c in checks.items() if c.predicts]
    assert predicts
    for page in pages():
        nb = source_notebook(page, checks)
        for c in nb["cells"]:
            name = c["metadata"].get("gearlib", {}).get("check")
            if name in predicts and c["id"].endswith("-guess"):
                region = c["source"].split("### BEGIN SOLUTION\n")[1].split("### END SOLUTION")[0]
                assert re.search(r"^\w+ = ", region, re.M) and "predict(" not in region
                assert f"gl.check.{name}.predict(" in c["source"].split("### END SOLUTION")[1]


def test_an_exercise_whose_solution_never_checks_the_answer_is_refused_or_noted():
    checks = {n: gl.check.get(n) for n in gl.check.names()}
    page = pages()[0]
    page.exercises[0].solution = "x = 1"
    with pytest.raises(CourseError, match=r"exercise 0\.1: its solution does not call gl\.check\.\w+\(\.\.\.\)"):
        source_notebook(page, checks)
    notes = []  # make course goes on, and says which exercise has no worked solution
    nb = source_notebook(page, checks, notes)
    assert len(notes) == 1 and "exercise 0.1" in notes[0]
    answer = [c for c in nb["cells"] if c["id"] == f"{page.exercises[0].label}-answer"][0]
    assert "### BEGIN SOLUTION\n\n### END SOLUTION" in answer["source"]


def test_a_class_list_is_read_or_refused_with_the_row_at_fault(tmp_path):
    path = tmp_path / "class.csv"
    path.write_text("# a comment\nid,first_name,last_name,email,variant\ns1,Ada,L,,\nt1,,,,book\ns2,,,,seed-7\n")
    students = read_class(path)
    assert [(s.id, s.first_name, s.variant) for s in students] == [("s1", "Ada", "s1"), ("t1", "", None),
                                                                   ("s2", "", "seed-7")]
    for text, message in (("name\nAda\n", "header has an 'id' column"), ("id\ns 1\n", "row 2: 's 1' is not a student id"),
                          ("id\na/b\n", "row 2: 'a/b'"), ("id\nx\nx\n", "row 3: student 'x' is listed twice")):
        path.write_text(text)
        with pytest.raises(CourseError, match=re.escape(message)):
            read_class(path)


def test_an_nbgitpuller_link_opens_the_notebook_in_the_pulled_folder():
    link = pull_link("https://hub.example.edu/", "https://git.example.edu/org/gearbook.git", "main",
                     "chapters/01_graph_representation.ipynb")
    parts = urlsplit(link)
    assert parts.netloc == "hub.example.edu" and parts.path == "/hub/user-redirect/git-pull"
    query = {k: v[0] for k, v in parse_qs(parts.query).items()}
    assert query == {"repo": "https://git.example.edu/org/gearbook.git", "branch": "main", "targetpath": "gearbook",
                     "urlpath": "lab/tree/gearbook/chapters/01_graph_representation.ipynb"}
    assert target_name("file:///srv/book/") == "book"


def test_the_hubs_start_page_is_the_link_of_chapter_zero(tmp_path, monkeypatch):
    from traitlets.config import Config

    monkeypatch.setenv("COURSE_STATE", str(tmp_path / "state"))
    monkeypatch.setenv("COURSE_REPO", "https://git.example.edu/gearbook.git")
    monkeypatch.setenv("COURSE_BRANCH", "main")
    monkeypatch.setenv("COURSE_ADMINS", "lecturer, tutor")
    (tmp_path / "class.csv").write_text("id,first_name\ns0001,Ada\ns0002,Bob\n")
    monkeypatch.setenv("COURSE_CLASS", str(tmp_path / "class.csv"))
    c = Config()
    runpy.run_path(str(ROOT / "course" / "jupyterhub_config.py"), init_globals={"get_config": lambda: c})
    first = sorted((ROOT / "chapters").glob("[0-9]*.ipynb"))[0].name
    link = pull_link("https://hub", "https://git.example.edu/gearbook.git", "main", f"chapters/{first}")
    assert c.JupyterHub.default_url == link[len("https://hub"):]
    assert c.Authenticator.allowed_users == {"s0001", "s0002"} and c.Authenticator.admin_users == {"lecturer", "tutor"}
    assert pathlib.Path(c.Spawner.cmd[0]).name == "jupyterhub-singleuser" and os.access(c.Spawner.cmd[0], os.X_OK)
    assert c.ConfigurableHTTPProxy.command[0].endswith("node_modules/.bin/configurable-http-proxy")


def test_the_course_toc_is_the_books_without_the_solutions():
    toc = yaml.safe_load((ROOT / "book" / "_toc.yml").read_text())
    course = course_toc(toc)
    text, course_text = yaml.safe_dump(toc), yaml.safe_dump(course)
    assert "book/solutions/" in text and "book/solutions/" not in course_text
    assert course_text.count("file:") == text.count("file:") - text.count("file: book/solutions/")


def _pins(path: pathlib.Path) -> dict:
    out = {}
    for line in path.read_text().splitlines():
        m = re.match(r"^([A-Za-z0-9_.\-]+)==(\S+)$", line.strip())
        if m:
            out[m.group(1).lower().replace("_", "-")] = m.group(2)
    return out


def test_binder_is_pinned_as_the_project_is():
    binder = ROOT / "binder"
    assert _pins(binder / "constraints.txt") == _pins(ROOT / "environment.txt"), \
        "binder/constraints.txt differs from environment.txt: make binder-constraints"
    lines = [ln.split("#")[0].strip() for ln in (binder / "requirements.txt").read_text().splitlines()]
    names = [ln for ln in lines if ln and not ln.startswith("-")]
    assert "-c constraints.txt" in lines and names
    pins = _pins(binder / "constraints.txt")
    assert [n for n in names if n.lower().replace("_", "-") not in pins] == []
    assert os.access(binder / "postBuild", os.X_OK) and (binder / "runtime.txt").read_text().strip() == "python-3.11"


def test_the_proxy_is_pinned_by_its_lock_file():
    import json

    folder = ROOT / "course" / "proxy"
    wanted = json.loads((folder / "package.json").read_text())["dependencies"]["configurable-http-proxy"]
    lock = json.loads((folder / "package-lock.json").read_text())
    assert lock["packages"]["node_modules/configurable-http-proxy"]["version"] == wanted
