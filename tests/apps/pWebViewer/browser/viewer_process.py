"""The programs a browser test starts (moosdb_harness must be importable: the tests put
tests/interop/pymoos2 on sys.path): started to die with the test, stopped with a bounded wait,
and pWebViewer's served URL read from its standard output."""

import re
import subprocess
import time
from typing import NamedTuple

import moosdb_harness

SERVED = re.compile(r"serving ((http://(\S+?):(\d+)/)\?token=([0-9a-f]+))\s")


class ServedUrl(NamedTuple):
    url: str    # what to open: the page with its token
    base: str   # the page without the token
    host: str
    port: int
    token: str


def start(args, log_path):
    """`args` as a child that dies with the test; stdout piped, stderr to `log_path`."""
    with open(log_path, "w") as log:
        return subprocess.Popen(args, stdout=subprocess.PIPE, stderr=log, text=True,
                                preexec_fn=moosdb_harness.die_with_parent)


def stop(proc):
    """SIGTERM, then SIGKILL after 10 s."""
    if proc.poll() is None:
        proc.terminate()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


def served_url(proc, timeout_s=20):
    """The URL pWebViewer prints at start-up (`pWebViewer: serving http://HOST:PORT/?token=T`)."""
    deadline = time.time() + timeout_s
    while time.time() < deadline:
        line = proc.stdout.readline()
        if not line:
            break
        m = SERVED.search(line)
        if m:
            return ServedUrl(m.group(1), m.group(2), m.group(3), int(m.group(4)), m.group(5))
    raise RuntimeError("pWebViewer printed no URL with a token")
