#!/usr/bin/python3
"""Open masonry's report pages in a real browser and check them.

For every run directory given, report.html is opened in headless Chromium
(one browser for all pages, driven over the DevTools protocol on a pipe: no
network, no extra Python package) and the test fails on:

- any console error or uncaught exception of the page;
- a page that does not finish drawing (body[data-ready] = "1") in time;
- a plot whose number of traces differs from the number expected from the
  run's summary.json (3D view of a rigid-block run, crack map; a wallette's
  3D view and curve), or whose screenshot is blank (fewer than 2 % of its
  pixels differ from the background);
- a number shown on the page (every element with data-key) whose exact
  value (data-value) differs from summary.json's at that path, or whose
  text differs from that value (times data-scale) by more than the display
  rounding;
- a page of 10 MB or more.

Usage: report_browser.py RUN_DIR... [--screenshot RUN_DIR=FILE.png]
       [--timeout S]
Chromium: /usr/bin/chromium (Debian's `chromium'), run as the brief of the
test asks: --headless --no-sandbox --disable-gpu --disable-quic
--no-first-run --disable-background-networking --disable-component-update
--disable-sync, a new empty --user-data-dir, and --enable-unsafe-swiftshader
(WebGL on the CPU: without it Chromium warns that the automatic fallback is
deprecated; the pages are local and trusted).
"""
import argparse
import base64
import io
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

CHROMIUM = "/usr/bin/chromium"
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--enable-unsafe-swiftshader", "--hide-scrollbars", "--window-size=1280,2400"]
LIMIT_BYTES = 10 * 1024 * 1024


class Browser:
    """Headless Chromium driven over --remote-debugging-pipe (fds 3 and 4)."""

    def __init__(self):
        self.profile = tempfile.mkdtemp(prefix="masonry-chromium-")
        to_chrome, self.command = os.pipe()
        self.answer, from_chrome = os.pipe()

        def child():
            a, b = os.dup(to_chrome), os.dup(from_chrome)
            os.dup2(a, 3)
            os.dup2(b, 4)
            os.set_inheritable(3, True)
            os.set_inheritable(4, True)

        self.process = subprocess.Popen(
            [CHROMIUM, *FLAGS, "--user-data-dir=" + self.profile, "--remote-debugging-pipe", "about:blank"],
            close_fds=False, preexec_fn=child, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL)
        os.close(to_chrome)
        os.close(from_chrome)
        self.buffer = b""
        self.next_id = 0
        self.events = []

    def _read(self, timeout):
        import select
        while b"\0" not in self.buffer:
            ready, _, _ = select.select([self.answer], [], [], timeout)
            if not ready:
                raise TimeoutError("Chromium did not answer")
            chunk = os.read(self.answer, 1 << 20)
            if not chunk:
                raise RuntimeError("Chromium closed the pipe")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, params=None, session=None, timeout=60):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.command, json.dumps(message).encode() + b"\0")
        while True:
            reply = self._read(timeout)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply["result"]
            self.events.append(reply)

    def close(self):
        try:
            self.call("Browser.close", timeout=10)
        except Exception:
            pass
        try:
            self.process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.process.kill()
        shutil.rmtree(self.profile, ignore_errors=True)


def errors_of(events, session):
    """Console errors and exceptions among the events of one page."""
    found = []
    for e in events:
        if e.get("sessionId") != session:
            continue
        method, p = e.get("method"), e.get("params", {})
        if method == "Runtime.exceptionThrown":
            d = p.get("exceptionDetails", {})
            found.append("exception: " + (d.get("exception", {}).get("description") or d.get("text", "")))
        elif method == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
            found.append("console." + p["type"] + ": " +
                         " ".join(str(a.get("value", a.get("description", ""))) for a in p.get("args", [])))
        elif method == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
            found.append("log: " + p["entry"].get("text", ""))
    return found


def resolve(summary, path):
    """The value at `a.b[2].c` in summary, or KeyError."""
    value = summary
    for name, index in re.findall(r"([^.\[\]]+)|\[(\d+)\]", path):
        value = value[int(index)] if index else value[name]
    return value


