"""The course kit: what a lecturer hands out and what stays with them (``make course``).

    python -m course.build notebooks [--classlist course/class.csv] [--out course/_build]
                                     [--hub URL] [--repo URL] [--branch NAME]
    python -m course.build html [--out course/_build]

``notebooks`` reads every exercise notebook and its solution page (``exercises/NN_*.ipynb``,
``book/solutions/NN_*.ipynb``) and writes, under ``--out``:

* ``nbgrader/``: an nbgrader course directory (run every ``nbgrader`` command there): the
  instructor's ``source/`` assignments, one per chapter (worked solutions and autograder test
  cells), the ``release/`` nbgrader generates from them (no solutions), the class list in its
  ``gradebook.db``, ``variants.json`` and ``nbgrader_config.py``. Submissions, grades and
  feedback already there are kept.
* ``students/<id>/<assignment>/<assignment>.ipynb``: each student's notebooks, with their id
  and their own numbers.
* ``links.md``: the nbgitpuller link of each chapter for the class's hub;
  ``README.md``: what is where, the assignments with their points and minutes.

``html`` builds the course's HTML book, ``--out/html``: the book without its solution pages,
from the notebooks the last book build executed (``make book``), so nothing runs twice.
"""

from __future__ import annotations

import argparse
import json
import os
import pathlib
import shutil
import subprocess
import sys

from .assignments import source_notebook
from .exercises import ROOT, CourseError, pages
from .links import markdown as links_markdown
from .links import table as links_table
from .students import read_class, student_copy

HERE = pathlib.Path(__file__).resolve().parent


def _nbgrader(course: pathlib.Path, *args: str) -> None:
    cmd = [sys.executable, "-m", "nbgrader", *args]
    # nbgrader runs alembic (its database migrations) by name: the environment's bin first
    env = {**os.environ, "PATH": f"{pathlib.Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}"}
    done = subprocess.run(cmd, cwd=course, capture_output=True, text=True, env=env)
    if done.returncode != 0:
        raise CourseError(f"nbgrader {' '.join(args)} failed:\n{(done.stdout + done.stderr)[-3000:]}")


def _write_json(path: pathlib.Path, data) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")


def _checks() -> dict:
    import gearlib as gl

    return {name: gl.check.get(name) for name in gl.check.names()}


def build_notebooks(out: pathlib.Path, classlist: pathlib.Path, hub: str, repo: str, branch: str) -> dict:
    students = read_class(classlist)
    checks = _checks()
    course = out / "nbgrader"
    course.mkdir(parents=True, exist_ok=True)
    shutil.copy(HERE / "nbgrader_config.py", course / "nbgrader_config.py")
    _write_json(course / "variants.json", {s.id: s.variant for s in students})
    with open(course / "students.csv", "w", encoding="utf-8") as f:
        f.write("id,first_name,last_name,email\n")
        for s in students:
            f.write(",".join(x.replace(",", " ") for x in (s.id, s.first_name, s.last_name, s.email)) + "\n")

    assignments = []
    for directory in ("source", "release"):
        shutil.rmtree(course / directory, ignore_errors=True)
    for page in pages():
        graded = [e for e in page.exercises if e.check in checks]
        if not graded:
            continue
        aid = page.name
        notes = []
        _write_json(course / "source" / aid / f"{aid}.ipynb", source_notebook(page, checks, notes))
        for note in notes:
            print(f"note: {note}")
        assignments.append({"assignment": aid, "chapter": int(page.chapter), "exercises": len(graded),
                            "points": sum(checks[e.check].points for e in graded),
                            "minutes": sum(e.minutes for e in page.exercises),
                            "variants": sum(checks[e.check].variants for e in graded)})
        unchecked = [e.number for e in page.exercises if e.check not in checks]
        if unchecked:
            print(f"note: {page.path.name}: exercises {', '.join(unchecked)} have no check and are not graded")

    _nbgrader(course, "db", "student", "import", "students.csv")
    if assignments:
        _nbgrader(course, "generate_assignment", "*", "--force")

    shutil.rmtree(out / "students", ignore_errors=True)
    for a in assignments:
        aid = a["assignment"]
        release = json.loads((course / "release" / aid / f"{aid}.ipynb").read_text(encoding="utf-8"))
        for s in students:
            _write_json(out / "students" / s.id / aid / f"{aid}.ipynb", student_copy(release, s, checks))

    rows = links_table(ROOT, hub, repo, branch)
    (out / "links.md").write_text(links_markdown(rows, hub, repo, branch), encoding="utf-8")
    summary = {"assignments": assignments, "students": [s.id for s in students], "links": rows}
    _write_json(out / "course.json", summary)
    (out / "README.md").write_text(_overview(summary), encoding="utf-8")
    return summary


