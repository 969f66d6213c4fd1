#!/usr/bin/python3
"""The graph editor of `ssgraph view`'s page in headless Chromium (tests/test_view_edit.sh
starts the server on a copy of graphs/ssdo_realtime.graph with a compare `c` appended).
Usage: view_edit.py URL OUTDIR GRAPHFILE BIN. In the page's "Edit graph" section it adds a
bilateral `b2` reading u.out (its inputs chosen in the add form), rewires img.modulation to
b2.out in the selected node's inputs, tries to remove u (refused: the error shows u's
readers at file:line:column) and removes c, then saves as NAME and checks that
`ssgraph check` and `ssgraph dot` of the saved file give the page's /api/state nodes and
connections (view_edit_check.py). Screenshots: OUTDIR/viewer-edit-*.png."""
import os
import re
import sys
import time

from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select

import view_edit_check
import view_page
from view_page import fail, server_state, shot, text, wait_for

URL, OUT, GRAPH, BIN = sys.argv[1:5]
view_page.OUT = OUT


def node(st, name):
    return next((n for n in st["nodes"] if n["name"] == name), None) if st else None


def input_from(st, name, port):
    n = node(st, name)
    return next((i["from"] for i in n["inputs"] if i["port"] == port), None) if n else None


def state_where(drv, what, cond):
    """The server's state once cond(state) holds (None after a failure named what)."""
    return wait_for(drv, what, lambda d: (lambda st: st if st and cond(st) else None)(
        server_state(d)))


def diagram_nodes(drv):
    """The node names of the diagram, read in one go (it is replaced as it loads)."""
    return drv.execute_script("""return [...document.querySelectorAll('#diagram g.node')]
        .map((g) => (g.querySelector('title') || {}).textContent);""")


def pick(drv, name):
    """Selects node `name` (its row of the last run's table)."""
    # clicked in the page: the table is drawn anew with each state, a found row may be gone
    drv.execute_script("document.querySelector(`#node-table tr[data-node='${arguments[0]}']`)"
                       ".click();", name)
    wait_for(drv, f"node {name} selected", lambda d: text(d, "node-name") == name)


def step_load(drv):
    drv.get(URL)
    wait_for(drv, "the diagram", lambda d: d.find_elements(By.CSS_SELECTOR, "#diagram g.node"))
    wait_for(drv, "the node types", lambda d: len(
        Select(d.find_element(By.ID, "edit-type")).options) > 10)


def step_add(drv):
    Select(drv.find_element(By.ID, "edit-type")).select_by_value("bilateral")
    form = wait_for(drv, "bilateral's inputs in the add form", lambda d: {
        s.get_attribute("data-port"): s for s in
        d.find_elements(By.CSS_SELECTOR, "#edit-add-inputs select")} or None)
    if not form:
        return
    # only outputs of a type the input takes are offered: no kernel for an image input
    offered = [o.get_attribute("value") for o in Select(form["in"]).options]
    if "k.samples" in offered or "u.out" not in offered:
        fail(f"bilateral.in offers {offered}")
    for port, value in (("in", "u.out"), ("depth", "g.depth"), ("normal", "g.normal")):
        Select(form[port]).select_by_value(value)
    drv.find_element(By.ID, "edit-name").send_keys("b2")
    drv.find_element(By.ID, "edit-add").click()
    state_where(drv, "b2 in the state", lambda st: input_from(st, "b2", "in") == "u.out")
    wait_for(drv, "b2 in the diagram", lambda d: "b2" in diagram_nodes(d))
    if not text(drv, "edit-result").startswith("added b2"):
        fail(f"the add said '{text(drv, 'edit-result')}'")


def step_rewire(drv):
    pick(drv, "img")
    sel = wait_for(drv, "img's input rows", lambda d: d.find_elements(
        By.CSS_SELECTOR, "#edit-inputs select[data-port='modulation']"))
    if not sel:
        return
    Select(sel[0]).select_by_value("b2.out")
    state_where(drv, "img.modulation read from b2.out",
                lambda st: input_from(st, "img", "modulation") == "b2.out")
    shot(drv, "edit-rewired")


def step_remove(drv):
    pick(drv, "u")
    drv.find_element(By.ID, "edit-remove").click()  # b2 and img read it: refused
    res = wait_for(drv, "the refusal", lambda d: text(d, "edit-result").startswith("refused")
                   and text(d, "edit-result"))
    where = re.escape(GRAPH)
    if not res or not re.search(f"{where}:[0-9]+:[0-9]+: error: cannot remove node 'u'", res):
        fail(f"removing u said '{res}'")
    if not node(server_state(drv), "u"):
        fail("the refused remove removed u")
    pick(drv, "c")
    drv.find_element(By.ID, "edit-remove").click()
    state_where(drv, "c removed", lambda st: not node(st, "c"))
    wait_for(drv, "the edit count", lambda d: "unsaved" in text(d, "edit-state"))
    # the port shown was c's: the page moves to another and asks for none of c's
    wait_for(drv, "port A off c", lambda d: not Select(
        d.find_element(By.ID, "port-a")).first_selected_option.text.startswith("c."))
    time.sleep(1)  # a late fetch of c's port would show its error by now
    if text(drv, "request-error"):
        fail(f"after removing c the page says '{text(drv, 'request-error')}'")


def step_save(drv):
    name = f"edittest_{os.getpid()}"
    drv.find_element(By.ID, "edit-save-name").send_keys(name)
    drv.find_element(By.ID, "edit-save").click()
    res = wait_for(drv, "the save result", lambda d: text(d, "edit-result").startswith(
        ("wrote", "error")) and text(d, "edit-result"))
    path = os.path.join(os.path.dirname(GRAPH), name + ".graph")
    if not res or not res.startswith("wrote") or not os.path.exists(path):
        fail(f"save said '{res}'; {path} exists: {os.path.exists(path)}")
        return
    shot(drv, "edit-saved")
    for problem in view_edit_check.problems(BIN, path, server_state(drv)):
        fail(f"the saved file is not the page's graph: {problem}")


if __name__ == "__main__":
    sys.exit(view_page.run_steps((step_load, step_add, step_rewire, step_remove, step_save),
                                 "edit-failure"))
