#!/usr/bin/env python3
"""The repository stands alone.

- No tracked text file names a path outside the repository (the folder beside it that held the
  project's working notes) or an internal issue number (the word "issue" or "issues" followed
  by a number, with or without a blank or "#" between, in any case). Binary files are skipped.
- Every relative link of README.md and docs/*.md resolves: `[text](path)`, `[text](path#anchor)`
  and `[text](#anchor)` name an existing file, and an anchor names a heading of the target
  (GitHub's slugs). Links inside code (fenced blocks and `code spans`) are not links.

The patterns are assembled from pieces, so this file does not match them itself.

Usage: test_standalone.py <repository root>
"""
import os
import pathlib
import re
import subprocess
import sys
import unittest

ROOT = pathlib.Path(sys.argv.pop(1) if len(sys.argv) > 1 else "../..").resolve()

# "../" + "shared", "shared" + "/spec", "issue" + " 12": written in pieces on purpose.
OUTSIDE = re.compile(re.escape(".." + "/") + "shared" + "|" + "shared" + re.escape("/") + "spec")
ISSUE = re.compile("(?<![A-Za-z])" + "iss" + "ues?" + r" ?#?[0-9]+", re.IGNORECASE)

LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*<?([^()\s<>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
FENCE = re.compile(r"^\s*(```|~~~)")
CODE_SPAN = re.compile(r"(`+)(?:(?!\1).)+?\1")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")


def tracked_files(root):
    """The tracked files (git ls-files), else every file outside .git and build/."""
    try:
        out = subprocess.run(["git", "-C", str(root), "ls-files", "-z"], check=True,
                             capture_output=True).stdout
        return [root / p for p in out.decode("utf-8", "surrogateescape").split("\0") if p]
    except (OSError, subprocess.CalledProcessError):
        found = []
        for folder, dirs, names in os.walk(root):
            dirs[:] = [d for d in dirs if d not in (".git", "build")]
            found += [pathlib.Path(folder) / n for n in names]
        return found


def text_of(path):
    """The file's text, or None for a binary file (a NUL byte, or not UTF-8)."""
    try:
        data = path.read_bytes()
    except OSError:
        return None
    if b"\0" in data:
        return None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return None


def outside_references(text):
    """(line number, excerpt) of every outside path or issue number in `text`."""
    found = []
    for number, line in enumerate(text.splitlines(), 1):
        for pattern in (OUTSIDE, ISSUE):
            for m in pattern.finditer(line):
                found.append((number, line[max(0, m.start() - 30):m.end() + 30].strip()))
    return found


def prose_lines(text):
    """(line number, line) outside fenced code blocks, with code spans blanked."""
    for number, line in prose_lines_keep_code(text):
        yield number, CODE_SPAN.sub(lambda m: " " * len(m.group(0)), line)


def slug(heading):
    """GitHub's anchor of a heading: markup dropped, lower case, punctuation removed except
    '-' and '_', blanks to '-'."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link keeps its text
    text = re.sub(r"[`*]", "", text).strip().lower()
    text = "".join(c for c in text if c.isalnum() or c in " -_")
    return text.replace(" ", "-")


def anchors(text):
    """Every anchor of a Markdown document, duplicates numbered as GitHub numbers them."""
    seen, result = {}, set()
    for _, line in prose_lines_keep_code(text):
        m = HEADING.match(line)
        if not m:
            continue
        base = slug(m.group(2))
        count = seen.get(base, 0)
        seen[base] = count + 1
        result.add(base if count == 0 else f"{base}-{count}")
    return result


def prose_lines_keep_code(text):
    """(line number, line) outside fenced code blocks, code spans kept (headings need them)."""
    inside = False
    for number, line in enumerate(text.splitlines(), 1):
        if FENCE.match(line):
            inside = not inside
            continue
        if not inside:
            yield number, line


def broken_links(document, root):
    """(line, target, reason) of every relative link of `document` that does not resolve."""
    text = document.read_text(encoding="utf-8")
    broken = []
    for number, line in prose_lines(text):
        for m in LINK.finditer(line):
            target = m.group(1)
            if SCHEME.match(target):
                continue
            path_part, _, anchor = target.partition("#")
            dest = (document.parent / path_part).resolve() if path_part else document
            if root not in dest.parents and dest != root:
                broken.append((number, target, "leaves the repository"))
                continue
            if not dest.exists():
                broken.append((number, target, "no such file"))
                continue
            if anchor and dest.suffix == ".md" and dest.is_file():
                if anchor not in anchors(dest.read_text(encoding="utf-8")):
                    broken.append((number, target, "no such heading"))
    return broken


def documents(root):
    return [root / "README.md"] + sorted((root / "docs").glob("*.md"))


class Standalone(unittest.TestCase):
    def test_no_tracked_file_names_an_outside_path_or_an_issue(self):
        problems = []
        for path in tracked_files(ROOT):
            text = text_of(path)
            if text is None:
                continue
            for number, excerpt in outside_references(text):
                problems.append(f"{path.relative_to(ROOT)}:{number}: {excerpt}")
        self.assertEqual(problems, [], "references outside the repository:\n" + "\n".join(problems))

    def test_every_relative_link_of_the_docs_resolves(self):
        problems = []
        for document in documents(ROOT):
            self.assertTrue(document.is_file(), document)
            for number, target, reason in broken_links(document, ROOT):
                problems.append(f"{document.relative_to(ROOT)}:{number}: ({target}) {reason}")
        self.assertEqual(problems, [], "broken links:\n" + "\n".join(problems))

    def test_the_checks_catch_what_they_look_for(self):
        # The checks themselves, on text assembled here so that this file stays clean.
        for bad in ["see " + ".." + "/shared/x.md", "shared" + "/spec/a.md", "(iss" + "ue 12)",
                    "_Iss" + "ue12", "ISS" + "UES 12 and 14", "iss" + "ue #5"]:
            self.assertTrue(outside_references(bad), bad)
        for good in ["the shared machine", "an issue of speed", "tissue 12", "spec_.port"]:
            self.assertEqual(outside_references(good), [], good)
        self.assertEqual(slug("5.6 Delivery rules"), "56-delivery-rules")
        self.assertEqual(slug("Command line (`moos/command_line.hpp`)"),
                         "command-line-mooscommand_linehpp")
        self.assertEqual(slug("The report (terminal and AppCast)"), "the-report-terminal-and-appcast")
        self.assertEqual(anchors("# A\n## B\n## B\n```\n# not a heading\n```\n"), {"a", "b", "b-1"})
        links = list(LINK.finditer("[a](x.md#y) and ![i](images/p.svg) and `[c](z.md)`"))
        self.assertEqual([m.group(1) for m in links], ["x.md#y", "images/p.svg", "z.md"])


if __name__ == "__main__":
    unittest.main(verbosity=2)