def _overview(summary: dict) -> str:
    lines = ["# The course build (made by `make course`)", "",
             "| folder | what | for |", "|---|---|---|",
             "| `students/<id>/` | each student's notebooks, with their own numbers | hand out |",
             "| `nbgrader/release/` | the same notebooks with the book's numbers (nbgrader's release) | hand out |",
             "| `html/` | the HTML book without its solution pages (`make course` after `make book`) | publish |",
             "| `links.md` | an nbgitpuller link per chapter for the hub | publish |",
             "| `nbgrader/` | nbgrader's course directory: `source/` (solutions), gradebook, config | keep |", "",
             "| assignment | chapter | graded exercises | with own numbers | points | minutes |",
             "|---|---|---|---|---|---|"]
    for a in summary["assignments"]:
        lines.append(f"| `{a['assignment']}` | {a['chapter']} | {a['exercises']} | {a['variants']} | "
                     f"{a['points']} | {a['minutes']} |")
    total = summary["assignments"]
    lines.append(f"| all | | {sum(a['exercises'] for a in total)} | {sum(a['variants'] for a in total)} | "
                 f"{sum(a['points'] for a in total)} | {sum(a['minutes'] for a in total)} |")
    lines += ["", f"Students: {len(summary['students'])}. To grade, in `nbgrader/`: copy each student's notebook "
              "to `submitted/<id>/<assignment>/`, then `nbgrader autograde <assignment>` and "
              "`nbgrader generate_feedback <assignment>`; `nbgrader export` writes grades.csv."]
    return "\n".join(lines) + "\n"


def _git(*args: str) -> str:
    done = subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True)
    return done.stdout.strip() if done.returncode == 0 else ""


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m course.build", description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    nb = sub.add_parser("notebooks", help="student notebooks, nbgrader course directory, links")
    nb.add_argument("--classlist", type=pathlib.Path, default=HERE / "class.csv")
    nb.add_argument("--hub", default=os.environ.get("COURSE_HUB") or "http://127.0.0.1:8000")
    nb.add_argument("--repo", default=None, help="the git URL students pull the book from (default: origin)")
    nb.add_argument("--branch", default=None, help="its branch (default: the current one)")
    html = sub.add_parser("html", help="the course's HTML book (no solution pages)")
    for p in (nb, html):
        p.add_argument("--out", type=pathlib.Path, default=HERE / "_build")
    args = parser.parse_args(argv)
    try:
        if args.command == "notebooks":
            repo = args.repo or _git("remote", "get-url", "origin") or ROOT.as_uri()
            branch = args.branch or _git("branch", "--show-current") or "main"
            summary = build_notebooks(args.out, args.classlist, args.hub, repo, branch)
            n = len(summary["assignments"])
            print(f"course: {n} assignments for {len(summary['students'])} students in {args.out}")
        else:
            from .html_book import build_html

            build_html(args.out)
            print(f"course book: {args.out / 'html' / 'index.html'}")
    except CourseError as err:
        print(f"course: {err}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
