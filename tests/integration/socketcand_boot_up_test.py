#!/usr/bin/python3
"""--power-on-first-client: a master that connects well after the start still sees every boot-up.

The plant is served over socketcand with `--power-on-first-client`; the test waits 1.5 s (a
master started late), connects with python-can and expects the boot-up message (700h + node-ID,
one byte 00h) of each of the reference plant's five nodes. A run without the option has sent them
before anyone listened: the same client then sees none (checked too, so the test can fail).

usage: socketcand_boot_up_test.py VPLANT SCENARIO
"""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from socketcand_harness import Failure, check, served_plant, stop  # noqa: E402

try:
    import can
except ImportError:
    sys.exit("python3-can is missing (Debian package python3-can; tools/setup-deps --test installs it)")

NODES = {2: "dsv", 3: "md2", 5: "hlt", 63: "vtvpcd", 127: "wdga"}


def boot_ups_seen(port, listen_s):
    time.sleep(1.5)  # a master that starts late
    bus = can.Bus(interface="socketcand", host="127.0.0.1", port=port, channel="main")
    try:
        seen = set()
        end = time.monotonic() + listen_s
        while time.monotonic() < end:
            msg = bus.recv(end - time.monotonic())
            if msg is None:
                continue
            node = msg.arbitration_id - 0x700
            if node in NODES and not msg.is_remote_frame and bytes(msg.data) == b"\x00":
                seen.add(node)
        return seen
    finally:
        bus.shutdown()


def main():
    vplant, scenario = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    try:
        with served_plant(vplant, scenario, ("--power-on-first-client",)) as (proc, port, reader):
            seen = boot_ups_seen(port, 3.0)
            stop(proc, reader)
        missing = sorted(NODES[n] for n in NODES if n not in seen)
        check(not missing, f"every node's boot-up reaches a late client (missing: {missing})")
        with served_plant(vplant, scenario) as (proc, port, reader):
            seen = boot_ups_seen(port, 1.0)
            stop(proc, reader)
        check(not seen, f"without the option the boot-ups went out before the client came ({sorted(seen)} seen)")
        return 0
    except Failure as e:
        print(f"FAILED: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
