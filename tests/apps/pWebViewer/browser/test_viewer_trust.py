"""pWebViewer's trust model in a real browser (docs/viewer.md, "Trust model").

moosdb-lite, pWebViewer with a DEPLOY button, and a pymoos2 client that watches DEPLOY_ALL.
Chromium maps evil.test to 127.0.0.1 (--host-resolver-rules), as a DNS-rebinding attacker's
name would resolve. Then:

- a page of another site (http://evil.test:<port of a second local server>/) posts a form to
  the button, and fetches it (no-cors, and cors with a guessed token): nothing is posted, and
  the viewer's AppCast counts the posts it refused;
- a page of the rebound origin http://evil.test:<the viewer's port>/ reads /replay.json,
  /events and the page, and posts the button, all same-origin for the browser: each gets 421
  and nothing of the mission;
- the viewer's page opened by a link with ?replay=<another origin> loads nothing from there;
- the viewer's page opened without the token shows the button disabled; opened with the URL
  pWebViewer printed (its token), its button posts DEPLOY_ALL;
- a posting stamped far in the future (a skewed clock) hides no later posting with a duration,
  on the open page nor on a page that connects later.

Usage: python test_viewer_trust.py --moosdb=BIN --viewer=BIN
"""

import functools
import http.server
import os
import re
import shutil
import sys
import tempfile
import threading
import time
import unittest
from contextlib import contextmanager
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[2] / "interop" / "pymoos2"))

from moosdb_harness import Mailbox, MoosdbLite, pymoos2_client, stop_client, wait_until  # noqa: E402
from browser_support import browser_page, run_with_binaries  # noqa: E402
from viewer_process import served_url, start, stop  # noqa: E402

BINARIES = {}
PAGE_TIMEOUT_MS = 20000
RESOLVER = "--host-resolver-rules=MAP evil.test 127.0.0.1"
# The rebound page is handed to the browser by Playwright (the viewer's port cannot serve it),
# so chromium would count it as public and its Private Network Access would stop its requests
# to loopback before they reach the server. That is a defence of some browsers only: turn it
# off, so that the server's own defence is what this test sees.
NO_PRIVATE_NETWORK_CHECKS = ("--disable-features=BlockInsecurePrivateNetworkRequests,"
                             "PrivateNetworkAccessSendPreflights,"
                             "PrivateNetworkAccessRespectPreflightResults,"
                             "LocalNetworkAccessChecks")
VIEWER_BLOCK = """\
  AppTick = 4
  http_port = 0
  button_one = DEPLOY # DEPLOY_ALL=true
"""
ATTACK_PAGE = """<!DOCTYPE html><html><body>
<iframe name="sink"></iframe>
<form id="f" method="POST" enctype="text/plain" target="sink"><input name="a" value="b"></form>
</body></html>"""
# Run in the attacker's page: a form post into the iframe, then two fetches. Returns what the
# attacker could observe.
CROSS_SITE_ATTACKS = """async (target) => {
  const out = {};
  const form = document.getElementById('f');
  form.action = target;
  const loaded = new Promise((r) => { document.querySelector('iframe').onload = r; });
  form.submit();
  await Promise.race([loaded, new Promise((r) => setTimeout(r, 3000))]);
  try {
    const r = await fetch(target, { method: 'POST', mode: 'no-cors', body: 'a=b' });
    out.no_cors = r.type;
  } catch (e) { out.no_cors = 'error: ' + e; }
  try {
    const r = await fetch(target, { method: 'POST', headers: { 'X-Viewer-Token': '0'.repeat(32) } });
    out.cors = r.status;
  } catch (e) { out.cors = 'blocked'; }
  return out;
}"""
REBOUND_READS = """async () => {
  const out = {};
  for (const path of ['/replay.json', '/events', '/index.html', '/viewer.js']) {
    try {
      const r = await fetch(path);
      out[path] = [r.status, (await r.text()).slice(0, 200)];
    } catch (e) { out[path] = ['error', String(e)]; }
  }
  try {
    const r = await fetch('/button/1', { method: 'POST', headers: { 'X-Viewer-Token': 'x' } });
    out.post = r.status;
  } catch (e) { out.post = 'error: ' + e; }
  return out;
}"""


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@contextmanager
def attacker_site(pages):
    """A second local HTTP server (the other site) serving `pages` {name: html}; yields its
    port and the paths it was asked for."""
    root = tempfile.mkdtemp(prefix="viewer-attacker-")
    asked = []

    class Handler(_Quiet):
        def do_GET(self):
            asked.append(self.path)
            super().do_GET()
    try:
        for name, html in pages.items():
            Path(root, name).write_text(html)
        server = http.server.ThreadingHTTPServer(
            ("127.0.0.1", 0), functools.partial(Handler, directory=root))
        threading.Thread(target=server.serve_forever, daemon=True).start()
        try:
            yield server.server_address[1], asked
        finally:
            server.shutdown()
            server.server_close()
    finally:
        shutil.rmtree(root, ignore_errors=True)


