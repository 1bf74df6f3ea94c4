"""What the browser tests share: Debian's chromium driven by Playwright (no browser download),
a static HTTP server for the page's files plus a replay.json, and mail-object builders."""

import argparse
import functools
import http.server
import json
import os
import shutil
import sys
import tempfile
import threading
import unittest
from contextlib import contextmanager
from pathlib import Path

from playwright.sync_api import sync_playwright

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[3]
WEB_DIR = REPO / "src" / "apps" / "pWebViewer" / "web"
CHROMIUM = os.environ.get("HAZARD_CHROMIUM", "/usr/bin/chromium")
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                 "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync"]


@contextmanager
def browser_page(width=1280, height=800, extra_args=()):
    """A fresh chromium with an empty profile (and `extra_args` on its command line); yields a
    Playwright page. Console errors of the page are collected in page.errors so a test can
    assert there were none."""
    profile = tempfile.mkdtemp(prefix="viewer-profile-")
    try:
        with sync_playwright() as pw:
            context = pw.chromium.launch_persistent_context(
                profile, executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS + list(extra_args),
                viewport={"width": width, "height": height})
            page = context.pages[0] if context.pages else context.new_page()
            page.errors = []
            page.profile_dir = profile  # names the browser's processes (bench: their CPU time)
            page.on("pageerror", lambda e: page.errors.append(str(e)))
            page.on("console", lambda m: m.type == "error" and page.errors.append(m.text))
            try:
                yield page
            finally:
                context.close()
    finally:
        shutil.rmtree(profile, ignore_errors=True)


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@contextmanager
def static_site(replay=None):
    """Serves the page's files (and `replay` as replay.json when given) on a free loopback
    port; yields the base URL."""
    root = tempfile.mkdtemp(prefix="viewer-site-")
    try:
        for f in WEB_DIR.iterdir():
            if f.is_file():
                shutil.copy(f, root)
        if replay is not None:
            Path(root, "replay.json").write_text(json.dumps(replay))
        handler = functools.partial(_QuietHandler, directory=root)
        server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        thread = threading.Thread(target=server.serve_forever, daemon=True)
        thread.start()
        try:
            yield f"http://127.0.0.1:{server.server_address[1]}/"
        finally:
            server.shutdown()
            server.server_close()
    finally:
        shutil.rmtree(root, ignore_errors=True)


def mail(var, val, time, src="test"):
    return {"type": "mail", "var": var, "val": val, "src": src, "time": time}


def replay_doc(mails, time=None):
    """A replay.json as pWebViewer serves it: the hello's time is the log's first time."""
    if time is None:
        time = min((m["time"] for m in mails), default=0.0)
    return {"hello": {"type": "hello", "app": "pWebViewer", "community": "shoreside",
                      "time": time, "warp": 1, "mode": "replay", "buttons": []},
            "mail": mails}


def open_replay(page, base_url):
    """Loads the page in replay mode and waits until the replay is ready."""
    page.goto(base_url + "?replay=replay.json")
    page.wait_for_function("window.viewerState && window.viewerState().replay !== undefined")


def state_at(page, t):
    page.evaluate(f"window.viewerSeek({t})")
    return page.evaluate("window.viewerState()")


def next_frame(page):
    """Waits until the page has drawn a frame after this call."""
    page.evaluate("new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")


class ReplayPageCase(unittest.TestCase):
    """One page for the whole class, in replay mode over the class's MAILS."""
    MAILS = []

    @classmethod
    def setUpClass(cls):
        cls._site = static_site(replay_doc(cls.MAILS))
        cls.url = cls._site.__enter__()
        cls._browser = browser_page()
        cls.page = cls._browser.__enter__()
        open_replay(cls.page, cls.url)

    @classmethod
    def tearDownClass(cls):
        cls._browser.__exit__(None, None, None)
        cls._site.__exit__(None, None, None)


def run_with_binaries(binaries, names):
    """Runs the calling module's tests with `--NAME=PATH` for each of `names` read into
    `binaries` (the programs the tests start); the other arguments go to unittest. Exit status."""
    parser = argparse.ArgumentParser()
    for name in names:
        parser.add_argument("--" + name, required=True)
    args, rest = parser.parse_known_args()
    binaries.update(vars(args))
    result = unittest.main(module="__main__", argv=[sys.argv[0]] + rest, exit=False).result
    return 0 if result.wasSuccessful() else 1
