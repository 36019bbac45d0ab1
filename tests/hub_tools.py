"""A student's browser, without the browser: the requests a JupyterHub page makes, for the
course's hub test (tests/test_course_hub.py). Logging in, following an nbgitpuller link
(the hub's spawn pages, the OAuth handshake with the student's server, the pull that the
link's page starts), and running a notebook cell by cell through the Jupyter server's REST
and kernel (websocket) APIs."""

from __future__ import annotations

import json
import os
import socket
import struct
import time
import uuid
from urllib.parse import urlsplit

import requests
import websocket


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(what: str, ok, timeout: float, every: float = 0.3):
    end = time.monotonic() + timeout
    while True:
        value = ok()
        if value:
            return value
        if time.monotonic() > end:
            raise TimeoutError(f"{what}: not within {timeout:.0f} s")
        time.sleep(every)


class Student:
    """One student with a session of their own (cookies) on the hub at *base*."""

    def __init__(self, base: str, name: str):
        self.base, self.name = base.rstrip("/"), name
        self.web = requests.Session()
        self.token = None

    def _xsrf(self, path="/hub/"):
        return next((c.value for c in self.web.cookies if c.name == "_xsrf" and path.startswith(c.path)), None)

    def login(self, password="a password") -> requests.Response:
        self.web.get(f"{self.base}/hub/login", timeout=30).raise_for_status()
        r = self.web.post(f"{self.base}/hub/login", data={"username": self.name, "password": password,
                                                         "_xsrf": self._xsrf()}, allow_redirects=False, timeout=60)
        assert r.status_code == 302, f"{self.name}: login answered {r.status_code}: {r.text[:500]}"
        return r

    def api(self, method: str, path: str, **kw) -> requests.Response:
        headers = {"X-XSRFToken": self._xsrf() or ""} if method != "GET" else {}
        return self.web.request(method, f"{self.base}/hub/api{path}", headers=headers, timeout=60, **kw)

    def follow(self, link: str, timeout: float = 180) -> requests.Response:
        """Open *link* as a browser would: when the hub says the server is not running, start it
        (the page's Launch button), wait while the hub shows its progress page, then load the link."""
        r = self.web.get(link, timeout=60)
        if f"/user/{self.name}/" in r.url and r.status_code == 200:
            return r
        assert r.status_code in (200, 202, 424, 503), f"{link}: {r.status_code} {r.url}"
        start = self.api("POST", f"/users/{self.name}/server")
        assert start.status_code in (201, 202, 400), start.text  # 400: already starting
        wait_for(f"{self.name}'s server", lambda: self.api("GET", f"/users/{self.name}").json()
                 ["servers"].get("", {}).get("ready"), timeout)
        r = self.web.get(link, timeout=60)
        assert r.status_code == 200 and urlsplit(r.url).path.startswith(f"/user/{self.name}/"), (r.status_code, r.url)
        return r

    def new_token(self) -> str:
        r = self.api("POST", f"/users/{self.name}/tokens", json={"note": "hub test", "expires_in": 3600})
        assert r.status_code in (200, 201), r.text
        self.token = r.json()["token"]
        return self.token

    def server(self, method: str, path: str, **kw) -> requests.Response:
        """The student's own Jupyter server, ``/user/<name>/<path>``, with their token."""
        headers = {"Authorization": f"token {self.token}"}
        return requests.request(method, f"{self.base}/user/{self.name}/{path.lstrip('/')}", headers=headers,
                                timeout=120, **kw)

    def pull(self, link: str, timeout: float = 120) -> list[dict]:
        """What the nbgitpuller page does once loaded: its event stream, ``git-pull/api``."""
        query = urlsplit(link).query
        events = []
        with self.server("GET", f"git-pull/api?{query}", stream=True) as r:
            assert r.status_code == 200, r.text[:500]
            end = time.monotonic() + timeout
            for line in r.iter_lines(decode_unicode=True):
                if line and line.startswith("data:"):
                    events.append(json.loads(line[5:]))
                    if events[-1].get("phase") in ("finished", "error"):
                        break
                assert time.monotonic() < end, "the pull did not finish"
        return events

    def run_notebook(self, path: str, then: str = "", timeout: float = 600) -> tuple[list[str], list[list]]:
        """Start a kernel for *path* (a session, as JupyterLab does), run its code cells in order,
        then the code *then*; ``(errors, outputs per code cell)``. The session is closed at the end."""
        nb = self.server("GET", f"api/contents/{path}").json()["content"]
        r = self.server("POST", "api/sessions", json={"path": path, "type": "notebook", "name": os.path.basename(path),
                                                       "kernel": {"name": "python3"}})
        assert r.status_code == 201, r.text
        session = r.json()
        ws_url = f"{self.base.replace('http', 'ws', 1)}/user/{self.name}/api/kernels/{session['kernel']['id']}/channels"
        ws = websocket.create_connection(ws_url, header=[f"Authorization: token {self.token}"], timeout=timeout)
        errors, outputs = [], []
        try:
            cells = ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code"] + ([then] if then else [])
            for i, code in enumerate(cells):
                status, out = _execute(ws, code, timeout)
                outputs.append(out)
                errors += [f"code cell {i + 1}: {o['ename']}: {o['evalue']}" for o in out if o["type"] == "error"]
                if status != "ok" and not errors:
                    errors.append(f"code cell {i + 1}: {status}")
        finally:
            ws.close()
            self.server("DELETE", f"api/sessions/{session['id']}")
        return errors, outputs


def _message(frame) -> dict:
    """A kernel message from the server's websocket: text, or binary when it carries buffers
    (a widget's state): the number of parts, their offsets, then the JSON message first."""
    if isinstance(frame, str):
        return json.loads(frame)
    parts = struct.unpack_from("!I", frame)[0]
    offsets = struct.unpack_from(f"!{parts}I", frame, 4)
    end = offsets[1] if parts > 1 else len(frame)
    return json.loads(frame[offsets[0]:end].decode("utf-8"))


def _execute(ws, code: str, timeout: float):
    msg_id = uuid.uuid4().hex
    ws.send(json.dumps({
        "header": {"msg_id": msg_id, "username": "student", "session": uuid.uuid4().hex, "msg_type": "execute_request",
                   "version": "5.3", "date": ""},
        "parent_header": {}, "metadata": {}, "channel": "shell", "buffers": [],
        "content": {"code": code, "silent": False, "store_history": True, "user_expressions": {},
                    "allow_stdin": False, "stop_on_error": True}}))
    out, status, idle = [], None, False
    end = time.monotonic() + timeout
    while status is None or not idle:
        assert time.monotonic() < end, "a cell did not finish"
        msg = _message(ws.recv())
        if msg.get("parent_header", {}).get("msg_id") != msg_id:
            continue
        kind, content = msg["msg_type"], msg["content"]
        if kind == "execute_reply":
            status = content["status"]
        elif kind == "status":
            idle = content["execution_state"] == "idle"
        elif kind == "error":
            out.append({"type": "error", "ename": content["ename"], "evalue": content["evalue"]})
        elif kind == "stream":
            out.append({"type": "stream", "text": content["text"]})
        elif kind in ("execute_result", "display_data"):
            out.append({"type": kind, "data": content["data"]})
    return status, out
