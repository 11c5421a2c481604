#!/usr/bin/python3
"""A classroom at scale (docs/classroom.md, docs/benchmarks.md): `vplant classroom` with N seats
(default 16) in real time, every seat started by NMT and watched by what its page does (the event
stream at 20 Hz with four signals; the dictionary of one node every second; faults and findings
every two seconds), the trainer's overview polling GET /api/seats every second. Prints the
process's CPU (cores, from /proc) over the measured window and each seat's tick lateness
(p50/p99/max, from the seats' histograms), then the worst p99 and the total.

    tools/bench/classroom_bench.py build/tools/vplant/vplant scenarios/reference-plant.yaml [--seats 16] [--seconds 30]
"""
import argparse
import http.client
import json
import os
import re
import signal
import socket
import subprocess
import sys
import threading
import time

SIGNALS = "pump.swivel_angle,p_supply.pressure,cyl.position,cyl.velocity"


def api(port, method, path, token, body=None):
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    headers = {"Authorization": f"Bearer {token}"}
    data = None
    if body is not None:
        data = json.dumps(body).encode()
        headers["Content-Type"] = "application/json"
    conn.request(method, path, body=data, headers=headers)
    res = conn.getresponse()
    raw = res.read()
    conn.close()
    return res.status, json.loads(raw) if raw else None


def stream(port, seat, token, stop, counts):
    """The page's event stream: read and count bytes until `stop`."""
    sock = socket.create_connection(("127.0.0.1", port), timeout=5)
    path = f"/seats/{seat}/api/events?signals={SIGNALS}&rate=20"
    sock.sendall(f"GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nAuthorization: Bearer {token}\r\n\r\n".encode())
    sock.settimeout(1)
    while not stop.is_set():
        try:
            chunk = sock.recv(65536)
        except socket.timeout:
            continue
        if not chunk:
            break
        counts[seat] += len(chunk)
    sock.close()


def page_polls(port, seat, token, stop):
    """The page's polling: one node's dictionary every second, faults and findings every two."""
    n = 0
    while not stop.wait(1.0):
        api(port, "GET", f"/seats/{seat}/api/nodes/dsv/od", token)
        if n % 2 == 0:
            api(port, "GET", f"/seats/{seat}/api/faults", token)
            api(port, "GET", f"/seats/{seat}/api/findings?since=0", token)
        n += 1


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat", encoding="ascii") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("vplant")
    p.add_argument("scenario")
    p.add_argument("--seats", type=int, default=16)
    p.add_argument("--seconds", type=float, default=30)
    p.add_argument("--warmup", type=float, default=5)
    a = p.parse_args()

    proc = subprocess.Popen([a.vplant, "classroom", a.scenario, "--seats", str(a.seats), "--realtime", "--ui", "127.0.0.1:0"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    tokens, port = {}, 0
    while len(tokens) < a.seats + 1:
        line = proc.stdout.readline()
        if not line:
            sys.exit(f"vplant classroom ended before printing its links (exit {proc.wait()})")
        m = re.search(r"http://127\.0\.0\.1:(\d+)/(?:seats/(\d+)/)?\?token=([0-9a-f]{32})", line)
        if m:
            port = int(m.group(1))
            tokens[int(m.group(2) or 0)] = m.group(3)
    stop = threading.Event()
    counts = {k: 0 for k in range(1, a.seats + 1)}
    threads = []
    try:
        time.sleep(1.5)  # every node has booted
        for k in range(1, a.seats + 1):
            api(port, "POST", f"/seats/{k}/api/nmt", tokens[k], {"command": "start", "node": 0})
            threads.append(threading.Thread(target=stream, args=(port, k, tokens[k], stop, counts)))
            threads.append(threading.Thread(target=page_polls, args=(port, k, tokens[k], stop)))
        trainer = threading.Thread(target=lambda: [api(port, "GET", "/api/seats", tokens[0]) for _ in iter(lambda: stop.wait(1.0), True)])
        threads.append(trainer)
        for t in threads:
            t.start()
        time.sleep(a.warmup)
        cpu0, t0 = cpu_seconds(proc.pid), time.monotonic()
        bytes0 = sum(counts.values())
        time.sleep(a.seconds)
        cpu1, t1 = cpu_seconds(proc.pid), time.monotonic()
        seats = api(port, "GET", "/api/seats", tokens[0])[1]["seats"]
        streamed = sum(counts.values()) - bytes0
    finally:
        stop.set()
        for t in threads:
            t.join(timeout=5)
        proc.send_signal(signal.SIGINT)
        proc.wait(timeout=30)

    cores = (cpu1 - cpu0) / (t1 - t0)
    print(f"classroom_bench: {a.seats} seats of {os.path.basename(a.scenario)}, real time, a page's streams and polls "
          f"on every seat and the trainer's overview; {t1 - t0:.1f} s measured after {a.warmup:.0f} s")
    print(f"{'seat':>4} {'ticks':>9} {'p50 us':>7} {'p99 us':>7} {'max us':>7}")
    worst = 0
    for s in seats:
        late = s["lateness_us"] or {}
        worst = max(worst, late.get("p99", 0))
        print(f"{s['seat']:>4} {late.get('ticks', 0):>9} {late.get('p50', 0):>7} {late.get('p99', 0):>7} {late.get('max', 0):>7}")
    print(f"tick lateness p99 (worst seat, since the start, 10 us buckets): {worst} us")
    print(f"process CPU: {cores:.2f} cores ({cores / a.seats * 100:.1f} % of a core per seat); "
          f"streams: {streamed / (t1 - t0) / 1024:.0f} KiB/s in all; machine: {os.cpu_count()} cores")


if __name__ == "__main__":
    main()
