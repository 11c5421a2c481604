#!/bin/bash
# vcan-run never hangs and never reports a false success:
#  - --timeout kills the command (or guest) and exits 124 with a message;
#  - in qemu mode, a guest that cannot boot or mount the share exits 125 with "guest did not
#    finish", the failing step and the console tail.
# usage: vcan_failure_test.sh /path/to/vcan-run
set -u
vcan_run=${1:?usage: $0 /path/to/vcan-run}

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

start=$SECONDS
"$vcan_run" --timeout 3 -- sleep 120 >"$tmp/out" 2>"$tmp/err"
rc=$?
took=$((SECONDS - start))
cat "$tmp/err"
[ "$rc" = 124 ] || fail "timeout: exit code $rc, want 124"
grep -q 'timed out after 3s' "$tmp/err" || fail "timeout: no clear message"
[ "$took" -lt 30 ] || fail "timeout: took ${took}s"
echo "timeout: OK (${took}s)"

mode=$("$vcan_run" --check) || fail "--check failed: $mode"
echo "--check: $mode"
case $mode in
  qemu*)
    # Make the kernel look for an init that is not there: it panics before our init runs.
    VPLANT_VCAN_APPEND="rdinit=/nonexistent init=/nonexistent" "$vcan_run" --timeout 120 -- true \
      >"$tmp/out" 2>"$tmp/err"
    rc=$?
    cat "$tmp/err"
    [ "$rc" = 125 ] || fail "boot failure: exit code $rc, want 125"
    grep -q 'guest did not finish' "$tmp/err" || fail "boot failure: no clear message"
    grep -q 'Kernel panic' "$tmp/err" || fail "boot failure: console tail missing"
    echo "boot failure: OK"
    # A 9p mount that fails inside our init: reported with its VPLANT-GUEST-FAIL line.
    VPLANT_VCAN_9P_CACHE=bogus "$vcan_run" --timeout 120 -- true >"$tmp/out" 2>"$tmp/err"
    rc=$?
    cat "$tmp/err"
    [ "$rc" = 125 ] || fail "mount failure: exit code $rc, want 125"
    grep -q "VPLANT-GUEST-FAIL: cannot mount the 9p share" "$tmp/err" || fail "mount failure: no clear message"
    echo "mount failure: OK"
    ;;
  *) echo "boot failure: not applicable in native mode" ;;
esac

"$vcan_run" --ifaces 'bad name' -- true 2>"$tmp/err"
rc=$?
[ "$rc" = 125 ] || fail "bad --ifaces: exit code $rc, want 125"
grep -q "bad interface name" "$tmp/err" || fail "bad --ifaces: no clear message"
echo "vcan harness failure modes: OK"
