#!/usr/bin/env python3
"""view_page_latency.py - what a user of `ssgraph view` waits for, measured in the page itself
(issue 31's acceptance: a parameter change shows the new image within 150 ms on 2 cores).
Starts the viewer, opens its page in headless Chromium (Debian's chromium, chromium-driver and
python3-selenium), selects node `do`, then for each value types it into the parameter's number
box and fires `change`; inside the page, one script notes performance.now(), and polls the
canvas every animation frame until its pixels differ: the time from the change to the new
image on screen (request, run, image transfer, decode and draw). Prints the median, minimum and
maximum. Measures; asserts nothing.

  bench/view_page_latency.py [--bin build/ssgraph] [--graph graphs/ssdo_realtime.graph]
                             [--size 640x360] [--node do] [--param radius]
                             [--values 0.3,0.45,...] [--runs 15]
"""
import argparse
import re
import statistics
import subprocess
import sys

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

# Sets the box, fires change, resolves with the ms until the canvas's pixels change.
CHANGE_AND_WAIT = """
const [id, value, done] = arguments;
const c = document.getElementById('view');
const hash = () => {
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let h = 0;
  for (let i = 0; i < d.length; i += 7) h = (Math.imul(h, 31) + d[i]) | 0;
  return h;
};
const before = hash(), box = document.getElementById(id), t0 = performance.now();
box.value = value;
box.dispatchEvent(new Event('change', {bubbles: true}));
const poll = () => {
  if (hash() !== before) done(performance.now() - t0);
  else if (performance.now() - t0 > 10000) done(-1);
  else requestAnimationFrame(poll);
};
requestAnimationFrame(poll);
"""


def browser():
    opts = webdriver.ChromeOptions()
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--window-size=1280,800"):
        opts.add_argument(flag)
    opts.binary_location = "/usr/bin/chromium"
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=opts)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default="build/ssgraph")
    ap.add_argument("--graph", default="graphs/ssdo_realtime.graph")
    ap.add_argument("--size", default="640x360")
    ap.add_argument("--node", default="do")
    ap.add_argument("--param", default="radius")
    ap.add_argument("--values", default="0.3,0.45,0.6,0.75,0.9")
    ap.add_argument("--runs", type=int, default=15)
    args = ap.parse_args()
    server = subprocess.Popen([args.bin, "view", args.graph, "--size", args.size,
                               "--threads", "2"], stdout=subprocess.PIPE, text=True)
    url = re.search(r"http://\S+", server.stdout.readline())
    if not url:
        server.kill()
        sys.exit("the viewer printed no URL")
    drv = browser()
    try:
        drv.get(url.group(0))
        wait = WebDriverWait(drv, 60, poll_frequency=0.1)
        wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, f"#node-table [data-node='{args.node}']"))
        drv.find_element(By.CSS_SELECTOR, f"#node-table [data-node='{args.node}']").click()
        box = f"param-{args.node}-{args.param}"
        wait.until(lambda d: d.find_elements(By.ID, box))
        drv.set_script_timeout(30)
        values = args.values.split(",")
        times = []
        for i in range(args.runs + 1):
            ms = drv.execute_async_script(CHANGE_AND_WAIT, box, values[i % len(values)])
            if i:  # the first change also warms the page's buffers
                times.append(ms)
    finally:
        drv.quit()
        server.terminate()
        server.wait()
    if min(times) < 0:
        sys.exit("a change never reached the canvas")
    print("%s at %s: %s.%s changed in the page -> new image drawn" %
          (args.graph, args.size, args.node, args.param))
    print("median %.0f ms   min %.0f   max %.0f   (%d changes)" %
          (statistics.median(times), min(times), max(times), len(times)))


if __name__ == "__main__":
    main()
