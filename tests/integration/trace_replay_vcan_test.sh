#!/usr/bin/env bash
# The trace `vplant run --trace` writes is a candump -L log that can-utils' canplayer replays:
# every frame of a scenario's trace, replayed onto vcan0, is seen there by candump with the same
# identifier, flags and data, in the same order. Runs inside vcan-run.
#   trace_replay_vcan_test.sh VPLANT_BINARY SCENARIO
set -u
vplant=$1
scenario=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# 0.6 s of the scenario on the virtual bus 'main' (the run ends before its script: exit 1 is fine).
"$vplant" run "$scenario" --duration 0.6 --trace "$work/run.log" >"$work/out" 2>&1
rc=$?
[ "$rc" -le 1 ] || { cat "$work/out"; fail "vplant run exit code $rc"; }
n=$(wc -l <"$work/run.log")
[ "$n" -ge 20 ] || fail "trace too short ($n frames): $(cat "$work/run.log")"
grep -qvE '^\([0-9]{10}\.[0-9]{6}\) main [0-9A-F]{3,8}#' "$work/run.log" &&
  fail "not candump -L lines: $(grep -vE '^\([0-9]{10}\.[0-9]{6}\) main [0-9A-F]{3,8}#' "$work/run.log" | head -3)"

# Listen first (give candump, under emulation, a moment to bind), then replay with the trace's
# own timing, interface 'main' mapped to vcan0.
timeout 60 candump -n "$n" -L vcan0 >"$work/seen" &
dump=$!
sleep 1
canplayer -I "$work/run.log" vcan0=main || fail "canplayer rejected the trace"
wait "$dump" || fail "candump saw $(wc -l <"$work/seen") of $n frames"

awk '{print $3}' "$work/run.log" >"$work/sent.frames"
awk '{print $3}' "$work/seen" >"$work/seen.frames"
diff "$work/sent.frames" "$work/seen.frames" >"$work/diff" || fail "replayed frames differ: $(head -20 "$work/diff")"
echo "ok: $n frames of the trace replayed by canplayer onto vcan0, identical"
