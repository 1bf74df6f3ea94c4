#!/usr/bin/env python3
"""The repository stands alone.

- No tracked text file names a path outside the repository (the folder beside it that held the
  project's working notes) or an internal issue number (the word "issue" or "issues" followed
  by a number, with or without a blank or "#" between, in any case). Binary files are skipped.
- Every relative link of README.md and docs/*.md resolves: `[text](path)`, `[text](path#anchor)`
  and `[text](#anchor)` name an existing file, and an anchor names a heading of the target
  (GitHub's slugs). Links inside code (fenced blocks and `code spans`) are not links.
- Every named ruling a tracked text file cites is written down in docs/differences.md: a citation
  is the word "ruling" or "rulings", or the file name differences.md, followed by one or more
  quoted names (D ids may stand between them), and each name must be a heading or the bold lead
  of an entry there (a trailing "(D7)" or full stop aside; any case).
- Every case id a tracked text file cites (D, N or T followed by one or two digits, in the forms
  the repository uses: "(N3)", "D8_T7", "T9)", "amended T7", "rulings T1", "md D36", "// N5:")
  is defined there: an N or T id as the bold lead of an entry ("- **N3**: ..."), a D id
  anywhere on the page, a short range such as "D14–D18" naming each id in it. In Markdown,
  code (fenced blocks and code spans) cites nothing.

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

DIFFERENCES = pathlib.Path("docs") / "differences.md"
# A quoted name may wrap onto one more line of a comment ("// ", "# ", " * ").
QUOTED = r'"[^"\n]*(?:\n[ \t]*(?://+|#+|\*)?[ \t]*[^"\n]*)?"'
CITATION = re.compile(r"(?<![A-Za-z])(?:rul" + r"ings?|differences\.md)\]?,?\s+"
                      r"((?:(?:D[0-9]+|" + QUOTED + r")(?:,\s*|\s+and\s+)?)+)", re.IGNORECASE)
NAME = re.compile(QUOTED)
CASE_ID = re.compile(r"(?:(?<=[(_`*])|(?<=[,;] )|(?<=// )|(?<=\) )|(?<=\.md )"
                     r"|(?<=[Aa]mended )|(?<=[Rr]uling )|(?<=[Rr]ulings ))"
                     r"([DNT][0-9]{1,2})(?=[)\s,.:;'_`*]|$)", re.MULTILINE)
BOLD_LEAD = re.compile(r"^\s*(?:[-*+]|[0-9]+\.)?\s*\*\*(.+?)\*\*")
D_RANGE = re.compile(r"\bD([0-9]{1,2})\s*[-\u2013]\s*D([0-9]{1,2})\b")
SHORT_RANGE = 10  # "D1–D38" describes the page; it defines nothing


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


def entry_name(text):
    """A heading's or bold lead's text as a citation names it: no markup, no trailing "(D7)",
    full stop or colon, in lower case."""
    text = re.sub(r"[`*]", "", text).strip().rstrip(".:").strip()
    return text.lower()


def defined_rulings(text):
    """(names, ids) that a differences page defines: the names of its headings and bold leads
    (also without a trailing parenthesis), the N and T ids led in bold, every D id on it."""
    names, ids = set(), set()
    for _, line in prose_lines_keep_code(text):
        heading = HEADING.match(line)
        lead = heading.group(2) if heading else (BOLD_LEAD.match(line) or [None, None])[1]
        if lead is None:
            continue
        name = entry_name(lead)
        names |= {name, re.sub(r"\s*\([^()]*\)$", "", name)}
        if re.fullmatch(r"[nt][0-9]{1,2}", name):
            ids.add(name.upper())
    ids |= set(re.findall(r"\bD[0-9]{1,2}\b", text))
    for low, high in D_RANGE.findall(text):
        if 0 < int(high) - int(low) <= SHORT_RANGE:
            ids |= {f"D{n}" for n in range(int(low), int(high) + 1)}
    return names, ids


def prose_text(text):
    """A Markdown text with fenced blocks and code spans blanked, line numbers kept: examples
    in code are not citations."""
    lines = text.splitlines()
    prose = dict(prose_lines(text))
    return "\n".join(prose.get(number, "") for number in range(1, len(lines) + 1))


def undefined_citations(text, names, ids):
    """(line number, what) of every cited ruling name or case id of `text` that the differences
    page does not define."""
    found = []
    line_of = lambda offset: text.count("\n", 0, offset) + 1
    for m in CITATION.finditer(text):
        for quoted in NAME.finditer(m.group(1)):
            name = re.sub(r"\s*\n[ \t]*(?://+|#+|\*)?[ \t]*", " ", quoted.group(0)[1:-1])
            if entry_name(name) not in names:
                found.append((line_of(m.start()), "the name " + repr(name)))
    for m in CASE_ID.finditer(text):
        if m.group(1) not in ids:
            found.append((line_of(m.start()), f"case {m.group(1)}"))
    return found


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

    def test_every_cited_ruling_and_case_is_defined_in_the_differences(self):
        page = ROOT / DIFFERENCES
        self.assertTrue(page.is_file(), page)
        names, ids = defined_rulings(page.read_text(encoding="utf-8"))
        problems = []
        for path in tracked_files(ROOT):
            text = text_of(path)
            if text is None:
                continue
            if path.suffix == ".md":
                text = prose_text(text)
            for number, what in undefined_citations(text, names, ids):
                problems.append(f"{path.relative_to(ROOT)}:{number}: {what}")
        self.assertEqual(problems, [], f"not defined in {DIFFERENCES}:\n" + "\n".join(problems))

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

    def test_the_citation_checks_catch_what_they_look_for(self):
        page = ("## Rulings\n- **Width choice** (D3): ...\n- **Credits (D7).** ...\n"
                "### Configuration (D14" + "\u2013D18)\n- **N3**: ...\n- **T7**: ...\n")
        names, ids = defined_rulings(page)
        self.assertTrue({"rulings", "width choice", "credits", "configuration"} <= names, names)
        self.assertTrue({"N3", "T7", "D3", "D7", "D15"} <= ids, ids)
        self.assertFalse({"N4", "D19"} & ids, ids)
        rul, diff = "rul" + "ings", "differences" + ".md "
        for good in [rul + ' "Width choice"', diff + '"Credits", "Width choice"',
                     rul[:-1] + ' "credits"', diff + "D3, " + '"Width choice"',
                     "(" + "N3)", "_" + "T7)", "(D15" + ", N3)", "t" + "1 and n" + "4",
                     "std::pair<T" + "1, T" + "2>", "${D" + "40}"]:
            self.assertEqual(undefined_citations(good, names, ids), [], good)
        for bad in [rul + ' "Pass"', diff + "D3, " + '"Pass"', rul + ' "What is\n// promised"',
                    rul + ' "Credits", "Who hears what"', "angles (" + "N4)", "Foo_" + "T9)",
                    "amended " + "T1", rul + " T" + "2", "// N" + "5: pow", ".md D" + "19)",
                    rul + " D" + "19", "x (D" + "1, T" + "8)"]:
            self.assertTrue(undefined_citations(bad, names, ids), bad)


if __name__ == "__main__":
    unittest.main(verbosity=2)
