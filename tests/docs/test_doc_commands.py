#!/usr/bin/env python3
"""The commands the docs show are run, and the output they show is what the programs print.

Every fenced block of README.md and docs/*.md names its language. Blocks in `sh` hold commands
a user types; blocks in `console` hold a session: lines starting with `$ ` are commands (a line
ending in `\\` continues on the next), the other lines are what the commands print. Both kinds
are run, in document order, in one scratch folder per document that holds a copy of
`missions/`, links to the tree's `bench/`, `build/`, `examples/` and `tools/`, and on `PATH` a
`bin/` with every program the build made (its `programs.txt`), so commands run as a user runs
them from the top of a clone, and what they write stays in the scratch folder.

A comment on the line right above a block's fence changes how it runs; options are separated by
`;` (a `;` inside COMMANDS is kept):
- `<!-- docs-test: skip: REASON -->`: not run. The reason says why, e.g. which test runs the
  same command or what the command needs that a test machine lacks.
- `<!-- docs-test: setup: COMMANDS -->`: run first, hidden, in the same folder.
- `<!-- docs-test: needs: TOOL -->`: run only when TOOL is on PATH (reported otherwise).
- `<!-- docs-test: servers -->`: each command starts a program that serves until stopped: it
  must still be running after two seconds, then SIGTERM must stop it with status 0.
- `<!-- docs-test: numbers vary -->`: digits are not compared (times, ports, paths by date).
- `<!-- docs-test: script; pause: S; then: COMMANDS -->` (console): the session runs as one
  script, S seconds apart as a user types them, its commands' output compared as a whole, then
  the hidden COMMANDS (e.g. `wait $!` for a program started in the background); what is left
  running is stopped at the end.

Output shown in a `console` block is what the command printed on its standard output, its
standard error, or both; it is compared line by line after trimming trailing blanks: a line
`...` stands for any number of lines, and `...` inside a line for any text.

Usage: test_doc_commands.py <repository root> <build folder>
"""
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

ROOT = pathlib.Path(sys.argv[1]).resolve() if len(sys.argv) > 1 else pathlib.Path("../..")
BUILD = pathlib.Path(sys.argv[2]).resolve() if len(sys.argv) > 2 else ROOT / "build/release"
del sys.argv[1:3]

FENCE = re.compile(r"^(\s*)(```+|~~~+)\s*(\S*)")
DIRECTIVE = re.compile(r"^\s*<!--\s*docs-test:\s*(.*?)\s*-->\s*$")
RUNNABLE = {"sh", "console"}
BLOCK_TIMEOUT_S = 600
SERVER_GRACE_S = 2.0
LINKED = ("bench", "build", "examples", "tools")


class Block:
    def __init__(self, doc, line, language, text, directive):
        self.doc, self.line, self.language, self.text = doc, line, language, text
        self.options = parse_directive(directive)

    def where(self):
        return f"{self.doc.relative_to(ROOT)}:{self.line}"


OPTION_START = re.compile(r";\s*(?=(?:skip|setup|needs|servers|numbers vary|script|pause|then)\b)")


def parse_directive(text):
    """{'skip': reason, 'setup': commands, 'needs': tool, 'servers': '', ...}. Options are split
    at a `;` followed by an option's name, so commands may hold `;` themselves."""
    options = {}
    for part in filter(None, (p.strip() for p in OPTION_START.split(text or ""))):
        key, _, value = part.partition(":")
        options[key.strip()] = value.strip()
    return options


