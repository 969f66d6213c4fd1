#!/usr/bin/python3
"""The page of `ssgraph view` in a real headless Chromium (tests/test_view_browser.sh starts
the server). Usage: view_browser.py URL OUTDIR GRAPHFILE [WxH [REFDIR]]. It checks that the
page is ES modules drawing in WebGL2 (none of the old page's globals), compares the canvas at
+1 stop under each tone curve with the CLI's PNGs in REFDIR (when given), clicks the node `do` in the
diagram, moves its radius slider, drags the camera, sets an A/B split with metrics, types a
bad value and breaks the graph file on disk (the errors show at file:line:col and clear), and
saves a variant; screenshots go to OUTDIR/viewer-*.png. Exits 1 with FAIL lines on failures.
The graph is graphs/ssdo_realtime.graph: its node names and ports are used below."""
import base64
import os
import re
import sys
import time

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.actions.wheel_input import ScrollOrigin
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

import view_page
from view_page import (CANVAS_BYTES, CANVAS_HASH, WAIT, canvas_colours,  # noqa: F401
                       canvas_vs_png, fail, generation, metric, outside_viridis,
                       ran_nodes, server_state, set_display, shot, text, wait_for)

URL, OUT, GRAPH = sys.argv[1], sys.argv[2], sys.argv[3]
SIZE = sys.argv[4] if len(sys.argv) > 4 else "160x90"  # the server's --size
# REFDIR/ref_CURVE/{img.out,f.out}.png: `ssgraph run --show img.out,f.out --exposure 1
# --tonemap CURVE` of the graph at SIZE (test_view_browser.sh writes them)
REFS = sys.argv[5] if len(sys.argv) > 5 else None
view_page.OUT = OUT

HOME = {}  # the camera the graph opened with (step_load)


def step_load(drv):
    drv.get(URL)
    wait_for(drv, "the diagram", lambda d: d.find_elements(By.CSS_SELECTOR, "#diagram g.node"))
    wait_for(drv, "the first image", lambda d: d.execute_script(CANVAS_HASH)[0] > 16)
    if text(drv, "hdr-graph") != "ssdo_realtime.graph":
        fail(f"header graph is '{text(drv, 'hdr-graph')}'")
    if text(drv, "hdr-size") != SIZE:
        fail(f"header size is '{text(drv, 'hdr-size')}'")
    if text(drv, "hdr-backend") not in ("cpu", "gl", "cpu + gl"):
        fail(f"header backend is '{text(drv, 'hdr-backend')}': expected what the nodes ran on")
    # the page opens on an output the run made, and marks those it did not (issue 46: the
    # tutorial's graph opened on c.flip, which nothing reads: a black canvas and an error)
    sel = Select(drv.find_element(By.ID, "port-a"))
    labels = [o.text for o in sel.options]
    if "(not computed)" in sel.first_selected_option.text or \
            "g.motion (not computed)" not in labels:
        fail(f"port A opened on '{sel.first_selected_option.text}' of {labels}")
    # the left column fits its width: the edit row's add button pushed it to scroll sideways
    wide = drv.execute_script("const l = document.getElementById('left');"
                              "return [l.scrollWidth, l.clientWidth];")
    if wide[0] > wide[1]:
        fail(f"the left column scrolls sideways: {wide[0]} px of content in {wide[1]}")
    st = server_state(drv)
    if not st or not st.get("camera"):
        fail(f"the state has no camera: {st}")
    else:
        HOME.update(st["camera"])
    shot(drv, "overview")


# Names the page's classic scripts declared at their top level, shared by load order: a page
# of ES modules leaves none of them (nor anything else) in the global scope.
OLD_GLOBALS = ("S", "TOKEN", "$", "api", "errorText", "LatestSender", "applyState", "draw",
               "toPixels", "decodeImage", "VIRIDIS_LUT", "SRGB_LUT", "orbit", "pan", "zoom",
               "paramRow", "sendParam", "sliderScale", "selectNode", "timeState", "sendFrame",
               "state", "render", "setDisplay")


