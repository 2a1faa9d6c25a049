"""`hexgait replay` end to end: the page's size, then headless Chromium opens it and must see no
console error and make no request; at #t=200&view=three-quarter its canvas must show the creature
where `hexgait still --time 200 --view three-quarter` draws it; seeking and playing must change
the picture. Exits 77 (skipped) only when no chromium is installed; the checks before it run.

Usage: replay_test.py HEXGAIT SCREENSHOT_DIR
"""
import io
import os
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import replay_browser  # noqa: E402

WIDTH, HEIGHT = 640, 360
# The creature's polygons (springs hidden on both sides) as silhouettes, compared by their
# intersection over union. Measured on this machine (scripts/replay_overlap.py): 0.962 between the page at #t=200 (its
# nearest frame, t = 200.2) and the still at t = 200; 0.981 against the still at t = 200.2, the
# same frame (the rest is the page's anti-aliasing); 0.743 one frame (2.2 time units) later,
# 0.670 three frames later and 0.006 for the side view. The threshold sits between one frame
# off and the same moment.
SAME_MOMENT_IOU = 0.9
MAX_BYTES = 3 * 1024 * 1024


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def run(*args):
    result = subprocess.run(args, capture_output=True, text=True)
    if result.returncode != 0:
        fail("%s exited %d: %s" % (" ".join(args), result.returncode, result.stderr.strip()))
    return result


def silhouette(png):
    """The creature's pixels: its polygons and motor springs are the only saturated colours in
    the frame (the ground, sky, shadow and the other springs are greys)."""
    rgb = np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(float) / 255
    high, low = rgb.max(axis=2), rgb.min(axis=2)
    return (high - low) > 0.25 * np.maximum(high, 1e-6)


def overlap(a, b):
    return np.logical_and(a, b).sum() / max(1, np.logical_or(a, b).sum())


def changed(a, b):
    """The fraction of pixels that differ between two PNGs."""
    x = np.asarray(Image.open(io.BytesIO(a)).convert("RGB")).astype(int)
    y = np.asarray(Image.open(io.BytesIO(b)).convert("RGB")).astype(int)
    return (np.abs(x - y).sum(axis=2) > 24).mean()


def settle(browser):
    """Waits for the page's next drawn frame."""
    browser.evaluate("new Promise(done => requestAnimationFrame(() => setTimeout(done, 50)))")


