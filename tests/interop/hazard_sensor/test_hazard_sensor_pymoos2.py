"""A pymoos2 vehicle plays against uFldHazardSensor on moosdb-lite.

pymoos2 0.1.0 is a synchronous client written against the reference MOOSDB (docs/protocol.md
section 9). The vehicle asks for a sensor setting, streams node reports and sensor requests
along a straight track over two objects, requests classifications and an AppCast, and checks
every reply against values computed by hand below. pd = 1 and pclass = 1.0 make every outcome
certain.

Usage: python test_hazard_sensor_pymoos2.py --server=/path/to/moosdb-lite
                                            --sensor=/path/to/uFldHazardSensor
"""

import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pymoos2"))

from pymoos2.core.time import set_moos_time_warp  # noqa: E402

import moosdb_harness  # noqa: E402
from moosdb_harness import Mailbox, MoosdbLite, pymoos2_client, stop_client  # noqa: E402

SERVER = None
SENSOR = None
WARP = 10
REPLY_TIMEOUT_S = 10.0
STOP_TIMEOUT_S = 10.0

BLOCK = """\
  AppTick = 4
  random_seed = 7
  min_reset_interval = 0
  min_classify_interval = 0
  swath_length = 4
  sensor_config = width=20, exp=2, pclass=1.0
  sensor_config = width=10, exp=4, pclass=0.90
  hazard = x=5,y=21,label=h1,type=hazard
  hazard = x=-8,y=41,label=b1,type=benign
"""

# Hand computations (manual 4, 10; differences.md D3, D21-D25).
# Options summary: file order, pclass= keys, values as written.
SUMMARY = "width=20,exp=2,pclass=1.0:width=10,exp=4,pclass=0.90"
# Width 15 is not an option: the next lower, 10 (exp 4, pclass 0.90). pfa = 0.9^4 = 0.6561,
# printed with 3 decimals and trailing zeros trimmed.
ACK_1 = "vname=alpha,width=10,pd=0.9,pfa=0.656,pclass=0.9"
# Width 20 (min_reset_interval 0), pd 1: pfa = 1^2 = 1.
ACK_2 = "vname=alpha,width=20,pd=1,pfa=1,pclass=1"
# Along x = 0, y = 0, 2, ..., 60 (heading 0), an object is inside the swath when
# |y_obj - y| <= 2 (swath_length 4) and |x_obj| <= 20: h1 first at y = 20, b1 at y = 40.
DETECTIONS = ["x=5,y=21,label=h1", "x=-8,y=41,label=b1"]
ANSWERS = ["x=5,y=21,label=h1,type=hazard", "x=-8,y=41,label=b1,type=benign"]


def swath(y):
    """The swath at (0, y), heading 0: 20 m to each side, 2 m fore and aft (differences.md T1)."""
    return ("pts={20,%d:20,%d:-20,%d:-20,%d},label=sensor_swath_alpha,msg=1.00,edge_color=green,"
            "fill_color=white,vertex_size=0,edge_size=0,fill_transparency=0.2"
            % (y + 2, y - 2, y - 2, y + 2))


