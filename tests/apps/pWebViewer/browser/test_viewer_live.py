"""A live moosdb-lite mission in a real browser, then the replay of its .alog.

moosdb-lite (logging every posting), uFldHazardSensor with four objects, pWebViewer, and a
pymoos2 vehicle that drives along x = 0 with a certain sensor (pd = 1). The page must show the
vehicle moving, a marker per object, a detection circle appearing and expiring, a marker removed
by active=false, the sensor's AppCast, and a configured button posting to the MOOSDB; a page
that connects late shows the same objects (the retained state); then
`pWebViewer --replay=<the log>` seeked to the times of two live snapshots, and the exported
HTML file opened from disk, must show the same objects.

Usage: python test_viewer_live.py --moosdb=BIN --sensor=BIN --viewer=BIN
"""

import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[2] / "interop" / "pymoos2"))

from pymoos2.core.time import set_moos_time_warp  # noqa: E402

from moosdb_harness import Mailbox, MoosdbLite, pymoos2_client, stop_client, wait_until  # noqa: E402
from browser_support import browser_page, run_with_binaries  # noqa: E402
from viewer_process import served_url, start, stop  # noqa: E402

BINARIES = {}
WARP = 4
DETECTION_DURATION_S = 6          # MOOS seconds a detection circle lasts (show_detections)
OBJECTS = {"h1": (5, 21), "h2": (-6, 31), "b1": (-8, 41), "b2": (30, 200)}
PAGE_TIMEOUT_MS = 20000

SENSOR_BLOCK = """\
  AppTick = 4
  random_seed = 7
  min_reset_interval = 0
  swath_length = 4
  show_detections = %d
  sensor_config = width=20, exp=2, pclass=1.0
""" % DETECTION_DURATION_S + "".join(
    "  hazard = x=%d,y=%d,label=%s,type=%s\n" % (x, y, label, "hazard" if label[0] == "h" else "benign")
    for label, (x, y) in OBJECTS.items())

VIEWER_BLOCK = """\
  AppTick = 4
  http_port = 0
  button_one = DEPLOY # DEPLOY_ALL=true # MOOS_MANUAL_OVERRIDE_ALL=false
"""


def view_sets(s):
    """What must agree between live and replay: the object sets and vehicle poses."""
    return {"markers": sorted(s["markers"]), "polygons": sorted(s["polygons"]),
            "seglists": len(s["seglists"]), "circles": len(s["circles"]),
            "points": sorted(s["points"]),
            "vehicles": {n: (round(v["x"], 1), round(v["y"], 1)) for n, v in s["vehicles"].items()}}