def step_modules(drv):
    """The page is ES modules (each script type=module, served as JavaScript), none of the
    old globals is visible, and the canvas is a WebGL2 canvas."""
    leaked = drv.execute_script(
        "return [" + ", ".join(f"typeof {n}" for n in OLD_GLOBALS) + "];")
    leaked = [n for n, ty in zip(OLD_GLOBALS, leaked) if ty != "undefined"]
    if leaked:
        fail(f"names visible in the page's global scope (scripts sharing globals): {leaked}")
    kinds = drv.execute_script("return [...document.scripts].map((s) => s.type);")
    if not kinds or any(k != "module" for k in kinds):
        fail(f"the page's scripts are {kinds}: expected type=module only")
    mime = drv.execute_async_script("""const done = arguments[0];
        fetch('app.js', {credentials: 'same-origin'}).then((r) => done(r.headers.get('Content-Type')));""")
    if not (mime or "").startswith("text/javascript"):
        fail(f"app.js is served as {mime}: a module script needs text/javascript")
    if not drv.execute_script("return document.getElementById('view').getContext('webgl2') !== null;"):
        fail("the canvas is not a WebGL2 canvas")


def step_tonemap(drv):
    """At +1 stop under each tone curve the canvas holds the bytes of the CLI's PNGs (within
    one code: the shader's pow is not libm's), for a colour port at the frame size and a
    one-channel port at half of it shown grey: the shader's curves are the CLI's."""
    if not REFS:
        print("step_tonemap: no REFDIR given, the CLI's PNGs are not compared")
        return
    for port in ("img.out", "f.out"):
        Select(drv.find_element(By.ID, "port-a")).select_by_value(port)
        for curve in ("clamp", "reinhard", "aces"):
            set_display(drv, 1, curve, "none")
            path = os.path.join(REFS, f"ref_{curve}", f"{port}.png")
            got = wait_for(drv, f"{port} under {curve} at +1 stop as {path}",
                           lambda d: canvas_vs_png(d, path)[0] <= 1)
            if not got:
                fail(f"{port} {curve}: the canvas differs from {path} by "
                     f"{canvas_vs_png(drv, path)} (codes, at x, y, channel)")
    # false colour: every pixel one of the 256 viridis entries (image.js's table)
    set_display(drv, 0, "clamp", "viridis")
    wait_for(drv, "f.out in viridis", lambda d: not outside_viridis(d))
    if outside_viridis(drv):
        fail(f"f.out in false colour has colours outside viridis: {outside_viridis(drv)[:5]}")


def step_click_node(drv):
    target = view_page.diagram_node(drv, "do")
    if not target:
        return
    before = drv.execute_script(CANVAS_HASH)
    # the diagram enlarged, and the node's label clicked, as a user would
    drv.find_element(By.ID, "diagram-expand").click()
    shot(drv, "diagram")
    target.find_element(By.TAG_NAME, "text").click()
    wait_for(drv, "the panel of node do", lambda d: text(d, "node-name") == "do")
    if not drv.find_elements(By.ID, "param-do-radius-slider"):
        fail("node do has no radius slider in its panel")
    # the page shows a change at its next animation frame (render.js)
    wait_for(drv, "clicking do to show do.out", lambda d: Select(
        d.find_element(By.ID, "port-a")).first_selected_option.text == "do.out")
    if "selected" not in (target.get_attribute("class") or ""):
        fail("the clicked node is not marked selected")
    wait_for(drv, "do.out drawn", lambda d: d.execute_script(CANVAS_HASH) != before)


