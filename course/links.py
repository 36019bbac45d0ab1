"""nbgitpuller links: one per chapter, each opening the chapter in JupyterLab on the class's hub
after pulling the book into the student's home (``<targetpath>/``).

A link is ``<hub>/hub/user-redirect/git-pull?repo=...&branch=...&targetpath=...&urlpath=...``:
the hub logs the student in, starts their server, and nbgitpuller clones the repository the
first time and later merges what changed upstream without overwriting the student's own
changes (a file the student changed keeps the student's version; a file they deleted comes
back).
"""

from __future__ import annotations

import json
import pathlib
import re
from urllib.parse import urlencode


def target_name(repo: str) -> str:
    """The folder nbgitpuller pulls *repo* into: its last path part, without ``.git``."""
    name = repo.rstrip("/").split("/")[-1]
    return re.sub(r"\.git$", "", name) or "book"


def pull_link(hub: str, repo: str, branch: str, path: str, targetpath: str | None = None) -> str:
    """The nbgitpuller link that opens *path* (a file of the repository) in JupyterLab."""
    target = targetpath or target_name(repo)
    query = {"repo": repo, "branch": branch, "targetpath": target, "urlpath": f"lab/tree/{target}/{path}"}
    return f"{hub.rstrip('/')}/hub/user-redirect/git-pull?{urlencode(query)}"


def _title(notebook: pathlib.Path) -> str:
    nb = json.loads(notebook.read_text(encoding="utf-8"))
    for cell in nb["cells"]:
        text = "".join(cell["source"]) if isinstance(cell["source"], list) else cell["source"]
        if cell["cell_type"] == "markdown" and text.lstrip().startswith("# "):
            return text.lstrip()[2:].splitlines()[0].strip()
    return notebook.stem


def table(root: pathlib.Path, hub: str, repo: str, branch: str) -> list[dict]:
    """Per chapter: its number, title and the links to the chapter and its exercises."""
    rows = []
    for chapter in sorted((root / "chapters").glob("[0-9]*_*.ipynb")):
        exercises = root / "exercises" / chapter.name
        rows.append({
            "chapter": int(chapter.name.split("_")[0]), "title": _title(chapter),
            "notebook": f"chapters/{chapter.name}",
            "link": pull_link(hub, repo, branch, f"chapters/{chapter.name}"),
            "exercises": pull_link(hub, repo, branch, f"exercises/{chapter.name}") if exercises.is_file() else "",
        })
    return rows


def markdown(rows: list[dict], hub: str, repo: str, branch: str) -> str:
    lines = [f"# nbgitpuller links for {hub}", "",
             f"Each link pulls `{repo}` (branch `{branch}`) into the student's home and opens a notebook in "
             "JupyterLab. Put them on the course page; a student who follows one again gets what changed "
             "upstream and keeps their own changes.", "",
             "| chapter | title | chapter link | exercises link |", "|---|---|---|---|"]
    for r in rows:
        ex = f"[exercises]({r['exercises']})" if r["exercises"] else ""
        lines.append(f"| {r['chapter']} | {r['title']} | [open]({r['link']}) | {ex} |")
    return "\n".join(lines) + "\n"
