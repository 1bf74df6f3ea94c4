"""Shared helpers for the pymoos2 wire-compatibility tests.

Contract:
- Every child process is started with die_with_parent (Linux PR_SET_PDEATHSIG), so even a
  test killed from outside leaves no server or client behind.
- MoosdbLite starts the moosdb-lite binary on 127.0.0.1 with --moos_port=0 and reads the
  port the OS chose from --port-file, so tests never race for ports. It is a context
  manager; leaving it (or the interpreter exiting) always stops the server (SIGTERM, then
  SIGKILL after a bounded wait).
- pymoos2_client() returns a started pymoos2 MOOSCommClient that is stopped at exit.
- wait_until() polls a condition with a bounded timeout; every wait in these tests is bounded.
- An exception in a pymoos2 comms thread silently ends that client (docs/protocol.md 9.2: e.g. a
  string that is not UTF-8). Such exceptions are recorded in `thread_errors` so a test can
  fail on them; only the known race of pymoos2's own stop() (it clears the socket while its
  thread is still reading) is ignored, for clients that were stopped on purpose.
"""

import atexit
import ctypes
import itertools
import os
import shutil
import signal
import subprocess
import tempfile
import threading
import time

from pymoos2 import MOOSCommClient

START_TIMEOUT_S = 10.0
STOP_TIMEOUT_S = 5.0
ARRIVAL_TIMEOUT_S = 5.0
POLL_PERIOD_S = 0.02
# pymoos2's lock-step period is 1/CommsTick; 20 Hz keeps the tests quick.
COMMS_TICK_HZ = 20.0

_live_processes = []
_live_clients = []
_stopped_threads = set()
thread_errors = []


def _record_thread_error(args):
    if args.thread in _stopped_threads:
        return
    thread_errors.append("%s in %s: %s" % (args.exc_type.__name__, args.thread.name, args.exc_value))


threading.excepthook = _record_thread_error


def _cleanup():
    for client in list(_live_clients):
        try:
            stop_client(client)
        except Exception:  # noqa: BLE001 - cleanup must go on
            pass
    for proc in list(_live_processes):
        _stop_process(proc)


atexit.register(_cleanup)


_PR_SET_PDEATHSIG = 1  # <sys/prctl.h>


def die_with_parent():
    """preexec_fn: the child gets SIGKILL when this test process ends, however it ends."""
    try:
        ctypes.CDLL("libc.so.6", use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)
    except OSError:
        pass  # not Linux: the atexit clean-up still runs on a normal exit


def _stop_process(proc):
    if proc.poll() is None:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=STOP_TIMEOUT_S)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
    if proc in _live_processes:
        _live_processes.remove(proc)
    return proc.returncode


def wait_until(condition, timeout_s=ARRIVAL_TIMEOUT_S):
    """Polls condition() until it is true or timeout_s passes; returns its last value."""
    deadline = time.monotonic() + timeout_s
    while True:
        value = condition()
        if value or time.monotonic() > deadline:
            return value
        time.sleep(POLL_PERIOD_S)


class MoosdbLite:
    """A moosdb-lite process for one test."""

    def __init__(self, binary, *extra_args):
        self.binary = binary
        self.extra_args = list(extra_args)
        self.dir = tempfile.mkdtemp(prefix="moosdb_lite_interop_")
        self.port = None
        self.proc = None
        self._stderr = None

    def __enter__(self):
        port_file = os.path.join(self.dir, "port")
        self._stderr = open(os.path.join(self.dir, "stderr.txt"), "w")
        self.proc = subprocess.Popen(
            [self.binary, "--moos_port=0", "--port-file=" + port_file] + self.extra_args,
            stdout=subprocess.DEVNULL, stderr=self._stderr, preexec_fn=die_with_parent)
        _live_processes.append(self.proc)

        def port_known():
            if self.proc.poll() is not None:
                raise RuntimeError("moosdb-lite exited at start-up:\n" + self.stderr_text())
            try:
                with open(port_file) as f:
                    text = f.read()
            except FileNotFoundError:
                return None
            return int(text) if text.endswith("\n") else None

        self.port = wait_until(port_known, START_TIMEOUT_S)
        if not self.port:
            self.stop()
            raise RuntimeError("moosdb-lite did not report its port")
        return self

    def __exit__(self, *exc):
        self.stop()
        shutil.rmtree(self.dir, ignore_errors=True)
        return False

    def stop(self):
        """SIGTERM and wait (bounded); returns the exit code."""
        code = _stop_process(self.proc) if self.proc else None
        if self._stderr:
            self._stderr.close()
            self._stderr = None
        return code

    def stderr_text(self):
        with open(os.path.join(self.dir, "stderr.txt")) as f:
            return f.read()


def pymoos2_client(port, name):
    """A started pymoos2 client (synchronous MOOS client), stopped at exit at the latest."""
    client = MOOSCommClient("127.0.0.1", port, name, COMMS_TICK_HZ)
    _live_clients.append(client)
    client.start()
    return client


def stop_client(client):
    if client._thread is not None:
        _stopped_threads.add(client._thread)
    client.stop()
    if client in _live_clients:
        _live_clients.remove(client)


class Mailbox:
    """Collects what a pymoos2 client fetches, so tests can wait for a number of messages."""

    def __init__(self, client):
        self.client = client
        self.messages = []

    def wait_for(self, count, keys=None, timeout_s=ARRIVAL_TIMEOUT_S):
        """Waits until `count` messages (with a key in `keys`, if given) have arrived."""
        def enough():
            self.messages.extend(self.client.fetch())
            return len(self.matching(keys)) >= count
        wait_until(enough, timeout_s)
        return self.matching(keys)

    def matching(self, keys):
        return [m for m in self.messages if keys is None or m.key in keys]


_sync_points = itertools.count()


def confirm_processed(client, box):
    """Returns once the server has processed everything `client` queued before this call.

    The client registers for a fresh variable and then posts it; the server handles one
    client's messages in order and delivers a publisher's own posts (protocol.md 5.3), so seeing the
    post come back proves that the earlier messages were handled. `box` keeps collecting.
    """
    key = "SYNC_POINT_%d" % next(_sync_points)
    client.register(key, 0.0)
    client.notify(key, 1.0)
    if len(box.wait_for(1, keys={key})) != 1:
        raise AssertionError("the server did not answer %s within %s s" % (key, ARRIVAL_TIMEOUT_S))


def run(args, timeout_s):
    """Runs a program to completion (bounded); returns CompletedProcess with text output."""
    return subprocess.run(args, capture_output=True, text=True, timeout=timeout_s,
                          preexec_fn=die_with_parent)