def step_slider(drv):
    """Moves do.radius with the mouse: the image changes, and only do and later nodes ran."""
    before, gen = drv.execute_script(CANVAS_HASH), generation(drv)
    radius = drv.find_element(By.ID, "param-do-radius").get_attribute("value")
    slider = drv.find_element(By.ID, "param-do-radius-slider")
    # grab the thumb where it is (a click elsewhere would jump) and drag it left a little
    thumb = (float(slider.get_attribute("value")) / 1000 - 0.5) * (slider.size["width"] - 16)
    ActionChains(drv).move_to_element_with_offset(slider, int(thumb), 0).click_and_hold() \
        .move_by_offset(-8, 0).pause(0.1).move_by_offset(-8, 0).release().perform()
    wait_for(drv, "a run after the slider", lambda d: generation(d) > gen)
    wait_for(drv, "the radius box to follow the slider",
             lambda d: d.find_element(By.ID, "param-do-radius").get_attribute("value") != radius)
    wait_for(drv, "the canvas to change after the slider",
             lambda d: d.execute_script(CANVAS_HASH) != before)
    wait_for(drv, "the last set to finish", lambda d: not d.find_element(By.ID, "busy").is_displayed())
    ran = ran_nodes(drv)
    if "do" not in ran or ran & {"g", "d", "k", "lit"}:
        fail(f"after do.radius the nodes that ran were {sorted(ran)}: expected do and after only")
    table_ran = {r.get_attribute("data-node") for r in
                 drv.find_elements(By.CSS_SELECTOR, "#node-table tbody tr.ran")}
    if table_ran != ran:
        fail(f"the time table's ran rows {sorted(table_ran)} differ from {sorted(ran)}")
    why = {r.get_attribute("data-node"): r.find_elements(By.TAG_NAME, "td")[2].text
           for r in drv.find_elements(By.CSS_SELECTOR, "#node-table tbody tr")}
    if why.get("do") != "parameter changed" or why.get("g") != "kept":
        fail(f"the time table's why column says {why}: expected do 'parameter changed', "
             "g 'kept'")
    shot(drv, "params")
    # the diagram says the same: a time under each node that ran, `kept` under the others
    drv.find_element(By.ID, "diagram-expand").click()
    labels = {g.find_element(By.TAG_NAME, "title").get_attribute("textContent"):
              g.find_element(By.CSS_SELECTOR, "text.ms").get_attribute("textContent")
              for g in drv.find_elements(By.CSS_SELECTOR, "#diagram g.node")}
    shot(drv, "ran")
    drv.find_element(By.ID, "diagram-close").click()
    kept = {n for n, t in labels.items() if t == "kept"}
    if ran & kept or "g" not in kept:
        fail(f"the diagram's labels {labels} disagree with the nodes that ran {sorted(ran)}")


def step_slider_drag(drv):
    """A 2 s slider drag sends while the hand moves (issue 46: the 60 ms timer was re-armed
    on every input event, so nothing went out until the hand paused). The drag is the input
    events a real one fires, one every 20 ms for 2 s, dispatched in the page (WebDriver's
    own pointer moves are 100-300 ms apart, slow enough for a debounce to fire between
    them); runs must arrive before it ends."""
    wait_for(drv, "no set on its way", lambda d: not d.find_element(By.ID, "busy").is_displayed())
    drv.set_script_timeout(WAIT)
    during = drv.execute_async_script("""
        const done = arguments[arguments.length - 1];
        const s = document.getElementById('param-do-radius-slider');
        const gen = () => +document.getElementById('generation').textContent;
        const g0 = gen(), v0 = +s.value;
        let i = 0;
        const t = setInterval(() => {
          i++;
          s.value = String(v0 - 20 + Math.abs((i % 40) - 20)); // back and forth, 20 steps
          s.dispatchEvent(new Event('input', { bubbles: true }));
          if (i === 100) { clearInterval(t); done(gen() - g0); }
        }, 20);""")
    if during < 2:
        fail(f"a 2 s slider drag ran the graph {during} times before it ended: the slider "
             "must send while it moves")
    wait_for(drv, "the drag's last set to finish",
             lambda d: not d.find_element(By.ID, "busy").is_displayed())
    print(f"slider drag: {during} runs during 2 s of input events", flush=True)


def step_checkbox(drv):
    """A bool parameter's checkbox sends its value (do.bounce off, then on again)."""
    box = drv.find_element(By.ID, "param-do-bounce")
    for want in (False, True):
        gen = generation(drv)
        box.click()
        wait_for(drv, f"a run after do.bounce={want}", lambda d: generation(d) > gen)
        wait_for(drv, "the set to finish", lambda d: not d.find_element(By.ID, "busy").is_displayed())
        if box.is_selected() != want or "do" not in ran_nodes(drv):
            fail(f"do.bounce checkbox: selected {box.is_selected()}, ran {sorted(ran_nodes(drv))}")


