"""view_zoom.py - the image viewer of `ssgraph view` in headless Chromium (driven by
tests/test_view_zoom.sh, helpers in view_page.py): the wheel zooms the image about the mouse
(nearest pixels, the readout names the pixel under it), Ctrl + wheel dollies the camera
instead, 1:1 and fit; the A/B difference modes draw the values they should on a known pair
(|A - B|, A - B, the relative error, the server's FLIP map) with their scale bar; X swaps
A and B; an EXR file opens as the reference and a bad path shows an error.

  view_zoom.py URL OUTDIR EXR   (EXR: img.out written by `ssgraph run --show img.out --out`)
"""
import base64
import math
import re
import sys
import time

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

import view_page
from view_page import (CANVAS_BYTES, CANVAS_HASH, VIRIDIS, fail, metric, run_steps,
                       server_state, shot, text, wait_for)

URL, OUT, EXR = sys.argv[1], sys.argv[2], sys.argv[3]
view_page.OUT = OUT

# A port's floats as the page fetches them: [w, h, c, values].
FETCH = """const [path, done] = arguments;
fetch(path, {credentials: 'same-origin'}).then((r) => r.arrayBuffer()).then((buf) => {
  const dv = new DataView(buf), [w, h, c] = [4, 8, 12].map((o) => dv.getUint32(o, true));
  done([w, h, c, Array.from(new Float32Array(buf.slice(20, 20 + w * h * c * 4)))]);
}, () => done(null));"""


def floats(drv, path):
    drv.set_script_timeout(60)
    return drv.execute_async_script(FETCH, path)


def canvas(drv):
    """(W, H, RGBA bytes) of the canvas."""
    W, H, b64 = drv.execute_script(CANVAS_BYTES)
    return W, H, base64.b64decode(b64)


def view_of(drv):
    """The canvas's zoom and pan (z, u, v) as render.js writes them; NaNs without them."""
    shown = drv.find_element(By.ID, "view").get_attribute("data-view") or "nan nan nan"
    z, u, v = (float(x) for x in shown.split())
    return z, u, v


def select(drv, elem_id, value):
    Select(drv.find_element(By.ID, elem_id)).select_by_value(value)


def fire(drv, elem_id, value):
    drv.execute_script("""const el = document.getElementById(arguments[0]);
        el.value = arguments[1]; el.dispatchEvent(new Event('change'));""", elem_id, value)


def viridis(i):
    t = i / 255 * 10
    k = min(9, int(t))
    return tuple(round(VIRIDIS[k][j] * (1 - (t - k)) + VIRIDIS[k + 1][j] * (t - k)) for j in range(3))


def diverging(i):
    """image.js's DIVERGING_RGBA entry i."""
    t = max(-1.0, min(1.0, (i - 128) / 127))
    end = (59, 76, 192) if t < 0 else (180, 4, 38)
    return tuple(round(221 + (end[j] - 221) * abs(t)) for j in range(3))


def nearest_entry(table, rgb):
    return min(range(256), key=lambda i: sum((a - b) ** 2 for a, b in zip(table(i), rgb)))


def mouse_at(drv, fx, fy):
    """Moves the mouse (DevTools events) to canvas point (fx, fy) in canvas pixels."""
    r = drv.execute_script("const r = document.getElementById('view').getBoundingClientRect();"
                           "return [r.left, r.top, r.width, r.height];")
    cv = drv.execute_script("const c = document.getElementById('view'); return [c.width, c.height];")
    x, y = r[0] + fx * r[2] / cv[0], r[1] + fy * r[3] / cv[1]
    drv.execute_cdp_cmd("Input.dispatchMouseEvent", dict(type="mouseMoved", x=x, y=y))
    return x, y


def wheel_at(drv, fx, fy, dy, modifiers=0):
    x, y = mouse_at(drv, fx, fy)
    drv.execute_cdp_cmd("Input.dispatchMouseEvent", dict(type="mouseWheel", x=x, y=y, deltaX=0,
                                                         deltaY=dy, modifiers=modifiers))


