#!/usr/bin/python3
"""A careless CANopen master over socketcand gets a verdict (docs/masters.md, "Verdict").

Serves the reference plant with `--master-report`, connects with python-can's socketcand
interface (Debian's python3-can) and does four things a master must not: an SDO to the DSV right
after resetting it, a write to the read-only 1000h, an upload from node 9 that is not on the bus,
and NMT Stop of the DSV in DEVICE_MODE_ACTIVE. The report must hold before-boot-up, sdo-abort,
sdo-no-answer and device-fault findings for them.

usage: socketcand_careless_master_test.py VPLANT SCENARIO
"""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from socketcand_harness import Failure, StderrReader, check, free_port  # noqa: E402
from socketcand_master_test import DSV, Master  # noqa: E402

try:
    import can
except ImportError:
    sys.exit("python3-can is missing (Debian package python3-can; tools/setup-deps --test installs it)")


def careless(master):
    master.run_for(1.0)  # the nodes boot
    master.nmt(0x81, DSV)  # reset_node, and at once an SDO: before its boot-up
    master.send(0x600 + DSV, [0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0])
    master.run_for(1.0)
    master.send(0x600 + DSV, [0x23, 0x00, 0x10, 0x00, 0x78, 0x56, 0x34, 0x12])  # 1000h is read-only
    master.wait_for("the DSV's abort", lambda m: m.arbitration_id == 0x580 + DSV and m.data[0] == 0x80, 2.0)
    master.send(0x600 + 9, [0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0])  # node 9 is not on the bus
    master.nmt(0x01)
    master.send(0x200 + DSV, [0x07, 0x00, 0x00, 0x00])  # DEVICE_MODE_ACTIVE
    master.wait_for("the DSV's status word 0x000F (TPDO1)",
                    lambda m: m.arbitration_id == 0x180 + DSV and m.data[:2] == b"\x0f\x00", 2.0)
    master.nmt(0x02, DSV)  # NMT Stop of the active valve
    master.run_for(1.5)  # past the SDO timeout of node 9's request


def main():
    vplant, scenario = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    workdir = tempfile.mkdtemp(prefix="vplant-verdict-")
    report = os.path.join(workdir, "master.json")
    proc = None
    try:
        port = free_port()
        proc = subprocess.Popen([vplant, "run", scenario, "--no-script", "--realtime", "--duration", "30",
                                 "--master-report", report, "--can", f"main=socketcand:127.0.0.1:{port}"],
                                cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        reader = StderrReader(proc.stderr)
        reader.start()
        deadline = time.monotonic() + 20
        while not reader.served.wait(0.1) and proc.poll() is None and time.monotonic() < deadline:
            pass
        if not reader.served.is_set():
            raise Failure("vplant did not serve the bus:\n" + "".join(reader.lines))
        bus = can.Bus(interface="socketcand", host="127.0.0.1", port=port, channel="main")
        try:
            careless(Master(bus))
        finally:
            bus.shutdown()
        proc.send_signal(signal.SIGINT)
        out, _ = proc.communicate(timeout=15)
        reader.join(5)
        print(out, end="")
        with open(report) as f:
            findings = json.load(f)["findings"]
        for finding in findings:
            print(f"{finding['rule']} node {finding['node']}: {finding['text']}", flush=True)

        def has(rule, node, words):
            return any(f["rule"] == rule and f["node"] == node and words in f["text"] for f in findings)

        check(has("before-boot-up", DSV, "the master reset it"), "before-boot-up: an SDO to the DSV right after its reset")
        check(has("sdo-abort", DSV, "1000h:00"), "sdo-abort: the write to 1000h")
        check(has("sdo-no-answer", 9, "there is no node 9"), "sdo-no-answer: the upload from node 9")
        check(has("device-fault", DSV, "NMT stop to node 2"), "device-fault: NMT Stop of the active DSV")
        return 0
    except (Failure, OSError, ValueError, KeyError) as e:
        if proc is not None and proc.poll() is None:
            proc.send_signal(signal.SIGINT)
            proc.wait(10)
        print(f"FAILED: {e}", file=sys.stderr)
        return 1
    finally:
        if proc is not None and proc.poll() is None:
            proc.kill()
            proc.wait()
        shutil.rmtree(workdir, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