def step_camera(drv):
    """Drags on the canvas: orbit, then pan; the image changes and updates/s is shown."""
    before = drv.execute_script(CANVAS_HASH)
    Select(drv.find_element(By.ID, "port-a")).select_by_value("img.out")
    wait_for(drv, "img.out drawn", lambda d: d.execute_script(CANVAS_HASH) != before)
    before = drv.execute_script(CANVAS_HASH)
    canvas = drv.find_element(By.ID, "view")
    chain = ActionChains(drv).move_to_element(canvas).click_and_hold()
    for _ in range(8):
        chain = chain.move_by_offset(6, 2).pause(0.05)
    chain.release().perform()
    wait_for(drv, "updates/s shown", lambda d: "updates/s" in text(d, "cam-ups"))
    wait_for(drv, "the full-size run after the drag",
             lambda d: text(d, "last-run") == "full" and
             not d.find_element(By.ID, "busy").is_displayed())
    wait_for(drv, "the canvas to change after the orbit",
             lambda d: d.execute_script(CANVAS_HASH) != before)
    # a drag ends on the full image: a late preview fetch must not run the preview again and
    # win (issue 46). A hand lets go right after its last move, while that move's preview is
    # on its way: mouse events through the DevTools protocol, milliseconds apart (WebDriver's
    # own are 100-300 ms apart, time enough for every preview to land before the release).
    r = canvas.rect
    x, y = int(r["x"] + r["width"] / 2), int(r["y"] + r["height"] / 2)
    mouse = lambda kind, dx, **kw: drv.execute_cdp_cmd("Input.dispatchMouseEvent", dict(
        type=kind, x=x + dx, y=y, button="left", clickCount=1, **kw))
    mouse("mousePressed", 0)
    for i in range(1, 13):
        mouse("mouseMoved", 3 * i, buttons=1)
        time.sleep(0.016)
    mouse("mouseReleased", 36)
    wait_for(drv, "the full-size run after the quick drag",
             lambda d: text(d, "last-run") == "full" and
             not d.find_element(By.ID, "busy").is_displayed())
    # the page polls every 0.5 s, so 2 s shows any run after the full one
    gen = generation(drv)
    time.sleep(2)
    shown = canvas.get_attribute("data-shown") or ""
    if text(drv, "last-run") != "full" or generation(drv) != gen or \
            not shown.startswith(SIZE + " ") or "preview" in shown:
        fail(f"after the drag the page settled on run {generation(drv)} "
             f"({text(drv, 'last-run')}), showing '{shown}': expected the full {SIZE} image")
    if "g" not in ran_nodes(drv):
        fail(f"a camera move did not re-run the G-buffer: {sorted(ran_nodes(drv))}")
    before = drv.execute_script(CANVAS_HASH)
    ActionChains(drv).move_to_element(canvas).key_down(Keys.SHIFT).click_and_hold() \
        .move_by_offset(-20, 10).pause(0.1).release().key_up(Keys.SHIFT).perform()
    wait_for(drv, "the canvas to change after the pan",
             lambda d: d.execute_script(CANVAS_HASH) != before)
    wait_for(drv, "the full-size run after the pan", lambda d: text(d, "last-run") == "full")
    before = drv.execute_script(CANVAS_HASH)
    # the plain wheel zooms the image (tests/view_zoom.py); "wheel: camera" dollies the camera
    Select(drv.find_element(By.ID, "wheel-mode")).select_by_value("camera")
    ActionChains(drv).scroll_from_origin(ScrollOrigin.from_element(canvas), 0, 300).perform()
    wait_for(drv, "the canvas to change after the wheel zoom",
             lambda d: d.execute_script(CANVAS_HASH) != before)
    wait_for(drv, "the full-size run after the wheel",
             lambda d: text(d, "last-run") == "full" and
             not d.find_element(By.ID, "busy").is_displayed())
    Select(drv.find_element(By.ID, "wheel-mode")).select_by_value("image")
    shot(drv, "camera")
    # home (and key H) go back to the camera the graph opened with (issue 46: an orbit past
    # the box's one-sided walls had no way back but a restart)
    for press in (lambda: drv.find_element(By.ID, "cam-home").click(),
                  lambda: ActionChains(drv).move_to_element(canvas).click()
                  .send_keys("h").perform()):
        ActionChains(drv).move_to_element(canvas).click_and_hold().move_by_offset(25, 0) \
            .release().perform()
        wait_for(drv, "the full-size run after a turn", lambda d: text(d, "last-run") == "full"
                 and not d.find_element(By.ID, "busy").is_displayed())
        press()
        wait_for(drv, "the camera back home", lambda d: all(
            abs(a - b) < 1e-5 for k in ("position", "target")
            for a, b in zip((server_state(d) or {}).get("camera", {}).get(k, [9e9] * 3),
                            HOME[k])))


