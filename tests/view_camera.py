#!/usr/bin/python3
"""The camera panel, keyboard fly, camera path recording and undo/redo of `ssgraph view`'s
page in a real headless Chromium (tests/test_view_camera.sh starts the server on a copy of
graphs/ssdo_realtime.graph). Usage: view_camera.py URL OUTDIR. It types a camera into the
panel (the server's camera follows) and a bad one (refused in the page, the server's camera
unchanged), holds W (the eye and the target move along the view direction), changes do.radius
twice (a typed value, then a slider drag: one step each) and checks the server's values after
undo, undo and redo, and records 3 keys and saves them as OUTDIR/../graph/flight.scene (the
shell test runs it); saving again under that name is refused in the page; flying with
*record while flying* ticked adds keys a period apart. Prints
`saved: PATH` and exits 1 with FAIL lines on failures."""
import math
import sys
import time

from selenium.common.exceptions import WebDriverException
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

import view_page
from view_page import (CANVAS_HASH, browser, fail, failures, js_errors, localhost_note,
                       server_state, shot, start_chromium, text, wait_for)

URL, OUT = sys.argv[1], sys.argv[2]
view_page.OUT = OUT


def close(a, b, eps=1e-3):
    return all(abs(x - y) <= eps * max(1.0, abs(y)) for x, y in zip(a, b))


def idle(drv):
    wait_for(drv, "no request on its way",
             lambda d: not d.find_element(By.ID, "busy").is_displayed())


def camera(drv):
    st = server_state(drv)
    return st and st.get("camera")


def type_into(drv, elem_id, value):
    box = drv.find_element(By.ID, elem_id)
    box.click()
    box.send_keys(Keys.CONTROL, "a")
    box.send_keys(value, Keys.ENTER)


def blur(drv):
    drv.execute_script("document.activeElement && document.activeElement.blur()")


def step_load(drv):
    drv.get(URL)
    wait_for(drv, "the first image", lambda d: d.execute_script(CANVAS_HASH)[0] > 16)
    wait_for(drv, "the camera panel filled",
             lambda d: d.find_element(By.ID, "cam-position").get_attribute("value"))


def step_numeric(drv):
    """A typed position moves the server's camera (a full run); the canvas changes."""
    cam, before = camera(drv), drv.execute_script(CANVAS_HASH)
    want = [cam["position"][0] + 0.3, cam["position"][1], cam["position"][2] - 0.2]
    type_into(drv, "cam-position", ", ".join(f"{x:.4f}" for x in want))
    wait_for(drv, f"the server's camera at {want}", lambda d: (c := camera(d)) and
             close(c["position"], want) and close(c["target"], cam["target"]))
    if server_state(drv)["last_run"] != "full":
        fail("a typed camera ran the preview graph: expected a full run")
    wait_for(drv, "the canvas to change", lambda d: d.execute_script(CANVAS_HASH) != before)
    shot(drv, "camera-numeric")


def step_refused(drv):
    """Text that is not a camera is refused in the page, with the reason; nothing is sent."""
    idle(drv)
    cam, gen = camera(drv), server_state(drv)["generation"]
    for box, bad, why in (("cam-position", "1, two, 3", "three numbers"),
                          ("cam-fov", "wide", "number of degrees"),
                          ("cam-target", ", ".join(map(str, cam["position"])), "same point")):
        type_into(drv, box, bad)
        msg = text(drv, "cam-msg")
        if why not in msg or "refused" not in msg:
            fail(f"{box}='{bad}': the message is '{msg}', expected one saying '{why}'")
        if "refused" not in (drv.find_element(By.ID, box).get_attribute("class") or ""):
            fail(f"{box}='{bad}' is not marked refused")
        blur(drv)
    time.sleep(0.3)
    st = server_state(drv)
    if st["generation"] != gen or not close(st["camera"]["position"], cam["position"]):
        fail(f"a refused camera reached the server: generation {gen} -> {st['generation']}")
    wait_for(drv, "the boxes back at the camera", lambda d: "two" not in
             d.find_element(By.ID, "cam-position").get_attribute("value"))


