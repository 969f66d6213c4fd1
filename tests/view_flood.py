"""view_flood.py - connections that hold `ssgraph view` busy without a token, as a hostile
local program would (tests/test_view_flood.sh): IDLE connections that send nothing and
TRICKLE ones that send a request line, then one header line every second, never ending
their headers (slowloris).

  view_flood.py PORT IDLE TRICKLE SECONDS READY_FILE

Opens them all, writes READY_FILE, keeps trickling for SECONDS, then prints
"idle IDLE closed N trickle TRICKLE closed M": how many of each the server had closed.
"""
import os
import select
import socket
import sys
import time


def closed(sock):
    """1 when the server closed sock (a read gives the end or an error)."""
    try:
        readable, _, _ = select.select([sock], [], [], 0)
        return 1 if readable and not sock.recv(4096) else 0
    except OSError:
        return 1


def main(argv):
    port, n_idle, n_trickle, seconds, ready = (int(argv[1]), int(argv[2]), int(argv[3]),
                                               float(argv[4]), argv[5])
    idle, trickle = [], []
    for i in range(n_idle + n_trickle):
        s = socket.create_connection(("127.0.0.1", port), timeout=5)
        s.setblocking(False)
        (idle if i < n_idle else trickle).append(s)
    for s in trickle:
        s.send(b"GET /api/state HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n" % port)
    with open(ready + ".tmp", "w") as f:
        f.write("ready\n")
    os.rename(ready + ".tmp", ready)
    end, line = time.time() + seconds, 0
    gone = set()
    while time.time() < end:
        time.sleep(1)
        line += 1
        for s in trickle:
            if s in gone:
                continue
            try:
                s.send(b"X-Slow-%d: x\r\n" % line)
            except OSError:
                gone.add(s)
    print("idle %d closed %d trickle %d closed %d" % (
        n_idle, sum(closed(s) for s in idle), n_trickle,
        sum(1 if s in gone else closed(s) for s in trickle)), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