def pan_drag(drv, button, buttons):
    """A 30 screen pixel drag to the right from the canvas's centre (DevTools events)."""
    r = drv.execute_script("const r = document.getElementById('view').getBoundingClientRect();"
                           "return [r.left + r.width / 2, r.top + r.height / 2];")
    ev = lambda kind, dx, **kw: drv.execute_cdp_cmd("Input.dispatchMouseEvent", dict(
        type=kind, x=r[0] + dx, y=r[1], button=button, clickCount=1, **kw))
    ev("mousePressed", 0, buttons=buttons)
    for dx in (10, 20, 30):
        ev("mouseMoved", dx, buttons=buttons)
    ev("mouseReleased", 30)


def panned(drv, z, u, v, W):
    """Whether the view moved right by 30 screen pixels at zoom z: u less by 30 canvas
    pixels' worth, v and z the same."""
    width = drv.execute_script("return document.getElementById('view').getBoundingClientRect().width;")
    z2, u2, v2 = view_of(drv)
    return z2 == z and v2 == v and abs(u - u2 - 30 * W / width / (z * W)) < 1e-6


def step_load(drv):
    drv.get(URL)
    wait_for(drv, "the first image", lambda d: d.execute_script(CANVAS_HASH)[0] > 16)
    select(drv, "port-a", "img.out")
    wait_for(drv, "img.out drawn", lambda d: (d.find_element(By.ID, "view")
                                              .get_attribute("data-shown") or "").startswith("160x90"))
    time.sleep(0.3)


def step_zoom(drv):
    """Three wheel steps in about canvas point (50, 30): an image pixel covers z x z canvas
    pixels of one colour (nearest, the grid on its first row and column), the frame point
    under the mouse stays there, and the readout names the pixel the transform puts there."""
    fit_hash = drv.execute_script(CANVAS_HASH)
    W, H, _ = canvas(drv)
    for _ in range(3):
        wheel_at(drv, 50, 30, -300)
    wait_for(drv, "the image zoomed in", lambda d: view_of(d)[0] > 16)
    z, u, v = view_of(drv)
    qx, qy = u * W + (50.5 - W / 2) / z, v * H + (30.5 - H / 2) / z
    if abs(qx - 50.5) > 1 or abs(qy - 30.5) > 1:
        fail(f"the frame point under the mouse moved from (50.5, 30.5) to ({qx:.2f}, {qy:.2f})")
    time.sleep(0.3)
    _, _, px = canvas(drv)
    # a row through the middle: canvas columns grouped by the frame pixel they show
    y = H // 2
    groups = {}
    for x in range(W):
        fx = math.floor(u * W + (x + 0.5 - W / 2) / z)
        groups.setdefault(fx, []).append(x)
    fy = v * H + (y + 0.5 - H / 2) / z
    whole = [g for g in groups.values() if len(g) >= int(z) - 1]
    if not whole:
        fail(f"at zoom {z:.1f} no frame pixel covers {int(z) - 1} canvas columns: {groups}")
    for g in whole:
        inner = [px[(y * W + x) * 4:(y * W + x) * 4 + 3] for x in g[1:]]  # g[0]: the grid
        if fy - math.floor(fy) > 1 / z and len(set(inner)) != 1:
            fail(f"a zoomed pixel (canvas columns {g[0]}-{g[-1]}) is not one colour: {set(inner)}")
            break
    # the readout names the frame pixel under the mouse and its floats
    A = floats(drv, "/api/image?port=img.out")
    for cx, cy in ((W / 2 + 3.3, H / 2 - 2.2), (W / 2 - 20.6, H / 2 + 11.4)):
        mouse_at(drv, cx, cy)
        ex, ey = math.floor(u * W + (cx - W / 2) / z), math.floor(v * H + (cy - H / 2) / z)
        want = [A[3][(ey * A[0] + ex) * 3 + k] for k in range(3)]
        got = wait_for(drv, f"the readout of pixel {ex},{ey}", lambda d: re.match(
            rf"img\.out +x,y {ex},{ey}: ([-0-9.e+]+), ([-0-9.e+]+), ([-0-9.e+]+)$", text(d, "pixel")))
        if got and any(abs(float(t) - w) > 1e-4 * max(1, abs(w)) for t, w in zip(got.groups(), want)):
            fail(f"readout '{text(drv, 'pixel')}' is not pixel {ex},{ey}'s {want}")
    # the statistics follow the view
    wait_for(drv, "the statistics of the view", lambda d: "in view" in text(d, "stats"))
    shot(drv, "zoom")
    # a middle drag, and a left drag with space held, pan the image (the camera stays)
    pan_drag(drv, "middle", 4)
    wait_for(drv, "a middle drag to pan the image", lambda d: panned(d, z, u, v, W))
    z, u, v = view_of(drv)
    body = drv.find_element(By.TAG_NAME, "body")
    ActionChains(drv).key_down(Keys.SPACE, body).perform()
    pan_drag(drv, "left", 1)
    ActionChains(drv).key_up(Keys.SPACE, body).perform()
    wait_for(drv, "a space drag to pan the image", lambda d: panned(d, z, u, v, W))
    z, u, v = view_of(drv)
    # Ctrl + wheel dollies the camera and leaves the image's zoom alone
    cam = server_state(drv)["camera"]
    wheel_at(drv, 80, 45, 200, modifiers=2)
    wait_for(drv, "Ctrl + wheel to move the camera",
             lambda d: server_state(d)["camera"]["position"] != cam["position"])
    if abs(view_of(drv)[0] - z) > 1e-9:
        fail(f"Ctrl + wheel changed the image's zoom from {z} to {view_of(drv)[0]}")
    wait_for(drv, "the full run after the dolly", lambda d: text(d, "last-run") == "full"
             and not d.find_element(By.ID, "busy").is_displayed())
    drv.find_element(By.ID, "cam-home").click()
    wait_for(drv, "the camera home", lambda d: server_state(d)["camera"]["position"] == cam["position"])
    # 1:1 (key 1 and the button): one frame pixel to one device pixel; fit (key F, button)
    body = drv.find_element(By.TAG_NAME, "body")
    for one, back in ((lambda: body.send_keys("1"), lambda: body.send_keys("f")),
                      (lambda: drv.find_element(By.ID, "zoom-one").click(),
                       lambda: drv.find_element(By.ID, "zoom-fit").click())):
        one()
        want = drv.execute_script("const c = document.getElementById('view');"
                                  "return c.width / (c.getBoundingClientRect().width * devicePixelRatio);")
        wait_for(drv, f"1:1 (zoom {want:.3f})", lambda d: abs(view_of(d)[0] - want) < 1e-6
                 and text(d, "zoom-val") == "100%")
        back()
        wait_for(drv, "fit", lambda d: view_of(d) == (1.0, 0.5, 0.5))
        wait_for(drv, "the fitted canvas as before the zoom",
                 lambda d: d.execute_script(CANVAS_HASH) == fit_hash)


