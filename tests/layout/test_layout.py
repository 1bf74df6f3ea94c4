#!/usr/bin/env python3
"""The architecture's rules, checked on the source tree (docs/architecture.md).

- Libraries use only what lies below them: base uses nothing of ours; hazard and moos use base
  and never each other; mission uses base and hazard; no library includes a header of an app.
- No benchmark links an app's code or includes an app's header.
- No source file is longer than MAX_LINES.

Usage: test_layout.py <repository root>
"""
import pathlib
import re
import sys
import unittest

ROOT = pathlib.Path(sys.argv.pop(1) if len(sys.argv) > 1 else ".").resolve()
MAX_LINES = 600
SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".py", ".sh", ".js"}
SOURCE_FOLDERS = ["include", "src", "tests", "bench", "tools", "missions", "fuzz"]
# What each library may include from our own headers (include/<part>/...).
ALLOWED_PARTS = {
    "base": {"base"},
    "hazard": {"base", "hazard"},
    "moos": {"base", "moos"},
    "mission": {"base", "hazard", "mission"},
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def library_files(part):
    for folder in (ROOT / "include" / part, ROOT / "src" / part):
        if folder.is_dir():
            yield from (p for p in folder.rglob("*") if p.suffix in {".cpp", ".hpp", ".h"})


def resolve(include, including_file):
    """Where a quoted include lands: beside the including file first, then include/."""
    for base in (including_file.parent, ROOT / "include"):
        candidate = (base / include).resolve()
        if candidate.is_file():
            return candidate
    return None


def app_folders():
    return {p.parent.resolve() for p in (ROOT / "src" / "apps").glob("*/CMakeLists.txt")}


def inside(path, folder):
    return folder == path or folder in path.parents


class Layering(unittest.TestCase):
    def test_each_library_includes_only_the_parts_below_it(self):
        bad = []
        for part, allowed in ALLOWED_PARTS.items():
            for f in library_files(part):
                for inc in INCLUDE.findall(f.read_text(errors="replace")):
                    target = resolve(inc, f)
                    if target is None:
                        continue  # a system header written with quotes
                    rel = target.relative_to(ROOT)
                    used = rel.parts[1] if rel.parts[0] in ("include", "src") else rel.parts[0]
                    if used not in allowed:
                        bad.append(f"{f.relative_to(ROOT)} includes {inc} ({used})")
        self.assertEqual(bad, [], "layering broken:\n" + "\n".join(bad))

    def test_no_library_or_benchmark_includes_an_app_header(self):
        apps = app_folders()
        bad = []
        scanned = [p for part in ALLOWED_PARTS for p in library_files(part)]
        scanned += [p for p in (ROOT / "bench").rglob("*") if p.suffix in {".cpp", ".hpp"}]
        for f in scanned:
            for inc in INCLUDE.findall(f.read_text(errors="replace")):
                target = resolve(inc, f)
                if target and any(inside(target, a) for a in apps):
                    bad.append(f"{f.relative_to(ROOT)} includes app header {inc}")
        self.assertEqual(bad, [], "\n".join(bad))

    def test_no_benchmark_links_app_code(self):
        app_targets = set()
        for cml in (ROOT / "src" / "apps").rglob("CMakeLists.txt"):
            app_targets |= set(re.findall(r"add_(?:library|executable)\(\s*([\w\-]+)",
                                          cml.read_text()))
        bad = []
        for cml in (ROOT / "bench").rglob("CMakeLists.txt"):
            text = cml.read_text()
            for libs in re.findall(r"target_link_libraries\(([^)]*)\)", text):
                for word in libs.split():
                    if word in app_targets:
                        bad.append(f"{cml.relative_to(ROOT)} links {word}")
            if "src/apps" in text:
                bad.append(f"{cml.relative_to(ROOT)} names sources under src/apps")
        self.assertGreater(len(app_targets), 5, "no app targets found: is ROOT right?")
        self.assertEqual(bad, [], "\n".join(bad))


class FileSizes(unittest.TestCase):
    def test_no_source_file_is_longer_than_the_limit(self):
        long_files = []
        for folder in SOURCE_FOLDERS:
            for p in (ROOT / folder).rglob("*"):
                if p.is_file() and p.suffix in SOURCE_SUFFIXES:
                    lines = p.read_bytes().count(b"\n")
                    if lines > MAX_LINES:
                        long_files.append(f"{p.relative_to(ROOT)}: {lines} lines")
        self.assertEqual(long_files, [], f"files over {MAX_LINES} lines:\n" + "\n".join(long_files))


if __name__ == "__main__":
    unittest.main(verbosity=2)