def step_fly(drv):
    """Holding W moves the eye and the target together along the view direction; the
    release ends on a full run."""
    idle(drv)
    blur(drv)
    cam = camera(drv)
    dir0 = [t - p for t, p in zip(cam["target"], cam["position"])]
    n = math.sqrt(sum(x * x for x in dir0))
    # held until the page has counted its previews (at least 0.6 s): on a loaded machine
    # a fixed 0.6 s could end before the second preview came back
    ActionChains(drv).key_down("w").pause(0.6).perform()
    wait_for(drv, "the fly's previews to be counted", lambda d: "updates/s" in
             text(d, "cam-ups"))
    ActionChains(drv).key_up("w").perform()
    wait_for(drv, "the fly to end on a full run", lambda d: (st := server_state(d)) and
             st["last_run"] == "full" and not close(st["camera"]["position"], cam["position"]))
    after = camera(drv)
    move = [a - b for a, b in zip(after["position"], cam["position"])]
    moved = math.sqrt(sum(x * x for x in move))
    along = sum(m * d for m, d in zip(move, dir0)) / (n * moved) if moved else 0
    tmove = [a - b for a, b in zip(after["target"], cam["target"])]
    print(f"fly: W held moved {moved:.3f} units, cos to the view {along:.4f}", flush=True)
    if along < 0.999:
        fail(f"W moved the eye by {move}, not along the view direction {dir0}")
    if not close(tmove, move, 1e-3):
        fail(f"the target moved by {tmove}, the eye by {move}: expected together")
    if "updates/s" not in text(drv, "cam-ups"):
        fail(f"the fly's previews are not counted: '{text(drv, 'cam-ups')}'")


def radius(drv):
    node = next(n for n in server_state(drv)["nodes"] if n["name"] == "do")
    return float(next(p for p in node["params"] if p["name"] == "radius")["value"])


def wait_radius(drv, want, what):
    wait_for(drv, f"do.radius {want} after {what}", lambda d: abs(radius(d) - want) < 1e-6)
    wait_for(drv, f"the panel showing do.radius {want} after {what}", lambda d: abs(float(
        d.find_element(By.ID, "param-do-radius").get_attribute("value")) - want) < 1e-6)


def step_undo(drv):
    """A typed value and a slider drag are a step each; undo, undo, redo give the values."""
    idle(drv)
    drv.find_element(By.CSS_SELECTOR, "#node-table tr[data-node='do']").click()
    wait_for(drv, "the panel of node do", lambda d: text(d, "node-name") == "do")
    r0 = radius(drv)
    type_into(drv, "param-do-radius", "0.7")
    wait_radius(drv, 0.7, "typing 0.7")
    idle(drv)
    slider = drv.find_element(By.ID, "param-do-radius-slider")
    ActionChains(drv).click_and_hold(slider).move_by_offset(-30, 0).pause(0.2) \
        .move_by_offset(-30, 0).release().perform()
    idle(drv)
    r2 = float(drv.find_element(By.ID, "param-do-radius").get_attribute("value"))
    wait_radius(drv, r2, "the slider drag")
    if abs(r2 - 0.7) < 1e-6:
        fail("the slider drag left do.radius at 0.7")
    if text(drv, "history-count") != "2 / 2":
        fail(f"history after a typed value and a drag: {text(drv, 'history-count')}, want 2 / 2")
    drv.find_element(By.ID, "undo-btn").click()
    wait_radius(drv, 0.7, "undo (the drag's start, not a value on its way)")
    idle(drv)
    blur(drv)
    ActionChains(drv).key_down(Keys.CONTROL).send_keys("z").key_up(Keys.CONTROL).perform()
    wait_radius(drv, r0, "Ctrl+Z")
    idle(drv)
    ActionChains(drv).key_down(Keys.CONTROL).key_down(Keys.SHIFT).send_keys("z") \
        .key_up(Keys.SHIFT).key_up(Keys.CONTROL).perform()
    wait_radius(drv, 0.7, "Ctrl+Shift+Z")
    if text(drv, "history-count") != "1 / 2":
        fail(f"history after undo, undo, redo: {text(drv, 'history-count')}, want 1 / 2")
    print(f"undo: radius {r0} -> 0.7 -> {r2}; undo, undo, redo -> 0.7", flush=True)


