"""view_page.py - what tests/view_browser.py's steps share: headless Chromium and its
driver at 127.0.0.1, waiting, reading the page's text, the canvas's pixels and the server's
state, PNG decoding for the tone-curve comparison, the viridis table, and the failure list.
view_browser.py sets OUT (the screenshots' folder) before the first step."""
import base64
import os
import re
import socket
import subprocess
import time
import zlib

from selenium import webdriver
from selenium.common.exceptions import TimeoutException, WebDriverException
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common import utils
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

OUT = None  # the screenshots' folder (view_browser.py)
WAIT = 30  # seconds for one step; the graph runs on 2 busy cores
failures = []

# The canvas's pixels as RGBA bytes, read through a 2D canvas (the page's is WebGL2).
CANVAS_READ = """
const c = document.getElementById('view');
const s = document.createElement('canvas');
s.width = c.width; s.height = c.height;
const x = s.getContext('2d');
x.drawImage(c, 0, 0);
const d = x.getImageData(0, 0, c.width, c.height).data;
"""
# A cheap fingerprint of the canvas pixels, to see that what is drawn changed.
CANVAS_HASH = CANVAS_READ + """
let h = 0;
for (let i = 0; i < d.length; i++) h = (Math.imul(h, 31) + d[i]) | 0;
return [c.width, c.height, h];
"""
# The canvas as [width, height, base64 of its RGBA bytes].
CANVAS_BYTES = CANVAS_READ + """
let b = '';
for (let i = 0; i < d.length; i += 8192) b += String.fromCharCode(...d.subarray(i, i + 8192));
return [c.width, c.height, btoa(b)];
"""


def fail(msg):
    print(f"FAIL: {msg}", flush=True)
    failures.append(msg)


class LoopbackService(Service):
    """chromedriver asked for at 127.0.0.1: selenium's Service names it `localhost`, which a
    minimal system without /etc/hosts does not resolve (the server is 127.0.0.1 too)."""

    @property
    def service_url(self):
        return f"http://127.0.0.1:{self.port}"

    def is_connectable(self):
        return utils.is_connectable(self.port, "127.0.0.1")


def localhost_note():
    """Why chromedriver may not start here, when the cause is the name `localhost`."""
    try:
        socket.getaddrinfo("localhost", None)
        return ""
    except OSError:
        return (" (`localhost` does not resolve here, e.g. no /etc/hosts: chromedriver and "
                "chromium may still need it among themselves)")


# --disable-gpu leaves WebGL2 to SwiftShader on the CPU, which --enable-unsafe-swiftshader
# keeps allowed in Chromiums that would otherwise refuse it.
CHROMIUM_FLAGS = ("--headless=new", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader",
                  "--disable-dev-shm-usage", "--window-size=1280,800", "--no-first-run",
                  "--disable-extensions")