class TrustInTheBrowser(unittest.TestCase):

    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="viewer_trust_")
        self.addCleanup(shutil.rmtree, self.dir, True)
        self.server = MoosdbLite(BINARIES["moosdb"], "--moos_community=shoreside").__enter__()
        self.addCleanup(self.server.__exit__, None, None, None)
        mission = os.path.join(self.dir, "m.moos")
        with open(mission, "w") as f:
            f.write("ServerHost = 127.0.0.1\nServerPort = %d\nCommunity = shoreside\n\n"
                    "ProcessConfig = pWebViewer\n{\n%s}\n" % (self.server.port, VIEWER_BLOCK))
        self.viewer = start([BINARIES["viewer"], mission], os.path.join(self.dir, "viewer.err"))
        self.addCleanup(stop, self.viewer)
        served = served_url(self.viewer)
        self.assertEqual((served.host, len(served.token)), ("127.0.0.1", 32), served.url)
        self.base, self.port, self.token = served.base, served.port, served.token
        self.client = pymoos2_client(self.server.port, "watcher_pymoos2")
        self.addCleanup(stop_client, self.client)
        self.assertTrue(self.client.wait_until_connected(10))
        self.client.register("DEPLOY_ALL", 0.0)
        self.client.register("APPCAST", 0.0)
        self.box = Mailbox(self.client)

    def deploys(self):
        self.box.messages.extend(self.client.fetch())
        return [m for m in self.box.matching({"DEPLOY_ALL"}) if m.is_string()]

    def viewer_appcast(self):
        self.box.messages.extend(self.client.fetch())
        casts = [m.string() for m in self.box.matching({"APPCAST"})
                 if m.is_string() and "proc=pWebViewer" in m.string()]
        return casts[-1] if casts else ""

    def refused_counts(self):
        m = re.search(r"Refused: +(\d+) requests by a foreign Host name, (\d+) posts",
                      self.viewer_appcast())
        return (int(m.group(1)), int(m.group(2))) if m else (0, 0)

    def wait_page(self, page, condition, what):
        try:
            page.wait_for_function(condition, timeout=PAGE_TIMEOUT_MS)
        except Exception:
            self.fail("%s; page state: %s" % (what, page.evaluate("window.viewerState()")))

    def test_other_sites_can_neither_press_nor_read_and_the_page_itself_can(self):
        with attacker_site({"attack.html": ATTACK_PAGE, "replay.json": '{"mail":[]}'}) as (ap, asked), \
                browser_page(extra_args=[RESOLVER, NO_PRIVATE_NETWORK_CHECKS]) as page:
            # Another site's page: a form post and two fetches at the button.
            page.goto("http://evil.test:%d/attack.html" % ap)
            seen = page.evaluate(CROSS_SITE_ATTACKS, self.base + "button/1")
            self.assertEqual(seen["no_cors"], "opaque", seen)  # sent, answer unreadable
            self.assertEqual(seen["cors"], "blocked", seen)    # its preflight is refused

            # The rebound name: the browser sees these requests as same-origin.
            rebound = "http://evil.test:%d/" % self.port
            page.route(rebound + "rebind.html",
                       lambda route: route.fulfill(status=200, content_type="text/html",
                                                   body="<!DOCTYPE html><p>rebound</p>"))
            page.goto(rebound + "rebind.html")
            read = page.evaluate(REBOUND_READS)
            for path in ("/replay.json", "/events", "/index.html", "/viewer.js"):
                self.assertEqual(read[path][0], 421, read)
                self.assertNotIn("pWebViewer", read[path][1])
            self.assertEqual(read["post"], 421, read)

            # A link that names a replay of another origin loads nothing from there.
            page.unroute(rebound + "rebind.html")
            page.goto(self.base + "?token=%s&replay=http://evil.test:%d/replay.json"
                      % (self.token, ap))
            self.wait_page(page, "document.getElementById('mode').textContent.includes('refused')",
                           "the foreign replay refused")
            self.assertNotIn("/replay.json", asked)

            time.sleep(2.0)  # a press would be posted at the viewer's next iteration (4 Hz)
            self.assertEqual(self.deploys(), [], "a foreign page pressed the button")
            # The viewer saw and refused them: the form post and the no-cors fetch (403), and
            # the five rebound requests (421).
            self.assertTrue(wait_until(lambda: all(n >= least for n, least in
                                               zip(self.refused_counts(), (5, 2))), 10),
                            self.viewer_appcast())

            # The page without its token: the button is there but disabled.
            page.goto(self.base)
            self.wait_page(page, "document.querySelector('#buttons button') !== null", "the button")
            self.assertTrue(page.is_disabled("#buttons button:has-text('DEPLOY')"))

            # The page opened with the printed URL presses it (the attacks' own errors aside).
            page.errors.clear()
            page.goto(self.base + "?token=" + self.token)
            self.wait_page(page, "document.querySelector('#buttons button') !== null", "the button")
            page.click("#buttons button:has-text('DEPLOY')")
            self.assertTrue(wait_until(lambda: any(m.string() == "true" for m in self.deploys()), 10),
                            "DEPLOY_ALL=true posted by the page's own button")
            self.assertEqual(page.errors, [])

    def test_a_posting_stamped_in_the_future_hides_no_later_one(self):
        with browser_page() as page:
            page.goto(self.base + "?token=" + self.token)
            self.wait_page(page, "window.viewerState().mode === 'live'", "the live page")
            page.wait_for_timeout(1500)  # a clock event or two
            self.client.notify("VIEW_MARKER", "x=5,y=5,label=skewed", time.time() + 1e6)
            self.wait_page(page, "window.viewerState().markers.includes('skewed')", "the skewed marker")
            self.client.notify("VIEW_MARKER", "x=9,y=9,duration=600,label=later")
            self.wait_page(page, "window.viewerState().markers.includes('later')",
                           "the later marker on the open page")
            page.wait_for_timeout(1500)
            self.assertIn("later", page.evaluate("window.viewerState().markers"))
            late = page.context.new_page()
            late.goto(self.base)
            self.wait_page(late, "window.viewerState().markers.includes('skewed')", "the late page")
            late.wait_for_timeout(1500)
            self.assertIn("later", late.evaluate("window.viewerState().markers"))
            self.assertEqual(page.errors, [])


if __name__ == "__main__":
    sys.exit(run_with_binaries(BINARIES, ("moosdb", "viewer")))
