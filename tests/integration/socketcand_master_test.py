#!/usr/bin/python3
"""A CANopen master on python-can's socketcand interface drives the reference plant, no vcan.

`vplant run scenarios/reference-plant.yaml --no-script --realtime --can main=socketcand:...`
serves the plant's bus over TCP; this master (Debian's python3-can; python-canopen is not in
Debian 12, so expedited SDO, NMT and PDOs are written out here) reads and writes SDOs, starts
the nodes and moves the cylinder, mirroring the scenario's own scripted master.

usage: socketcand_master_test.py VPLANT SCENARIO
"""
import os
import struct
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from socketcand_harness import Failure, check, served_plant, stop  # noqa: E402

try:
    import can
except ImportError:
    sys.exit("python3-can is missing (Debian package python3-can; tools/setup-deps --test installs it)")

SYNC_PERIOD = 0.010
SDO_TIMEOUT = 2.0  # generous: sanitizer builds run the plant slower than real time
DSV, MD2, HLT, VTVPCD, WDGA = 2, 3, 5, 63, 127


class Master:
    """Expedited SDO client, NMT and SYNC producer over one python-can bus."""

    def __init__(self, bus):
        self.bus = bus
        self.next_sync = time.monotonic()
        self.last = {}  # COB-ID -> latest data
        self.frames = 0

    def _pump(self, timeout):
        """Receives one frame (or none within `timeout`), sending SYNC when it is due."""
        now = time.monotonic()
        if now >= self.next_sync:
            self.bus.send(can.Message(arbitration_id=0x080, data=b"", is_extended_id=False))
            self.next_sync = max(self.next_sync + SYNC_PERIOD, now)
        msg = self.bus.recv(min(timeout, max(0.0, self.next_sync - time.monotonic())))
        if msg is not None:
            self.frames += 1
            self.last[msg.arbitration_id] = bytes(msg.data)
        return msg

    def wait_for(self, what, predicate, timeout):
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            msg = self._pump(end - time.monotonic())
            if msg is not None and predicate(msg):
                return msg
        raise Failure(f"timeout after {timeout} s waiting for {what}")

    def run_for(self, seconds):
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            self._pump(end - time.monotonic())

    def send(self, cob_id, data):
        self.bus.send(can.Message(arbitration_id=cob_id, data=bytes(data), is_extended_id=False))

    def nmt(self, command, node=0):
        self.send(0x000, [command, node])

    def _sdo(self, node, request, what):
        self.send(0x600 + node, request)
        index, sub = request[1] | request[2] << 8, request[3]

        def answer(m):
            return m.arbitration_id == 0x580 + node and m.data[1:4] == bytes(request[1:4])

        reply = self.wait_for(f"the SDO answer of node {node} ({what})", answer, SDO_TIMEOUT).data
        if reply[0] == 0x80:
            code = struct.unpack_from("<I", reply, 4)[0]
            raise Failure(f"node {node} aborts SDO {what} of {index:04X}h:{sub:02X}: 0x{code:08X}")
        return reply

    def sdo_read(self, node, index, sub=0):
        """Expedited upload: returns (value, size in bytes)."""
        reply = self._sdo(node, [0x40, index & 0xFF, index >> 8, sub, 0, 0, 0, 0], "upload")
        if reply[0] & 0xE2 != 0x42:
            raise Failure(f"node {node}: {index:04X}h:{sub:02X} is not an expedited upload ({reply.hex()})")
        size = 4 - ((reply[0] >> 2) & 3) if reply[0] & 0x01 else 4
        return int.from_bytes(reply[4:4 + size], "little"), size

    def sdo_write(self, node, index, sub, value, size):
        command = 0x23 | ((4 - size) << 2)
        data = list(value.to_bytes(size, "little")) + [0] * (4 - size)
        reply = self._sdo(node, [command, index & 0xFF, index >> 8, sub] + data, "download")
        if reply[0] != 0x60:
            raise Failure(f"node {node}: unexpected download answer {reply.hex()}")