def step_display(drv):
    """Exposure, channel and false colour redraw the same floats; the pixel under the mouse
    is read out."""
    canvas = drv.find_element(By.ID, "view")
    ActionChains(drv).move_to_element_with_offset(canvas, 10, 5).perform()
    wait_for(drv, "the pixel readout", lambda d: re.search(
        r"img\.out +x,y \d+,\d+: [-0-9.e+]+, [-0-9.e+]+, [-0-9.e+]+$", text(d, "pixel")))
    gen, before = generation(drv), drv.execute_script(CANVAS_HASH)
    drv.find_element(By.ID, "exposure").send_keys(*[Keys.ARROW_RIGHT] * 10)
    wait_for(drv, "the exposure to show 1.0 after +1 stop",
             lambda d: text(d, "exposure-val") == "1.0")
    wait_for(drv, "the canvas to brighten", lambda d: d.execute_script(CANVAS_HASH) != before)
    before = drv.execute_script(CANVAS_HASH)
    Select(drv.find_element(By.ID, "channel")).select_by_value("g")
    wait_for(drv, "the G channel in false colour",
             lambda d: d.execute_script(CANVAS_HASH) != before)
    if generation(drv) != gen:
        fail("a display setting ran the graph")
    Select(drv.find_element(By.ID, "channel")).select_by_value("rgb")
    drv.find_element(By.ID, "fit-btn").click()


def step_range(drv):
    """A one-channel port of values far from [0, 1] (g.depth, 3-5 units) in false colour:
    with range auto it spreads over the scale and the toolbar names its ends; over [0, 1]
    it is one solid colour (issue 46)."""
    Select(drv.find_element(By.ID, "port-a")).select_by_value("g.depth")
    set_display(drv, 0, "clamp", "viridis")
    fire = "const el = document.getElementById('range'); el.value = arguments[0]; " \
           "el.dispatchEvent(new Event('change'));"
    drv.execute_script(fire, "auto")
    ends = wait_for(drv, "the false colour's range in the toolbar", lambda d: re.fullmatch(
        r"([-0-9.e+]+) \.\. ([-0-9.e+]+)", text(d, "range-val")))
    if ends and not 0 < float(ends.group(1)) < float(ends.group(2)):
        fail(f"g.depth's auto range is '{text(drv, 'range-val')}'")
    wait_for(drv, "g.depth spread over viridis", lambda d: len(canvas_colours(d)) >= 16)
    # its statistics and histogram (issue 46): min <= mean <= max, the auto range's ends
    # among them, and a histogram with a spread of bins lit
    st = wait_for(drv, "g.depth's statistics", lambda d: re.fullmatch(
        r"A g\.depth\s+Y ([-0-9.e+]+) / ([-0-9.e+]+) / ([-0-9.e+]+)\s+\(min / mean / max\)",
        text(d, "stats")))
    if st and not float(st.group(1)) <= float(st.group(2)) <= float(st.group(3)):
        fail(f"g.depth's statistics are out of order: {text(drv, 'stats')}")
    # columns with a bar of 3 pixels or more: the background's 0s, below the auto range, must
    # not pile into the first bin and flatten the surfaces' depths to dots
    lit = drv.execute_script("""const c = document.getElementById('hist');
        const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        const height = new Array(c.width).fill(0);
        for (let i = 0; i < d.length; i += 4) if (d[i] > 100) height[(i / 4) % c.width]++;
        return height.filter((h) => h >= 3).length;""")
    if lit < 10:
        fail(f"g.depth's histogram has {lit} of 128 columns with a bar of 3 pixels or more")
    drv.execute_script(fire, "unit")
    wait_for(drv, "g.depth over [0, 1]: one colour on the surfaces",
             lambda d: len(canvas_colours(d)) <= 3 and text(d, "range-val") == "0 .. 1")
    shot(drv, "range")
    drv.execute_script(fire, "auto")
    Select(drv.find_element(By.ID, "port-a")).select_by_value("img.out")


