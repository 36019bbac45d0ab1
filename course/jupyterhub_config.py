"""JupyterHub for a class on the book, on one machine: ``make hub`` (or, once ``make venv`` and
``make proxy`` have run, ``.venv/bin/jupyterhub -f course/jupyterhub_config.py``), as root.

Students log in with their accounts on the machine (PAM); each gets a JupyterLab server
running as their own user, with this environment's Python and gearlib, and their home as
its root. Following a chapter's nbgitpuller link (``make course`` writes them to
``course/_build/links.md``; the hub's start page is the link of chapter 0) pulls the book
into ``~/<repository name>/`` and opens the chapter: the first time it clones the
repository, later it merges what changed upstream and keeps what the student changed.

Settings from the environment (the defaults suit a first try on the machine itself):

    COURSE_BIND_URL  where the hub listens (default http://:8000, every interface; put TLS
                     in front of it, or set c.JupyterHub.ssl_cert/ssl_key below)
    COURSE_REPO      the git URL students pull the book from (default: this checkout's origin)
    COURSE_BRANCH    its branch (default: the branch checked out here)
    COURSE_CLASS     a class list (CSV with an id column, as for make course): only these
                     accounts may log in (default: any account of the machine)
    COURSE_ADMINS    comma-separated admin accounts (the lecturer, the tutors)
    COURSE_STATE     a folder for the hub's database, cookie secret and proxy pid
                     (default course/_hub, ignored by git)

For a class that outgrows one machine, Zero to JupyterHub on Kubernetes runs the same hub
with KubeSpawner: each student's server is a container of the image repo2docker builds from
this repository (binder/), and the same nbgitpuller links open the same chapters (see the
book's page for lecturers).
"""

import csv
import os
import pathlib
import subprocess
import sys
from urllib.parse import urlencode

c = get_config()  # noqa: F821 (JupyterHub's configuration loader provides it)

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent
BIN = pathlib.Path(sys.executable).parent
STATE = pathlib.Path(os.environ.get("COURSE_STATE") or HERE / "_hub")
STATE.mkdir(parents=True, exist_ok=True)


def _git(*args):
    done = subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True)
    return done.stdout.strip() if done.returncode == 0 else ""


# --- where the hub listens, and the state it keeps -------------------------------------------
c.JupyterHub.bind_url = os.environ.get("COURSE_BIND_URL", "http://:8000")
c.JupyterHub.db_url = f"sqlite:///{STATE / 'jupyterhub.sqlite'}"
c.JupyterHub.cookie_secret_file = str(STATE / "jupyterhub_cookie_secret")
c.ConfigurableHTTPProxy.pid_file = str(STATE / "jupyterhub-proxy.pid")

# --- the proxy: configurable-http-proxy from npm, pinned in course/proxy/package-lock.json ---
c.ConfigurableHTTPProxy.command = [str(HERE / "proxy" / "node_modules" / ".bin" / "configurable-http-proxy")]

# --- who may log in: the machine's accounts (PAM), limited to the class list if one is given --
c.JupyterHub.authenticator_class = "pam"
if os.environ.get("COURSE_CLASS"):
    with open(os.environ["COURSE_CLASS"], encoding="utf-8") as f:
        rows = csv.DictReader(line for line in f if line.strip() and not line.lstrip().startswith("#"))
        c.Authenticator.allowed_users = {row["id"].strip() for row in rows}
else:
    c.Authenticator.allow_all = True
c.Authenticator.admin_users = {u.strip() for u in os.environ.get("COURSE_ADMINS", "").split(",") if u.strip()}

# --- each student's server: a local process under their account, JupyterLab, this Python ---
c.JupyterHub.spawner_class = "localprocess"
c.Spawner.cmd = [str(BIN / "jupyterhub-singleuser")]
c.Spawner.default_url = "/lab"
c.Spawner.notebook_dir = "~"
c.Spawner.environment = {"JUPYTER_PREFER_ENV_PATH": "1"}  # kernels from this environment first
c.Spawner.start_timeout = 120
c.Spawner.http_timeout = 120
# a student who follows a chapter's link while their server is stopped gets it started (after 2 s)
c.JupyterHub.implicit_spawn_seconds = 2

# --- the start page: the nbgitpuller link of chapter 0 (every chapter's is in links.md) ---------
REPO = os.environ.get("COURSE_REPO") or _git("remote", "get-url", "origin") or ROOT.as_uri()
BRANCH = os.environ.get("COURSE_BRANCH") or _git("branch", "--show-current") or "main"
TARGET = REPO.rstrip("/").split("/")[-1].removesuffix(".git") or "book"
FIRST = next(iter(sorted((ROOT / "chapters").glob("[0-9]*_*.ipynb"))), None)
if FIRST is not None:
    c.JupyterHub.default_url = "/hub/user-redirect/git-pull?" + urlencode(
        {"repo": REPO, "branch": BRANCH, "targetpath": TARGET, "urlpath": f"lab/tree/{TARGET}/chapters/{FIRST.name}"})
