#!/usr/bin/env python3
"""serve_browser.py: `shadowlab --serve` driven by headless Chromium through
chromedriver (the W3C WebDriver protocol, over HTTP on this machine only).

  serve_browser.py test VIEWER IMAGE_COMPARE WORK_DIR
      loads the page, waits for a frame, presses V (the visibility view) and
      sees the picture change, checks that the page shows the overlay's text
      (O), that a drag orbits the camera, and takes a screenshot whose frame
      must match VIEWER's own --headless picture of the same view; then that
      the page's keys are the viewer's key table (--list-keys) and that every
      key of it, pressed in the browser in labs 4 to 7, is acted on; and
      --case in the browser: its labels and summary on the page, its keys
      (not Esc) taken from its own table, Tab changing the picture; and
      --split: the page shows the split frame (each half its setting, the
      labels, the divider), not the same frame with its halves swapped.
  serve_browser.py security VIEWER WORK_DIR
      only the URL the viewer printed connects: the page and the WebSocket
      without the token or with a wrong one, with Host: evil.example (DNS
      rebinding; in Chromium too, with evil.example resolved to this
      machine), and from another site's page (a second server's port) are
      refused, and the real page opened after them still receives frames;
      X on the page saves into --screenshot-dir, nowhere else.
  serve_browser.py measure VIEWER WORK_DIR [SIZE]
      prints the frame rate the page receives at SIZE (default 960x540) and
      the latency from a key press to the first frame that shows it (median
      of 20). Printed, never asserted: it depends on the machine.

Only the standard library: WebDriver is JSON over HTTP."""
import base64
import json
import http.server
import os
import re
import shutil
import signal
import socket
import statistics
import struct
import subprocess
import sys
import tempfile
import threading
import time
import urllib.error
import urllib.parse
import urllib.request
import zlib


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(what, condition, timeout=60.0, step=0.1):
    end = time.time() + timeout
    while time.time() < end:
        value = condition()
        if value:
            return value
        time.sleep(step)
    raise SystemExit(f"serve_browser: FAIL: timed out waiting for {what}")


