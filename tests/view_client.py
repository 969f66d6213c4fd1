"""view_client.py - the HTTP side of `ssgraph view` from outside, for tests/test_view_http.sh:
small commands over urllib (no third-party module), each printing what the shell test checks.

  view_client.py BASE TOKEN state [KEY]            -> the state JSON, pretty (KEY: that field)
  view_client.py BASE TOKEN ran                    -> the names of the nodes that ran, sorted
  view_client.py BASE TOKEN images                 -> "NODE.PORT true|false" a line: whether
                                                      the last run made the output's image
  view_client.py BASE TOKEN param NODE PARAM       -> its current value
  view_client.py BASE TOKEN dump PORT OUT.pfm [preview] -> writes the port's image as a PFM
                                                         (oiiotool reads it)
  view_client.py BASE TOKEN size PORT [preview]    -> "W H C"
  view_client.py BASE TOKEN wait_gen GEN SECONDS   -> waits until generation > GEN; prints it
"""
import json
import struct
import sys
import time
import urllib.error
import urllib.request


def get(base, token, path):
    req = urllib.request.Request(base + path, headers={"X-SSG-Token": token})
    with urllib.request.urlopen(req, timeout=120) as r:
        return r.status, r.read()


def state(base, token):
    return json.loads(get(base, token, "/api/state")[1])


def image(base, token, port, preview):
    _, data = get(base, token, "/api/image?port=%s&preview=%s" % (port, preview))
    if data[:4] != b"SSGI":
        raise SystemExit("no SSGI magic")
    w, h, c, _ = struct.unpack("<4I", data[4:20])
    if len(data) != 20 + 4 * w * h * c:
        raise SystemExit("%d bytes for %dx%dx%d" % (len(data), w, h, c))
    return w, h, c, data[20:]


def write_pfm(path, w, h, c, pixels):
    """The image as a little-endian PFM (rows bottom to top), which oiiotool reads."""
    if c not in (1, 3):
        raise SystemExit("PFM holds 1 or 3 channels, not %d" % c)
    row = 4 * w * c
    rows = [pixels[i * row:(i + 1) * row] for i in range(h)]
    with open(path, "wb") as f:
        f.write(b"%s\n%d %d\n-1.0\n" % (b"PF" if c == 3 else b"Pf", w, h))
        f.write(b"".join(reversed(rows)))


def main(argv):
    base, token, cmd = argv[1], argv[2], argv[3]
    if cmd == "state" and len(argv) > 4:
        print(state(base, token)[argv[4]])
    elif cmd == "state":
        print(json.dumps(state(base, token), indent=1))
    elif cmd == "images":
        for n in state(base, token)["nodes"]:
            for o in n["outputs"]:
                print("%s.%s %s" % (n["name"], o["port"], "true" if o["image"] else "false"))
    elif cmd == "ran":
        print(" ".join(sorted(n["name"] for n in state(base, token)["nodes"] if n["ran"])))
    elif cmd == "param":
        node = next(n for n in state(base, token)["nodes"] if n["name"] == argv[4])
        print(next(p["value"] for p in node["params"] if p["name"] == argv[5]))
    elif cmd == "size":
        w, h, c, _ = image(base, token, argv[4], argv[5] if len(argv) > 5 else "0")
        print(w, h, c)
    elif cmd == "dump":
        write_pfm(argv[5], *image(base, token, argv[4], argv[6] if len(argv) > 6 else "0"))
    elif cmd == "wait_gen":
        gen, deadline = int(argv[4]), time.time() + float(argv[5])
        while time.time() < deadline:
            g = state(base, token)["generation"]
            if g > gen:
                print(g)
                return 0
            time.sleep(0.2)
        print("timeout")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