def set_ab(drv, a, b, mode):
    if not drv.find_element(By.ID, "ab-enable").is_selected():
        drv.find_element(By.ID, "ab-enable").click()
    select(drv, "port-a", a)
    select(drv, "port-b", b)
    select(drv, "ab-mode", mode)


SAMPLES = [(10, 10), (80, 45), (120, 60), (40, 70), (150, 20), (95, 30)]


def samples(expect):
    """SAMPLES and the pixels of the lowest, the highest and a middle expected entry (where a
    wrong sign or scale shows; most pixels of a small difference are near one entry)."""
    every = [(expect(x, y), (x, y)) for y in range(90) for x in range(160)]
    lo, hi = min(every), max(every)
    mid = min(every, key=lambda e: abs(e[0] - (lo[0] + hi[0]) / 2))
    return SAMPLES + [lo[1], hi[1], mid[1]]


def check_mode(drv, mode, expect, table, what):
    """Waits until every sample pixel's colour is table's entry expect(x, y), within one."""
    points = samples(expect)

    def ok(d):
        W, H, px = canvas(d)
        bad = []
        for x, y in points:
            rgb = tuple(px[(y * W + x) * 4:(y * W + x) * 4 + 3])
            got, want = nearest_entry(table, rgb), expect(x, y)
            if abs(got - want) > 1 or sum(abs(a - b) for a, b in zip(table(got), rgb)) > 6:
                bad.append((x, y, rgb, got, want))
        ok.bad = bad
        return not bad
    ok.bad = []
    if not wait_for(drv, what, ok):
        fail(f"{what}: (x, y, colour, entry, expected entry): {ok.bad}")


