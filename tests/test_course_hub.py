"""A class on JupyterHub, on 127.0.0.1: the lecturers' configuration (course/jupyterhub_config.py)
with a test authenticator and a test spawner, the proxy from npm, and each student's server
from a fresh environment installed from binder/ as repo2docker would (the image a hub on
Kubernetes runs).

* ``binder/`` installs into a fresh virtual environment (from a local folder of wheels that
  pip downloads once, then with no index), ``binder/postBuild`` installs gearlib from a
  clone of the repository, and the chapters' imports come from there.
* Two students log in, each opens chapter 1 through its nbgitpuller link (cloned from a bare
  copy of this repository, file://, no network) and runs it from top to bottom through the
  Jupyter server's REST and kernel APIs; then the lecturer pushes a change, both follow the
  link again, and the change one student made to the chapter survives the pull.
* Everything started is stopped at the end: the hub, its proxy and both servers.

The repository pulled is this checkout's last commit (uncommitted changes are not in it).
"""

from __future__ import annotations

import hashlib
import json
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import pytest
import requests

from course.links import pull_link
from hub_tools import Student, free_port, wait_for
from notebook_tools import ROOT

pytestmark = pytest.mark.course

BIN = pathlib.Path(sys.executable).parent
PROXY = ROOT / "course" / "proxy" / "node_modules" / ".bin" / "configurable-http-proxy"
CHAPTER = "chapters/01_graph_representation.ipynb"


def _run(cmd, **kw):
    done = subprocess.run(cmd, capture_output=True, text=True, **kw)
    assert done.returncode == 0, f"{cmd}: {(done.stdout + done.stderr)[-3000:]}"
    return done.stdout


def _git(*args, cwd):
    return _run(["git", "-c", "user.name=Lecturer", "-c", "user.email=lecturer@example.edu", *args], cwd=cwd)


@pytest.fixture(scope="module")
def upstream(tmp_path_factory):
    """A bare copy of this checkout's last commit, branch main: what the class pulls from."""
    tmp = tmp_path_factory.mktemp("upstream")
    bare = tmp / "gearbook.git"
    _git("init", "--quiet", "--bare", "--initial-branch=main", str(bare), cwd=tmp)
    _git("push", "--quiet", str(bare), "HEAD:refs/heads/main", cwd=ROOT)
    return bare


def _wheelhouse() -> pathlib.Path:
    """binder/'s wheels, downloaded by pip once per version of its requirements (kept beside .venv)."""
    files = [ROOT / "binder" / "requirements.txt", ROOT / "binder" / "constraints.txt"]
    key = hashlib.sha256(b"".join(p.read_bytes() for p in files)).hexdigest()[:12]
    house = pathlib.Path(sys.prefix) / "binder-wheels" / key
    if not house.is_dir():
        part = house.with_name(key + ".part")
        shutil.rmtree(part, ignore_errors=True)
        _run([sys.executable, "-m", "pip", "download", "--quiet", "--disable-pip-version-check", "-d", str(part),
              "-r", str(files[0]), "setuptools>=68"], timeout=900)
        part.rename(house)
    return house


@pytest.fixture(scope="module")
def binder(tmp_path_factory, upstream):
    """A fresh environment with binder/requirements.txt, and gearlib installed by binder/postBuild
    from a clone of the repository (as repo2docker does)."""
    tmp = tmp_path_factory.mktemp("binder")
    house = _wheelhouse()
    venv = tmp / "venv"
    started = time.monotonic()
    _run([sys.executable, "-m", "venv", str(venv)], timeout=300)
    # only the wheels of binder/ (no index, none of this machine's pip configuration); no byte
    # compilation, which Python does on first import anyway
    env = {**{k: v for k, v in os.environ.items() if not k.startswith("PIP_")}, "PIP_CONFIG_FILE": os.devnull,
           "PIP_NO_INDEX": "1", "PIP_FIND_LINKS": str(house), "PIP_DISABLE_PIP_VERSION_CHECK": "1",
           "PATH": f"{venv / 'bin'}{os.pathsep}{os.environ['PATH']}"}
    _run([str(venv / "bin" / "python"), "-m", "pip", "install", "--quiet", "--no-compile", "-r",
          str(ROOT / "binder" / "requirements.txt")], env=env, timeout=1200)
    clone = tmp / "repo"
    _git("clone", "--quiet", str(upstream), str(clone), cwd=tmp)
    _run(["bash", "binder/postBuild"], cwd=clone, env=env, timeout=600)
    print(f"binder environment installed in {time.monotonic() - started:.0f} s")
    return venv


