"""Command of chapter 7 (:mod:`gearlib.linkages`).

``python -m gearlib linkage FILE [--task NAME | --cycle JOINT | --trajectory PATH] [--action PORT=VALUE]
[--steps N] [--mu MU] [--law cosine|constant] [--json]``: a linkage (a YAML/JSON file, or a
catalogue entry such as ``laus_3upu``) rated by Davies' method over a task: energy in and out,
efficiency, and the share of the losses per coupling. The task is one of the file's tasks
(``--task lift``; the first by default), one turn of a driven revolute joint at unit speed
(``--cycle A``, with the known actions from ``--action``), or a trajectory read from a file
(``--trajectory path.csv``: a column ``t`` and one column per coordinate of each motion input,
``A`` for a joint, ``M.x``, ``M.y``, ``M.z`` for a load port's point; or YAML/JSON with ``t``,
``motion`` and ``actions``). ``--action BC=0`` sets a port's known action (a number, or an
expression in ``t``); ``--mu`` and ``--law`` change every joint's friction.
"""

from __future__ import annotations

import csv
import io
import math
import pathlib

from ..errors import FileFormatError, InputError
from ._args import Command, print_json

__all__ = ["COMMANDS"]


def _arguments(p):
    p.add_argument("file", metavar="FILE", help="linkage file (YAML/JSON) or catalogue name (laus_slider_crank, laus_3upu)")
    what = p.add_mutually_exclusive_group()
    what.add_argument("--task", metavar="NAME", help="one of the file's tasks (default: its first)")
    what.add_argument("--cycle", metavar="JOINT", help="one turn of this revolute joint at unit speed")
    what.add_argument("--trajectory", metavar="PATH", help="a trajectory file: CSV, YAML or JSON")
    p.add_argument("--action", action="append", default=[], metavar="PORT=VALUE",
                   help="known action at a port (a number or an expression in t); repeat")
    p.add_argument("--steps", type=int, metavar="N", help="number of time steps (intervals) of the task")
    p.add_argument("--mu", type=float, metavar="MU", help="Coulomb coefficient of every joint")
    p.add_argument("--law", choices=("cosine", "constant"),
                   help="pressure law on pins: cosine (worn, 4/pi) or constant (new, pi/2)")
    p.add_argument("--json", action="store_true", help="print the result as JSON")


def _actions(items) -> dict:
    out = {}
    for item in items:
        key, sep, value = item.partition("=")
        if not sep or not key.strip() or not value.strip():
            raise InputError(f"--action {item!r}: expected PORT=VALUE such as M=10000")
        out[key.strip()] = value.strip()
    return out


def _trajectory(path: str, actions: dict):
    from ..linkages.io import read_data
    from ..linkages.tasks import Task

    p = pathlib.Path(path)
    if not p.is_file():
        raise FileFormatError(f"{p}: no such trajectory file")
    try:
        text = p.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise FileFormatError(f"{p}: not a text file") from None
    if p.suffix.lower() == ".csv":
        rows = list(csv.reader(io.StringIO(text)))
        if len(rows) < 4 or not rows[0] or rows[0][0].strip() != "t":
            raise FileFormatError(f"{p}: a trajectory CSV has a header starting with t and at least three rows")
        head = [h.strip() for h in rows[0]]
        try:
            table = [[float(x) for x in r] for r in rows[1:] if r]
        except ValueError as err:
            raise FileFormatError(f"{p}: {err}") from None
        if any(len(r) != len(head) for r in table):
            raise FileFormatError(f"{p}: every row needs {len(head)} values")
        motion: dict = {}
        for k, h in enumerate(head[1:], start=1):
            name = h.split(".")[0]
            motion.setdefault(name, []).append([r[k] for r in table])
        motion = {k: list(zip(*cols)) for k, cols in motion.items()}
        return Task.from_samples(p.stem, [r[0] for r in table], motion, actions)
    data = read_data(text, str(p))
    if "t" not in data or "motion" not in data:
        raise FileFormatError(f"{p}: a trajectory has `t` (the times) and `motion` (the inputs' positions)")
    merged = {**(data.get("actions") or {}), **actions}
    try:
        return Task.from_samples(p.stem, data["t"], data["motion"], merged)
    except (TypeError, ValueError) as err:
        raise FileFormatError(f"{p}: {err}") from None


def _task(args, linkage):
    from ..linkages.tasks import Task

    actions = _actions(args.action)
    if args.trajectory is not None:
        if not actions and not linkage.tasks:
            raise InputError("give the known actions of the trajectory with --action PORT=VALUE")
        if not actions:
            actions = {k: str(v) for k, v in linkage.tasks[0].actions}
        return _trajectory(args.trajectory, actions)
    if args.cycle is not None:
        j = linkage.joint(args.cycle)
        if j.kind != "revolute":
            raise InputError(f"--cycle {j.name}: a cycle turns a revolute joint; {j.name} is {j.kind}")
        if not actions:
            raise InputError(f"--cycle {j.name}: give the known action(s) with --action PORT=VALUE (e.g. the torque "
                             f"at {j.name})")
        return ("cycle", j.name, actions)
    if not linkage.tasks:
        raise InputError(f"{linkage.name!r} has no tasks: give --cycle JOINT or --trajectory PATH")
    task = linkage.task(args.task) if args.task is not None else linkage.tasks[0]
    if actions:
        unknown = [k for k in actions if k not in {p.name for p in linkage.ports}]
        if unknown:
            raise InputError(f"--action {unknown[0]}: not a port; ports are {', '.join(p.name for p in linkage.ports)}")
        merged = {k: str(v) for k, v in task.actions}
        merged.update(actions)
        task = Task.from_dict(task.name, {"time": [task.start, task.stop], "steps": task.steps, "rule": task.rule,
                                          "motion": {k: [str(e) for e in v] for k, v in task.motion},
                                          "actions": merged, "roles": dict(task.roles)})
    if args.steps is not None:
        task = task.replace(steps=args.steps)
    return task


def _run(args) -> int:
    from ..linkages import io as lio
    from ..linkages.rating import run

    if args.steps is not None and not 1 <= args.steps <= 100_000:
        raise InputError(f"--steps {args.steps}: give a whole number from 1 to 100000")
    if args.mu is not None and not (math.isfinite(args.mu) and args.mu >= 0):
        raise InputError(f"--mu {args.mu}: a Coulomb coefficient is a number >= 0")
    linkage = lio.load(args.file)
    if args.mu is not None or args.law is not None:
        kw = {} if args.law is None else {"law": args.law}
        linkage = linkage.with_friction(args.mu, **kw)
    task = _task(args, linkage)
    if isinstance(task, tuple):  # one turn, split where the motions reverse
        from ..linkages.rating import cycle

        result = cycle(linkage, task[1], task[2], panels=args.steps or 8)
    else:
        result = run(linkage, task)
    if args.json:
        out = result.to_json()
        out["losses_total"] = sum(out["losses"].values())
        print_json(out)
    else:
        print(result)
    return 0


COMMANDS = (
    Command("linkage", "rate a linkage or a parallel robot by Davies' method over a task, a crank cycle or a "
            "trajectory file: energy in and out, efficiency, loss share per coupling", _arguments, _run),
)
