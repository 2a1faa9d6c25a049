#!/usr/bin/env python3
"""How the replay test's silhouette threshold was chosen: the creature's silhouette in a replay
page at #t=200 (three-quarter view, springs hidden) against `hexgait still` at the same moment,
at the page's own frame, one and three frames later, and from the side, as intersection over
union (tests/cli/replay_test.py's measure). Needs headless Chromium and PIL.

    /usr/bin/python3 scripts/replay_overlap.py [build/hexgait]
"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests"))
import replay_browser  # noqa: E402
import replay_test  # noqa: E402

WIDTH, HEIGHT = replay_test.WIDTH, replay_test.HEIGHT


def still(hexgait, work, time, view="three-quarter"):
    path = os.path.join(work, "still.png")
    subprocess.run([hexgait, "still", "--unoptimized", "--no-overlay", "--time", time, "--view",
                    view, "--size", "%dx%d" % (WIDTH, HEIGHT), "--out", path], check=True,
                   capture_output=True)
    return open(path, "rb").read()


def main():
    hexgait = sys.argv[1] if len(sys.argv) > 1 else "build/hexgait"
    work = tempfile.mkdtemp(prefix="hexgait-overlap-")
    page = os.path.join(work, "unoptimized.html")
    subprocess.run([hexgait, "replay", "--unoptimized", "--out", page], check=True,
                   capture_output=True)
    browser = replay_browser.Browser(WIDTH, HEIGHT)
    try:
        browser.open("file://" + os.path.realpath(page) + "#t=200&view=three-quarter")
        browser.evaluate("document.getElementById('cue-overlay').click()")
        replay_test.settle(browser)
        shown = browser.evaluate("hexgaitReplay.time()")
        canvas = replay_test.silhouette(browser.canvas_png())
    finally:
        browser.close()
    print("page at #t=200 shows t = %.1f" % shown)
    for label, time, view in (("the still at t = 200", "200", "three-quarter"),
                              ("the still at the page's frame", "%.1f" % shown, "three-quarter"),
                              ("one frame later", "%.1f" % (shown + 2.2), "three-quarter"),
                              ("three frames later", "%.1f" % (shown + 6.6), "three-quarter"),
                              ("the side view at t = 200", "200", "side")):
        score = replay_test.overlap(canvas, replay_test.silhouette(still(hexgait, work, time, view)))
        print("%-32s %.3f" % (label, score))


if __name__ == "__main__":
    main()
