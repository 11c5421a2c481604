"""`vplant classroom` end to end over HTTP (docs/classroom.md): the links it prints, 401 without a
token or with another seat's, the trainer's read-only view of a seat, seats that share nothing
(NMT start on seat 1 leaves seat 2 in PRE-OPERATIONAL), the trainer's endpoints, the Host check,
and the command line's errors (seat count, non-loopback address, a SocketCAN bus, a matrix).

    /usr/bin/python3 classroom_cli_test.py --vplant BIN --scenario scenarios/reference-plant.yaml --exercises exercises
"""
import argparse
import http.client
import json
import os
import queue
import re
import signal
import subprocess
import sys
import tempfile
import threading
import time
import unittest

ARGS = None


def request(port, method, path, token=None, cookie=None, body=None, host=None):
    """One request; returns (status, headers, parsed JSON or raw text)."""
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    headers = {"Host": host or f"127.0.0.1:{port}"}
    if token:
        headers["Authorization"] = f"Bearer {token}"
    if cookie:
        headers["Cookie"] = f"vplant_token={cookie}"
    data = None
    if body is not None:
        data = json.dumps(body).encode()
        headers["Content-Type"] = "application/json"
    conn.request(method, path, body=data, headers=headers)
    res = conn.getresponse()
    raw = res.read().decode("utf-8", "replace")
    conn.close()
    try:
        parsed = json.loads(raw)
    except ValueError:
        parsed = raw
    return res.status, dict(res.getheaders()), parsed


def nmt_states(port, seat, token):
    status, _, nodes = request(port, "GET", f"/seats/{seat}/api/nodes", token=token)
    assert status == 200, nodes
    return {n["name"]: n["nmt"] for n in nodes}


class Classroom:
    """A running `vplant classroom --seats N`, its port and its tokens (0 = the trainer's).

    Its output is read by a thread all along: the wait for the links has a real deadline (a
    blocking readline has none), and whatever the process logs later (late ticks on a loaded
    machine) can never fill the pipe and stall it."""

    def __init__(self, seats, extra=()):
        self.proc = subprocess.Popen(
            [ARGS.vplant, "classroom", ARGS.scenario, "--seats", str(seats), "--ui", "127.0.0.1:0", *extra],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        self.lines = []
        self.tokens = {}
        self.queue = queue.Queue()
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()
        deadline = time.monotonic() + 30
        while len(self.tokens) < seats + 1:
            try:
                line = self.queue.get(timeout=max(0.0, deadline - time.monotonic()))
            except queue.Empty:
                line = None
            if not line:
                self.stop()
                raise AssertionError("vplant classroom printed no links:\n" + "".join(self.lines))
            m = re.search(r"http://127\.0\.0\.1:(\d+)/(?:seats/(\d+)/)?\?token=([0-9a-f]{32})", line)
            if m:
                self.port = int(m.group(1))
                self.tokens[int(m.group(2) or 0)] = m.group(3)

    def _read(self):
        for line in self.proc.stdout:
            self.lines.append(line)
            self.queue.put(line)
        self.queue.put("")  # the end of its output

    def stop(self):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGINT)
        self.proc.wait(timeout=20)
        self.reader.join(timeout=20)
        return self.proc.returncode, "".join(self.lines)


def wait_booted(port, seat, token, deadline):
    """Until every node of the seat is PRE-OPERATIONAL (a node still initialising ignores NMT)."""
    while set(nmt_states(port, seat, token).values()) != {"PRE-OPERATIONAL"}:
        assert time.monotonic() < deadline, f"seat {seat} did not boot: {nmt_states(port, seat, token)}"
        time.sleep(0.05)


class RoomTest(unittest.TestCase):
    """A classroom of two seats for the whole class of tests, stopped cleanly (exit 0) after them."""

    room_args = []

    @classmethod
    def setUpClass(cls):
        cls.room = Classroom(2, cls.room_args)
        cls.port = cls.room.port
        cls.t = cls.room.tokens

    @classmethod
    def tearDownClass(cls):
        rc, cls.output = cls.room.stop()
        assert rc == 0, cls.output

    def progress(self, seat):
        status, _, body = request(self.port, "GET", f"/seats/{seat}/api/exercise", token=self.t[seat])
        self.assertEqual(status, 200, body)
        return [step["done"] for step in body["steps"]]