def blank(png, fraction=0.02):
    """Whether a screenshot is (nearly) one colour."""
    try:
        from PIL import Image
        image = Image.open(io.BytesIO(png)).convert("RGB")
        pixels = list(image.getdata())
    except ImportError:
        import matplotlib.image
        array = matplotlib.image.imread(io.BytesIO(png), format="png")
        pixels = [tuple(int(255 * c) for c in p[:3]) for row in array for p in row]
    background = max(set(pixels[:: max(1, len(pixels) // 2000)]), key=pixels.count)
    different = sum(1 for p in pixels if max(abs(a - b) for a, b in zip(p, background)) > 12)
    return different < fraction * len(pixels), different / max(1, len(pixels))


def expected_traces(summary, n_fixed, n_settling, plot):
    """The traces a plot of a rigid-block page must have, from summary.json
    and the supports of parameters.prm alone."""
    n_cracks = summary.get("n_cracks", 0)
    if plot == "view3d":  # blocks, edges; gaps and lines; pivots; supports
        return (2 + (2 if n_cracks else 0) + (1 if summary.get("n_hinges", 0) else 0)
                + (1 if n_fixed else 0) + (3 if n_settling else 0))
    # crack map: patch edges, joints, one line per crack and their markers,
    # supports
    return (2 + n_cracks + (1 if n_cracks else 0) + (1 if n_fixed else 0)
            + (1 if n_settling else 0))


def supports_of(run):
    """Which kinds of supports the run has (fixed, settling), from its
    parameters.prm: a settlement's `Settling edges' move, the other
    `Supported edges' stay."""
    text = open(os.path.join(run, "parameters.prm")).read()
    analysis = re.search(r"^\s*set Analysis\s*=\s*(.+?)\s*$", text, re.M).group(1)
    section = {"settlement": "Settlement", "limit load": "Limit load",
               "minimum thickness": "Minimum thickness"}.get(analysis)
    if section is None:
        return 0, 0
    body = re.search(r"^subsection " + section + r"\s*$(.*?)^end\s*$", text, re.M | re.S)
    body = body.group(1) if body else ""

    def labels(entry):
        m = re.search(r"^\s*set " + entry + r"\s*=\s*(.*?)\s*$", body, re.M)
        return {x.strip() for x in m.group(1).split(",") if x.strip()} if m else set()
    supported = labels("Supported edges")
    settling = labels("Settling edges") if analysis == "settlement" else set()
    return len(supported - settling), len(settling & supported)


def wallette_traces(run, plot):
    """The traces a plot of a wallette page must have, from the run's files:
    the 3D view (cells, their edges, the open joints) where fields were
    written; the curve, the output step's marker, the cycle peaks and the
    envelope where cycles.csv and envelope.csv have rows."""
    def rows(name):
        path = os.path.join(run, name)
        if not os.path.exists(path):
            return []
        lines = [l for l in open(path) if l.strip() and not l.startswith("#")]
        return lines[1:]
    if plot == "view3d":
        fields = any(os.path.exists(os.path.join(run, f)) for f in ("solution.pvd", "solution.xdmf"))
        return 3 if fields else None
    envelope = [r for r in rows("envelope.csv") if len(r.split(",")) > 2 and r.split(",")[2].strip()]
    return 2 + (1 if rows("cycles.csv") else 0) + (1 if envelope else 0)


def check_page(browser, run, timeout, screenshot=None, listed=True):
    """Problems of the report of run directory `run`, and the seconds the
    page took to draw."""
    problems = []
    page = os.path.join(os.path.abspath(run), "report.html")
    summary = json.load(open(os.path.join(run, "summary.json")))
    if not os.path.isfile(page) or (listed and "report.html" not in summary.get("files", [])):
        return [f"{run}: no report.html among the files of summary.json"], 0
    size = os.path.getsize(page)
    if size >= LIMIT_BYTES:
        problems.append(f"report.html is {size / 2**20:.1f} MB (limit 10 MB)")
    target = browser.call("Target.createTarget", {"url": "about:blank"})["targetId"]
    session = browser.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
    for domain in ("Runtime.enable", "Log.enable", "Page.enable"):
        browser.call(domain, session=session)
    browser.call("Emulation.setDeviceMetricsOverride",
                 {"width": 1280, "height": 2400, "deviceScaleFactor": 1, "mobile": False}, session=session)
    start = time.time()
    browser.call("Page.navigate", {"url": "file://" + page}, session=session)
    state = None
    while time.time() - start < timeout:
        state = browser.call("Runtime.evaluate", {"expression": "document.body && document.body.dataset.ready",
                                                  "returnByValue": True}, session=session)["result"].get("value")
        if state in ("1", "error"):
            break
        time.sleep(0.2)
    seconds = time.time() - start
    if state != "1":
        problems.append(f"the page did not finish drawing in {timeout} s (state {state!r})")
    time.sleep(0.5)  # WebGL frames after the promise
    probe = """JSON.stringify({
      plots: [...document.querySelectorAll('[data-expected-traces]')].map(e => ({
        id: e.id, traces: e.dataset.traces, expected: e.dataset.expectedTraces,
        rendered: e.dataset.rendered, rect: e.getBoundingClientRect().toJSON()})),
      numbers: [...document.querySelectorAll('[data-key]')].map(e => ({
        key: e.dataset.key, value: e.dataset.value, scale: e.dataset.scale || '1', text: e.textContent})),
      data: Report.data.summary})"""
    result = json.loads(browser.call("Runtime.evaluate", {"expression": probe, "returnByValue": True},
                                     session=session)["result"]["value"])

    # the rigid-block page's expectations, from summary.json and parameters.prm
    wanted = {}
    if "n_blocks" in summary:
        n_fixed, n_settling = supports_of(run)
        if summary.get("max_settlement", 0) == 0:
            n_fixed, n_settling = n_fixed + n_settling, 0
        wanted = {plot: expected_traces(summary, n_fixed, n_settling, plot) for plot in ("view3d", "crackmap")}
    elif summary.get("analysis") == "wallette":
        wanted = {plot: wallette_traces(run, plot) for plot in ("view3d", "curveplot")}
        wanted = {k: v for k, v in wanted.items() if v is not None}
    for plot in result["plots"]:
        name = plot["id"]
        if plot["rendered"] != "1":
            problems.append(f"plot {name} not drawn")
            continue
        want = wanted.get(name, int(plot["expected"]))
        if int(plot["traces"]) != want:
            problems.append(f"plot {name}: {plot['traces']} traces, expected {want}")
        r = plot["rect"]
        clip = {"x": r["x"], "y": r["y"] + 0, "width": r["width"], "height": r["height"], "scale": 1}
        shot = base64.b64decode(browser.call("Page.captureScreenshot",
                                             {"format": "png", "clip": clip, "captureBeyondViewport": True},
                                             session=session)["data"])
        is_blank, share = blank(shot)
        if is_blank:
            problems.append(f"plot {name}: blank screenshot ({100 * share:.2f} % of pixels drawn)")
    for plot in wanted:
        if plot not in [p["id"] for p in result["plots"]]:
            problems.append(f"plot {plot} missing")

    # every number shown equals summary.json's
    page_summary = result["data"]
    for key, value in page_summary.items():
        if key in summary and summary[key] != value:
            problems.append(f"summary entry {key}: {value!r} on the page, {summary[key]!r} in summary.json")
    compared = 0
    for n in result["numbers"]:
        try:
            truth = resolve(summary, n["key"])
        except (KeyError, IndexError, TypeError):
            problems.append(f"{n['key']}: shown on the page, not in summary.json")
            continue
        if json.loads(n["value"]) != truth:
            problems.append(f"{n['key']}: data-value {n['value']}, summary.json {truth!r}")
            continue
        if isinstance(truth, (int, float)) and not isinstance(truth, bool):
            shown = float(re.sub(r"[^0-9eE+\-.]", "", n["text"]) or "nan")
            scaled = truth * float(n["scale"])
            if not math.isclose(shown, scaled, rel_tol=1e-5, abs_tol=1e-300):
                problems.append(f"{n['key']}: shows {n['text']!r}, summary.json gives {scaled!r}")
        compared += 1
    if compared == 0:
        problems.append("no number of summary.json on the page")

    if screenshot:
        # the page's header and its first plots, at half size (for doc/)
        rect = json.loads(browser.call("Runtime.evaluate", {"expression": (
            "JSON.stringify(document.getElementById('view').getBoundingClientRect().toJSON())"),
            "returnByValue": True}, session=session)["result"]["value"])
        clip = {"x": 0, "y": 0, "width": 1280, "height": rect["bottom"] + 10, "scale": 0.5}
        shot = browser.call("Page.captureScreenshot", {"format": "png", "clip": clip}, session=session)["data"]
        with open(screenshot, "wb") as f:
            f.write(base64.b64decode(shot))
    problems += errors_of(browser.events, session)
    browser.call("Target.closeTarget", {"targetId": target})
    return problems, seconds, compared, size


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--screenshot", action="append", default=[], help="RUN_DIR=FILE.png")
    parser.add_argument("--timeout", type=float, default=120)
    parser.add_argument("--standalone", action="append", default=[],
                        help="RUN_DIR whose report.html was written afterwards (not in its summary.json)")
    args = parser.parse_args()
    shots = dict(s.split("=", 1) for s in args.screenshot)
    if not os.path.exists(CHROMIUM):
        print(f"report_browser: {CHROMIUM} not found (install the Debian package chromium; contrib/setup does)")
        return 1
    browser = Browser()
    failed = 0
    try:
        for run in args.runs:
            outcome = check_page(browser, run, args.timeout, shots.get(run), run not in args.standalone)
            problems = outcome[0]
            name = os.path.basename(os.path.normpath(run))
            if problems:
                failed += 1
                print(f"FAILED {name}:")
                for p in problems:
                    print("  " + p)
            else:
                _, seconds, compared, size = outcome
                print(f"OK {name}: drawn, {compared} numbers equal summary.json's, "
                      f"{size / 2**20:.1f} MB")
                sys.stderr.write(f"  ({seconds:.1f} s)\n")
    finally:
        browser.close()
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
