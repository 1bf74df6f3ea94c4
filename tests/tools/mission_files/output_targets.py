"""What the Python tests of user-named outputs share (the Python twin of
tests/support/output_targets.hpp): a mixin of unittest cases that write to each kind of output
and expect the rule of tools/mission_files/output_file.py.

A test class mixes OutputTargetChecks into unittest.TestCase and defines
  write_to(path) -> (exit code, standard error)   the tool (or function) writing to `path`
  check_bytes(data)                               what must have arrived (bytes)
  NAME                                            the output's file name (e.g. "summary.json")

Device nodes are made in the test's own folder (os.mknod, allowed to root), so that a tool that
wrongly renames over its output replaces the test's node, never the machine's /dev/null; without
the right to make one the machine's device is used when not root (who cannot replace it), else
the case is skipped. A FIFO's reader is a thread that gives up after READ_WAIT_S: never a hang.
"""

import os
import select
import shutil
import stat
import tempfile
import threading
import time

READ_WAIT_S = 60.0
NULL, FULL = 3, 7  # minor numbers of /dev/null and /dev/full


def make_device(path, minor):
    """A character device like /dev/null or /dev/full at `path`, or the machine's own when
    not root; None when neither can be used."""
    try:
        os.mknod(path, 0o666 | stat.S_IFCHR, os.makedev(1, minor))
        os.close(os.open(path, os.O_WRONLY))
        return path
    except OSError:
        if os.path.lexists(path):
            os.unlink(path)
    if os.geteuid() == 0:
        return None
    return "/dev/null" if minor == NULL else "/dev/full"


def kind(path):
    """The file type bits of `path` itself (a link is a link); 0 when missing."""
    try:
        return stat.S_IFMT(os.lstat(path).st_mode)
    except FileNotFoundError:
        return 0


def read_fifo(path, wait_s, into):
    """Appends to `into` what the FIFO's writers write, until one has come and gone."""
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    give_up = time.monotonic() + wait_s
    poller = select.poll()
    poller.register(fd, select.POLLIN)
    try:
        while time.monotonic() < give_up:
            events = poller.poll(50)
            if not events:
                continue
            block = os.read(fd, 65536)
            if block:
                into.append(block)
            elif events[0][1] & select.POLLHUP:
                break  # (Linux: POLLHUP only once a writer has come and gone)
    finally:
        os.close(fd)


class OutputTargetChecks:
    NAME = "out"

    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="output_targets_")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def at(self, name):
        return os.path.join(self.dir, name)

    def test_a_null_device_stays_a_device(self):
        device = make_device(self.at("null"), NULL)
        if device is None:
            self.skipTest("no device node can be made here")
        code, err = self.write_to(device)
        self.assertEqual(code, 0, err)
        self.assertEqual(kind(device), stat.S_IFCHR)

    def test_a_full_device_is_an_error_naming_it(self):
        device = make_device(self.at("full"), FULL)
        if device is None:
            self.skipTest("no device node can be made here")
        code, err = self.write_to(device)
        self.assertNotEqual(code, 0)
        self.assertIn("cannot write '%s': No space left on device" % device, err)
        self.assertEqual(kind(device), stat.S_IFCHR)

    def test_a_fifo_with_a_reader_gets_the_bytes(self):
        fifo = self.at("fifo")
        os.mkfifo(fifo)
        got = []
        reader = threading.Thread(target=read_fifo, args=(fifo, READ_WAIT_S, got))
        reader.start()
        code, err = self.write_to(fifo)
        reader.join()
        self.assertEqual(code, 0, err)
        self.check_bytes(b"".join(got))
        self.assertEqual(kind(fifo), stat.S_IFIFO)

    def test_a_fifo_without_a_reader_is_an_error_after_the_wait(self):
        fifo = self.at("fifo")
        os.mkfifo(fifo)
        start = time.monotonic()
        code, err = self.write_to(fifo)
        self.assertNotEqual(code, 0)
        self.assertIn("cannot write '%s': no process is reading the FIFO" % fifo, err)
        self.assertLess(time.monotonic() - start, 30.0)
        self.assertEqual(kind(fifo), stat.S_IFIFO)

    def test_a_symlink_stays_a_link_and_its_file_gets_the_bytes(self):
        os.mkdir(self.at("real"))
        target = os.path.join(self.at("real"), self.NAME)
        with open(target, "w") as f:
            f.write("old content\n")
        link = self.at(self.NAME)
        os.symlink(os.path.join("real", self.NAME), link)  # relative
        code, err = self.write_to(link)
        self.assertEqual(code, 0, err)
        self.assertEqual(kind(link), stat.S_IFLNK)
        with open(target, "rb") as f:
            self.check_bytes(f.read())

    def test_a_regular_file_is_replaced_by_a_rename(self):
        path = self.at(self.NAME)
        with open(path, "w") as f:
            f.write("old content\n")
        before = os.stat(path).st_ino
        code, err = self.write_to(path)
        self.assertEqual(code, 0, err)
        self.assertNotEqual(os.stat(path).st_ino, before, "written in place, not replaced")
        with open(path, "rb") as f:
            self.check_bytes(f.read())
        self.assertEqual([n for n in os.listdir(self.dir) if ".tmp." in n], [])

    def test_a_directory_is_refused_naming_it(self):
        folder = self.at("folder")
        os.mkdir(folder)
        code, err = self.write_to(folder)
        self.assertNotEqual(code, 0)
        self.assertIn("cannot write '%s': it is a directory" % folder, err)
        self.assertEqual(kind(folder), stat.S_IFDIR)
        self.assertEqual(os.listdir(folder), [])
