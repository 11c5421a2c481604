#!/usr/bin/python3
"""Benchmark: the plant's speed and memory while its control plane is attacked (issue 25).

Runs `vplant run SCENARIO --ui --ui-run --ui-speed 0 --duration D` (virtual time, as fast as it
goes) and measures simulated seconds per wall second until the clock pauses at D, once quietly and
once while up to 500 silent connections are held open and two threads send abusive requests
(endless headers, a foreign Host, noise, an oversized chunked body, a 2,000-part Range) as fast as
they are answered. Prints both speeds and the process's resident memory at the end.

usage: tools/bench/http_attack_bench.py VPLANT SCENARIO [DURATION_S]   (default 3000)
"""
import http.client
import json
import random
import socket
import subprocess
import sys
import threading
import time


def measure(vplant, scen, attack, dur):
    with socket.socket() as s:  # a free port
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    p = subprocess.Popen([vplant, "run", scen, "--ui", f"127.0.0.1:{port}", "--ui-run", "--ui-speed", "0", "--duration", dur, "--quiet"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    def clock():
        c = http.client.HTTPConnection("127.0.0.1", port, timeout=2)
        c.request("GET", "/api/clock", headers={"Host": f"127.0.0.1:{port}"})
        r = json.loads(c.getresponse().read())
        c.close()
        return r
    for _ in range(100):
        try:
            clock()
            break
        except OSError:
            time.sleep(0.05)
    stop = False
    socks = []
    sent = [0]
    def attacker(seed):
        rng = random.Random(seed)
        while not stop:
            try:
                c = socket.create_connection(("127.0.0.1", port), timeout=1)
                junk = rng.choice([b"GET /api/nodes HTTP/1.1\r\nHost: 127.0.0.1\r\n" + b"X: y\r\n" * 100 + b"\r\n",
                                   b"POST /api/nmt HTTP/1.1\r\nHost: evil\r\nContent-Length: 5\r\n\r\nhello",
                                   bytes(rng.randrange(256) for _ in range(300)),
                                   b"POST /api/nmt HTTP/1.1\r\nHost: 127.0.0.1\r\nTransfer-Encoding: chunked\r\n\r\n" + b"ffff\r\n" + b"a" * 65535 + b"\r\n" * 2,
                                   b"GET /assets/app.js HTTP/1.1\r\nHost: 127.0.0.1\r\nRange: bytes=" + b"0-," * 2000 + b"0-\r\n\r\n"])
                c.sendall(junk)
                sent[0] += 1
                c.settimeout(0.2)
                try:
                    c.recv(65536)
                except OSError:
                    pass
                c.close()
            except OSError:
                time.sleep(0.01)
    if attack:
        for _ in range(500):
            try:
                socks.append(socket.create_connection(("127.0.0.1", port), timeout=1))
            except OSError:
                break  # the listen queue is full: hold what is open
        th = [threading.Thread(target=attacker, args=(i,)) for i in range(2)]
        for t in th:
            t.start()
    t0 = time.monotonic()
    c0 = clock()["t_us"]
    while True:
        r = clock()
        if r["end_reached"] or r["paused"]:
            break
        time.sleep(0.05)
    wall = time.monotonic() - t0
    stop = True
    rss = int(open(f"/proc/{p.pid}/status").read().split("VmRSS:")[1].split()[0])
    p.send_signal(2)
    p.wait()
    for t in th if attack else []:
        t.join()
    for c in socks:
        c.close()
    print(f"attack={attack} silent={len(socks)} abusive requests={sent[0]} simulated {(r['t_us']-c0)/1e6:.1f} s in {wall:.2f} s wall = {(r['t_us']-c0)/1e6/wall:.0f}x, RSS {rss/1024:.0f} MB")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    dur = sys.argv[3] if len(sys.argv) > 3 else "3000"
    for attack in (False, True):
        measure(sys.argv[1], sys.argv[2], attack, dur)


if __name__ == "__main__":
    main()