def step_path(drv):
    """Three keys at three typed cameras, their times edited, saved as flight.scene."""
    idle(drv)
    cam = camera(drv)
    for i in range(3):
        pos = [cam["position"][0] + 0.15 * i, cam["position"][1] + 0.05 * i, cam["position"][2]]
        type_into(drv, "cam-position", ", ".join(f"{x:.4f}" for x in pos))
        wait_for(drv, f"key {i}'s camera", lambda d, pos=pos: (c := camera(d)) and
                 close(c["position"], pos))
        idle(drv)
        drv.find_element(By.ID, "path-record").click()
    times = drv.find_elements(By.CSS_SELECTOR, "#path-keys input.key-time")
    if [t.get_attribute("value") for t in times] != ["0", "1", "2"]:
        fail(f"the keys' times are {[t.get_attribute('value') for t in times]}: want 0, 1, 2")
    for box, t in zip(times, ("0", "0.05", "0.1")):  # 30 fps: frames 1 and 2 between keys
        box.send_keys(Keys.CONTROL, "a")
        box.send_keys(t, Keys.TAB)
    type_into(drv, "path-name", "flight")  # Enter saves
    res = wait_for(drv, "the path saved", lambda d: text(d, "path-result") or None) or ""
    if not res.startswith("wrote ") or not res.endswith("flight.scene"):
        fail(f"save path answered '{res}'")
    else:
        print(f"saved: {res[6:]}", flush=True)
    shot(drv, "camera-path")
    drv.find_element(By.ID, "path-save").click()
    wait_for(drv, "saving over flight.scene refused", lambda d: "exists already" in
             text(d, "path-result") and "err" in
             (d.find_element(By.ID, "path-result").get_attribute("class") or ""))


def step_auto(drv):
    """Record while flying: holding W with a 0.1 s period adds keys 0.1 s apart."""
    idle(drv)
    drv.find_element(By.ID, "path-clear").click()
    type_into(drv, "path-period", "0.1")
    drv.find_element(By.ID, "path-auto").click()
    blur(drv)
    ActionChains(drv).key_down("w").pause(0.8).key_up("w").perform()
    drv.find_element(By.ID, "path-auto").click()
    times = [float(t.get_attribute("value")) for t in
             drv.find_elements(By.CSS_SELECTOR, "#path-keys input.key-time")]
    print(f"record while flying: keys at {times}", flush=True)
    if len(times) < 2 or any(abs(b - a - 0.1) > 1e-6 for a, b in zip(times, times[1:])) \
            or times[0] != 0:
        fail(f"0.8 s of flying with a key every 0.1 s recorded keys at {times}")


def main():
    """Chromium and its driver, then each step until the first that fails (a screenshot of
    the page then), then the console's errors; 0, or 1 with FAIL lines."""
    chromium = drv = None
    try:
        chromium, port = start_chromium()
        drv = browser(port)
        steps = [step_load, step_numeric, step_refused, step_fly, step_undo, step_path,
                 step_auto]
        while steps and not failures:
            began, step = time.time(), steps.pop(0)
            step(drv)
            print(f"{step.__name__}: {time.time() - began:.1f} s", flush=True)
        if failures:
            shot(drv, "failure")
        js_errors(drv)
    except WebDriverException as e:
        fail(f"chromedriver (/usr/bin/chromedriver, at 127.0.0.1) could not drive headless "
             f"chromium (/usr/bin/chromium): {e.msg}{localhost_note()}")
    finally:
        if drv:
            drv.quit()
        if chromium:
            chromium.kill()
            chromium.wait()
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