def step_diff(drv):
    """A = img.out, B = g.direct, channel R, viridis over [0, 1]: each difference mode's
    colours are the ones its values give (floats fetched from the server)."""
    set_ab(drv, "img.out", "g.direct", "diff")
    fire(drv, "channel", "r")
    fire(drv, "colormap", "viridis")
    fire(drv, "range", "unit")
    A, B = floats(drv, "/api/image?port=img.out"), floats(drv, "/api/image?port=g.direct")
    a = lambda x, y: A[3][(y * 160 + x) * 3]
    b = lambda x, y: B[3][(y * 160 + x) * 3]
    idx = lambda t: 0 if not t > 0 else 255 if t >= 1 else int(t * 255)
    check_mode(drv, "diff", lambda x, y: idx(abs(a(x, y) - b(x, y))), viridis, "|A - B| in viridis")
    select(drv, "ab-mode", "relative")
    check_mode(drv, "relative", lambda x, y: idx(abs(a(x, y) - b(x, y)) / (abs(b(x, y)) + 0.01)),
               viridis, "the relative error in viridis")
    # A - B over the auto range [-m, m], m the largest |A.r - B.r|
    fire(drv, "range", "auto")
    select(drv, "ab-mode", "signed")
    m = max(abs(p - q) for p, q in zip(A[3][0::3], B[3][0::3]))
    sgn = lambda x, y: max(0, min(255, math.floor(128 + (a(x, y) - b(x, y)) / m * 127 + 0.5)))
    check_mode(drv, "signed", sgn, diverging, "A - B in the diverging map")
    lo = wait_for(drv, "the scale bar's ends", lambda d: not d.find_element(By.ID, "scale")
                  .get_attribute("hidden") and text(d, "scale-lo"))
    if lo:
        ends = [float(text(drv, i)) for i in ("scale-lo", "scale-mid", "scale-hi")]
        if abs(ends[0] + m) > 1e-3 * m or ends[1] != 0 or abs(ends[2] - m) > 1e-3 * m:
            fail(f"the A - B scale bar reads {ends}, expected [-{m}, 0, {m}]")
    shot(drv, "signed")
    # the server's FLIP map of A against B, viridis over [0, 1]
    fire(drv, "range", "unit")
    select(drv, "ab-mode", "flip")
    F = floats(drv, "/api/flip?a=img.out&b=g.direct")
    if not F or F[2] != 1 or not 0 <= min(F[3]) <= max(F[3]) <= 1 or max(F[3]) == 0:
        fail(f"/api/flip is not a one-channel map in [0, 1]: {F and F[:3]}")
        return
    check_mode(drv, "flip", lambda x, y: idx(F[3][y * 160 + x]), viridis, "the FLIP map in viridis")
    if [text(drv, i) for i in ("scale-lo", "scale-mid", "scale-hi")] != ["0", "0.5", "1"]:
        fail(f"the FLIP scale bar is not 0 / 0.5 / 1: {text(drv, 'scale')}")
    shot(drv, "flip")
    # a port against itself: no difference (zeros) in every mode
    select(drv, "port-b", "img.out")
    for mode, table, zero in (("flip", viridis, 0), ("diff", viridis, 0), ("signed", diverging, 128),
                              ("relative", viridis, 0)):
        select(drv, "ab-mode", mode)
        check_mode(drv, mode, lambda x, y: zero, table, f"{mode} of img.out with itself")


