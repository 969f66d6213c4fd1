#!/usr/bin/python3
"""The viewer's number sliders span each parameter's useful range (soft_min .. soft_max,
core/lang/params.h), in a real headless Chromium (tests/test_view_sliders.sh starts the
server on graphs/ssdo_realtime.graph). Usage: view_sliders.py URL OUTDIR. For node do's
radius (valid 1e-6 .. 1e6, useful 0.05 .. 5 scene units):
  - /api/state gives soft_min 0.05 and soft_max 5;
  - the slider's far left sets 0.05 and its far right 5 (before, a logarithmic slider over
    the 4 decades around the value: 0.005 .. 50);
  - a 30 px drag of the thumb from 0.5 moves the value by less than a factor 4 either way
    (the slider is about 140 px wide: 30 px are a quarter of its two decades, a factor 3;
    before, a quarter of four decades, 0.5 to 4.6);
  - 20 typed into the box (valid, above the useful range) is kept by the server and the
    box, the slider's thumb goes to its far right, and a drag from there still works,
    moving below 20 over the widened span 0.05 .. 20.
Screenshots: OUTDIR/viewer-sliders*.png. Exits 1 with FAIL lines on failures."""
import sys
import time

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By

import view_page
from view_page import CANVAS_HASH, fail, generation, server_state, shot, text, wait_for

URL, OUT = sys.argv[1], sys.argv[2]
view_page.OUT = OUT
BOX, SLIDER = "param-do-radius", "param-do-radius-slider"


def box_value(drv):
    return drv.find_element(By.ID, BOX).get_attribute("value")


def radius_state(drv):
    """do.radius as the server has it: its descriptor in /api/state."""
    st = server_state(drv) or {}
    for n in st.get("nodes", []):
        if n["name"] == "do":
            return next((p for p in n["params"] if p["name"] == "radius"), None)
    return None


def settle(drv, gen):
    """Waits for the run after generation gen, and for no set to be on its way."""
    wait_for(drv, "a run after the change", lambda d: generation(d) > gen)
    time.sleep(0.3)  # a debounced slider send still to go out
    last = -1
    while generation(drv) != last:
        last = generation(drv)
        time.sleep(0.5)


def slide_to(drv, value):
    """Sets the slider's position (0 .. 1000) as a user's input event would."""
    gen = generation(drv)
    drv.execute_script("""const s = document.getElementById(arguments[0]);
        s.value = arguments[1]; s.dispatchEvent(new Event('input'));""", SLIDER, str(value))
    settle(drv, gen)


def type_value(drv, value):
    gen = generation(drv)
    drv.execute_script("""const b = document.getElementById(arguments[0]);
        b.value = arguments[1]; b.dispatchEvent(new Event('change'));""", BOX, value)
    settle(drv, gen)


def drag(drv, dx):
    """Grabs the thumb where it is and drags it dx px; returns the box's value after."""
    slider = drv.find_element(By.ID, SLIDER)
    thumb = (float(slider.get_attribute("value")) / 1000 - 0.5) * (slider.size["width"] - 16)
    gen = generation(drv)
    ActionChains(drv).move_to_element_with_offset(slider, int(thumb), 0).click_and_hold() \
        .move_by_offset(dx // 3, 0).move_by_offset(dx - dx // 3, 0).release().perform()
    settle(drv, gen)
    return float(box_value(drv))


def step_select(drv):
    drv.get(URL)
    wait_for(drv, "the diagram", lambda d: d.find_elements(By.CSS_SELECTOR, "#diagram g.node"))
    wait_for(drv, "the first image", lambda d: d.execute_script(CANVAS_HASH)[0] > 16)
    target = view_page.diagram_node(drv, "do")
    if not target:
        return
    drv.find_element(By.ID, "diagram-expand").click()
    target.find_element(By.TAG_NAME, "text").click()
    wait_for(drv, "the panel of node do", lambda d: text(d, "node-name") == "do")
    wait_for(drv, "do's radius slider", lambda d: d.find_elements(By.ID, SLIDER))


def step_state(drv):
    p = radius_state(drv)
    if not p or p.get("soft_min") != 0.05 or p.get("soft_max") != 5:
        fail(f"/api/state's do.radius has no useful range 0.05 .. 5: {p}")


def step_ends(drv):
    """The slider's two ends are the useful range's."""
    for pos, want in ((0, "0.05"), (1000, "5")):
        slide_to(drv, pos)
        if box_value(drv) != want:
            fail(f"the radius slider at {pos} sets {box_value(drv)}: expected {want}")
    shot(drv, "sliders-end")


def step_drag(drv):
    """A 30 px drag from 0.5 changes the radius by a small factor, both ways."""
    for dx in (30, -30):
        type_value(drv, "0.5")
        got = drag(drv, dx)
        ok = 0.5 < got < 2 if dx > 0 else 0.125 < got < 0.5
        print(f"a {dx:+d} px drag from 0.5 set {got}", flush=True)
        if not ok:
            fail(f"a {dx:+d} px drag of the radius slider from 0.5 set {got}: expected a "
                 "change by less than a factor 4")


def step_outside(drv):
    """A valid value above the useful range is kept, and the slider still moves from it."""
    type_value(drv, "20")
    p = radius_state(drv)
    if box_value(drv) != "20" or not p or p["value"] != "20":
        fail(f"20 typed into the radius box became box {box_value(drv)}, graph "
             f"{p and p['value']}: expected 20 kept")
    pos = drv.find_element(By.ID, SLIDER).get_attribute("value")
    if pos != "1000":
        fail(f"with 20 in the box the radius slider's thumb is at {pos}: expected the far "
             "right of a span widened to 20")
    got = drag(drv, -30)
    shot(drv, "sliders-outside")
    # over the span widened to 0.05 .. 20 (2.6 decades) 30 px are a factor 4; a thumb
    # clamped to 0.05 .. 5 would have moved from 5 to 1.6
    if not 20 / 6 < got < 20:
        fail(f"a -30 px drag from 20 set {got}: expected a value below 20 by less than a "
             "factor 6 (the span widened to 20, not clamped to 0.05 .. 5)")
    p = radius_state(drv)
    if not p or abs(float(p["value"]) - got) > 1e-4 * got:
        fail(f"after the drag the graph's radius is {p and p['value']}, the box's {got}")


def main():
    return view_page.run_steps((step_select, step_state, step_ends, step_drag, step_outside),
                               "sliders-failure")


if __name__ == "__main__":
    sys.exit(main())