def main():
    hexgait, screenshots = sys.argv[1], sys.argv[2]
    work = tempfile.mkdtemp(prefix="hexgait-replay-")
    page = os.path.join(work, "unoptimized.html")
    run(hexgait, "replay", "--unoptimized", "--time", "1000", "--out", page)
    size = os.path.getsize(page)
    if size > MAX_BYTES:
        fail("a 1000-time-unit replay is %d bytes, over 3 MB" % size)
    text = open(page, encoding="utf-8").read()
    for needle in ("http://", "https://", "<link", " src="):
        if needle in text:
            fail("the page names something outside itself: %r" % needle)

    # A run too long for a page: decimated with a message, and still under the limit; longer
    # still: refused with one line. 39,500 time units are 17,956 movie frames, one in 2 kept:
    # 8,978 frames, 2,399,344 bytes, within 0.3% of the largest page (9,000 frames at the longest
    # run allowed, 118,795 time units: 2,405,291 bytes), from 16 M steps where that takes 48 M.
    long_page = os.path.join(work, "long.html")
    result = run(hexgait, "replay", "--unoptimized", "--time", "39500", "--out", long_page)
    if "keeping one in 2," not in result.stderr:
        fail("a 39500-time-unit replay did not keep one frame in 2: %r" % result.stderr)
    if os.path.getsize(long_page) > MAX_BYTES:
        fail("a decimated replay is %d bytes" % os.path.getsize(long_page))
    refused = subprocess.run([hexgait, "replay", "--unoptimized", "--time", "500000", "--out",
                              os.path.join(work, "refused.html")], capture_output=True, text=True)
    if refused.returncode == 0 or "at most" not in refused.stderr or \
            os.path.exists(os.path.join(work, "refused.html")):
        fail("a 500000-time-unit replay was not refused: %r" % refused.stderr)

    still = os.path.join(work, "still.png")
    run(hexgait, "still", "--unoptimized", "--no-overlay", "--time", "200", "--view",
        "three-quarter", "--size",
        "%dx%d" % (WIDTH, HEIGHT), "--out", still)
    still_png = open(still, "rb").read()

    if not replay_browser.find_chromium():
        print("SKIP: no chromium installed")
        sys.exit(77)
    browser = replay_browser.Browser(WIDTH, HEIGHT)
    try:
        url = "file://" + os.path.realpath(page)
        seconds = browser.open(url + "#t=200&view=three-quarter")
        print("page ready in %.2f s (%d bytes)" % (seconds, size))
        if browser.evaluate("hexgaitReplay.playing()"):
            fail("a page opened at #t=200 is playing")
        shown = browser.evaluate("hexgaitReplay.time()")
        if abs(shown - 200) > 1.2:
            fail("#t=200 opened at t = %s" % shown)
        with open(os.path.join(screenshots, "replay_page.png"), "wb") as f:
            f.write(browser.screenshot_png())
        # The springs off, by the page's own checkbox: the silhouette is the polygons.
        browser.evaluate("document.getElementById('cue-overlay').click()")
        settle(browser)
        canvas = browser.canvas_png()
        score = overlap(silhouette(canvas), silhouette(still_png))
        print("silhouette overlap with the still: %.3f (threshold %.2f)" % (score, SAME_MOMENT_IOU))
        if score < SAME_MOMENT_IOU:
            fail("the page at t=200 and the still at t=200 overlap %.3f" % score)

        # Seeking moves the creature; so does playing.
        browser.evaluate("hexgaitReplay.seek(300)")
        seeked = browser.canvas_png()
        if changed(canvas, seeked) < 0.02:
            fail("seeking from t=200 to t=300 changed %.4f of the picture" %
                 changed(canvas, seeked))
        frame = browser.evaluate("hexgaitReplay.frame()")
        browser.evaluate("hexgaitReplay.play()")
        browser.evaluate("new Promise(done => setTimeout(done, 1500))")
        browser.evaluate("hexgaitReplay.pause()")
        if browser.evaluate("hexgaitReplay.frame()") <= frame:
            fail("playing for 1.5 s did not advance the replay")
        if changed(seeked, browser.canvas_png()) < 0.005:
            fail("playing did not change the picture")

        # The mouse orbits (drag) and zooms (wheel); a finger orbits too.
        before = browser.canvas_png()
        mouse = lambda kind, x, **more: browser.call(  # noqa: E731
            "Input.dispatchMouseEvent", session=True, type=kind, x=x, y=HEIGHT // 2, **more)
        mouse("mousePressed", 300, button="left", buttons=1, clickCount=1)
        mouse("mouseMoved", 360, button="left", buttons=1)
        mouse("mouseReleased", 360, button="left", buttons=0, clickCount=1)
        settle(browser)
        orbited = browser.canvas_png()
        if changed(before, orbited) < 0.05:
            fail("dragging changed %.4f of the picture" % changed(before, orbited))
        mouse("mouseWheel", 320, deltaX=0, deltaY=400)
        settle(browser)
        zoomed = browser.canvas_png()
        if changed(orbited, zoomed) < 0.05:
            fail("the wheel changed %.4f of the picture" % changed(orbited, zoomed))
        for kind, x in (("touchStart", 300), ("touchMove", 250), ("touchEnd", None)):
            points = [] if x is None else [{"x": x, "y": HEIGHT // 2}]
            browser.call("Input.dispatchTouchEvent", session=True, type=kind, touchPoints=points)
        settle(browser)
        if changed(zoomed, browser.canvas_png()) < 0.05:
            fail("a finger's drag did not orbit")

        # Another preset from the address changes the camera, not the moment.
        browser.evaluate("location.hash = 't=200&view=side'")
        settle(browser)
        side = browser.canvas_png()
        side_score = overlap(silhouette(side), silhouette(still_png))
        if side_score > SAME_MOMENT_IOU:
            fail("the side view overlaps the three-quarter still %.3f" % side_score)

        problems = browser.problems()
        if problems:
            fail("the page had problems: %s" % problems)
        if any(not u.startswith("file://") for u in browser.requests()):
            fail("requests left the file: %s" % browser.requests())
    finally:
        browser.close()
    print("ok")


if __name__ == "__main__":
    main()