def test_binder_installs_and_the_chapters_import_gearlib_from_it(binder, tmp_path):
    """Every module the chapters, exercises and solutions import, imported in the fresh
    environment, and gearlib from its own site-packages (not this checkout)."""
    modules = set()
    for path in sorted([*ROOT.glob("chapters/*.ipynb"), *ROOT.glob("exercises/*.ipynb"),
                        *ROOT.glob("book/solutions/*.ipynb")]):
        for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]:
            if cell["cell_type"] == "code":
                for line in "".join(cell["source"]).splitlines():
                    words = line.split()
                    if words[:1] in (["import"], ["from"]) and len(words) > 1:
                        modules.add(words[1].split(".")[0].rstrip(","))
    assert {"gearlib", "sympy", "myst_nb"} <= modules
    code = ("import importlib, json, sys; mods = json.loads(sys.argv[1]); "
            "print(json.dumps({m: getattr(importlib.import_module(m), '__file__', None) or 'built-in' for m in mods}))")
    out = _run([str(binder / "bin" / "python"), "-c", code, json.dumps(sorted(modules))], cwd=tmp_path, timeout=300)
    found = json.loads(out.strip().splitlines()[-1])
    assert pathlib.Path(found["gearlib"]).resolve().is_relative_to(binder.resolve())
    kernel = json.loads((binder / "share" / "jupyter" / "kernels" / "python3" / "kernel.json").read_text())
    assert pathlib.Path(kernel["argv"][0]).parent == binder / "bin"


def _processes_under(folder: pathlib.Path) -> list[int]:
    """Processes whose working directory is in *folder* (the students' servers and kernels)."""
    pids = []
    for proc in pathlib.Path("/proc").iterdir():
        if proc.name.isdigit():
            try:
                if pathlib.Path(os.readlink(proc / "cwd")).is_relative_to(folder):
                    pids.append(int(proc.name))
            except OSError:
                continue
    return pids


@pytest.fixture
def hub(tmp_path, upstream, binder):
    """The lecturers' hub configuration, started on free ports of 127.0.0.1, with
    DummyAuthenticator and SimpleLocalProcessSpawner; stopped at the end."""
    assert PROXY.is_file(), "configurable-http-proxy is missing: make proxy (make test installs it)"
    port, api_port, hub_port = free_port(), free_port(), free_port()
    homes = tmp_path / "home"
    config = tmp_path / "jupyterhub_config.py"
    config.write_text(f"""
load_subconfig({str(ROOT / "course" / "jupyterhub_config.py")!r})
c.JupyterHub.authenticator_class = "dummy"
c.JupyterHub.spawner_class = "simple"
c.SimpleLocalProcessSpawner.home_dir_template = {str(homes)!r} + "/{{username}}"
c.Spawner.cmd = [{str(binder / "bin" / "jupyterhub-singleuser")!r}]
c.Spawner.args = {["--allow-root"] if os.geteuid() == 0 else []!r}
c.JupyterHub.bind_url = "http://127.0.0.1:{port}"
c.JupyterHub.hub_bind_url = "http://127.0.0.1:{hub_port}"
c.ConfigurableHTTPProxy.api_url = "http://127.0.0.1:{api_port}"
""", encoding="utf-8")
    env = {**os.environ, "COURSE_REPO": upstream.as_uri(), "COURSE_BRANCH": "main",
           "COURSE_STATE": str(tmp_path / "state"), "PATH": f"{BIN}{os.pathsep}{os.environ['PATH']}"}
    env.pop("MPLBACKEND", None)
    log = open(tmp_path / "hub.log", "wb")
    proc = subprocess.Popen([str(BIN / "jupyterhub"), "-f", str(config)], cwd=tmp_path, env=env, stdout=log,
                            stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, start_new_session=True)
    base = f"http://127.0.0.1:{port}"

    def up():
        if proc.poll() is not None:
            raise AssertionError(f"the hub stopped:\n{(tmp_path / 'hub.log').read_text()[-4000:]}")
        try:
            return requests.get(f"{base}/hub/api/", timeout=2).status_code == 200
        except requests.RequestException:
            return False

    def stop() -> list[int]:
        """Stop the hub as its operator would (SIGTERM): it stops the servers and the proxy.
        Returns what was still running after it had stopped (and is then killed)."""
        if proc.poll() is None:
            proc.send_signal(signal.SIGTERM)
            try:
                proc.wait(timeout=60)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
        left = _processes_under(homes)
        proxy = proxy_pid.read_text().strip() if proxy_pid.is_file() else ""
        if proxy.isdigit() and pathlib.Path(f"/proc/{proxy}").exists():
            left.append(int(proxy))
        for pid in left:  # never leave anything running, even when the test fails
            os.kill(pid, signal.SIGKILL)
        return left

    proxy_pid = tmp_path / "state" / "jupyterhub-proxy.pid"
    try:
        wait_for("the hub", up, 120)
        yield {"base": base, "homes": homes, "stop": stop, "ports": (port, api_port, hub_port)}
    finally:
        stop()
        log.close()