def documents():
    return [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md"))


def blocks_of(doc):
    """The fenced blocks of `doc`, each with the directive on the line above its fence."""
    lines = doc.read_text(encoding="utf-8").split("\n")
    found, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        indent, fence, language = m.group(1), m.group(2), m.group(3)
        above = DIRECTIVE.match(lines[i - 1]) if i > 0 else None
        body, j = [], i + 1
        while j < len(lines) and not lines[j].strip().startswith(fence):
            body.append(lines[j][len(indent):] if lines[j].startswith(indent) else lines[j])
            j += 1
        found.append(Block(doc, i + 1, language, "\n".join(body), above.group(1) if above else None))
        i = j + 1
    return found


def session(text):
    """[(command, [expected output lines])] of a console block."""
    steps, continuing = [], False
    for line in text.split("\n"):
        in_command = continuing or line.startswith("$ ")
        if continuing:
            steps[-1][0] += "\n" + line
        elif line.startswith("$ "):
            steps.append([line[2:], []])
        elif steps:
            steps[-1][1].append(line)
        continuing = in_command and line.rstrip().endswith("\\")
    return [(command, output) for command, output in steps]


def matches(expected, actual, numbers_vary):
    """Whether the printed lines match the shown ones (`...` wildcards, trailing blanks)."""
    def norm(line):
        line = line.rstrip()
        return re.sub(r"\d+", "0", line) if numbers_vary else line

    def line_pattern(line):
        return re.compile("^" + ".*".join(re.escape(p) for p in norm(line).split("...")) + "$")

    expected = list(expected)
    while expected and not expected[-1].strip():
        expected.pop()
    actual = [norm(a) for a in actual]
    while actual and not actual[-1].strip():
        actual.pop()

    def walk(e, a):
        if e == len(expected):
            return a == len(actual)
        if expected[e].strip() == "...":
            return any(walk(e + 1, k) for k in range(a, len(actual) + 1))
        return a < len(actual) and line_pattern(expected[e]).match(actual[a]) is not None \
            and walk(e + 1, a + 1)

    return walk(0, 0)


def shows(expected, out, err, numbers_vary):
    """Whether the shown lines are what the command printed: its standard output, its standard
    error, or both (in either order: a terminal interleaves them by timing)."""
    candidates = (out, err, out + err, err + out)
    return any(matches(expected, text.split("\n"), numbers_vary) for text in candidates)


class Scratch:
    """A folder laid out like the top of a clone, with the built programs on PATH."""

    def __init__(self):
        self.dir = pathlib.Path(tempfile.mkdtemp(prefix="docs-test-"))
        shutil.copytree(ROOT / "missions", self.dir / "missions")
        for name in LINKED:
            if (ROOT / name).exists():
                os.symlink(ROOT / name, self.dir / name)
        bin_dir = self.dir / "bin"
        bin_dir.mkdir()
        for line in (BUILD / "programs.txt").read_text().splitlines():
            name, _, path = line.partition(" ")
            if name and path:
                os.symlink(path, bin_dir / name)
        self.env = dict(os.environ, PATH=f"{bin_dir}:{os.environ.get('PATH', '')}",
                        HOME=str(self.dir), LC_ALL="C.UTF-8")

    def run(self, script):
        """(exit status, standard output, standard error). The output goes to files, so a
        program the script leaves in the background cannot hold the test; the script's process
        group is stopped when the script ends."""
        with tempfile.TemporaryFile(mode="w+") as out, tempfile.TemporaryFile(mode="w+") as err:
            process = subprocess.Popen(["bash", "-e", "-o", "pipefail", "-c", script],
                                       cwd=self.dir, env=self.env, stdout=out, stderr=err,
                                       start_new_session=True)
            try:
                status = process.wait(timeout=BLOCK_TIMEOUT_S)
            except subprocess.TimeoutExpired:
                status = f"no end within {BLOCK_TIMEOUT_S} s"
            finally:
                try:
                    os.killpg(process.pid, signal.SIGTERM)
                except ProcessLookupError:
                    pass
                process.wait()
            out.seek(0)
            err.seek(0)
            return status, out.read(), err.read()

    def remove(self):
        shutil.rmtree(self.dir, ignore_errors=True)


def commands_of(block):
    """The commands of a block, one string each (continuation lines kept together)."""
    if block.language == "console":
        return [c for c, _ in session(block.text)]
    commands, current = [], ""
    for line in block.text.split("\n"):
        current = current + "\n" + line if current else line
        if not line.rstrip().endswith("\\"):
            if current.strip() and not current.strip().startswith("#"):
                commands.append(current)
            current = ""
    return commands


def run_servers(scratch, block):
    """Each command must serve for SERVER_GRACE_S, then stop cleanly on SIGTERM."""
    problems = []
    for command in commands_of(block):
        with tempfile.TemporaryFile(mode="w+") as out:
            process = subprocess.Popen(["bash", "-c", "exec " + command.split("#")[0]],
                                       cwd=scratch.dir, env=scratch.env, stdout=out,
                                       stderr=subprocess.STDOUT)
            time.sleep(SERVER_GRACE_S)
            stopped_early = process.poll() is not None
            if not stopped_early:
                process.send_signal(signal.SIGTERM)
            try:
                status = process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
                status = "no stop within 10 s of SIGTERM"
            out.seek(0)
            if stopped_early:
                problems.append(f"`{command}` stopped at once ({status}):\n{out.read()[-2000:]}")
            elif status != 0:
                problems.append(f"`{command}` ended with {status} on SIGTERM:\n{out.read()[-2000:]}")
    return problems


def run_block(scratch, block):
    """The problems of one block (empty: it ran as shown)."""
    if "setup" in block.options:
        status, out, err = scratch.run(block.options["setup"])
        if status != 0:
            return [f"setup failed ({status}): {out[-1000:]}{err[-2000:]}"]
    if "servers" in block.options:
        return run_servers(scratch, block)
    if block.language == "sh":
        status, out, err = scratch.run(block.text)
        return [] if status == 0 else [f"exit {status}:\n{out[-1000:]}{err[-3000:]}"]
    steps = session(block.text)
    if "script" in block.options:  # one script: output of programs left in the background
        pause = f"\nsleep {block.options['pause']}\n" if "pause" in block.options else "\n"
        script = pause.join(c for c, _ in steps) + "\n" + block.options.get("then", "")
        steps = [(script, [line for _, out in steps for line in out])]
    for command, expected in steps:
        status, out, err = scratch.run(command)
        if status != 0:
            return [f"`{command}` exit {status}:\n{out[-1000:]}{err[-3000:]}"]
        if not shows(expected, out, err, "numbers vary" in block.options):
            return [f"`{command}` printed:\n{out[:3000]}\nand on standard error:\n"
                    f"{err[:3000]}\nbut the document shows:\n" + "\n".join(expected)]
    return []


class DocCommands(unittest.TestCase):
    def test_every_block_names_its_language(self):
        unnamed = [b.where() for d in documents() for b in blocks_of(d) if not b.language]
        self.assertEqual(unnamed, [], "fenced blocks without a language (sh, console, text, ...)")

    def test_every_skip_gives_its_reason(self):
        bare = [b.where() for d in documents() for b in blocks_of(d)
                if "skip" in b.options and not b.options["skip"]]
        self.assertEqual(bare, [])

    def test_directives_stand_only_above_runnable_blocks(self):
        stray = [b.where() for d in documents() for b in blocks_of(d)
                 if b.options and b.language not in RUNNABLE]
        self.assertEqual(stray, [])

    def test_the_commands_run_as_shown(self):
        ran = 0
        only = os.environ.get("DOCS_TEST_ONLY")  # one document's name, while writing it
        for doc in documents():
            if only and doc.name != only:
                continue
            runnable = [b for b in blocks_of(doc) if b.language in RUNNABLE]
            if not runnable:
                continue
            scratch = Scratch()
            try:
                for block in runnable:
                    if "skip" in block.options:
                        continue
                    tool = block.options.get("needs")
                    if tool and shutil.which(tool) is None:
                        print(f"{block.where()}: not run, {tool} is not installed", file=sys.stderr)
                        continue
                    with self.subTest(block=block.where()):
                        self.assertEqual(run_block(scratch, block), [])
                    ran += 1
            finally:
                scratch.remove()
        self.assertGreater(ran, 0 if only else 10)


class Matching(unittest.TestCase):
    """The comparison itself, so a loose rule cannot pass everything."""

    def test_wildcards(self):
        self.assertTrue(matches(["a", "...", "z"], ["a", "b", "c", "z"], False))
        self.assertTrue(matches(["x ... y"], ["x 1 2 y"], False))
        self.assertFalse(matches(["a", "z"], ["a", "b", "z"], False))
        self.assertFalse(matches(["x ... y"], ["x 1 2 z"], False))

    def test_numbers(self):
        self.assertTrue(matches(["t=1.25 ok"], ["t=3.75 ok"], True))
        self.assertFalse(matches(["t=1.25 ok"], ["t=3.75 ok"], False))

    def test_directive(self):
        self.assertEqual(parse_directive("needs: jq; setup: a; b; numbers vary"),
                         {"needs": "jq", "setup": "a; b", "numbers vary": ""})

    def test_session(self):
        steps = session("$ a \\\n  b\nout1\n$ c\nout2\nout3")
        self.assertEqual(steps, [("a \\\n  b", ["out1"]), ("c", ["out2", "out3"])])


if __name__ == "__main__":
    unittest.main(verbosity=2)
