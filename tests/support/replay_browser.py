"""Opens a `hexgait replay` page in headless Chromium and reports what a browser sees.

Talks to Chromium over the DevTools protocol on a pipe (--remote-debugging-pipe: file
descriptors 3 and 4, NUL-terminated JSON), so it needs nothing but the standard library.
Used by tests/cli/replay_test.py and scripts/replay_pages.sh; also by hand:

    tests/support/replay_browser.py PAGE.html --at '#t=200&view=side' --screenshot OUT.png --opens 5
"""
import base64
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


class Browser:
    """One headless Chromium with one page; console messages, exceptions and requests are
    collected from the moment the page starts loading."""

    def __init__(self, width, height):
        chromium = find_chromium()
        if not chromium:
            raise RuntimeError("no chromium installed")
        self.profile = tempfile.mkdtemp(prefix="hexgait-chromium-")
        to_chrome_r, self._to_chrome = os.pipe()
        self._from_chrome, from_chrome_w = os.pipe()

        def child_fds():
            os.dup2(to_chrome_r, 3)
            os.dup2(from_chrome_w, 4)

        args = [
            chromium, "--headless=new", "--no-sandbox", "--remote-debugging-pipe",
            "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
            "--window-size=%d,%d" % (width, height), "--force-device-scale-factor=1",
            "--hide-scrollbars", "--mute-audio", "--no-first-run", "--no-default-browser-check",
            "--disable-extensions", "--disable-background-networking", "--disable-sync",
            "--disable-component-update", "--user-data-dir=" + self.profile, "about:blank",
        ]
        self.process = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                        stderr=subprocess.DEVNULL, preexec_fn=child_fds,
                                        # The numbers the pipes have in the child (dup2 above).
                                        pass_fds=(3, 4))
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        self._buffer = b""
        self._next_id = 0
        self.events = []
        targets = self.call("Target.getTargets")["targetInfos"]
        page = next(t for t in targets if t["type"] == "page")
        self.session = self.call("Target.attachToTarget", targetId=page["targetId"],
                                 flatten=True)["sessionId"]
        for domain in ("Page", "Runtime", "Network", "Log"):
            self.call(domain + ".enable", session=True)
        # The viewport exactly width x height (a headless window keeps some for its frame).
        self.call("Emulation.setDeviceMetricsOverride", session=True, width=width, height=height,
                  deviceScaleFactor=1, mobile=False)

    def _send(self, message):
        os.write(self._to_chrome, json.dumps(message).encode() + b"\0")

    def _receive(self, deadline):
        while b"\0" not in self._buffer:
            if time.monotonic() > deadline:
                raise TimeoutError("chromium did not answer")
            chunk = os.read(self._from_chrome, 1 << 20)
            if not chunk:
                raise RuntimeError("chromium closed the pipe")
            self._buffer += chunk
        message, self._buffer = self._buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, session=False, timeout=30, **params):
        self._next_id += 1
        message = {"id": self._next_id, "method": method, "params": params}
        if session:
            message["sessionId"] = self.session
        self._send(message)
        deadline = time.monotonic() + timeout
        while True:
            reply = self._receive(deadline)
            if reply.get("id") == self._next_id:
                if "error" in reply:
                    raise RuntimeError("%s: %s" % (method, reply["error"]))
                return reply.get("result", {})
            if "method" in reply:
                self.events.append(reply)

    def evaluate(self, expression, timeout=30):
        result = self.call("Runtime.evaluate", session=True, timeout=timeout,
                           expression=expression, returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in result:
            raise RuntimeError("page script failed: %s" % result["exceptionDetails"])
        return result["result"].get("value")

    def open(self, url, timeout=20):
        """Navigates and waits for the replay to say it is ready; returns the seconds from the
        navigation to that moment."""
        start = time.monotonic()
        self.call("Page.navigate", session=True, url=url)
        while time.monotonic() - start < timeout:
            if self.evaluate("document.body && document.body.dataset.ready === '1'"):
                return time.monotonic() - start
            if self.problems():
                break
            time.sleep(0.02)
        raise RuntimeError("the page never became ready: %s" % self.problems())

    def canvas_png(self):
        url = self.evaluate("document.getElementById('scene').toDataURL('image/png')")
        return base64.b64decode(url.split(",", 1)[1])

    def screenshot_png(self):
        return base64.b64decode(self.call("Page.captureScreenshot", session=True)["data"])

    def problems(self):
        """Console errors and warnings, uncaught exceptions, and requests for anything other
        than the page's own file."""
        found = []
        for event in self.events:
            method, params = event["method"], event.get("params", {})
            if method == "Runtime.consoleAPICalled" and params["type"] in ("error", "warning",
                                                                          "assert"):
                found.append("console.%s: %s" % (params["type"], " ".join(
                    str(a.get("value", a.get("description"))) for a in params["args"])))
            elif method == "Runtime.exceptionThrown":
                found.append("exception: %s" % params["exceptionDetails"])
            elif method == "Log.entryAdded" and params["entry"]["level"] in ("error", "warning"):
                found.append("log: %s" % params["entry"]["text"])
            elif method == "Network.requestWillBeSent":
                url = params["request"]["url"]
                if not (url.startswith("file://") and params.get("type") == "Document") and \
                        not url.startswith("data:"):
                    found.append("request: %s" % url)
        return found

    def requests(self):
        return [e["params"]["request"]["url"] for e in self.events
                if e["method"] == "Network.requestWillBeSent"]

    def close(self):
        try:
            self._send({"id": 0, "method": "Browser.close"})
        except OSError:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        os.close(self._to_chrome)
        os.close(self._from_chrome)
        shutil.rmtree(self.profile, ignore_errors=True)


def main():
    import argparse
    import statistics
    parser = argparse.ArgumentParser(description="Open a replay page in headless Chromium.")
    parser.add_argument("page")
    parser.add_argument("--at", default="", help="the address's fragment, e.g. '#t=200&view=top'")
    parser.add_argument("--size", default="1280x720", help="viewport WIDTHxHEIGHT")
    parser.add_argument("--screenshot", help="PNG of the whole page to write")
    parser.add_argument("--opens", type=int, default=1,
                        help="open it this many times, each in a new browser, and print the "
                             "median time to the first frame drawn")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    url = "file://" + os.path.realpath(args.page) + args.at
    page_ms, wall = [], []
    for _ in range(args.opens):
        browser = Browser(width, height)
        try:
            wall.append(browser.open(url))
            timings = browser.evaluate("hexgaitReplay.timings")
            page_ms.append(timings["firstFrame"])
            print("  " + ", ".join("%s %.0f" % kv for kv in timings.items()) + " ms")
            problems = browser.problems()
            if problems:
                sys.exit("problems: %s" % problems)
            if args.screenshot:
                with open(args.screenshot, "wb") as f:
                    f.write(browser.screenshot_png())
        finally:
            browser.close()
    print("%s: %d bytes; first frame %.0f ms after the navigation began (median of %d opens, "
          "each in a new browser; %s ms); ready seen by the driver after %.2f s" %
          (args.page, os.path.getsize(args.page), statistics.median(page_ms), len(page_ms),
           ", ".join("%.0f" % v for v in page_ms), statistics.median(wall)))


if __name__ == "__main__":
    main()
