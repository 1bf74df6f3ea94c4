"""Our C++ client (moos-cli, on libmoos) and pymoos2 exchange posts through moosdb-lite.

pymoos2 is a synchronous client written against the reference MOOSDB; moos-cli is our
asynchronous client. Each direction is checked with exact variables, types, values, sources
and order, so a private dialect between our client and our server would show up here.

Usage: python test_pymoos2_cli.py --server=/path/to/moosdb-lite --cli=/path/to/moos-cli
"""

import argparse
import subprocess
import sys
import unittest

from pymoos2.core.constants import DATA_DOUBLE, DATA_STRING

import moosdb_harness
from moosdb_harness import (ARRIVAL_TIMEOUT_S, MoosdbLite, Mailbox, confirm_processed,
                            pymoos2_client, run, stop_client, wait_until)

SERVER = None
CLI = None
TIME_STAMP = 1700000000.25  # exactly representable (protocol.md 8); differences print exactly
WATCH_TIMEOUT_S = 20
PROCESS_TIMEOUT_S = 30


def parse_line(line):
    """TIME VARIABLE SOURCE VALUE (value may contain blanks)."""
    time, variable, source, value = line.split(None, 3)
    return float(time), variable, source, value


class MoosCliAndPymoos2(unittest.TestCase):

    def setUp(self):
        self.server = MoosdbLite(SERVER, "--moos_community=interop").__enter__()
        self.addCleanup(self.server.__exit__, None, None, None)
        self.addCleanup(self.assert_no_comms_thread_died)
        self.py = pymoos2_client(self.server.port, "pyPeer")
        self.addCleanup(stop_client, self.py)
        self.assertTrue(self.py.wait_until_connected(5.0))

    def assert_no_comms_thread_died(self):
        errors, moosdb_harness.thread_errors[:] = list(moosdb_harness.thread_errors), []
        self.assertEqual(errors, [], "a pymoos2 comms thread died")

    def cli(self, *args):
        return [CLI, args[0], "--host=127.0.0.1", "--port=%d" % self.server.port] + list(args[1:])

    def start_watch(self, name, count, *variables):
        """Starts `moos-cli watch` and returns once the server has seen it connect."""
        proc = subprocess.Popen(
            self.cli("watch", "--name=" + name, "--count=%d" % count,
                     "--timeout=%d" % WATCH_TIMEOUT_S, *variables),
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
            preexec_fn=moosdb_harness.die_with_parent)
        self.addCleanup(self.kill, proc)
        connected = 'client "%s" (' % name
        self.assertTrue(wait_until(lambda: connected in self.server.stderr_text()),
                        "moos-cli watch did not connect")
        return proc

    @staticmethod
    def kill(proc):
        if proc.poll() is None:
            proc.kill()
        proc.communicate(timeout=PROCESS_TIMEOUT_S)

    def finish(self, proc):
        out, err = proc.communicate(timeout=PROCESS_TIMEOUT_S)
        self.assertEqual(proc.returncode, 0, err)
        return [parse_line(line) for line in out.splitlines() if line.strip()]

    def wait_registered(self, name, variables):
        """The server has processed the watch's registrations (its DB_RWSUMMARY entry lists them)."""
        self.py.register("DB_RWSUMMARY", 0.0)
        box = Mailbox(self.py)

        def listed():
            box.messages.extend(self.py.fetch())
            summaries = [m.string() for m in box.messages if m.key == "DB_RWSUMMARY"]
            return summaries and all(v in summaries[-1].split(name + "=", 1)[-1].split("&")[0]
                                     for v in variables)
        self.assertTrue(wait_until(listed, ARRIVAL_TIMEOUT_S), "watch registrations not seen")

    def test_moos_cli_watch_prints_pymoos2_posts_exactly(self):
        variables = ["PYC_D", "PYC_S", "PYC_B"]
        watch = self.start_watch("cliWatch", 4, *variables)
        self.wait_registered("cliWatch", variables)
        self.py.notify("PYC_D", 1.5, time_val=TIME_STAMP)
        self.py.notify("PYC_S", "hello world, h\u00e9llo", time_val=TIME_STAMP + 1)
        self.py.notify("PYC_B", b"\x00\xff\x10\x7f", time_val=TIME_STAMP + 2)
        self.py.notify("PYC_D", -2.25, time_val=TIME_STAMP + 3)
        lines = self.finish(watch)
        self.assertEqual([line[1:] for line in lines], [
            ("PYC_D", "pyPeer", "1.5"),
            ("PYC_S", "pyPeer", "hello world, h\u00e9llo"),
            ("PYC_B", "pyPeer", "<binary:4:00ff107f>"),
            ("PYC_D", "pyPeer", "-2.25"),
        ])
        # The time column is the message's own time stamp minus one start time.
        self.assertEqual([round(t - lines[0][0], 3) for t, *_ in lines], [0.0, 1.0, 2.0, 3.0])

    def test_moos_cli_watch_gets_a_snapshot_of_an_earlier_pymoos2_post(self):
        self.py.register("PYC_SNAP", 0.0)
        self.py.notify("PYC_SNAP", "before", time_val=TIME_STAMP)
        self.assertEqual(len(Mailbox(self.py).wait_for(1, keys={"PYC_SNAP"})), 1)
        lines = self.finish(self.start_watch("cliSnap", 1, "PYC_SNAP"))
        self.assertEqual([line[1:] for line in lines], [("PYC_SNAP", "pyPeer", "before")])

    def test_moos_cli_wildcard_watch_sees_pymoos2_posts(self):
        watch = self.start_watch("cliWild", 2, "PYC_W_*")
        # No need to wait for the wildcard registration: one that arrives after the posts
        # still delivers them, as snapshots in the same order (protocol.md 5.5).
        self.py.notify("PYC_OTHER", 1.0)
        self.py.notify("PYC_W_1", 2.0)
        self.py.notify("PYC_W_2", "two")
        lines = self.finish(watch)
        self.assertEqual([line[1:] for line in lines],
                         [("PYC_W_1", "pyPeer", "2"), ("PYC_W_2", "pyPeer", "two")])

    def test_pymoos2_receives_moos_cli_pokes_exactly(self):
        keys = {"PYC_POKE_D", "PYC_POKE_S", "PYC_POKE_Q"}
        for key in sorted(keys):
            self.py.register(key, 0.0)
        box = Mailbox(self.py)
        confirm_processed(self.py, box)
        result = run(self.cli("poke", "--name=cliPoke", "PYC_POKE_D=3.25",
                              "PYC_POKE_S=two words", "PYC_POKE_Q:=12", "PYC_POKE_D=-0.5"),
                     PROCESS_TIMEOUT_S)
        self.assertEqual(result.returncode, 0, result.stderr)
        mail = box.wait_for(4, keys=keys)
        self.assertEqual(
            [(m.key, m.data_type, m.double() if m.data_type == DATA_DOUBLE else m.string(), m.src)
             for m in mail],
            [("PYC_POKE_D", DATA_DOUBLE, 3.25, "cliPoke"),
             ("PYC_POKE_S", DATA_STRING, "two words", "cliPoke"),
             ("PYC_POKE_Q", DATA_STRING, "12", "cliPoke"),
             ("PYC_POKE_D", DATA_DOUBLE, -0.5, "cliPoke")])
        for m in mail:
            self.assertEqual(m.community, "interop")

    def test_pymoos2_wildcard_receives_moos_cli_pokes(self):
        self.py.wildcard_register("PYC_PW_*")
        box = Mailbox(self.py)
        confirm_processed(self.py, box)
        result = run(self.cli("poke", "--name=cliPoke2", "PYC_PW_A=1", "PYC_NOT=2", "PYC_PW_B=x"),
                     PROCESS_TIMEOUT_S)
        self.assertEqual(result.returncode, 0, result.stderr)
        mail = box.wait_for(2, keys={"PYC_PW_A", "PYC_PW_B", "PYC_NOT"})
        self.assertEqual([(m.key, m.src) for m in mail],
                         [("PYC_PW_A", "cliPoke2"), ("PYC_PW_B", "cliPoke2")])
        self.assertEqual(mail[0].double(), 1.0)
        self.assertEqual(mail[1].string(), "x")


def main():
    global SERVER, CLI
    parser = argparse.ArgumentParser()
    parser.add_argument("--server", required=True, help="path of the moosdb-lite binary")
    parser.add_argument("--cli", required=True, help="path of the moos-cli binary")
    args, rest = parser.parse_known_args()
    SERVER, CLI = args.server, args.cli
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)


if __name__ == "__main__":
    main()
