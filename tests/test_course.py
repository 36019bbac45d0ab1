"""The course kit as a lecturer and a grader use it (``make course``; book/lecturers.ipynb).

``python -m course.build notebooks`` builds a course for a small class into a temporary
folder; then nbgrader, by its own command line, grades submissions made from it: the worked
solutions (full marks), untouched notebooks (zero), one with a wrong and a missing answer
(partial marks, the checks' hints as feedback, no answer in it), and students answering
their own numbers, one of whom hands in another student's notebook. Everything handed to
students is searched for every reference answer by value (as tests/test_exercise_leaks.py
does), and so is everything public on a check for each student's numbers.

The exercises are found as the kit finds them, so the tests grow with the book.
"""

from __future__ import annotations

import ast
import contextlib
import io
import json
import re

import pytest

import gearlib as gl
from check_tools import leaks_in, public_texts
from course_tools import (answer_with, cell, grades, html_text, literal, load, nbgrader, run_course_build, save,
                          solved, text)
from gearlib.check import _core
from test_exercise_leaks import leaks

pytestmark = pytest.mark.course

CLASS_LIST = """\
# a test class: a lecturer's test account and a student with the book's numbers, four with their own
id,first_name,last_name,email,variant
lecturer,Test,Account,,book
s0001,Ada,Lovelace,ada@example.edu,
s0002,Charles,Babbage,,
s0003,Mary,Somerville,,
s0004,Emmy,Noether,,
s0005,Sophie,Germain,,book
"""
VARIANT_STUDENTS = ("s0001", "s0002", "s0003", "s0004")