class TwoSeats(RoomTest):
    @classmethod
    def tearDownClass(cls):
        super().tearDownClass()
        # The tokens appear on the start lines only, nowhere after them.
        for token in cls.t.values():
            assert cls.output.count(token) == 1, cls.output

    def test_links_one_per_seat_and_the_trainer(self):
        self.assertEqual(sorted(self.t), [0, 1, 2])
        self.assertEqual(len(set(self.t.values())), 3)

    def test_no_token_or_another_seats_token_is_401_and_changes_nothing(self):
        for path in ("/", "/api/seats", "/seats/1/", "/seats/1/api/nodes", "/seats/1/assets/app.js"):
            status, headers, body = request(self.port, "GET", path)
            self.assertEqual(status, 401, path)
            self.assertIn("error", body)
        status, _, body = request(self.port, "POST", "/seats/2/api/nmt", token=self.t[1],
                                  body={"command": "stop", "node": 0})
        self.assertEqual(status, 401)
        self.assertIn("seat 2", body["error"])
        status, _, _ = request(self.port, "GET", "/api/seats", token=self.t[2])
        self.assertEqual(status, 401)
        self.assertNotIn("STOPPED", nmt_states(self.port, 2, self.t[2]).values())

    def test_seats_share_nothing(self):
        # Every node of both seats has booted (a node still initialising ignores the NMT command,
        # and seat 2 is compared with PRE-OPERATIONAL below: on a loaded machine it may boot later).
        deadline = time.monotonic() + 10
        wait_booted(self.port, 1, self.t[1], deadline)
        wait_booted(self.port, 2, self.t[2], deadline)
        status, _, body = request(self.port, "POST", "/seats/1/api/nmt", token=self.t[1],
                                  body={"command": "start", "node": 0})
        self.assertEqual(status, 200, body)
        deadline = time.monotonic() + 10
        while set(nmt_states(self.port, 1, self.t[1]).values()) != {"OPERATIONAL"}:
            self.assertLess(time.monotonic(), deadline, f"seat 1 did not start: {nmt_states(self.port, 1, self.t[1])}")
            time.sleep(0.05)
        self.assertEqual(set(nmt_states(self.port, 2, self.t[2]).values()), {"PRE-OPERATIONAL"})

    def test_the_trainer_looks_at_a_seat_read_only_from_the_browser(self):
        status, _, _ = request(self.port, "GET", "/seats/2/api/nodes", cookie=self.t[0])
        self.assertEqual(status, 200)
        status, _, body = request(self.port, "POST", "/seats/2/api/nmt", cookie=self.t[0],
                                  body={"command": "reset", "node": 0})
        self.assertEqual(status, 403)
        self.assertIn("read-only", body["error"])

    def test_a_token_link_sets_the_cookie_that_then_opens_the_page(self):
        status, headers, _ = request(self.port, "GET", f"/seats/2?token={self.t[2]}")
        self.assertEqual(status, 303)
        self.assertEqual(headers["Location"], "/seats/2/")
        cookie = headers["Set-Cookie"]
        self.assertIn("HttpOnly", cookie)
        self.assertIn("SameSite=Strict", cookie)
        self.assertIn("Path=/seats/2/", cookie)
        status, headers, page = request(self.port, "GET", "/seats/2/", cookie=self.t[2])
        self.assertEqual(status, 200)
        self.assertIn("text/html", headers["Content-Type"])
        self.assertIn('src="assets/app.js"', page)
        status, _, _ = request(self.port, "GET", "/seats/2/assets/app.js", cookie=self.t[2])
        self.assertEqual(status, 200)

    def test_the_trainers_overview_and_endpoints(self):
        status, headers, page = request(self.port, "GET", "/", cookie=self.t[0])
        self.assertEqual(status, 200)
        self.assertIn("vplant classroom", page)
        status, _, body = request(self.port, "GET", "/api/seats", token=self.t[0])
        self.assertEqual(status, 200)
        self.assertEqual([s["seat"] for s in body["seats"]], [1, 2])
        self.assertEqual(len(body["seats"][0]["nodes"]), 5)
        status, _, body = request(self.port, "POST", "/api/seats/exercise", token=self.t[0], body={"nope": 1})
        self.assertEqual(status, 400)
        status, _, _ = request(self.port, "POST", "/api/seats/9/restart", token=self.t[0], body={})
        self.assertEqual(status, 404)
        status, _, _ = request(self.port, "GET", "/seats/3/api/nodes", token=self.t[0])
        self.assertEqual(status, 404)

    def test_the_trainer_restarts_one_seat(self):
        time.sleep(0.3)  # both clocks past 0.3 s
        status, _, body = request(self.port, "POST", "/api/seats/1/restart", token=self.t[0], body={})
        self.assertEqual(status, 200, body)
        status, _, body = request(self.port, "GET", "/api/seats", token=self.t[0])
        clocks = {s["seat"]: s["clock"]["t_us"] for s in body["seats"]}
        self.assertLess(clocks[1], clocks[2], "seat 1 starts again at t = 0, seat 2 runs on")
        # A seat's token cannot restart through the trainer's endpoint.
        status, _, _ = request(self.port, "POST", "/api/seats/2/restart", token=self.t[2], body={})
        self.assertEqual(status, 401)

    def test_the_host_check_stays(self):
        status, _, body = request(self.port, "GET", "/seats/1/api/nodes", token=self.t[1], host="evil.example:80")
        self.assertEqual(status, 403)
        self.assertIn("Host", body["error"])