def start_chromium():
    """Chromium started here, its DevTools on 127.0.0.1 at a free port, which chromedriver is
    told (debuggerAddress): a chromium that chromedriver starts is reached at `localhost`."""
    port = utils.free_port()
    proc = subprocess.Popen(["/usr/bin/chromium", *CHROMIUM_FLAGS,
                             "--remote-debugging-address=127.0.0.1",
                             f"--remote-debugging-port={port}",
                             f"--user-data-dir={os.path.join(OUT, 'chromium-profile')}",
                             "about:blank"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    for _ in range(300):
        if utils.is_connectable(port, "127.0.0.1"):
            return proc, port
        if proc.poll() is not None:
            break
        time.sleep(0.1)
    proc.kill()
    raise WebDriverException(f"chromium opened no DevTools port on 127.0.0.1:{port}")


def browser(port):
    opts = webdriver.ChromeOptions()
    opts.debugger_address = f"127.0.0.1:{port}"
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=LoopbackService("/usr/bin/chromedriver"), options=opts)


def wait_for(drv, what, cond):
    """Waits until cond(drv) is truthy; a timeout is a failure named `what`."""
    try:  # after a failure, the rest of the step need not wait long to fail too
        return WebDriverWait(drv, 3 if failures else WAIT, poll_frequency=0.1).until(
            lambda d: cond(d))
    except TimeoutException:
        fail(f"timed out waiting for {what}")
        return None


def text(drv, elem_id):
    return drv.find_element(By.ID, elem_id).text


def shot(drv, name):
    drv.save_screenshot(os.path.join(OUT, f"viewer-{name}.png"))


def generation(drv):
    t = text(drv, "generation")
    return int(t) if t.isdigit() else -1


def ran_nodes(drv):
    return set(text(drv, "ran-list").split())


def server_state(drv):
    """The server's /api/state as the page's cookie fetches it."""
    drv.set_script_timeout(WAIT)
    return drv.execute_async_script("""const done = arguments[arguments.length - 1];
        fetch('/api/state', {credentials: 'same-origin'}).then((r) => r.json()).then(done,
            (e) => done(null));""")


def read_png(path):
    """(width, height, channels, bytes) of an 8-bit gray or RGB PNG, non-interlaced (what
    the CLI writes): the IDAT stream inflated and its row filters undone."""
    with open(path, "rb") as f:
        data = f.read()
    pos, idat, head = 8, b"", None
    while pos < len(data):
        n = int.from_bytes(data[pos:pos + 4], "big")
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        head = body if kind == b"IHDR" else head
        idat += body if kind == b"IDAT" else b""
        pos += 12 + n
    w, h = int.from_bytes(head[0:4], "big"), int.from_bytes(head[4:8], "big")
    c = {0: 1, 2: 3}[head[9]]
    raw, stride, out = zlib.decompress(idat), w * c, bytearray()
    for y in range(h):
        row = raw[y * (stride + 1):(y + 1) * (stride + 1)]
        kind, line = row[0], bytearray(row[1:])
        up = out[(y - 1) * stride:y * stride] if y else bytearray(stride)
        for i in range(stride):
            a, b, cc = line[i - c] if i >= c else 0, up[i], up[i - c] if i >= c else 0
            pred = (0, a, b, (a + b) // 2, paeth(a, b, cc))[kind]
            line[i] = (line[i] + pred) & 255
        out += line
    return w, h, c, bytes(out)


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else b if pb <= pc else c


def canvas_vs_png(drv, path):
    """The largest difference, in 8-bit codes, between the canvas and the PNG (scaled to the
    canvas by nearest pixel, grey as R = G = B), and where it is."""
    W, H, b64 = drv.execute_script(CANVAS_BYTES)
    px = base64.b64decode(b64)
    w, h, c, ref = read_png(path)
    worst = (0, None)
    for y in range(H):
        for x in range(W):
            r = ((y * h // H) * w + x * w // W) * c
            for k in range(3):
                d = abs(px[(y * W + x) * 4 + k] - ref[r + (k if c == 3 else 0)])
                worst = max(worst, (d, (x, y, k)), key=lambda t: t[0])
    return worst


def set_display(drv, stops, curve, colormap):
    drv.execute_script("""const [stops, curve, cmap] = arguments, fire = (id, v, ev) => {
        const el = document.getElementById(id); el.value = v; el.dispatchEvent(new Event(ev)); };
        fire('exposure', stops, 'input'); fire('tonemap', curve, 'change');
        fire('colormap', cmap, 'change');""", str(stops), curve, colormap)


# matplotlib's viridis at 11 stops, as image.js interpolates it into 256 entries
VIRIDIS = [(68, 1, 84), (72, 36, 117), (65, 68, 135), (53, 95, 141), (42, 120, 142),
           (33, 145, 140), (34, 168, 132), (68, 191, 112), (122, 209, 81), (189, 223, 38),
           (253, 231, 37)]


def viridis_256():
    """The 256 entries as bytes (a Uint8ClampedArray rounds half to even, as round does)."""
    out = set()
    for i in range(256):
        t = i / 255 * 10
        k = min(9, int(t))
        out.add(bytes(round(VIRIDIS[k][j] * (1 - (t - k)) + VIRIDIS[k + 1][j] * (t - k))
                      for j in range(3)))
    return out


def outside_viridis(drv):
    """The canvas colours that are not viridis entries."""
    px = base64.b64decode(drv.execute_script(CANVAS_BYTES)[2])
    return sorted({px[i:i + 3] for i in range(0, len(px), 4)} - viridis_256())


def metric(drv, which, port):
    """(RMSE, SSIM) of A or B in the metrics text when it is for that port, else None."""
    m = re.search(f"{which} {re.escape(port)}: RMSE ([-0-9.e+]+) SSIM ([-0-9.e+]+)",
                  text(drv, "metrics"))
    return (float(m.group(1)), float(m.group(2))) if m else None


def canvas_colours(drv):
    px = base64.b64decode(drv.execute_script(CANVAS_BYTES)[2])
    return {px[i:i + 3] for i in range(0, len(px), 4)}


def js_errors(drv):
    """Console errors other than the HTTP errors the test provokes on purpose."""
    try:
        logs = drv.get_log("browser")
    except WebDriverException:
        return
    for e in logs:
        if e["level"] == "SEVERE" and "Failed to load resource" not in e["message"]:
            fail(f"browser console: {e['message']}")


def run_steps(steps, failure_shot="failure"):
    """Starts chromium and its driver, runs each step(drv) in order (its time printed) up to
    the first failure (screenshot viewer-FAILURE_SHOT.png), then the console check; the exit
    status: 1 on any failure."""
    chromium = None
    try:
        chromium, port = start_chromium()
        drv = browser(port)
    except WebDriverException as e:
        print(f"FAIL: chromedriver (/usr/bin/chromedriver, at 127.0.0.1) could not drive "
              f"headless chromium (/usr/bin/chromium): {e.msg}{localhost_note()}")
        if chromium:
            chromium.kill()
        return 1
    try:
        for step in steps:
            t0 = time.time()
            step(drv)
            print(f"{step.__name__}: {time.time() - t0:.1f} s", flush=True)
            if failures:
                shot(drv, failure_shot)
                break
        js_errors(drv)
    finally:
        drv.quit()
        chromium.kill()
        chromium.wait()
    return 1 if failures else 0
