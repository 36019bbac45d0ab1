"""A small driver for headless Chromium over the Chrome DevTools Protocol (CDP).

Used by ``tests/test_browser.py``. It talks to the browser through a pipe
(``--remote-debugging-pipe``: JSON messages separated by NUL bytes on file descriptors 3
and 4), so it opens no port and needs no package beyond the standard library.

    with Chromium(executable, workdir) as browser:
        page = browser.new_page(width=1280, height=900)
        page.goto("file:///.../index.html")
        page.evaluate("document.title")
        page.screenshot("shot.png")

The browser runs with the network cut off (every host name resolves to nothing); the
page records every request it makes, every JavaScript exception and every console or
log error, for the tests to judge.
"""

from __future__ import annotations

import base64
import fcntl
import itertools
import json
import os
import queue
import shutil
import subprocess
import threading
import time

#: Flags for a quiet, sandbox-free, network-free headless Chromium (see the machine notes).
FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--no-default-browser-check",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-extensions",
    "--disable-dev-shm-usage",
    "--mute-audio",
    "--hide-scrollbars",
    "--no-proxy-server",
    "--remote-debugging-pipe",
]


def find_chromium() -> str | None:
    """The Chromium executable: ``$CHROMIUM``, else ``chromium`` or ``chromium-browser`` on PATH."""
    env = os.environ.get("CHROMIUM")
    if env:
        return env if os.path.exists(env) else shutil.which(env)
    for name in ("chromium", "chromium-browser"):
        path = shutil.which(name)
        if path:
            return path
    return None


def _above_9(fd: int) -> int:
    high = fcntl.fcntl(fd, fcntl.F_DUPFD, 10)
    os.close(fd)
    return high


class CDPError(RuntimeError):
    """The browser answered a command with an error, or did not answer in time."""