class WebDriver:
    """The few WebDriver commands the test needs."""

    def __init__(self, work, extra_args=()):
        self.port = free_port()
        driver = shutil.which("chromedriver") or "/usr/bin/chromedriver"
        self.log = open(os.path.join(work, "chromedriver.log"), "w")
        self.process = subprocess.Popen([driver, f"--port={self.port}"], stdout=self.log, stderr=subprocess.STDOUT)
        self.base = f"http://127.0.0.1:{self.port}"
        wait_for("chromedriver", lambda: self._ready(), timeout=30)
        profile = tempfile.mkdtemp(prefix="shadowlab-chromium-")
        self.profile = profile
        browser = shutil.which("chromium") or "/usr/bin/chromium"
        args = ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--no-first-run", "--force-device-scale-factor=1", "--window-size=1000,800",
                f"--user-data-dir={profile}"] + list(extra_args)
        caps = {"capabilities": {"alwaysMatch": {"browserName": "chrome",
                                                 "goog:chromeOptions": {"binary": browser, "args": args}}}}
        # Chromium that cannot start its renderer here (seen under a chroot: "unable to connect to
        # renderer") is this machine's limit, not the viewer's: tried three times, then skipped (77),
        # saying why. Anything after a session exists fails as usual.
        for attempt in range(3):
            try:
                self.session = self.call("POST", "/session", caps)["sessionId"]
                break
            except SystemExit as e:
                if "session not created" not in str(e):
                    raise
                reason = str(e)
                time.sleep(2)
        else:
            self.process.kill()
            print(f"serve_browser: skipped: Chromium does not start a session on this machine: {reason[:400]}")
            sys.exit(77)

    def _ready(self):
        try:
            with urllib.request.urlopen(self.base + "/status", timeout=2) as r:
                return json.load(r)["value"].get("ready")
        except (urllib.error.URLError, OSError, ValueError, KeyError):
            return False

    def call(self, method, path, body=None):
        data = json.dumps(body).encode() if body is not None else None
        request = urllib.request.Request(self.base + path, data=data, method=method,
                                         headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(request, timeout=120) as r:
                return json.load(r)["value"]
        except urllib.error.HTTPError as e:
            raise SystemExit(f"serve_browser: FAIL: WebDriver {method} {path}: {e.read().decode()[:800]}")

    def s(self, path):
        return f"/session/{self.session}{path}"

    def go(self, url):
        self.call("POST", self.s("/url"), {"url": url})

    def js(self, script, *args):
        return self.call("POST", self.s("/execute/sync"), {"script": script, "args": list(args)})

    def press(self, *keys):
        steps = []
        for key in keys:
            steps += [{"type": "keyDown", "value": key}, {"type": "keyUp", "value": key}]
        self.call("POST", self.s("/actions"), {"actions": [{"type": "key", "id": "keyboard", "actions": steps}]})

    def drag(self, x, y, dx, dy):
        steps = [{"type": "pointerMove", "duration": 0, "origin": "viewport", "x": x, "y": y},
                 {"type": "pointerDown", "button": 0}]
        for i in range(1, 6):
            steps.append({"type": "pointerMove", "duration": 50, "origin": "viewport",
                          "x": x + dx * i // 5, "y": y + dy * i // 5})
        steps.append({"type": "pointerUp", "button": 0})
        self.call("POST", self.s("/actions"),
                  {"actions": [{"type": "pointer", "id": "mouse", "parameters": {"pointerType": "mouse"},
                                "actions": steps}]})

    def screenshot(self, path):
        with open(path, "wb") as f:
            f.write(base64.b64decode(self.call("GET", self.s("/screenshot"))))

    def close(self):
        try:
            self.call("DELETE", self.s(""))
        except SystemExit:
            pass
        self.process.terminate()
        try:
            self.process.wait(10)
        except subprocess.TimeoutExpired:
            self.process.kill()
        self.log.close()
        shutil.rmtree(self.profile, ignore_errors=True)


def png_crop_to_ppm(png_path, width, height, ppm_path):
    """The top-left width x height of an 8-bit RGB(A) PNG (Chromium's
    screenshots), written as a binary PPM that the image module reads."""
    channels, rows = png_rows(png_path, height)
    with open(ppm_path, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (width, height))
        for row in rows[:height]:
            for x in range(width):
                f.write(bytes(row[x * channels:x * channels + 3]))


def png_rows(png_path, height=None):
    """The channels and the first `height` rows (all: None) of an 8-bit RGB(A) PNG."""
    data = open(png_path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + length
    w, h, depth, colour, _, _, interlace = header
    assert depth == 8 and colour in (2, 6) and interlace == 0, f"unexpected PNG format {header}"
    channels = 4 if colour == 6 else 3
    raw = zlib.decompress(idat)
    stride = w * channels
    rows, previous = [], bytearray(stride)
    for y in range(h):
        kind = raw[y * (stride + 1)]
        row = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = row[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                row[i] = (row[i] + a) & 255
            elif kind == 2:
                row[i] = (row[i] + b) & 255
            elif kind == 3:
                row[i] = (row[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(row)
        previous = row
        if len(rows) == height:
            break
    return channels, rows


def fitted(browser, work, size, check):
    """The frame fills the page's width or height with its aspect kept, centred, in a window of another
    shape (a projector's): where the screenshot is not the bars' black is the contained rectangle."""
    box = browser.js("const r = document.getElementById('frame').getBoundingClientRect();"
                     "return [r.left, r.top, r.width, r.height, window.innerHeight];")
    left, top, width, height, inner = box
    check("the frame's box is the window's height", abs(height - inner) < 1, json.dumps(box))
    scale = min(width / size[0], height / size[1])
    want = (left + (width - size[0] * scale) / 2, top + (height - size[1] * scale) / 2)
    want = (want[0], want[1], want[0] + size[0] * scale, want[1] + size[1] * scale)
    shot = os.path.join(work, "page-fitted.png")
    browser.screenshot(shot)
    channels, rows = png_rows(shot, int(inner))
    end = int(left + width) * channels  # the page's scroll bar, right of the box, is not the picture's
    ys = [y for y, row in enumerate(rows) if any(sum(row[x:x + 3]) > 40 for x in range(0, end, channels * 4))]
    xs = [x // channels for x in range(0, end, channels)
          if any(sum(rows[y][x:x + 3]) > 40 for y in range(0, len(rows), 4))]
    got = (min(xs), min(ys), max(xs) + 1, max(ys) + 1) if xs and ys else (0, 0, 0, 0)
    check("the frame is fitted to the window, its aspect kept (the picture where expected, black bars around)",
          all(abs(g - w) <= 4 for g, w in zip(got, want)) and scale > 1.5,
          f"picture at {got}, expected {tuple(round(w) for w in want)} (scale {scale:.2f})")


MEAN = """const img = document.getElementById('frame');
if (!img.naturalWidth) return -1;
const c = document.createElement('canvas'); c.width = img.naturalWidth; c.height = img.naturalHeight;
const g = c.getContext('2d'); g.drawImage(img, 0, 0);
const d = g.getImageData(0, 0, c.width, c.height).data; let s = 0;
for (let i = 0; i < d.length; i += 4) s += d[i] + d[i + 1] + d[i + 2];
return s / (d.length / 4 * 3);"""


class Server:
    def __init__(self, viewer, work, args):
        self.port = free_port()
        self.log_path = os.path.join(work, "serve.log")
        self.log = open(self.log_path, "w")
        for folder in (work, os.path.join(work, "shadowlab-screenshots")):  # the X key's screenshots
            for old in os.listdir(folder) if os.path.isdir(folder) else []:
                if old.startswith("shadowlab-") and old.endswith(".png"):
                    os.remove(os.path.join(folder, old))
        self.process = subprocess.Popen([os.path.abspath(viewer), "--serve", str(self.port)] + args, stdout=self.log,
                                        stderr=subprocess.STDOUT, cwd=work)
        # The URL the viewer prints, its token included: the one way in.
        self.base = f"http://127.0.0.1:{self.port}/"
        printed = re.compile(r"serving the (?:viewer|case view) at (" + re.escape(self.base) + r"\S*)")
        found = wait_for("the viewer's URL line",
                         lambda: printed.search(open(self.log_path).read()) or self._dead(), 60)
        if self.process.poll() is not None:
            raise SystemExit("serve_browser: FAIL: shadowlab --serve stopped:\n" + open(self.log_path).read())
        self.url = found.group(1)
        self.token = urllib.parse.parse_qs(urllib.parse.urlsplit(self.url).query).get("token", [""])[0]

    def _dead(self):
        return self.process.poll() is not None

    def stop(self):
        self.process.send_signal(signal.SIGINT)
        try:
            self.process.wait(10)
        except subprocess.TimeoutExpired:
            self.process.kill()
        self.log.close()


def mean(browser):
    """The shown frame's mean brightness (waits while the page swaps in the next frame)."""
    return wait_for("a decoded frame", lambda: (lambda m: [m] if m >= 0 else None)(browser.js(MEAN)), 30)[0]


def frames_after(browser, count):
    start = browser.js("return window.sl.frames")
    wait_for(f"{count} more frames", lambda: browser.js("return window.sl.frames") >= start + count)


def press_and_wait(browser, key):
    """Presses a key; waits for the first frame that reflects it; its latency in ms."""
    before = browser.js("return window.sl.latencies.length")
    browser.press(key)
    wait_for(f"a frame after pressing {key}", lambda: browser.js("return window.sl.latencies.length") > before, 60)
    return browser.js("return window.sl.latencies[window.sl.latencies.length - 1]")


# WebDriver's key values for the browser's key codes the viewer's table uses.
WEBDRIVER_KEYS = {"Comma": ",", "Period": ".", "Minus": "-", "Equal": "=", "BracketLeft": "[",
                  "BracketRight": "]", "ArrowLeft": "\ue012", "ArrowUp": "\ue013", "ArrowRight": "\ue014",
                  "ArrowDown": "\ue015", "PageUp": "\ue00e", "PageDown": "\ue00f"}


def webdriver_key(code):
    if code.startswith("Key") and len(code) == 4:
        return code[3].lower()
    if code.startswith("Digit") and len(code) == 6:
        return code[5]
    return WEBDRIVER_KEYS.get(code)


def every_key(browser, viewer, work, check):
    """The page's keys are the viewer's table, and each is acted on when pressed in the browser."""
    table = browser.js("return window.sl.keyTable")
    listed = subprocess.run([viewer, "--list-keys"], check=True, capture_output=True, text=True).stdout
    expected = {tuple(line.split("\t")) for line in listed.splitlines()
                if line and not line.startswith("case\t") and line.split("\t")[1] != "Esc"}
    got = {("all" if b["lab"] == 0 else str(b["lab"]), b["names"], b["help"]) for b in table["keys"]}
    check("the page's key table is --list-keys' (Esc apart: a page is closed in the browser)", got == expected,
          f"missing {sorted(expected - got)[:3]}, extra {sorted(got - expected)[:3]}")
    unmapped = [b["names"] for b in table["keys"] for c in b["codes"] if not c["code"] or not webdriver_key(c["code"])]
    check("every key of the table has its browser key", not unmapped, ", ".join(unmapped))
    # Lab by lab: the lab's digit, its own keys, then every lab's keys (digits
    # apart); each press must be acted on (the frames' keys_acted count).
    for lab in (5, 6, 7, 4):
        presses = [str(lab)]
        own = [c for b in table["keys"] if b["lab"] == lab for c in b["codes"]]
        taken = {c["key"] for c in own}
        common = [c for b in table["keys"] if b["lab"] == 0 for c in b["codes"]
                  if c["key"] not in taken and not c["code"].startswith("Digit")]
        if lab != 4:
            common = [c for c in common if c["code"] != "KeyX"]  # one screenshot is enough
        presses += [webdriver_key(c["code"]) for c in own + common if webdriver_key(c["code"])]
        before = browser.js("return window.sl.header.keys_acted")
        browser.press(*presses)
        try:
            wait_for(f"lab {lab}'s keys", lambda: browser.js("return window.sl.header.keys_acted") >= before + len(presses)
                     and browser.js("return window.sl.header.lab") == lab, 60)
            acted = browser.js("return window.sl.header.keys_acted") - before
        except SystemExit:
            acted = browser.js("return window.sl.header.keys_acted") - before
        check(f"lab {lab}: each of its {len(presses)} keys pressed in the browser is acted on", acted == len(presses),
              f"{acted} of {len(presses)}")
    folder = os.path.join(work, "shadowlab-screenshots")
    shots = [f for f in os.listdir(folder) if f.startswith("shadowlab-") and f.endswith(".png")]
    stray = [f for f in os.listdir(work) if f.startswith("shadowlab-") and f.endswith(".png")]
    check("X on the page saves a screenshot into shadowlab-screenshots/, none where the viewer runs",
          len(shots) == 1 and not stray, ", ".join(shots + stray) or "none")
    frames_after(browser, 1)
    title = browser.js("return document.getElementById('keys-title').textContent")
    keys_text = browser.js("return document.getElementById('keys').textContent")
    check("the page lists the lab's keys", title == "keys, lab 4" and "the constant depth bias" in keys_text, title)
    browser.js("document.getElementById('keys-box').open = true")
    browser.screenshot(os.path.join(work, "page-keys.png"))


def case_view(viewer, work, check):
    """--serve with --case: the case view's labels and keys on the page."""
    server = Server(viewer, work, ["--case", "lab4_pcss"])
    browser = None
    try:
        browser = WebDriver(work)
        browser.go(server.url)
        wait_for("the case view's first frame", lambda: browser.js("return window.sl.frames") >= 1)
        frames_after(browser, 1)
        text = browser.js("return document.getElementById('text').textContent")
        check("--case: the page shows the panels' labels and the check's summary",
              "[label] yours" in text and "[label] reference" in text and "pass" in text.lower(),
              " | ".join(text.splitlines()[:3]))
        names = sorted(b["names"] for b in browser.js("return window.sl.keyTable.keys"))
        check("--case: the page's keys are the case view's (Esc apart)", names == ["C", "D", "Space", "Tab"],
              ", ".join(names))
        side_by_side = mean(browser)
        before = browser.js("return window.sl.header.keys_acted")
        browser.press("\ue004")  # Tab: one panel at a time
        wait_for("the Tab key's frame", lambda: browser.js("return window.sl.header.keys_acted") > before, 60)
        frames_after(browser, 1)
        one = mean(browser)
        check("--case: Tab on the page changes the picture (side by side to one panel)", abs(one - side_by_side) > 1,
              f"mean brightness {side_by_side:.1f} -> {one:.1f}")
        browser.screenshot(os.path.join(work, "page-case.png"))
    finally:
        if browser:
            browser.close()
        server.stop()
    check("--case: the server said where it serves",
          f"serving the case view at {server.url}" in open(server.log_path).read())


def split_view(viewer, compare, work, check):
    """--serve with --split: the frame the page shows is the split frame the viewer renders headless (lab 1,
    no shadows, beside lab 4's: the halves differ well beyond JPEG's noise), and not the same two halves
    swapped (--split 4,1)."""
    size = (480, 270)
    view = ["--scene", "boxes_on_floor", "--size", f"{size[0]}x{size[1]}", "--no-overlay"]
    server = Server(viewer, work, view + ["--split", "1,4"])
    browser = None
    try:
        browser = WebDriver(work)
        browser.go(server.url)
        wait_for("the split view's first frame", lambda: browser.js("return window.sl.frames") >= 1)
        bar = browser.js("return window.innerWidth - document.documentElement.clientWidth")
        browser.call("POST", browser.s("/goog/cdp/execute"),
                     {"cmd": "Emulation.setDeviceMetricsOverride",
                      "params": {"width": size[0] + bar, "height": size[1], "deviceScaleFactor": 1, "mobile": False}})
        frames_after(browser, 2)
        shot = os.path.join(work, "page-split.png")
        browser.screenshot(shot)
        crop = os.path.join(work, "page-split.ppm")
        png_crop_to_ppm(shot, size[0], size[1], crop)
        text = browser.js("return document.getElementById('text').textContent")
    finally:
        if browser:
            browser.close()
        server.stop()
    references = {}
    for sides in ("1,4", "4,1"):
        references[sides] = os.path.join(work, f"headless-split-{sides.replace(',', '-')}.png")
        subprocess.run([viewer, "--headless", "--frames", "1", "--split", sides, "--screenshot", references[sides]] + view,
                       check=True, stdout=subprocess.DEVNULL)
    same = subprocess.run([compare, crop, references["1,4"], "0.1", "1.0"], stdout=subprocess.DEVNULL).returncode == 0
    check("--split: the page shows the split frame the viewer renders (JPEG: 0.1, 1% of pixels)", same)
    swapped = subprocess.run([compare, crop, references["4,1"], "0.1", "1.0"], stdout=subprocess.DEVNULL).returncode != 0
    check("--split: the page's halves are not the other way round (--split 4,1)", swapped)
    check("--split: the page shows the halves' labels", "[label] no shadows (only lab 1's depth map)" in text and
          "[label] lab 4's PCF grid 3x3" in text, " | ".join(text.splitlines()[:3]))


def test(viewer, compare, work):
    failures = []

    def check(what, ok, detail=""):
        print(f"serve_browser: {'ok' if ok else 'FAIL'}: {what}{': ' + detail if detail else ''}", flush=True)
        if not ok:
            failures.append(what)

    size = (480, 270)
    view = ["--lab", "4", "--scene", "boxes_on_floor", "--size", f"{size[0]}x{size[1]}"]
    server = Server(viewer, work, view + ["--no-overlay"])
    browser = None
    try:
        browser = WebDriver(work)
        browser.go(server.url)
        wait_for("the first frame", lambda: browser.js("return window.sl.frames") >= 1)
        header = browser.js("return window.sl.header")
        check("a frame arrives with its size", header["width"] == size[0] and header["height"] == size[1],
              json.dumps(header)[:200])
        before = browser.js("return window.sl.keysBeforeFrame")
        check("the page lists the starting lab's keys before the first frame", before == "keys, lab 4", str(before))
        fitted(browser, work, size, check)
        # The checks below compare the page's pixels with the viewer's own: a window of the frame's size
        # (and the page's scroll bar), where fitting draws it at 1:1.
        bar = browser.js("return window.innerWidth - document.documentElement.clientWidth")
        browser.call("POST", browser.s("/goog/cdp/execute"),
                     {"cmd": "Emulation.setDeviceMetricsOverride",
                      "params": {"width": size[0] + bar, "height": size[1], "deviceScaleFactor": 1, "mobile": False}})
        frames_after(browser, 1)
        frames_after(browser, 2)
        shaded = mean(browser)
        latency = press_and_wait(browser, "v")
        frames_after(browser, 1)
        visibility = mean(browser)
        check("V changes the picture (shaded to the visibility view)", abs(visibility - shaded) > 15,
              f"mean brightness {shaded:.1f} -> {visibility:.1f}, the key's frame after {latency:.0f} ms")
        # The frame as the page shows it: the top left of a screenshot, against
        # the same view rendered offscreen by the viewer itself.
        shot = os.path.join(work, "page.png")
        browser.screenshot(shot)
        crop = os.path.join(work, "page-frame.ppm")
        png_crop_to_ppm(shot, size[0], size[1], crop)
        reference = os.path.join(work, "headless.png")
        subprocess.run([viewer, "--headless", "--frames", "1", "--keys", "V", "--screenshot", reference] + view,
                       check=True, stdout=subprocess.DEVNULL)
        same = subprocess.run([compare, crop, reference, "0.1", "1.0"]).returncode == 0
        check("the screenshot shows the scene as the viewer renders it (JPEG: 0.1, 1% of pixels)", same)
        # A drag orbits the camera.
        before = mean(browser)
        start = browser.js("return window.sl.frames")
        browser.drag(240, 135, 120, 0)
        wait_for("frames after the drag", lambda: browser.js("return window.sl.frames") >= start + 3)
        frames_after(browser, 2)
        browser.screenshot(os.path.join(work, "page-dragged.png"))
        after = mean(browser)
        png_crop_to_ppm(os.path.join(work, "page-dragged.png"), size[0], size[1], os.path.join(work, "dragged.ppm"))
        moved = subprocess.run([compare, os.path.join(work, "dragged.ppm"), reference, "0.1", "1.0"],
                               stdout=subprocess.DEVNULL).returncode != 0
        check("a drag orbits the camera (the picture is no longer the reference's)", moved,
              f"mean brightness {before:.1f} -> {after:.1f}")
        # The overlay (O): drawn in the frame and its text shown on the page.
        press_and_wait(browser, "o")
        frames_after(browser, 1)
        text = browser.js("return document.getElementById('text').textContent")
        check("O shows the overlay, and the page its text", "lab 4: PCF & PCSS" in text and "boxes_on_floor" in text,
              text.splitlines()[0] if text else "(no text)")
        browser.screenshot(os.path.join(work, "page-overlay.png"))
        check("the key panel does not offer Esc on a page", "Esc quit" not in text)
        every_key(browser, viewer, work, check)
    finally:
        if browser:
            browser.close()
        server.stop()
    log = open(server.log_path).read()
    check("the server said where it serves", f"serving the viewer at {server.url}" in log)
    case_view(viewer, work, check)
    split_view(viewer, compare, work, check)
    print("serve_browser: " + ("passed" if not failures else f"{len(failures)} failed"))
    return 1 if failures else 0


def raw_request(port, lines, timeout=5.0):
    """Sends an HTTP request (its lines) to 127.0.0.1:port and reads the answer's head and what body
    arrives within timeout: (status code or 0 if none, the text)."""
    with socket.create_connection(("127.0.0.1", port), timeout=timeout) as s:
        s.sendall(("\r\n".join(lines) + "\r\n\r\n").encode())
        data, end = b"", time.time() + timeout
        while time.time() < end:
            try:
                chunk = s.recv(65536)
            except socket.timeout:
                break
            if not chunk:
                break
            data += chunk
            head, _, body = data.partition(b"\r\n\r\n")
            if _ and (head.startswith(b"HTTP/1.1 101") or b"content-length" not in head.lower()
                      or len(body) >= int(re.search(rb"(?i)content-length:\s*(\d+)", head).group(1))):
                break
    text = data.decode("latin-1")
    match = re.match(r"HTTP/1\.[01] (\d{3})", text)
    return (int(match.group(1)) if match else 0), text


def websocket_request(port, path, host, origin=None):
    lines = [f"GET {path} HTTP/1.1", f"Host: {host}", "Upgrade: websocket", "Connection: Upgrade",
             "Sec-WebSocket-Key: " + base64.b64encode(os.urandom(16)).decode(), "Sec-WebSocket-Version: 13",
             "Sec-WebSocket-Protocol: shadowlab"]
    return raw_request(port, lines + ([f"Origin: {origin}"] if origin else []))


# Another site's page (served from a second port): it tries the viewer's page and its WebSocket, without
# the token and with it (as if it had leaked), and records what it got.
ATTACK_PAGE = """<!doctype html><meta charset="utf-8"><title>another site</title><script>
window.result = {};
const target = "127.0.0.1:PORT";
fetch("http://" + target + "/").then((r) => r.text()).then((t) => { window.result.fetch = "read: " + t.slice(0, 40); },
  () => { window.result.fetch = "blocked"; });
function tryWs(name, url) {
  let ws = new WebSocket(url, "shadowlab");
  ws.binaryType = "arraybuffer";
  ws.onmessage = () => { window.result[name] = "got a message"; ws.close(); };
  ws.onerror = () => { if (!window.result[name]) window.result[name] = "refused"; };
  ws.onclose = () => { if (!window.result[name]) window.result[name] = "closed"; };
}
tryWs("ws", "ws://" + target + "/");
tryWs("ws_with_token", "ws://" + target + "/?token=TOKEN");
</script>"""


class OtherSite:
    """A second HTTP server on this machine, on a port of its own: another origin."""

    def __init__(self, page):
        class Handler(http.server.BaseHTTPRequestHandler):
            def do_GET(self):
                body = page.encode()
                self.send_response(200)
                self.send_header("Content-Type", "text/html; charset=utf-8")
                self.send_header("Content-Length", str(len(body)))
                self.end_headers()
                self.wfile.write(body)

            def log_message(self, *args):
                pass

        self.httpd = http.server.HTTPServer(("127.0.0.1", 0), Handler)
        self.port = self.httpd.server_address[1]
        threading.Thread(target=self.httpd.serve_forever, daemon=True).start()

    def stop(self):
        self.httpd.shutdown()
        self.httpd.server_close()


def security(viewer, work):
    """Only the URL the viewer printed connects: no token or a wrong one, a Host that is not this machine
    (DNS rebinding), another site's page, all refused (403) and never counted as a page, so the real page
    opened after them still receives frames; X from the page saves into the folder the viewer names."""
    failures = []
    browser_missing = False

    def check(what, ok, detail=""):
        print(f"serve_browser: {'ok' if ok else 'FAIL'}: {what}{': ' + detail if detail else ''}", flush=True)
        if not ok:
            failures.append(what)

    for old in os.listdir(work):
        if old.startswith("shadowlab-") and old.endswith(".png"):
            os.remove(os.path.join(work, old))
    shots = os.path.join(work, "shots")
    shutil.rmtree(shots, ignore_errors=True)
    server = Server(viewer, work, ["--lab", "4", "--scene", "boxes_on_floor", "--size", "320x180",
                                   "--screenshot-dir", "shots"])
    port, token = server.port, server.token
    here = f"127.0.0.1:{port}"
    other = OtherSite("")
    browser = None
    try:
        check("the printed URL carries a token of 128 bits or more", len(token) >= 32, server.url)
        wrong = ("0" if token[:1] != "0" else "1") + token[1:]
        # The page over raw HTTP.
        code, text = raw_request(port, ["GET / HTTP/1.1", f"Host: {here}"])
        check("the page without the token: 403, saying to use the printed URL",
              code == 403 and "URL the viewer printed" in text, text.splitlines()[0] if text else "no answer")
        code, text = raw_request(port, [f"GET /?token={wrong} HTTP/1.1", f"Host: {here}"])
        check("the page with a wrong token: 403", code == 403, text.splitlines()[0] if text else "no answer")
        code, text = raw_request(port, [f"GET /?token={token} HTTP/1.1", f"Host: {here}"])
        check("the page with the token: 200", code == 200 and "<html" in text, text.splitlines()[0] if text else "")
        code, text = raw_request(port, [f"GET /?token={token} HTTP/1.1", f"Host: evil.example:{port}"])
        check("the page with the token but Host: evil.example (DNS rebinding): 403", code == 403,
              text.splitlines()[0] if text else "no answer")
        # The WebSocket over raw sockets: refused before it is a connection.
        for what, path, host, origin in [
                ("no token", "/", here, f"http://{here}"),
                ("a wrong token", f"/?token={wrong}", here, f"http://{here}"),
                ("the token but Host: evil.example", f"/?token={token}", f"evil.example:{port}",
                 f"http://evil.example:{port}"),
                ("the token but another site's Origin", f"/?token={token}", here, f"http://127.0.0.1:{other.port}"),
                ("no token and no Origin", "/", here, None)]:
            code, text = websocket_request(port, path, host, origin)
            check(f"a WebSocket with {what}: refused (403)", code == 403, text.splitlines()[0] if text else "no answer")
        code, text = websocket_request(port, f"/?token={token}", here, None)
        check("a WebSocket with the token and no Origin (not a browser's script): accepted", code == 101,
              text.splitlines()[0] if text else "no answer")

        # In Chromium: evil.example resolves to this machine, as a rebinding name would.
        browser = WebDriver(work, ["--host-resolver-rules=MAP evil.example 127.0.0.1", "--no-proxy-server"])
        other.stop()
        other = OtherSite(ATTACK_PAGE.replace("PORT", str(port)).replace("TOKEN", token))
        browser.go(f"http://127.0.0.1:{other.port}/")
        result = wait_for("the other site's attempts",
                          lambda: (lambda r: r if r and len(r) == 3 else None)(browser.js("return window.result")), 20)
        check("another site's page cannot read the viewer's page", result["fetch"] == "blocked", result["fetch"])
        check("another site's page gets no WebSocket, with or without the token",
              result["ws"] != "got a message" and result["ws_with_token"] != "got a message", json.dumps(result))
        browser.go(f"http://evil.example:{port}/?token={token}")
        time.sleep(0.5)
        body = browser.js("return document.body ? document.body.innerText : ''")
        frames = browser.js("return window.sl ? window.sl.frames : -1")
        check("the page at http://evil.example:PORT (a rebound name) is refused, even with the token",
              frames == -1 and "answers only at" in body, body[:120])
        # After every refused attempt, the real page.
        browser.go(server.url)
        wait_for("frames on the real page after the refused attempts",
                 lambda: browser.js("return window.sl.frames") >= 3, 20)
        check("the real page still receives frames after the refused attempts", True)
        # A refused attempt while the page is open does not stop its frames either.
        websocket_request(port, "/", here, f"http://127.0.0.1:{other.port}")
        start = browser.js("return window.sl.frames")
        time.sleep(1.0)
        wait_for("frames after another refused attempt", lambda: browser.js("return window.sl.frames") >= start + 3, 20)
        check("frames go on after a refused attempt during the page's connection", True)
        browser.press("x")
        wait_for("the screenshot", lambda: os.path.isdir(shots) and os.listdir(shots), 20)
        stray = [f for f in os.listdir(work) if f.startswith("shadowlab-") and f.endswith(".png")]
        check("X on the page saves into --screenshot-dir, with the viewer's own name, nothing where it runs",
              os.listdir(shots) == ["shadowlab-001.png"] and not stray, ", ".join(os.listdir(shots) + stray))
    except SystemExit as e:
        if e.code == 77 and not failures:
            browser_missing = True  # the checks without a browser passed; the browser's cannot run here
        else:
            check("the checks ran to the end", False, str(e))
    finally:
        if browser:
            browser.close()
        other.stop()
        server.stop()
    if browser_missing:
        print("serve_browser: the checks without a browser passed; the rest skipped (77)")
        return 77
    print("serve_browser: " + ("passed" if not failures else f"{len(failures)} failed"))
    return 1 if failures else 0


def measure(viewer, work, size):
    server = Server(viewer, work, ["--lab", "4", "--scene", "boxes_on_floor", "--size", size, "--no-overlay"])
    browser = None
    try:
        browser = WebDriver(work)
        browser.go(server.url)
        wait_for("the first frame", lambda: browser.js("return window.sl.frames") >= 1)
        time.sleep(2)
        f0, t0 = browser.js("return window.sl.frames"), time.time()
        time.sleep(10)
        f1, t1 = browser.js("return window.sl.frames"), time.time()
        fps = (f1 - f0) / (t1 - t0)
        latencies = []
        for i in range(20):
            latencies.append(press_and_wait(browser, "v"))
            time.sleep(0.3)
        print(f"serve: {size}: {fps:.1f} frames/s received by Chromium over 10 s")
        print(f"serve: key press to changed frame: median {statistics.median(latencies):.0f} ms of 20 "
              f"(min {min(latencies):.0f}, max {max(latencies):.0f})")
    finally:
        if browser:
            browser.close()
        server.stop()
    return 0


def main(argv):
    if len(argv) >= 5 and argv[1] == "test":
        os.makedirs(argv[4], exist_ok=True)
        return test(argv[2], argv[3], argv[4])
    if len(argv) >= 4 and argv[1] == "security":
        os.makedirs(argv[3], exist_ok=True)
        return security(argv[2], argv[3])
    if len(argv) >= 4 and argv[1] == "measure":
        os.makedirs(argv[3], exist_ok=True)
        return measure(argv[2], argv[3], argv[4] if len(argv) > 4 else "960x540")
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