@pytest.fixture(scope="module")
def build(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("course")
    (tmp / "class.csv").write_text(CLASS_LIST, encoding="utf-8")
    done = run_course_build("notebooks", "--classlist", str(tmp / "class.csv"), "--out", str(tmp / "build"),
                            "--hub", "https://hub.example.edu", "--repo", "https://git.example.edu/gearbook.git",
                            "--branch", "main")
    assert done.returncode == 0, done.stdout + done.stderr
    return tmp / "build"


def _checks():
    return {name: gl.check.get(name) for name in gl.check.names()}


def _assignments(build):
    return sorted(p.name for p in (build / "nbgrader" / "source").iterdir())


def _notebook(build, where, assignment):
    return build / where / assignment / f"{assignment}.ipynb"


def _graded_cells(nb):
    """``{check name: [its cells]}`` of a course notebook."""
    out = {}
    for c in nb["cells"]:
        name = c.get("metadata", {}).get("gearlib", {}).get("check")
        if name and "nbgrader" in c["metadata"]:
            out.setdefault(name, []).append(c)
    return out


# ----------------------------------------------------------------------------- the build
def test_every_check_is_a_graded_exercise_worth_its_stars(build):
    checks = _checks()
    tests, answers = {}, {}
    for a in _assignments(build):
        source = load(_notebook(build, "nbgrader/source", a))
        release = load(_notebook(build, "nbgrader/release", a))
        for name, cells in _graded_cells(source).items():
            test = [c for c in cells if c["metadata"]["nbgrader"].get("grade")]
            assert len(test) == 1, f"{name}: {len(test)} test cells"
            meta = test[0]["metadata"]["nbgrader"]
            tests[name] = meta["points"]
            assert meta["locked"] and not meta["solution"]
            assert f"gl.check.grade({name!r}, " in text(test[0]) and "variant=STUDENT" in text(test[0])
            answers[name] = [c for c in cells if c["metadata"]["nbgrader"].get("solution")]
            for c in answers[name]:
                assert "### BEGIN SOLUTION" in text(c) and f"gl.check.{name}" in text(c)
                assert "variant=STUDENT" in text(c)
        for name, cells in _graded_cells(release).items():
            for c in cells:
                assert "BEGIN SOLUTION" not in text(c), f"{a}: a solution is left in {c['id']}"
            released_test = [c for c in cells if c["metadata"]["nbgrader"].get("grade")][0]
            assert text(released_test) == text([c for c in _graded_cells(source)[name]
                                                if c["metadata"]["nbgrader"].get("grade")][0])
    assert sorted(tests) == sorted(checks), "every check, and only checks, are graded"
    for name, points in tests.items():
        assert points == checks[name].stars == checks[name].points, name


def test_the_gradebook_knows_the_class_and_the_points(build):
    from nbgrader.api import Gradebook

    checks = _checks()
    with Gradebook(f"sqlite:///{build / 'nbgrader' / 'gradebook.db'}") as gb:
        assert sorted(s.id for s in gb.students) == ["lecturer", "s0001", "s0002", "s0003", "s0004", "s0005"]
        assert gb.find_student("s0001").email == "ada@example.edu"
        for assignment in gb.assignments:
            chapter = assignment.name.split("_")[0]
            assert assignment.max_score == sum(c.points for c in checks.values() if c.chapter == chapter)
    variants = json.loads((build / "nbgrader" / "variants.json").read_text())
    assert variants["lecturer"] is None and variants["s0001"] == "s0001"


def _unescape(markdown: str) -> str:
    return re.sub(r"\\([\\`*_\[\]<>])", r"\1", markdown)


def test_each_student_notebook_carries_its_own_numbers(build):
    checks = _checks()
    seen = {}
    for a in _assignments(build):
        book = load(_notebook(build, "nbgrader/release", a))
        for sid in ("lecturer", *VARIANT_STUDENTS):
            nb = load(_notebook(build, f"students/{sid}", a))
            variant = None if sid == "lecturer" else sid
            assert text(cell(nb, "course-student")).endswith(f"STUDENT = gl.check.student({variant!r})")
            assert cell(nb, "course-student")["metadata"]["editable"] is False
            for name, check in checks.items():
                if check.chapter != a.split("_")[0]:
                    continue
                statement = [c for c in nb["cells"] if c.get("id", "").endswith("-statement")
                             and c["metadata"]["gearlib"]["check"] == name][0]
                book_statement = [c for c in book["cells"] if c.get("id") == statement["id"]][0]
                if variant and check.variants:
                    assert check.statement(variant) in _unescape(text(statement)), (sid, name)
                    seen.setdefault(name, set()).add(text(statement).split("). ", 1)[1])
                    for option in re.findall(r"^- \*\*[A-Z]\.\*\*.*$", text(book_statement), re.M):
                        assert option in text(statement), f"{sid}, {name}: the option {option!r} is missing"
                else:
                    assert text(statement) == text(book_statement), (sid, name)
    assert seen and all(len(s) > 1 for s in seen.values()), "students share numbers"


def _reference(check, variant):
    return _core._reference(check, variant)[1]


def _files_text(folder):
    for path in sorted(folder.rglob("*")):
        if path.is_file():
            if path.suffix == ".ipynb":
                nb = load(path)
                yield path, "\n".join(text(c) for c in nb["cells"])
            else:
                yield path, path.read_text(encoding="utf-8", errors="replace")


def test_no_file_handed_to_students_holds_a_reference_value(build):
    """The release and the links are searched for every answer with the book's numbers; a
    student's notebook must differ from the release only in the cells that carry the
    student's id and numbers, and no exercise's statement shows its answer for them."""
    checks = _checks()
    found = []
    files = list(_files_text(build / "nbgrader" / "release")) + [(build / "links.md", (build / "links.md").read_text())]
    for path, content in files:
        for name, check in checks.items():
            if path.suffix == ".ipynb" and check.chapter != path.name[:2]:
                continue
            hit = leaks(content, _reference(check, None))
            if hit:
                found.append(f"{path.relative_to(build)}: {check.exercise} {name}: {hit[:3]}")
    for folder in sorted((build / "students").iterdir()):
        variant = None if folder.name in ("lecturer", "s0005") else folder.name
        for a in _assignments(build):
            release = {c["id"]: c for c in load(_notebook(build, "nbgrader/release", a))["cells"]}
            nb = load(folder / a / f"{a}.ipynb")
            assert [c["id"] for c in nb["cells"]] == list(release), f"{folder.name}/{a}: other cells than the release"
            for c in nb["cells"]:
                name = c["metadata"].get("gearlib", {}).get("check")
                own = (c["id"] in ("course-intro", "course-student")
                       or (name and c["id"].endswith("-statement") and variant and checks[name].variants))
                if not own:
                    assert c == release[c["id"]], f"{folder.name}/{a}: cell {c['id']} differs from the release"
                elif name:
                    hit = leaks(text(c), _reference(checks[name], variant))
                    if hit:
                        found.append(f"{folder.name}/{a}: {checks[name].exercise} {name} ({variant}): {hit[:3]}")
    assert not found, "\n".join(found)


def test_nothing_public_on_a_check_carries_a_students_answer():
    """check_tools' search of a check's public surface (tests/test_checks.py does it for the
    book's numbers), for each student's numbers, with what a course notebook adds:
    gl.check.grade's printout and gl.check.student."""
    found = []
    for name, check in _checks().items():
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            points = gl.check.grade(name, None)
        assert (out.getvalue().strip(), points) == (str(check(None)), 0.0)
        if not check.variants:
            continue
        for variant in VARIANT_STUDENTS:
            reference = _reference(check, variant)
            out = io.StringIO()
            with contextlib.redirect_stdout(out):
                points = gl.check.grade(name, None, variant=variant)
            texts = {**public_texts(check), "statement": check.statement(variant), "given": repr(check.given(variant)),
                     "empty answer": str(check(None, variant=variant)), "grade": out.getvalue() + repr(points),
                     "student": repr(gl.check.student(variant))}
            allowed = check.statement(variant) + " " + check.form  # a choice's options are in its statement
            for where, content in texts.items():
                hit = [x for x in leaks_in(content, reference, percent=True) if x not in allowed]
                if hit:
                    found.append(f"{name} ({variant}): {where} shows {hit[:3]}")
    assert not found, "\n".join(found)


def test_a_bad_class_list_is_refused_with_one_line(tmp_path):
    bad = tmp_path / "class.csv"
    bad.write_text("id,first_name\ns0001,Ada\ns0001,Bob\n", encoding="utf-8")
    done = run_course_build("notebooks", "--classlist", str(bad), "--out", str(tmp_path / "out"))
    assert done.returncode == 2
    assert done.stderr.strip().splitlines() == ["course: " + f"{bad}, row 3: student 's0001' is listed twice"]


# ----------------------------------------------------------------------------- grading
def _variant_assignment(build):
    """The assignment with the most exercises whose numbers vary and whose answer is a value."""
    checks = _checks()

    def count(a):
        return sum(1 for c in checks.values() if c.chapter == a[:2] and c.variants and not c.predicts
                   and _fillable(c))

    return max(_assignments(build), key=count)


def _fillable(check, variant="s0001"):
    try:
        literal(_core._example(check, variant))
    except TypeError:
        return False
    return True


def _own_answers(nb, variant):
    """*nb* (a student's notebook) with the right answer to each exercise whose numbers vary
    (not the predictions); returns the names answered."""
    answered = []
    for name, cells in _graded_cells(nb).items():
        check = gl.check.get(name)
        if not check.variants or check.predicts or not _fillable(check, variant):
            continue
        c = [c for c in cells if c["id"].endswith("-answer")][0]
        variable = re.match(r"(\w+)\s*=", text(c)).group(1)
        c["source"] = answer_with(text(c), variable, literal(_core._example(check, variant)))
        answered.append(name)
    return answered


@pytest.fixture(scope="module")
def graded(build):
    """Submissions for every case, graded in one run of ``nbgrader autograde``: (a) the
    lecturer's test account hands in the worked solutions, (b) a student hands in untouched
    notebooks, (c) a student with the book's numbers hands in the worked solutions of one
    chapter with one answer wrong and one missing, and two students answer their own numbers
    while a third hands in the first one's notebook."""
    course = build / "nbgrader"
    submitted = course / "submitted"
    plan = {}
    for a in _assignments(build):
        # (a) the lecturer's test account hands in the worked solutions (the book's numbers)
        source = load(_notebook(build, "nbgrader/source", a))
        for c in source["cells"]:
            if c["cell_type"] == "code":
                c["source"] = solved(text(c))
        save(submitted / "lecturer" / a / f"{a}.ipynb", source)
    # (b) a student hands in their notebook of the largest assignment untouched (that no
    # answer cell of any assignment starts with more than None is checked without running it)
    a = _largest_assignment(build)
    save(submitted / "s0004" / a / f"{a}.ipynb", load(_notebook(build, "students/s0004", a)))
    # (c) a student with the book's numbers: the worked solutions, one answer wrong, one missing
    a = _assignments(build)[0]
    nb = load(_notebook(build, "nbgrader/source", a))
    graded_names = list(_graded_cells(nb))
    wrong = next(n for n in graded_names if not gl.check.get(n).predicts and
                 getattr(_reference(gl.check.get(n), None), "is_number", False) and _reference(gl.check.get(n), None))
    missing = next(n for n in graded_names if n != wrong)
    for name, cells in _graded_cells(nb).items():
        for c in cells:
            code = solved(text(c))  # the student's work is the worked solution, but for the answers below
            if name in (wrong, missing) and c["id"].endswith("-answer"):
                variable = re.match(r"(\w+)\s*=", code).group(1)
                given = literal(-_reference(gl.check.get(name), None)) if name == wrong else "None"
                code = answer_with(code, variable, given)
            c["source"] = code
    save(submitted / "s0005" / a / f"{a}.ipynb", nb)
    plan["partial"] = (a, wrong, missing)
    # two students answer their own numbers; a third hands in the first one's notebook
    a = _variant_assignment(build)
    answered = {}
    for sid in ("s0001", "s0002"):
        nb = load(_notebook(build, f"students/{sid}", a))
        answered[sid] = _own_answers(nb, sid)
        save(submitted / sid / a / f"{a}.ipynb", nb)
    save(submitted / "s0003" / a / f"{a}.ipynb", load(submitted / "s0001" / a / f"{a}.ipynb"))
    plan["variants"] = (a, answered["s0001"])
    nbgrader(course, "autograde", "*")
    return course, grades(course), plan


def test_the_worked_solutions_get_full_marks(build, graded):
    course, marks, _ = graded
    for a in _assignments(build):
        lost = {g: s for g, s in marks[("lecturer", a)].items() if s[0] != s[1]}
        assert not lost, f"{a}: the worked solutions lose points: {lost}"
        assert sum(s[1] for s in marks[("lecturer", a)].values()) > 0


def _largest_assignment(build):
    return max(_assignments(build), key=lambda a: len(_graded_cells(load(_notebook(build, "nbgrader/source", a)))))


def test_untouched_notebooks_get_zero(build, graded):
    course, marks, _ = graded
    a = _largest_assignment(build)
    scores = marks[("s0004", a)]
    assert len(scores) >= 10 and all(s[0] == 0 for s in scores.values()), f"{a}: {scores}"
    assert [key for key in marks if key[0] == "s0004"] == [("s0004", a)]


def test_every_answer_starts_as_none(build):
    """In every notebook handed out, each answer cell gives its answer variable nothing but
    None before the check (so that an untouched notebook earns nothing in any assignment)."""
    for folder in ("nbgrader/release", "students/s0004"):
        for a in _assignments(build):
            for cells in _graded_cells(load(_notebook(build, folder, a))).values():
                for c in cells:
                    if c["metadata"]["nbgrader"].get("grade"):
                        continue
                    tree = ast.parse(text(c))
                    stub = [n for n in tree.body if isinstance(n, ast.Assign)]
                    call = [n for n in tree.body if "gl.check." in ast.unparse(n)]
                    assert stub and call and tree.body.index(stub[-1]) < tree.body.index(call[0]), (a, c["id"])
                    value = ast.literal_eval(stub[-1].value)
                    values = value.values() if isinstance(value, dict) else [value]
                    assert all(v is None for v in values), (a, c["id"], value)


def test_some_wrong_answers_get_partial_marks_and_their_hints_as_feedback(build, graded):
    course, marks, plan = graded
    a, wrong, missing = plan["partial"]
    checks = _checks()
    label = {name: f"ex-{checks[name].exercise.replace('.', '-')}" for name in checks}
    scores = marks[("s0005", a)]
    assert scores[label[wrong]][0] == 0 and scores[label[missing]][0] == 0
    full = {g: s for g, s in scores.items() if g not in (label[wrong], label[missing])}
    assert full and all(s[0] == s[1] for s in full.values())
    total, most = sum(s[0] for s in scores.values()), sum(s[1] for s in scores.values())
    assert 0 < total < most

    nbgrader(course, "generate_feedback", a, "--student", "s0005")
    page = course / "feedback" / "s0005" / a / f"{a}.html"
    shown = html_text(page)
    hint = checks[wrong](-_reference(checks[wrong], None)).message
    empty = checks[missing](None).message
    assert hint != empty and hint in shown and empty in shown
    assert f"(Score: {total:.1f} / {most:.1f})" in shown, "the feedback gives the score"
    for name in (wrong, missing):
        assert not leaks(shown, _reference(checks[name], None)), f"the feedback shows the answer to {name}"


def test_each_student_is_graded_against_their_own_numbers(build, graded):
    course, marks, plan = graded
    a, answered = plan["variants"]
    checks = _checks()
    assert len(answered) >= 3
    label = {name: f"ex-{checks[name].exercise.replace('.', '-')}" for name in answered}
    for sid in ("s0001", "s0002"):
        got = marks[(sid, a)]
        assert all(got[label[n]][0] == got[label[n]][1] > 0 for n in answered), (sid, got)
    # s0003 handed in s0001's notebook (its STUDENT cell says s0001): graded with s0003's numbers
    copied = marks[("s0003", a)]
    differ = [n for n in answered if checks[n].given("s0001") != checks[n].given("s0003")
              and getattr(_reference(checks[n], "s0001"), "is_number", False)
              and _reference(checks[n], "s0001") != _reference(checks[n], "s0003")]
    assert len(differ) >= 3
    assert all(copied[label[n]][0] == 0 for n in differ), {n: copied[label[n]] for n in differ}
    assert sum(s[0] for s in copied.values()) < sum(s[0] for s in marks[("s0001", a)].values())
