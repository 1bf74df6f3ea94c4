#!/usr/bin/env python3
"""The docs' picture of the viewer (docs/images/viewer.png), taken from a real run.

Opens a run folder's view.html (the self-contained replay that `./build.sh demo` writes) in
headless chromium, moves the replay to a fraction of the run, and saves a screenshot.

  build/pyenv/bin/python bench/viewer/screenshot.py RUN_DIR/view.html [--at=0.35]
                         [--output=docs/images/viewer.png]
"""

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests/apps/pWebViewer/browser"))
from browser_support import browser_page  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("html", help="an exported view.html")
    ap.add_argument("--at", type=float, default=0.35, help="fraction of the run, 0..1")
    ap.add_argument("--output", default="docs/images/viewer.png")
    ap.add_argument("--width", type=int, default=1400)
    ap.add_argument("--height", type=int, default=860)
    args = ap.parse_args()
    with browser_page(args.width, args.height) as page:
        page.goto(Path(args.html).resolve().as_uri())
        page.wait_for_function("window.viewerState && window.viewerState().replay !== undefined",
                               timeout=120000)
        r = page.evaluate("window.viewerState().replay")
        page.evaluate("window.viewerSeek(%r)" % (r["start"] + args.at * (r["end"] - r["start"])))
        page.wait_for_timeout(800)  # the side pane refreshes a few times a second
        Path(args.output).parent.mkdir(parents=True, exist_ok=True)
        page.screenshot(path=args.output)
        if page.errors:
            print("page errors:", page.errors, file=sys.stderr)
            return 1
    print(args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
