"""pymoos2 0.1.0 (a foreign, pure-Python MOOS client) against moosdb-lite.

These tests are the proof that moosdb-lite speaks the MOOS protocol rather than a private
dialect: pymoos2 was written against the reference MOOSDB (docs/protocol.md section 9), and here
two pymoos2 clients exchange doubles, strings and binary data through our server, with
exact values, types, sources, time stamps and order.

Usage: python test_pymoos2_server.py --server=/path/to/moosdb-lite
"""

import argparse
import os
import sys
import tempfile
import unittest

from pymoos2.core.constants import (DATA_BINARY, DATA_DOUBLE, DATA_STRING, MSG_NOTIFY,
                                    MSG_TIMING)

import moosdb_harness
from moosdb_harness import (MoosdbLite, Mailbox, confirm_processed, pymoos2_client, stop_client,
                            wait_until)

SERVER = None
COMMUNITY = "interop"
# Same host, same clock: the WELCOME skew must be small (docs/protocol.md 1.8).
SKEW_TOLERANCE_S = 1.0
TIME_STAMP = 1700000000.25  # a fixed, exactly representable time stamp (protocol.md 8)


def connected_pair(server):
    a = pymoos2_client(server.port, "pyA")
    b = pymoos2_client(server.port, "pyB")
    assert a.wait_until_connected(5.0), "pyA did not connect"
    assert b.wait_until_connected(5.0), "pyB did not connect"
    return a, b


class Pymoos2AgainstMoosdbLite(unittest.TestCase):

    def setUp(self):
        self.server = MoosdbLite(SERVER, "--moos_community=" + COMMUNITY).__enter__()
        self.addCleanup(self.server.__exit__, None, None, None)
        self.addCleanup(self.assert_no_comms_thread_died)

    def assert_no_comms_thread_died(self):
        errors, moosdb_harness.thread_errors[:] = list(moosdb_harness.thread_errors), []
        self.assertEqual(errors, [], "a pymoos2 comms thread died")

    def clients(self):
        a, b = connected_pair(self.server)
        self.addCleanup(stop_client, a)
        self.addCleanup(stop_client, b)
        return a, b

    def test_welcome_gives_community_and_small_skew(self):
        a, _ = self.clients()
        self.assertEqual(a.community, COMMUNITY)
        self.assertLess(abs(a._skew), SKEW_TOLERANCE_S)

    def test_doubles_strings_and_binary_arrive_exactly_and_in_order(self):
        a, b = self.clients()
        for key in ("PY_D", "PY_S", "PY_B"):
            a.register(key, 0.0)
        box = Mailbox(a)
        confirm_processed(a, box)
        b.notify("PY_D", 1.5, time_val=TIME_STAMP)
        b.notify("PY_S", "hello world, h\u00e9llo \u2713", time_val=TIME_STAMP + 1)
        b.notify("PY_D", -2.25, time_val=TIME_STAMP + 2)
        b.notify("PY_B", b"\x00\xff\x10\x7f", time_val=TIME_STAMP + 3)
        b.notify("PY_S", "x" * 100000, time_val=TIME_STAMP + 4)  # spans many TCP segments
        mail = box.wait_for(5, keys={"PY_D", "PY_S", "PY_B"})
        self.assertEqual(len(mail), 5, mail)
        expected = [
            ("PY_D", DATA_DOUBLE, 1.5, TIME_STAMP),
            ("PY_S", DATA_STRING, "hello world, h\u00e9llo \u2713", TIME_STAMP + 1),
            ("PY_D", DATA_DOUBLE, -2.25, TIME_STAMP + 2),
            ("PY_B", DATA_BINARY, b"\x00\xff\x10\x7f", TIME_STAMP + 3),
            ("PY_S", DATA_STRING, "x" * 100000, TIME_STAMP + 4),
        ]
        for msg, (key, data_type, value, stamp) in zip(mail, expected):
            self.assertEqual(msg.msg_type, MSG_NOTIFY)
            self.assertEqual(msg.key, key)
            self.assertEqual(msg.data_type, data_type)
            self.assertEqual(msg.double() if data_type == DATA_DOUBLE else msg.sval, value)
            self.assertEqual(msg.src, "pyB")
            self.assertEqual(msg.community, COMMUNITY)
            self.assertEqual(msg.time, stamp)

    def test_registration_gets_a_snapshot_of_an_earlier_post(self):
        a, b = self.clients()
        # b sees its own post come back, so the server has stored it before a registers.
        b.register("PY_SNAP", 0.0)
        b.notify("PY_SNAP", 7.0, time_val=TIME_STAMP)
        self.assertEqual(len(Mailbox(b).wait_for(1, keys={"PY_SNAP"})), 1)
        a.register("PY_SNAP", 0.0)
        mail = Mailbox(a).wait_for(1, keys={"PY_SNAP"})
        self.assertEqual(len(mail), 1)
        self.assertEqual(mail[0].double(), 7.0)
        self.assertEqual(mail[0].src, "pyB")
        self.assertEqual(mail[0].time, TIME_STAMP)

    def test_wildcard_registration_in_pymoos2_blank_separated_form(self):
        a, b = self.clients()
        a.wildcard_register("PY_WILD_*")  # "AppPattern=* VarPattern=PY_WILD_* Interval=0.0"
        box = Mailbox(a)
        confirm_processed(a, box)
        b.notify("PY_OTHER", 1.0)
        b.notify("PY_WILD_1", 2.0)
        b.notify("PY_WILD_2", "two")
        mail = box.wait_for(2, keys={"PY_WILD_1", "PY_WILD_2", "PY_OTHER"})
        self.assertEqual([m.key for m in mail], ["PY_WILD_1", "PY_WILD_2"])
        self.assertEqual(mail[0].double(), 2.0)
        self.assertEqual(mail[1].string(), "two")

    def test_publisher_receives_its_own_posts(self):
        a, _ = self.clients()
        a.register("PY_SELF", 0.0)
        a.notify("PY_SELF", 3.0)
        mail = Mailbox(a).wait_for(1, keys={"PY_SELF"})
        self.assertEqual([(m.key, m.double(), m.src) for m in mail], [("PY_SELF", 3.0, "pyA")])

    def test_empty_string_is_posted_by_pymoos2_as_double_zero(self):
        a, b = self.clients()
        a.register("PY_EMPTY", 0.0)
        box = Mailbox(a)
        confirm_processed(a, box)
        b.notify("PY_EMPTY", "")
        mail = box.wait_for(1, keys={"PY_EMPTY"})
        self.assertEqual(len(mail), 1)
        self.assertEqual(mail[0].data_type, DATA_DOUBLE)
        self.assertEqual(mail[0].double(), 0.0)

    def test_db_clients_lists_both_names_each_followed_by_a_comma(self):
        a, _ = self.clients()
        a.register("DB_CLIENTS", 0.0)
        mail = Mailbox(a).wait_for(1, keys={"DB_CLIENTS"})
        self.assertTrue(mail)
        value = mail[-1].string()
        self.assertTrue(value.endswith(","), value)
        self.assertEqual(sorted(value.split(",")[:-1]), ["pyA", "pyB"])
        self.assertEqual(mail[-1].src, "MOOSDB_" + COMMUNITY)

    def test_sync_client_never_receives_timing_or_null(self):
        a, b = self.clients()
        a.register("PY_T", 0.0)
        box = Mailbox(a)
        confirm_processed(a, box)
        for i in range(20):
            b.notify("PY_T", float(i))
        mail = box.wait_for(20, keys={"PY_T"})
        self.assertEqual([m.double() for m in mail], [float(i) for i in range(20)])
        self.assertFalse([m for m in box.messages if m.msg_type == MSG_TIMING])

    def test_duplicate_name_is_refused_with_the_reference_reason(self):
        a, _ = self.clients()
        twin = pymoos2_client(self.server.port, "pyA")
        self.addCleanup(stop_client, twin)
        self.assertFalse(twin.wait_until_connected(1.5))
        self.assertIn('A client of this name ("pyA") already exists', self.server.stderr_text())
        # The original keeps working.
        a.register("PY_STILL", 0.0)
        a.notify("PY_STILL", 1.0)
        self.assertEqual(len(Mailbox(a).wait_for(1, keys={"PY_STILL"})), 1)

    def test_name_is_free_again_as_soon_as_the_client_closes(self):
        a, _ = self.clients()
        stop_client(a)
        again = pymoos2_client(self.server.port, "pyA")
        self.addCleanup(stop_client, again)
        self.assertTrue(again.wait_until_connected(5.0))