def step_ab(drv):
    """A = img.out, B = g.direct against the reference g.direct: B is exact, A's error
    changes when the radius changes."""
    drv.find_element(By.ID, "ab-enable").click()
    Select(drv.find_element(By.ID, "port-a")).select_by_value("img.out")
    Select(drv.find_element(By.ID, "port-b")).select_by_value("g.direct")
    Select(drv.find_element(By.ID, "port-ref")).select_by_value("g.direct")
    wait_for(drv, "metrics against g.direct",
             lambda d: "against g.direct" in text(d, "metrics") and metric(d, "A", "img.out"))
    b = metric(drv, "B", "g.direct")
    if not b or b[0] != 0 or abs(b[1] - 1) > 1e-6:
        fail(f"B == reference but its metrics are {b}: {text(drv, 'metrics')}")
    a = metric(drv, "A", "img.out")
    box = drv.find_element(By.ID, "param-do-radius")
    box.clear()
    box.send_keys("0.05", Keys.ENTER)
    wait_for(drv, "A's metrics to update after a run",
             lambda d: metric(d, "A", "img.out") not in (None, a))
    shot(drv, "ab")
    # the difference of a port with itself is black; with another, not
    Select(drv.find_element(By.ID, "ab-mode")).select_by_value("diff")
    wait_for(drv, "|img.out - g.direct| drawn", lambda d: any(
        base64.b64decode(d.execute_script(CANVAS_BYTES)[2])[0::4]))
    Select(drv.find_element(By.ID, "port-b")).select_by_value("img.out")
    wait_for(drv, "|img.out - img.out| black", lambda d: not any(
        v for i, v in enumerate(base64.b64decode(d.execute_script(CANVAS_BYTES)[2])) if i % 4 != 3))
    Select(drv.find_element(By.ID, "ab-mode")).select_by_value("split")
    # the numbers go with the A/B view (issue 46: an old metric stayed on screen)
    drv.find_element(By.ID, "ab-enable").click()
    wait_for(drv, "the metrics cleared with A/B off", lambda d: text(d, "metrics") == "metrics: -")


def step_errors(drv):
    """A bad value shows the server's file:line:col message; the file watcher's reload
    error shows and clears when the file is good again."""
    box = drv.find_element(By.ID, "param-do-radius")
    kept = box.get_attribute("value")
    box.clear()
    box.send_keys("-1", Keys.ENTER)
    err = wait_for(drv, "the error of a bad value",
                   lambda d: d.find_element(By.ID, "request-error").is_displayed()
                   and text(d, "request-error"))
    if err and not re.search(r":\d+:\d+: error", err):
        fail(f"the bad value's error is not file:line:col: {err}")
    # the refused value stays for correcting, marked, and leaves with the focus: the box then
    # shows what the graph kept (issue 46: the refused value stayed on screen)
    wait_for(drv, "the refused box marked", lambda d: "refused" in (
        d.find_element(By.ID, "param-do-radius").get_attribute("class") or ""))
    drv.find_element(By.ID, "node-name").click()
    wait_for(drv, f"the radius box back at the kept {kept}",
             lambda d: d.find_element(By.ID, "param-do-radius").get_attribute("value") == kept
             and "refused" not in (d.find_element(By.ID, "param-do-radius")
                                   .get_attribute("class") or ""))
    box = drv.find_element(By.ID, "param-do-radius")
    box.clear()
    box.send_keys("0.3", Keys.ENTER)
    wait_for(drv, "the error to clear after a good value",
             lambda d: not d.find_element(By.ID, "request-error").is_displayed())
    with open(GRAPH) as f:
        good = f.read()
    with open(GRAPH, "a") as f:
        f.write("\nbroken = nosuchnode(\n")
    err = wait_for(drv, "the reload error", lambda d: d.find_element(By.ID, "state-error")
                   .is_displayed() and text(d, "state-error"))
    if err and not re.search(r":\d+:\d+:", err):
        fail(f"the reload error is not file:line:col: {err}")
    shot(drv, "error")
    with open(GRAPH, "w") as f:
        f.write(good)
    wait_for(drv, "the reload error to clear",
             lambda d: not d.find_element(By.ID, "state-error").is_displayed())


def step_save(drv):
    name = f"viewtest_{os.getpid()}"
    drv.find_element(By.ID, "save-name").send_keys(name)
    drv.find_element(By.ID, "save-btn").click()
    res = wait_for(drv, "the save result", lambda d: text(d, "save-result"))
    path = os.path.join(os.path.dirname(GRAPH), name + ".graph")
    if not res or not res.startswith("wrote ") or not os.path.exists(path):
        fail(f"save said '{res}', {path} exists: {os.path.exists(path)}")
        return
    with open(path) as f:
        saved = f.read()
    if "include" not in saved or "do.radius" not in saved:
        fail(f"the variant lacks the include or the radius: {saved}")
    drv.find_element(By.ID, "save-btn").click()  # the same name again: 409
    wait_for(drv, "the second save's error", lambda d: text(d, "save-result").startswith("error"))


def main():
    return view_page.run_steps((step_load, step_modules, step_tonemap, step_click_node,
                                step_slider, step_slider_drag, step_checkbox, step_camera,
                                step_display, step_range, step_ab, step_errors, step_save))


if __name__ == "__main__":
    sys.exit(main())