class Exercises(RoomTest):
    """The trainer gives every seat the same exercise; a trainee's steps are checked on their seat only."""

    @classmethod
    def setUpClass(cls):
        cls.room_args = ["--exercises", ARGS.exercises]
        super().setUpClass()

    def test_steps_are_done_on_the_seat_that_did_them_only(self):
        status, _, body = request(self.port, "GET", "/seats/1/api/exercises", token=self.t[1])
        self.assertIn("nmt", body)
        status, _, body = request(self.port, "POST", "/api/seats/exercise", token=self.t[0], body={"name": "nmt"})
        self.assertEqual(status, 200, body)
        self.assertEqual([(a["seat"], a["status"]) for a in body["seats"]], [(1, 200), (2, 200)])
        status, _, body = request(self.port, "POST", "/api/seats/exercise", token=self.t[0], body={"name": "nope"})
        self.assertEqual(status, 404, body)
        deadline = time.monotonic() + 10
        while nmt_states(self.port, 1, self.t[1])["dsv"] != "PRE-OPERATIONAL":
            self.assertLess(time.monotonic(), deadline, "the DSV of seat 1 did not boot")
            time.sleep(0.05)
        for command, state in (("start", "OPERATIONAL"), ("stop", "STOPPED"), ("pre_operational", "PRE-OPERATIONAL")):
            status, _, body = request(self.port, "POST", "/seats/1/api/nmt", token=self.t[1],
                                      body={"command": command, "node": "dsv"})
            self.assertEqual(status, 200, body)
            while nmt_states(self.port, 1, self.t[1])["dsv"] != state:
                self.assertLess(time.monotonic(), deadline, f"the DSV of seat 1 is not {state}")
                time.sleep(0.05)
        while self.progress(1)[:3] != [True, True, True]:
            self.assertLess(time.monotonic(), deadline, f"seat 1's steps: {self.progress(1)}")
            time.sleep(0.05)
        self.assertEqual(self.progress(2), [False] * len(self.progress(2)))
        # The overview shows the same.
        status, _, body = request(self.port, "GET", "/api/seats", token=self.t[0])
        seats = {s["seat"]: s["exercise"] for s in body["seats"]}
        self.assertEqual(seats[1]["name"], "nmt")
        self.assertEqual([st["done"] for st in seats[1]["steps"]][:3], [True, True, True])
        self.assertFalse(any(st["done"] for st in seats[2]["steps"]))


