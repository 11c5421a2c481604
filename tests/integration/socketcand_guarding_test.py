#!/usr/bin/python3
"""Node guarding of the HLT 1100 over socketcand, as python-canopen does it with python-can 4.1.

python-can 4.1 (Debian 12's python3-can) writes a remote frame as `< send 705 N >` without data
bytes; python-canopen's guard request is a remote frame on 700h + node-ID with no data (N = 0).
This test sends those remote frames with python-can (python-canopen is not packaged in Debian 12)
and checks the HLT 1100's answers: one byte, the NMT state in bits 0-6 and a toggle bit 7 that
starts at 0 and alternates (CiA 301), also with the guard time and life time factor set.

usage: socketcand_guarding_test.py VPLANT SCENARIO
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

HLT = 5
PRE_OPERATIONAL, OPERATIONAL = 0x7F, 0x05
ANSWER_TIMEOUT = 2.0  # generous: sanitizer builds run the plant slower than real time


def recv_until(bus, predicate, timeout, what):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        msg = bus.recv(end - time.monotonic())
        if msg is not None and predicate(msg):
            return msg
    raise Failure(f"timeout after {timeout} s waiting for {what}")


def guard(bus, dlc):
    """One guard request as python-canopen sends it (dlc 0) or with the answer's length (dlc 1)."""
    bus.send(can.Message(arbitration_id=0x700 + HLT, is_remote_frame=True, dlc=dlc, is_extended_id=False))
    answer = recv_until(bus, lambda m: m.arbitration_id == 0x700 + HLT, ANSWER_TIMEOUT,
                        f"the HLT 1100's guard answer (remote frame with DLC {dlc})")
    if len(answer.data) != 1:
        raise Failure(f"guard answer of {len(answer.data)} bytes: {answer.data.hex()}")
    return answer.data[0]


def sdo_download(bus, index, sub, value, size):
    command = 0x23 | ((4 - size) << 2)
    data = list(value.to_bytes(size, "little")) + [0] * (4 - size)
    bus.send(can.Message(arbitration_id=0x600 + HLT, data=[command, index & 0xFF, index >> 8, sub] + data,
                         is_extended_id=False))
    reply = recv_until(bus, lambda m: m.arbitration_id == 0x580 + HLT, ANSWER_TIMEOUT, f"the answer to {index:04X}h")
    check(reply.data[0] == 0x60, f"HLT 1100 {index:04X}h:{sub:02X} = {value} (answer {reply.data.hex()})")


def run(bus):
    time.sleep(1.0)  # the nodes boot within the run's first 500 ms
    while bus.recv(0.05) is not None:  # what is already waiting (boot-ups)
        pass
    answers = [guard(bus, dlc) for dlc in (0, 1, 0, 1)]
    check([a & 0x7F for a in answers] == [PRE_OPERATIONAL] * 4,
          f"four guard answers in Pre-operational: {[hex(a) for a in answers]}")
    check([a & 0x80 for a in answers] == [0x00, 0x80, 0x00, 0x80], "the toggle bit starts at 0 and alternates")

    # Guarding as python-canopen sets it up: guard time 100 ms, life time factor 3, then NMT start.
    sdo_download(bus, 0x100C, 0, 100, 2)
    sdo_download(bus, 0x100D, 0, 3, 1)
    bus.send(can.Message(arbitration_id=0x000, data=[0x01, HLT], is_extended_id=False))
    toggles = []
    for _ in range(10):
        time.sleep(0.1)
        answer = guard(bus, 0)
        check(answer & 0x7F in (PRE_OPERATIONAL, OPERATIONAL), f"guard answer 0x{answer:02X}")
        toggles.append(answer & 0x80)
    check(answer & 0x7F == OPERATIONAL, "the HLT 1100 reports Operational after NMT start")
    expected = [0x00 if (i % 2 == 0) else 0x80 for i in range(10)]
    check(toggles == expected, "the toggle bit keeps alternating under periodic guarding")


def main():
    vplant, scenario = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    try:
        with served_plant(vplant, scenario) as (proc, port, reader):
            bus = can.Bus(interface="socketcand", host="127.0.0.1", port=port, channel="main")
            try:
                run(bus)
            finally:
                bus.shutdown()
            stop(proc, reader)
        return 0
    except Failure as e:
        print(f"FAILED: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