def step_swap(drv):
    """X swaps A and B, and so does the button."""
    set_ab(drv, "img.out", "g.direct", "split")
    drv.find_element(By.TAG_NAME, "body").send_keys("x")
    wait_for(drv, "X to swap A and B", lambda d: Select(d.find_element(By.ID, "port-a"))
             .first_selected_option.get_attribute("value") == "g.direct"
             and Select(d.find_element(By.ID, "port-b")).first_selected_option
             .get_attribute("value") == "img.out" and text(d, "ab-label-a") == "A g.direct")
    drv.find_element(By.ID, "ab-swap").click()
    wait_for(drv, "the button to swap them back", lambda d: Select(d.find_element(By.ID, "port-a"))
             .first_selected_option.get_attribute("value") == "img.out")
    # zoomed in, the divider still splits the view: A's pixels left of it, B's right
    wheel_at(drv, 80, 45, -600)
    wait_for(drv, "the image zoomed in", lambda d: view_of(d)[0] > 4)
    for fx, port in ((60, "img.out"), (100, "g.direct")):
        mouse_at(drv, fx, 45)
        wait_for(drv, f"{port}'s readout at canvas column {fx} of the zoomed split",
                 lambda d: text(d, "pixel").startswith(f"{port} "))
    drv.find_element(By.TAG_NAME, "body").send_keys("f")


def step_keys_after_controls(drv):
    """Keys reach the page after a list was used with the mouse, and after a press on the
    image took the keyboard from a text box (issue 46's newcomer pass: H after choosing a
    port went to the list's type-ahead and picked port h.depth)."""
    def one_to_one(what):
        ActionChains(drv).send_keys("1").perform()  # to whatever has the keyboard
        wait_for(drv, f"key 1 to zoom 1:1 {what}", lambda d: text(d, "zoom-val") == "100%")
        ActionChains(drv).send_keys("f").perform()
        wait_for(drv, f"key F to fit {what}", lambda d: view_of(d) == (1.0, 0.5, 0.5))
    select(drv, "port-a", "g.direct")
    # as a mouse chooses: a press on the list (it opens), then the choice
    ActionChains(drv).click(drv.find_element(By.ID, "port-a")).perform()
    select(drv, "port-a", "img.out")
    one_to_one("after choosing port A in its list")
    box = drv.find_element(By.ID, "ref-path")
    box.click()
    ActionChains(drv).move_to_element(drv.find_element(By.ID, "view")).click().perform()
    one_to_one("after a press on the image took the keyboard from the path box")
    if box.get_attribute("value"):
        fail(f"keys meant for the page went into the path box: {box.get_attribute('value')!r}")


def step_reference(drv):
    """An EXR of img.out opens as B and the reference: its metrics are 0 and 1, A - B is 0;
    a missing file and a file that is no EXR show their errors."""
    box = drv.find_element(By.ID, "ref-path")
    for bad, why in (("/nonexistent/ref.exr", "No such file"), (OUT + "/notes.txt", "OpenEXR")):
        box.clear()
        box.send_keys(bad, Keys.ENTER)
        # the error bar names the path it is about (the last path's error stays until the
        # answer for this one comes: slow under the sanitizers)
        err = wait_for(drv, f"the error of {bad}", lambda d: d.find_element(
            By.ID, "request-error").is_displayed() and bad in text(d, "request-error")
            and text(d, "request-error"))
        if err and why not in err:
            fail(f"opening {bad} says '{err}', expected '{why}'")
    box.clear()
    box.send_keys(EXR)
    drv.find_element(By.ID, "ref-open").click()
    port = f"file:{EXR}"
    wait_for(drv, "the file as B and the reference", lambda d: all(
        Select(d.find_element(By.ID, i)).first_selected_option.get_attribute("value") == port
        for i in ("port-b", "port-ref")))
    wait_for(drv, "the error cleared", lambda d: not d.find_element(By.ID, "request-error").is_displayed())
    got = wait_for(drv, "B's metrics against the file", lambda d: metric(d, "B", port))
    if got and (got[0] != 0 or abs(got[1] - 1) > 1e-6):
        fail(f"the file against itself: {text(drv, 'metrics')}")
    a = metric(drv, "A", "img.out")
    if not a or a[0] > 1e-6:
        fail(f"img.out against its own EXR: {text(drv, 'metrics')}")
    select(drv, "ab-mode", "signed")
    check_mode(drv, "signed", lambda x, y: 128, diverging, "img.out - its EXR: 0")
    shot(drv, "reference")


def main():
    with open(OUT + "/notes.txt", "w") as f:
        f.write("not an image\n")
    return run_steps((step_load, step_zoom, step_diff, step_swap, step_keys_after_controls,
                      step_reference))


if __name__ == "__main__":
    sys.exit(main())