class Dsp408(RoomTest):
    """Issue 22's "done when": `dsp408` on both seats, seat 1's DSV driven to DEVICE_MODE_ACTIVE by
    SDO; seat 1's steps are done, none of seat 2's."""

    @classmethod
    def setUpClass(cls):
        cls.room_args = ["--exercises", ARGS.exercises]
        super().setUpClass()

    def dsp408_state(self, seat):
        status, _, body = request(self.port, "GET", f"/seats/{seat}/api/nodes/dsv/machines", token=self.t[seat])
        self.assertEqual(status, 200, body)
        return next(m["state"] for m in body["machines"] if m["machine"] == "dsp408")

    def test_driving_seat_1s_dsv_to_active_marks_seat_1s_steps_only(self):
        deadline = time.monotonic() + 20
        wait_booted(self.port, 1, self.t[1], deadline)
        wait_booted(self.port, 2, self.t[2], deadline)
        status, _, body = request(self.port, "POST", "/api/seats/exercise", token=self.t[0], body={"name": "dsp408"})
        self.assertEqual(status, 200, body)
        self.assertEqual([(a["seat"], a["status"]) for a in body["seats"]], [(1, 200), (2, 200)])
        for cw, state in ((0x0001, "DISABLED"), (0x0003, "HOLD"), (0x0007, "DEVICE_MODE_ACTIVE")):
            status, _, body = request(self.port, "POST", "/seats/1/api/nodes/dsv/sdo", token=self.t[1],
                                      body={"index": 0x6040, "sub": 0, "value": cw})
            self.assertEqual(status, 200, body)
            self.assertTrue(body["ok"], body)
            while self.dsp408_state(1) != state:
                self.assertLess(time.monotonic(), deadline, f"seat 1's DSV is not {state}")
                time.sleep(0.05)
        while self.progress(1)[:3] != [True, True, True]:
            self.assertLess(time.monotonic(), deadline, f"seat 1's steps: {self.progress(1)}")
            time.sleep(0.05)
        self.assertEqual(self.progress(2), [False] * len(self.progress(2)))
        self.assertEqual(self.dsp408_state(2), "INIT")
        status, _, body = request(self.port, "GET", "/api/seats", token=self.t[0])
        seats = {s["seat"]: s["exercise"] for s in body["seats"]}
        self.assertEqual(seats[1]["name"], "dsp408")
        self.assertEqual([st["done"] for st in seats[1]["steps"]][:3], [True, True, True])
        self.assertFalse(any(st["done"] for st in seats[2]["steps"]))


class CommandLine(unittest.TestCase):
    def run_vplant(self, *args, scenario=None):
        p = subprocess.run([ARGS.vplant, "classroom", scenario or ARGS.scenario, *args],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=30)
        return p.returncode, p.stdout

    def test_seat_count_is_bounded(self):
        for n in ("0", "33", "x"):
            rc, out = self.run_vplant("--seats", n, "--ui", "0")
            self.assertEqual(rc, 2, out)
            self.assertIn("--seats", out)

    def test_a_non_loopback_address_needs_the_flag(self):
        rc, out = self.run_vplant("--seats", "1", "--ui", "0.0.0.0:0")
        self.assertEqual(rc, 2, out)
        self.assertIn("--ui-allow-remote", out)

    def test_a_socketcan_bus_is_refused(self):
        with open(ARGS.scenario, encoding="utf-8") as f:
            text = f.read().replace("transport: virtual", "transport: socketcan:vcan0")
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "socketcan.yaml")
            with open(path, "w", encoding="utf-8") as f:
                f.write(text.replace("../", os.path.dirname(os.path.abspath(ARGS.scenario)) + "/../"))
            rc, out = self.run_vplant("--seats", "2", "--ui", "0", scenario=path)
        self.assertEqual(rc, 2, out)
        self.assertIn("virtual buses only", out)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--vplant", required=True)
    parser.add_argument("--scenario", required=True)
    parser.add_argument("--exercises", required=True)
    ARGS, rest = parser.parse_known_args()
    unittest.main(argv=[sys.argv[0], *rest], verbosity=2)