def position_mm(data):
    # HLT 1100 TPDO2: position (6004h), i32 in 0.1 mm steps (docs/devices/hlt1100.md).
    return struct.unpack_from("<i", data, 0)[0] * 0.1


def drive(master):
    # The nodes boot within the run's first 500 ms (the scripted master waits 900 ms as well); a
    # slow (sanitizer) build may need longer: the first request is repeated until answered.
    master.run_for(1.0)
    for attempt in range(5):
        try:
            device_type = master.sdo_read(HLT, 0x1000)[0]
            break
        except Failure:
            if attempt == 4:
                raise
    # SDO reads: every node answers with its device type (1000h), in Pre-operational.
    check(device_type == 0x000A0196, "HLT 1100 device type 0x000A0196 (CiA 406)")
    check(master.sdo_read(MD2, 0x1000)[0] == 0x10000198, "MD2 device type 0x10000198 (CiA 408)")
    check(master.sdo_read(DSV, 0x1000)[0] & 0xFFFF == 408, "DSV device type: profile 408")
    check(master.sdo_read(WDGA, 0x1000)[0] & 0xFFFF == 406, "WDGA device type: profile 406")
    vendor, _ = master.sdo_read(VTVPCD, 0x1018, 1)
    print(f"VT-VPCD vendor-ID 0x{vendor:08X}", flush=True)

    # NMT start: the HLT 1100 sends its TPDO1 on entering Operational.
    master.nmt(0x01)
    master.wait_for("the HLT 1100's TPDO1 after NMT start", lambda m: m.arbitration_id == 0x180 + HLT, 2.0)
    print("ok: the nodes are Operational", flush=True)

    # SDO write: pump swivel angle command 50 % (Angle CMD (BUS) 2C72h), read back.
    _, size = master.sdo_read(VTVPCD, 0x2C72)
    master.sdo_write(VTVPCD, 0x2C72, 0, 16384, size)
    check(master.sdo_read(VTVPCD, 0x2C72)[0] == 16384, "VT-VPCD 2C72h reads back 16384 (50 %)")
    master.run_for(1.0)  # the pump builds up the supply pressure

    # The cylinder's start position from the HLT 1100's TPDO2 (on every SYNC).
    start = position_mm(master.wait_for("HLT 1100 TPDO2 on SYNC", lambda m: m.arbitration_id == 0x280 + HLT, 2.0).data)
    print(f"cylinder at {start:.1f} mm", flush=True)

    # DSV to DEVICE_MODE_ACTIVE, set point +50 %: RPDO1 = control word 6040h, set point 6300h.
    master.send(0x200 + DSV, [0x07, 0x00, 0x00, 0x20])
    master.wait_for("the DSV's status word 0x000F (TPDO1)",
                    lambda m: m.arbitration_id == 0x180 + DSV and m.data[:2] == b"\x0f\x00", 2.0)
    status, _ = master.sdo_read(DSV, 0x6041)
    check(status & 0x0F == 0x0F, f"DSV status word 6041h = 0x{status:04X} (DEVICE_MODE_ACTIVE)")

    # The rod moves out: the HLT 1100's position rises by 50 mm.
    moved = master.wait_for("the HLT 1100 position 50 mm beyond the start",
                            lambda m: m.arbitration_id == 0x280 + HLT and position_mm(m.data) > start + 50.0, 10.0)
    check(True, f"the cylinder moved out to {position_mm(moved.data):.1f} mm")
    master.send(0x200 + DSV, [0x07, 0x00, 0x00, 0x00])
    master.run_for(0.2)


def main():
    vplant, scenario = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    try:
        with served_plant(vplant, scenario) as (proc, port, reader):
            bus = can.Bus(interface="socketcand", host="127.0.0.1", port=port, channel="main")
            try:
                master = Master(bus)
                drive(master)
                print(f"{master.frames} frames received", flush=True)
            finally:
                bus.shutdown()
            stop(proc, reader)
        return 0
    except Failure as e:
        print(f"FAILED: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
