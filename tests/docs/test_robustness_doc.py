#!/usr/bin/env python3
"""docs/robustness.md against the test sources.

- Every test the document names (`Suite.Name` or `Suite.*` in code spans) is a GoogleTest test
  (or suite) of tests/; a file it names under tests/ exists.
- Every row of the bad-input tables (the sections headed "Bad input: ...") names at least one
  test, no two rows name the same tests, and the count the document gives is the number of rows
  (at least 80 kinds).

Usage: test_robustness_doc.py <repository root>
"""
import pathlib
import re
import sys
import unittest

ROOT = pathlib.Path(sys.argv.pop(1) if len(sys.argv) > 1 else "../..").resolve()
DOC = ROOT / "docs" / "robustness.md"
MIN_KINDS = 80
TEST_MACRO = re.compile(r"\bTEST(?:_F|_P)?\(\s*(\w+)\s*,\s*(\w+)\s*\)")
CODE_SPAN = re.compile(r"`([^`]+)`")
TEST_NAME = re.compile(r"^([A-Z]\w*)\.([A-Z]\w*|\*)$")
TEST_FILE = re.compile(r"^tests/[\w/.-]+\.(cpp|py)$")
COUNT = re.compile(r"hold (\d+) kinds of bad input")


def defined_tests(root):
    """{suite: {names}} of every TEST, TEST_F and TEST_P under tests/."""
    suites = {}
    for path in (root / "tests").rglob("*.cpp"):
        for suite, name in TEST_MACRO.findall(path.read_text(errors="replace")):
            suites.setdefault(suite, set()).add(name)
    return suites


def references(text):
    """The test names and test files named in code spans of `text`."""
    names, files = [], []
    for span in CODE_SPAN.findall(text):
        span = span.strip()
        if TEST_NAME.match(span):
            names.append(span)
        elif TEST_FILE.match(span):
            files.append(span)
    return names, files


def bad_input_rows(text):
    """The body rows (cells) of every table in the sections headed '## Bad input'."""
    rows, inside = [], False
    for line in text.splitlines():
        if line.startswith("## "):
            inside = line.startswith("## Bad input")
            continue
        if not inside or not line.startswith("|"):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells[0] == "Input" or set(line.replace("|", "").strip()) <= set("-: "):
            continue
        rows.append(cells)
    return rows


def resolves(reference, suites, exact):
    """Whether `Suite.Name` / `Suite.*` names a defined test. Outside the bad-input tables a
    suite may be shortened to its end, as the bounds tables do (`Hardening.*`)."""
    suite, name = reference.split(".")
    candidates = [s for s in suites if s == suite or (not exact and s.endswith(suite))]
    return any(name == "*" or name in suites[s] for s in candidates)


class RobustnessDoc(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.text = DOC.read_text()
        cls.suites = defined_tests(ROOT)
        cls.rows = bad_input_rows(cls.text)

    def test_every_named_test_exists(self):
        names, files = references(self.text)
        self.assertTrue(names)
        missing = [n for n in names if not resolves(n, self.suites, exact=False)]
        self.assertEqual(missing, [], "tests named in docs/robustness.md that do not exist")
        self.assertEqual([f for f in files if not (ROOT / f).is_file()], [])

    def test_bad_input_rows_name_tests_that_exist_exactly(self):
        for cells in self.rows:
            self.assertEqual(len(cells), 3, "a row needs input, answer and test: " + cells[0])
            names, files = references(cells[-1])
            self.assertTrue(names or files, "a row without a test: " + cells[0])
            for n in names:
                self.assertTrue(resolves(n, self.suites, exact=True), n + " in: " + cells[0])

    def test_no_two_rows_name_the_same_tests(self):
        seen = {}
        for cells in self.rows:
            key = tuple(sorted(references(cells[-1])[0] + references(cells[-1])[1]))
            self.assertNotIn(key, seen, f"'{cells[0]}' and '{seen.get(key)}' name the same tests")
            seen[key] = cells[0]

    def test_the_count_given_is_the_number_of_rows(self):
        counts = [int(c) for c in COUNT.findall(self.text)]
        self.assertEqual(counts, [len(self.rows)])
        self.assertGreaterEqual(len(self.rows), MIN_KINDS)

    def test_a_missing_test_is_found(self):
        # The check itself: a name that no TEST defines does not resolve, nor a wrong case.
        self.assertFalse(resolves("HostileHttp.NoSuchTestAnywhere", self.suites, exact=True))
        self.assertFalse(resolves("Hardening.*", self.suites, exact=True))
        self.assertTrue(resolves("Hardening.*", self.suites, exact=False))


if __name__ == "__main__":
    unittest.main(verbosity=2)