class Chromium:
    """A headless Chromium process driven over a CDP pipe."""

    def __init__(self, executable: str, workdir: str, *, timeout: float = 30.0, allow_hosts=()):
        self.timeout = timeout
        profile = os.path.join(workdir, "profile")
        os.makedirs(profile, exist_ok=True)
        to_browser_r, self._to_browser = os.pipe()
        self._from_browser, from_browser_w = os.pipe()
        # the child's ends go above 9, so that wiring them to fds 3 and 4 cannot clobber them
        to_browser_r, from_browser_w = (_above_9(fd) for fd in (to_browser_r, from_browser_w))

        # no network: every host name fails to resolve, but for ``allow_hosts`` (say, a
        # JupyterLab server on 127.0.0.1)
        rules = ", ".join(["MAP * ~NOTFOUND", *(f"EXCLUDE {h}" for h in allow_hosts)])
        self._stderr = open(os.path.join(workdir, "chromium.log"), "wb")
        # the browser reads commands on its fd 3 and writes answers on its fd 4
        wire = f'exec "$0" "$@" 3<&{to_browser_r} 4>&{from_browser_w}'
        self.process = subprocess.Popen(
            ["/bin/bash", "-c", wire, executable, *FLAGS, f"--host-resolver-rules={rules}",
             f"--user-data-dir={profile}", "about:blank"],
            stdin=subprocess.DEVNULL, stdout=self._stderr, stderr=self._stderr,
            pass_fds=(to_browser_r, from_browser_w),
        )
        os.close(to_browser_r)
        os.close(from_browser_w)
        self._ids = itertools.count(1)
        self._answers: dict[int, queue.Queue] = {}
        self._lock = threading.Lock()
        self._listeners: dict[str, list] = {}
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()
        self.version = self.send("Browser.getVersion")["product"]

    # -- plumbing -------------------------------------------------------------------------
    def _read(self):
        buf = b""
        while True:
            try:
                chunk = os.read(self._from_browser, 1 << 16)
            except OSError:
                chunk = b""
            if not chunk:
                for q in list(self._answers.values()):
                    q.put({"error": {"message": "the browser closed its pipe"}})
                return
            buf += chunk
            *messages, buf = buf.split(b"\0")
            for raw in messages:
                msg = json.loads(raw)
                if "id" in msg:
                    with self._lock:
                        q = self._answers.get(msg["id"])
                    if q is not None:
                        q.put(msg)
                else:
                    for listener in self._listeners.get(msg.get("sessionId", ""), []):
                        listener(msg["method"], msg.get("params", {}))

    def send(self, method: str, params: dict | None = None, session: str | None = None,
             timeout: float | None = None) -> dict:
        """Send one command and wait for its answer; raise CDPError on an error answer."""
        msg_id = next(self._ids)
        msg = {"id": msg_id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        q: queue.Queue = queue.Queue()
        with self._lock:
            self._answers[msg_id] = q
        os.write(self._to_browser, json.dumps(msg).encode() + b"\0")
        try:
            answer = q.get(timeout=timeout or self.timeout)
        except queue.Empty:
            raise CDPError(f"{method}: no answer from the browser in {timeout or self.timeout} s") from None
        finally:
            with self._lock:
                self._answers.pop(msg_id, None)
        if "error" in answer:
            raise CDPError(f"{method}: {answer['error'].get('message')}")
        return answer.get("result", {})

    def post(self, method: str, params: dict | None = None, session: str | None = None):
        """Send one command without waiting for its answer (safe from an event listener)."""
        msg = {"id": next(self._ids), "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        os.write(self._to_browser, json.dumps(msg).encode() + b"\0")

    def new_page(self, width: int = 1280, height: int = 900) -> Page:
        target = self.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        return Page(self, session, width, height)

    def close(self):
        if self.process.poll() is None:
            try:
                self.send("Browser.close", timeout=5)
            except CDPError:
                pass
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        for fd in (self._to_browser, self._from_browser):
            try:
                os.close(fd)
            except OSError:
                pass
        self._stderr.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


class Page:
    """One browser tab: navigation, JavaScript, screenshots, and what the page did."""

    def __init__(self, browser: Chromium, session: str, width: int, height: int):
        self.browser = browser
        self.session = session
        self.requests: list[str] = []       # every URL the page asked for
        self.errors: list[str] = []         # exceptions, console errors, failed loads
        self._loaded = threading.Event()
        browser._listeners[session] = [self._on_event]
        for domain in ("Page", "Runtime", "Network", "Log"):
            self.send(f"{domain}.enable")
        self.send("Emulation.setDeviceMetricsOverride",
                  {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})

    def send(self, method: str, params: dict | None = None, timeout: float | None = None) -> dict:
        return self.browser.send(method, params, session=self.session, timeout=timeout)

    def _on_event(self, method: str, params: dict):
        if method == "Page.loadEventFired":
            self._loaded.set()
        elif method == "Page.javascriptDialogOpening":  # "leave this page?" and the like: yes
            self.browser.post("Page.handleJavaScriptDialog", {"accept": True}, session=self.session)
        elif method == "Network.requestWillBeSent":
            self.requests.append(params["request"]["url"])
        elif method == "Runtime.exceptionThrown":
            d = params["exceptionDetails"]
            text = d.get("exception", {}).get("description") or d.get("text", "")
            self.errors.append(f"JavaScript exception: {text.splitlines()[0] if text else d}"
                               f" ({d.get('url', '')}:{d.get('lineNumber', '?')})")
        elif method == "Runtime.consoleAPICalled" and params["type"] in ("error", "assert"):
            args = " ".join(str(a.get("value", a.get("description", ""))) for a in params["args"])
            self.errors.append(f"console.{params['type']}: {args}")
        elif method == "Log.entryAdded" and params["entry"]["level"] == "error":
            e = params["entry"]
            self.errors.append(f"{e['source']} error: {e['text']} {e.get('url', '')}".strip())
        elif method == "Network.loadingFailed" and not params.get("canceled"):
            self.errors.append(f"failed to load a resource: {params.get('errorText')}")

    def goto(self, url: str, timeout: float = 30.0):
        """Open ``url`` and wait for its load event; forget what earlier pages did."""
        self.requests.clear()
        self.errors.clear()
        self._loaded.clear()
        answer = self.send("Page.navigate", {"url": url})
        if answer.get("errorText"):
            raise CDPError(f"cannot open {url}: {answer['errorText']}")
        if not self._loaded.wait(timeout):
            raise CDPError(f"{url} did not finish loading in {timeout} s")

    def evaluate(self, expression: str, timeout: float = 30.0):
        """Evaluate JavaScript (promises are awaited) and return its value as JSON data."""
        answer = self.send("Runtime.evaluate", {
            "expression": expression, "awaitPromise": True, "returnByValue": True,
            "timeout": int(timeout * 1000),
        }, timeout=timeout + 5)
        if "exceptionDetails" in answer:
            d = answer["exceptionDetails"]
            raise CDPError(f"JavaScript failed: {d.get('exception', {}).get('description') or d.get('text')}")
        return answer["result"].get("value")

    def screenshot(self, path: str, clip: dict | None = None, *, below: int = 0):
        """Save a PNG of the viewport, or of ``clip`` (x, y, width, height in CSS pixels of the
        document): the page is scrolled to put the region ``below`` pixels under the top of
        the viewport (say, under a sticky header), and the region is cut to the viewport.
        (Chromium's captureBeyondViewport would lay the whole page out again at its full
        height: seconds a shot on a long page.)"""
        params = {"format": "png"}
        if clip:
            self.evaluate(f"window.scrollTo(0, {max(0.0, clip['y'] - below)})")
            scroll, height = self.evaluate("[window.scrollY, window.innerHeight]")
            top = max(clip["y"], scroll)
            params["clip"] = {**clip, "y": top, "height": max(1, min(clip["height"], scroll + height - top)),
                              "scale": 1}
        data = self.send("Page.captureScreenshot", params)["data"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(data))

    def press(self, key: str, code: int):
        """Press and release one key (``key`` as in KeyboardEvent.key, ``code`` its key code)."""
        for kind in ("keyDown", "keyUp"):
            self.send("Input.dispatchKeyEvent", {"type": kind, "key": key, "code": key,
                                                 "windowsVirtualKeyCode": code, "nativeVirtualKeyCode": code})

    def wait_for(self, expression: str, timeout: float = 20.0, interval: float = 0.1) -> bool:
        """Poll a JavaScript expression until it is truthy; False if it never was."""
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            try:
                if self.evaluate(expression):
                    return True
            except CDPError as err:
                # asked while the page navigates (a redirect): the old document is gone and
                # the new one not ready yet; ask again. Anything else is a real error.
                if not any(m in str(err) for m in ("navigated or closed", "context was destroyed",
                                                   "Cannot find context")):
                    raise
            time.sleep(interval)
        return False
