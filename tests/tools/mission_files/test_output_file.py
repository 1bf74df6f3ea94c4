"""mission_files.output_file.write_output_file, the one writer of the Python tools' user-named
outputs: each kind of output (output_targets.py), a reader that never sees half a file, the
permissions, links to nothing yet, chains and loops."""

import os
import stat
import sys
import threading
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))
sys.path.insert(0, HERE)
from mission_files.output_file import write_output_file  # noqa: E402
from output_targets import OutputTargetChecks  # noqa: E402

TEXT = "x" * 200000 + "\n"


class WriteOutputFileTargets(OutputTargetChecks, unittest.TestCase):
    def write_to(self, path):
        try:
            write_output_file(path, TEXT)
        except OSError as e:
            return 1, str(e)
        return 0, ""

    def check_bytes(self, data):
        self.assertEqual(data, TEXT.encode())


class WriteOutputFileRules(unittest.TestCase):
    setUp = OutputTargetChecks.setUp
    tearDown = OutputTargetChecks.tearDown
    at = OutputTargetChecks.at

    def test_a_reader_never_sees_half_a_file(self):
        path = self.at("out")
        a, b = b"a" * 300000, b"b" * 100000
        write_output_file(path, a)
        done = threading.Event()

        def writer():
            for i in range(100):
                write_output_file(path, a if i % 2 else b)
            done.set()

        thread = threading.Thread(target=writer)
        thread.start()
        while not done.is_set():
            with open(path, "rb") as f:
                data = f.read()
            self.assertIn(data, (a, b), "a read of %d bytes" % len(data))
        thread.join()

    def test_a_replaced_file_keeps_its_permissions(self):
        path = self.at("kept")
        write_output_file(path, "old\n")
        os.chmod(path, 0o640)
        write_output_file(path, "new\n")
        self.assertEqual(stat.S_IMODE(os.stat(path).st_mode), 0o640)

    def test_a_link_to_nothing_yet_creates_its_target_through_a_chain(self):
        os.symlink(self.at("made"), self.at("dangling"))
        os.symlink("dangling", self.at("chain"))
        write_output_file(self.at("chain"), "x\n")
        self.assertTrue(os.path.islink(self.at("chain")))
        with open(self.at("made")) as f:
            self.assertEqual(f.read(), "x\n")

    def test_a_link_loop_and_a_missing_folder_are_errors_naming_the_path(self):
        os.symlink("b", self.at("a"))
        os.symlink("a", self.at("b"))
        with self.assertRaises(OSError) as loop:
            write_output_file(self.at("a"), "x\n")
        self.assertIn("cannot write '%s'" % self.at("a"), str(loop.exception))
        missing = os.path.join(self.dir, "no_such_folder", "out")
        with self.assertRaises(OSError) as gone:
            write_output_file(missing, "x\n")
        self.assertEqual(str(gone.exception),
                         "cannot write '%s': No such file or directory" % missing)


if __name__ == "__main__":
    unittest.main(verbosity=2)