class LiveMissionThenReplay(unittest.TestCase):

    def setUp(self):
        set_moos_time_warp(WARP)
        self.dir = tempfile.mkdtemp(prefix="viewer_live_")
        self.addCleanup(shutil.rmtree, self.dir, True)
        self.alog = os.path.join(self.dir, "run.alog")
        self.server = MoosdbLite(BINARIES["moosdb"], "--moos_community=shoreside",
                                 "--moos_time_warp=%d" % WARP, "--log=" + self.alog).__enter__()
        self.addCleanup(self.server.__exit__, None, None, None)
        self.mission = os.path.join(self.dir, "m.moos")
        with open(self.mission, "w") as f:
            f.write("ServerHost = 127.0.0.1\nServerPort = %d\nCommunity = shoreside\n"
                    "MOOSTimeWarp = %d\n\nProcessConfig = uFldHazardSensor\n{\n%s}\n\n"
                    "ProcessConfig = pWebViewer\n{\n%s}\n"
                    % (self.server.port, WARP, SENSOR_BLOCK, VIEWER_BLOCK))
        self.sensor = start([BINARIES["sensor"], self.mission], os.path.join(self.dir, "sensor.err"))
        self.addCleanup(stop, self.sensor)
        self.viewer = start([BINARIES["viewer"], self.mission], os.path.join(self.dir, "viewer.err"))
        self.addCleanup(stop, self.viewer)
        self.url = served_url(self.viewer).url
        self.vehicle = pymoos2_client(self.server.port, "alpha_pymoos2")
        self.addCleanup(stop_client, self.vehicle)
        self.assertTrue(self.vehicle.wait_until_connected(10))
        self.vehicle.register("DEPLOY_ALL", 0.0)
        self.box = Mailbox(self.vehicle)

    def wait_page(self, page, condition, what):
        try:
            page.wait_for_function(condition, timeout=PAGE_TIMEOUT_MS)
        except Exception:  # the page's state says more than Playwright's timeout
            self.fail("%s; page state: %s" % (what, page.evaluate("window.viewerState()")))

    def test_live_view_then_replay_of_its_log(self):
        with browser_page() as page:
            page.goto(self.url)
            # A hazard marker per object, from the retained state the sensor posted at start-up.
            self.wait_page(page, "window.viewerState().markers.length === %d" % len(OBJECTS),
                           "a marker per object")
            self.assertEqual(page.evaluate("window.viewerState().mode"), "live")
            self.assertEqual(sorted(page.evaluate("window.viewerState().markers")), sorted(OBJECTS))

            # A marker posted and then removed with active=false.
            self.vehicle.notify("VIEW_MARKER", "x=60,y=60,width=5,primary_color=orange,"
                                               "type=diamond,label=temp_marker")
            self.wait_page(page, "window.viewerState().markers.includes('temp_marker')",
                           "the posted marker shown")
            self.vehicle.notify("VIEW_MARKER", "x=60,y=60,label=temp_marker,active=false")
            self.wait_page(page, "!window.viewerState().markers.includes('temp_marker')",
                           "the marker removed by active=false")

            # The vehicle drives north along x = 0 with a certain sensor.
            self.vehicle.notify("UHZ_CONFIG_REQUEST", "vname=alpha,width=20,pd=1")
            ys_seen, circles_seen, snapshot_with_circle = set(), 0, None
            for y in range(0, 52, 2):
                self.vehicle.notify("UHZ_SENSOR_REQUEST", "vname=alpha")
                self.vehicle.notify("NODE_REPORT", "NAME=alpha,X=0,Y=%d,SPD=2,HDG=0,TYPE=kayak,"
                                                   "LENGTH=4,COLOR=yellow" % y)
                time.sleep(1.0 / WARP)  # one MOOS second per step
                s = page.evaluate("window.viewerState()")
                if "alpha" in s["vehicles"]:
                    ys_seen.add(s["vehicles"]["alpha"]["y"])
                if s["circles"] and snapshot_with_circle is None:
                    page.wait_for_timeout(300)  # let the step's postings settle
                    snapshot_with_circle = page.evaluate("window.viewerState()")
                circles_seen = max(circles_seen, len(s["circles"]))
            self.assertGreater(len(ys_seen), 5, "the vehicle is seen moving")
            self.assertGreaterEqual(circles_seen, 1, "a detection circle appeared")
            self.assertIsNotNone(snapshot_with_circle)
            self.assertIn("sensor_swath_alpha", snapshot_with_circle["polygons"])

            # Every detection circle expires DETECTION_DURATION_S MOOS seconds after it came.
            self.wait_page(page, "window.viewerState().circles.length === 0",
                           "the detection circles expired")

            # The sensor's AppCast (pWebViewer asks for it with APPCAST_REQ).
            self.wait_page(page, "(window.viewerState().appcasts['shoreside/uFldHazardSensor'] || '')"
                                 ".includes('alpha')", "the sensor's AppCast naming the vehicle")
            self.wait_page(page, "document.getElementById('appcast-text').textContent"
                                 ".includes('uFldHazardSensor')", "the AppCast pane")
            # The configured button, pressed in the page, posts its assignments to the MOOSDB.
            page.click("#buttons button:has-text('DEPLOY')")

            def deployed():
                self.box.messages.extend(self.vehicle.fetch())
                return any(m.string() == "true" for m in self.box.matching({"DEPLOY_ALL"})
                           if m.is_string())
            self.assertTrue(wait_until(deployed, 10), "DEPLOY_ALL=true posted by the button")

            page.wait_for_timeout(1000)
            quiet_snapshot = page.evaluate("window.viewerState()")
            self.assertEqual(page.errors, [])

            # A page that connects now draws what the first one does, from the retained state.
            late = page.context.new_page()
            late.goto(self.url)
            self.wait_page(late, "window.viewerState().markers.length === %d" % len(OBJECTS),
                           "the late page's markers")
            late.wait_for_timeout(500)
            self.assertEqual(view_sets(late.evaluate("window.viewerState()")),
                             view_sets(page.evaluate("window.viewerState()")))
            self.assertEqual(sorted(late.evaluate("window.viewerState().appcasts")),
                             sorted(quiet_snapshot["appcasts"]))

        stop(self.viewer)
        stop(self.sensor)
        stop_client(self.vehicle)
        self.server.__exit__(None, None, None)
        self.check_replay(snapshot_with_circle, quiet_snapshot)

    def check_replay(self, *snapshots):
        replay = start([BINARIES["viewer"], self.mission, "--replay=" + self.alog],
                       os.path.join(self.dir, "replay.err"))
        self.addCleanup(stop, replay)
        url = served_url(replay).url
        with browser_page() as page:
            page.goto(url)
            self.wait_page(page, "window.viewerState().replay !== undefined", "replay loaded")
            for live in snapshots:
                page.evaluate("window.viewerSeek(%r)" % live["time"])
                replayed = page.evaluate("window.viewerState()")
                self.assertEqual(view_sets(replayed), view_sets(live),
                                 "replay at MOOS time %.2f" % live["time"])
                self.assertEqual(sorted(replayed["appcasts"]), sorted(live["appcasts"]))
            self.assertEqual(page.errors, [])
        self.check_export(*snapshots)

    def check_export(self, *snapshots):
        """The self-contained HTML file of --export, opened from disk, replays the same."""
        html = os.path.join(self.dir, "view.html")
        done = subprocess.run([BINARIES["viewer"], "--export=" + self.alog, "--output=" + html],
                              capture_output=True, text=True, timeout=60)
        self.assertEqual(done.returncode, 0, done.stderr)
        with browser_page() as page:
            page.goto(Path(html).as_uri())
            self.wait_page(page, "window.viewerState && window.viewerState().replay !== undefined",
                           "exported replay loaded")
            for live in snapshots:
                page.evaluate("window.viewerSeek(%r)" % live["time"])
                self.assertEqual(view_sets(page.evaluate("window.viewerState()")), view_sets(live))
            self.assertEqual(page.errors, [])


if __name__ == "__main__":
    sys.exit(run_with_binaries(BINARIES, ("moosdb", "sensor", "viewer")))