def _note(nb: dict) -> dict:
    nb["cells"].insert(1, {"cell_type": "markdown", "id": "alices-note", "metadata": {},
                           "source": "Alice's note: the carrier is the link that holds the planet's axis."})
    return nb


def test_two_students_pull_and_run_chapter_one_on_the_hub(hub, upstream, binder, tmp_path):
    base = hub["base"]
    link = pull_link(base, upstream.as_uri(), "main", CHAPTER)
    students = {name: Student(base, name) for name in ("alice", "bob")}
    # after logging in, the hub's start page is the link of chapter 0 (the configuration's default_url)
    students["alice"].login()
    start = students["alice"].web.get(f"{base}/hub/", allow_redirects=False, timeout=30)
    assert start.status_code == 302 and "git-pull" in start.headers["Location"], start.headers
    assert "chapters%2F00_" in start.headers["Location"]
    students["bob"].login()

    def open_and_run(student):
        page = student.follow(link)
        assert "git-pull" in page.text  # nbgitpuller's page, which starts the pull
        student.new_token()
        events = student.pull(link)
        assert events[-1]["phase"] == "finished", events[-3:]
        return student.run_notebook(f"gearbook/{CHAPTER}", then="import sys, gearlib\nprint(sys.prefix, gearlib.__file__)")

    with ThreadPoolExecutor(2) as pool:
        results = dict(zip(students, pool.map(open_and_run, students.values())))
    for name, (errors, outputs) in results.items():
        assert not errors, f"{name}: {errors}"
        assert len(outputs) > 10 and any(o["type"] == "display_data" for out in outputs for o in out)
        assert (hub["homes"] / name / "gearbook" / CHAPTER).is_file()

    # the kernels are the binder environment's, with gearlib installed there
    alice, bob = students["alice"], students["bob"]
    for name, (_, outputs) in results.items():
        prefix, gearlib_file = outputs[-1][-1]["text"].split()
        assert pathlib.Path(prefix).resolve() == binder.resolve(), f"{name}'s kernel runs in {prefix}"
        assert pathlib.Path(gearlib_file).resolve().is_relative_to(binder.resolve()), name

    # Alice writes a note into the chapter and saves it; the lecturer pushes a change upstream
    path = f"api/contents/gearbook/{CHAPTER}"
    nb = alice.server("GET", path).json()["content"]
    assert alice.server("PUT", path, json={"type": "notebook", "format": "json", "content": _note(nb)}).ok
    work = tmp_path / "lecturer"
    subprocess.run(["git", "clone", "--quiet", str(upstream), str(work)], check=True, capture_output=True)
    (work / "NEWS.md").write_text("Exercises of chapter 1 are due on Friday.\n")
    for args in (["add", "NEWS.md"], ["commit", "--quiet", "-m", "News for the class"], ["push", "--quiet"]):
        subprocess.run(["git", "-c", "user.name=Lecturer", "-c", "user.email=l@example.edu", *args], cwd=work,
                       check=True, capture_output=True)

    # both follow the link again: the news arrive, Alice's note stays hers
    for student in (alice, bob):
        student.follow(link)
        events = student.pull(link)
        assert events[-1]["phase"] == "finished", events[-3:]
        home = hub["homes"] / student.name / "gearbook"
        assert (home / "NEWS.md").read_text().startswith("Exercises of chapter 1")
    assert "Alice's note" in (hub["homes"] / "alice" / "gearbook" / CHAPTER).read_text()
    assert "Alice's note" not in (hub["homes"] / "bob" / "gearbook" / CHAPTER).read_text()

    # the hub stops with everything it started: the proxy, both servers and their kernels
    assert hub["stop"]() == []
    for p in hub["ports"]:
        with pytest.raises(requests.ConnectionError):
            requests.get(f"http://127.0.0.1:{p}/", timeout=5)