class Pymoos2Vehicle(unittest.TestCase):

    def setUp(self):
        set_moos_time_warp(WARP)
        self.dir = tempfile.mkdtemp(prefix="uhz_pymoos2_")
        self.addCleanup(shutil.rmtree, self.dir, True)
        self.server = MoosdbLite(SERVER, "--moos_community=shoreside",
                                 "--moos_time_warp=%d" % WARP).__enter__()
        self.addCleanup(self.server.__exit__, None, None, None)
        mission = os.path.join(self.dir, "m.moos")
        with open(mission, "w") as f:
            f.write("ServerHost = 127.0.0.1\nServerPort = %d\nCommunity = shoreside\n"
                    "MOOSTimeWarp = %d\n\nProcessConfig = uFldHazardSensor\n{\n%s}\n"
                    % (self.server.port, WARP, BLOCK))
        self.sensor_err = open(os.path.join(self.dir, "sensor.err"), "w")
        self.addCleanup(self.sensor_err.close)
        self.sensor = subprocess.Popen([SENSOR, mission], stdout=subprocess.DEVNULL,
                                       stderr=self.sensor_err,
                                       preexec_fn=moosdb_harness.die_with_parent)
        self.addCleanup(self.kill_sensor)
        self.addCleanup(self.assert_no_comms_thread_died)
        self.vehicle = pymoos2_client(self.server.port, "alpha_pymoos2")
        self.addCleanup(stop_client, self.vehicle)
        self.assertTrue(self.vehicle.wait_until_connected(REPLY_TIMEOUT_S))
        for var in ("UHZ_OPTIONS_SUMMARY", "UHZ_CONFIG_ACK_ALPHA", "UHZ_DETECTION_REPORT_ALPHA",
                    "UHZ_HAZARD_REPORT_ALPHA", "VIEW_POLYGON", "APPCAST"):
            self.vehicle.register(var, 0.0)
        self.box = Mailbox(self.vehicle)

    def kill_sensor(self):
        if self.sensor.poll() is None:
            self.sensor.kill()
            self.sensor.wait()

    def assert_no_comms_thread_died(self):
        errors, moosdb_harness.thread_errors[:] = list(moosdb_harness.thread_errors), []
        self.assertEqual(errors, [], "a pymoos2 comms thread died")

    def values(self, key):
        return [m.string() for m in self.box.matching({key}) if m.is_string()]

    def wait_value(self, key, value):
        """Waits (bounded) until `value` has arrived on `key`."""
        def arrived():
            self.box.messages.extend(self.vehicle.fetch())
            return value in self.values(key)
        self.assertTrue(moosdb_harness.wait_until(arrived, REPLY_TIMEOUT_S),
                        "no %s = %s; got %s" % (key, value, self.values(key)[-3:]))

    def test_vehicle_gets_setting_detections_and_classifications(self):
        self.wait_value("UHZ_OPTIONS_SUMMARY", SUMMARY)

        self.vehicle.notify("UHZ_CONFIG_REQUEST", "vname=alpha,width=15,pd=0.9")
        self.wait_value("UHZ_CONFIG_ACK_ALPHA", ACK_1)
        self.vehicle.notify("UHZ_CONFIG_REQUEST", "vname=alpha,width=20,pd=1")
        self.wait_value("UHZ_CONFIG_ACK_ALPHA", ACK_2)

        for y in range(0, 62, 2):
            self.vehicle.notify("UHZ_SENSOR_REQUEST", "vname=alpha")
            self.vehicle.notify("NODE_REPORT", "NAME=alpha,X=0,Y=%d,SPD=1,HDG=0,TYPE=kayak" % y)
            self.wait_value("VIEW_POLYGON", swath(y))
        self.assertEqual(self.values("UHZ_DETECTION_REPORT_ALPHA"), DETECTIONS)

        for label in ("h1", "b1"):
            self.vehicle.notify("UHZ_CLASSIFY_REQUEST", "vname=alpha,label=%s,priority=70" % label)
        for answer in ANSWERS:
            self.wait_value("UHZ_HAZARD_REPORT_ALPHA", answer)
        self.assertEqual(self.values("UHZ_HAZARD_REPORT_ALPHA"), ANSWERS)

        # An AppCast on request (uMAC's form of the request), with the seed in its header block.
        self.vehicle.notify("APPCAST_REQ",
                            "node=shoreside,app=uFldHazardSensor,duration=3.0,key=pytest,thresh=any")

        def appcast_with_seed():
            self.box.messages.extend(self.vehicle.fetch())
            return any("!@       Seed: 7 (random_seed)!@" in v and "!@alpha " in v
                       for v in self.values("APPCAST"))
        self.assertTrue(moosdb_harness.wait_until(appcast_with_seed, REPLY_TIMEOUT_S))

        self.sensor.send_signal(signal.SIGTERM)
        self.assertEqual(self.sensor.wait(timeout=STOP_TIMEOUT_S), 0)
        with open(os.path.join(self.dir, "sensor.err")) as f:
            self.assertEqual(f.read(), "")


def main():
    global SERVER, SENSOR
    parser = argparse.ArgumentParser()
    parser.add_argument("--server", required=True, help="path of the moosdb-lite binary")
    parser.add_argument("--sensor", required=True, help="path of the uFldHazardSensor binary")
    args, rest = parser.parse_known_args()
    SERVER, SENSOR = args.server, args.sensor
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)


if __name__ == "__main__":
    main()
