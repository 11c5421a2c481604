#!/usr/bin/env bash
# A CAN interface that goes down and comes back while `vplant node` runs on it: the node reports
# it, keeps running and resumes (its heartbeat is on the wire again). Runs inside vcan-run.
#   link_down_up_vcan_test.sh VPLANT_BINARY EDS_FILE
set -u
vplant=$1
eds=$2
work=$(mktemp -d)
trap 'kill "$pid" 2>/dev/null; rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; echo "--- vplant stderr:"; cat "$work/err"; exit 1; }

# The boot-up frame is sent once, at start: listen for it before the node starts (and give
# candump, under emulation, a moment to bind its socket).
timeout 30 candump -n 1 -L vcan0,705:7FF >"$work/boot" &
dump=$!
sleep 1
"$vplant" node --eds "$eds" --node-id 5 --can vcan0 2>"$work/err" &
pid=$!
# Wait for the boot-up frame, then switch the heartbeat on (100 ms).
wait "$dump" || fail "no boot-up frame"
grep -q "705#00" "$work/boot" || fail "first frame is not the boot-up: $(cat "$work/boot")"
cansend vcan0 605#2B17100064000000
timeout 20 candump -n 3 -L vcan0,705:7FF >"$work/hb1" || fail "no heartbeat before the link went down"
grep -q "705#7F" "$work/hb1" || fail "heartbeat not in pre-operational: $(cat "$work/hb1")"

ip link set vcan0 down
sleep 1
kill -0 "$pid" 2>/dev/null || fail "vplant exited while the link was down"
ip link set vcan0 up
timeout 20 candump -n 3 -L vcan0,705:7FF >"$work/hb2" || fail "heartbeat did not resume after the link came back"
grep -q "705#7F" "$work/hb2" || fail "unexpected frames after resume: $(cat "$work/hb2")"
kill -0 "$pid" 2>/dev/null || fail "vplant is not running"

kill -INT "$pid"
wait "$pid"
rc=$?
[ "$rc" -eq 0 ] || fail "vplant exit code $rc after SIGINT"
grep -q "CAN interface 'vcan0' is down" "$work/err" || fail "link down was not reported"
grep -q "CAN interface 'vcan0' is up again; resuming" "$work/err" || fail "resume was not reported"
echo "ok: link down reported, node kept running, heartbeat resumed, clean exit on SIGINT"
