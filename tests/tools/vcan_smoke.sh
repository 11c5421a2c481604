#!/bin/sh
# Runs under tools/vcan/vcan-run --ifaces vcan0,vcan1: both interfaces exist, are up, and a frame
# sent with cansend comes back through candump on the same interface.
set -eu

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# One frame through IFACE: candump must be listening before cansend, so resend until it has one.
loop_frame() { # IFACE FRAME
  iface=$1 frame=$2 out=$tmp/$1.log
  candump -L -n 1 "$iface" >"$out" 2>"$tmp/$1.err" &
  pid=$!
  i=0
  while kill -0 "$pid" 2>/dev/null; do
    i=$((i + 1))
    [ "$i" -le 100 ] || { kill "$pid"; fail "candump on $iface received nothing in 100 tries"; }
    cansend "$iface" "$frame" || fail "cansend $iface $frame"
    sleep 0.1
  done
  wait "$pid" || fail "candump on $iface failed: $(cat "$tmp/$1.err")"
  line=$(cat "$out")
  echo "$iface: $line"
  # candump -L: "(1700000000.123456) vcan0 123#DEADBEEF"
  echo "$line" | grep -Eq "^\([0-9]+\.[0-9]+\) $iface $frame\$" ||
    fail "unexpected candump line on $iface: '$line' (want '$iface $frame')"
}

for iface in vcan0 vcan1; do
  ip -d link show dev "$iface" >"$tmp/link" 2>&1 || fail "$iface does not exist: $(cat "$tmp/link")"
  grep -q 'link/can' "$tmp/link" || fail "$iface is not a CAN interface: $(cat "$tmp/link")"
  grep -q 'vcan' "$tmp/link" || fail "$iface is not a vcan: $(cat "$tmp/link")"
  grep -Eq '[<,]UP[,>]' "$tmp/link" || fail "$iface is not up: $(cat "$tmp/link")"
done

loop_frame vcan0 123#DEADBEEF
loop_frame vcan1 18FEF100#0102030405060708
echo "vcan harness smoke: OK (mode ${VPLANT_VCAN_HARNESS:-?})"