class Pymoos2AndTheLog(unittest.TestCase):

    def test_log_records_pymoos2_posts_exactly(self):
        folder = tempfile.TemporaryDirectory(prefix="moosdb_lite_log_")
        self.addCleanup(folder.cleanup)
        log_path = os.path.join(folder.name, "run.alog")
        with MoosdbLite(SERVER, "--log=" + log_path) as server:
            b = pymoos2_client(server.port, "pyLog")
            self.addCleanup(stop_client, b)
            self.assertTrue(b.wait_until_connected(5.0))
            b.notify("PY_LOG_D", 12.5)
            b.notify("PY_LOG_S", "two words")
            confirm_processed(b, Mailbox(b))
            stop_client(b)
            self.assertEqual(server.stop(), 0)
            with open(log_path) as f:
                lines = f.read().splitlines()
        self.assertTrue(lines[0].startswith("%% LOG FILE:"))
        self.assertTrue(lines[1].startswith("%% LOGSTART"))
        entries = [line.split(None, 3) for line in lines[3:]]
        mine = [(e[1], e[2], e[3]) for e in entries
                if len(e) == 4 and e[2] == "pyLog" and e[1].startswith("PY_LOG_")]
        self.assertEqual(mine, [("PY_LOG_D", "pyLog", "12.5"), ("PY_LOG_S", "pyLog", "two words")])


def main():
    global SERVER
    parser = argparse.ArgumentParser()
    parser.add_argument("--server", required=True, help="path of the moosdb-lite binary")
    args, rest = parser.parse_known_args()
    SERVER = args.server
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)


if __name__ == "__main__":
    main()
