#!/bin/bash
# vcan-run's native-mode decisions, with stub `perl`, `ip`, `id` and `modprobe` commands that
# simulate a host kernel with SocketCAN (this machine's kernel has none). Boots nothing.
# usage: vcan_native_mode_test.sh /path/to/vcan-run
set -u
vcan_run=${1:?usage: $0 /path/to/vcan-run}

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
stubs=$tmp/bin
mkdir "$stubs"
state=$tmp/links # one "NAME STATE" line per simulated CAN interface
: >"$state"
export STUB_STATE=$state STUB_PF_CAN=1 STUB_UID=0

cat >"$stubs/perl" <<'STUB'
#!/bin/sh
[ "$STUB_PF_CAN" = 1 ]
STUB
cat >"$stubs/id" <<'STUB'
#!/bin/sh
[ "$1" = -u ] && { echo "$STUB_UID"; exit 0; }
exec /usr/bin/id "$@"
STUB
cat >"$stubs/modprobe" <<'STUB'
#!/bin/sh
exit 0
STUB
cat >"$stubs/ip" <<'STUB'
#!/bin/bash
# ip -o link show dev X | ip link add dev X type vcan | ip link set dev X up
args="$*"
case $args in
  "-o link show dev "*)
    n=${args##* }
    st=$(awk -v n="$n" '$1 == n { print $2 }' "$STUB_STATE")
    [ -n "$st" ] || { echo "Device \"$n\" does not exist." >&2; exit 1; }
    flags="NOARP"; [ "$st" = up ] && flags="NOARP,UP,LOWER_UP"
    echo "3: $n: <$flags> mtu 72 qdisc noqueue state UNKNOWN mode DEFAULT group default qlen 1000\\    link/can "
    ;;
  "link add dev "*" type vcan")
    n=${args#link add dev }; n=${n%% *}
    echo "$n down" >>"$STUB_STATE"; echo "add $n" >>"$STUB_STATE.log"
    ;;
  "link set dev "*" up")
    n=${args#link set dev }; n=${n%% *}
    sed -i "s/^$n down\$/$n up/" "$STUB_STATE"; echo "up $n" >>"$STUB_STATE.log"
    ;;
  *) echo "ip stub: unexpected: $args" >&2; exit 2 ;;
esac
STUB
chmod +x "$stubs"/*
export PATH=$stubs:$PATH

# 1. SocketCAN + root: --check says native; a run creates and raises the interfaces.
out=$("$vcan_run" --ifaces vcan0,vcan1 --check) || fail "--check failed: $out"
[ "$out" = native ] || fail "--check said '$out', want native"
# shellcheck disable=SC2016 # expanded by the command's shell
out=$("$vcan_run" --ifaces vcan0,vcan1 -- sh -c 'echo "harness=$VPLANT_VCAN_HARNESS"; exit 3')
rc=$?
[ "$rc" = 3 ] || fail "native run: exit code $rc, want 3"
[ "$out" = "harness=native" ] || fail "native run printed '$out'"
[ "$(cat "$state.log")" = "$(printf 'add vcan0\nup vcan0\nadd vcan1\nup vcan1')" ] ||
  fail "native run did: $(cat "$state.log")"
echo "native run creates interfaces: OK"

# 2. Interfaces present and up: nothing is created again; stdin reaches the command.
: >"$state.log"
out=$(echo piped | "$vcan_run" --ifaces vcan0,vcan1 -- cat) || fail "native cat failed"
[ "$out" = piped ] || fail "stdin did not reach the native command: '$out'"
[ ! -s "$state.log" ] || fail "existing interfaces were touched: $(cat "$state.log")"
echo "native run reuses interfaces and keeps stdin: OK"

# 3. Native timeout.
"$vcan_run" --timeout 1 -- sleep 30 2>"$tmp/err"
rc=$?
[ "$rc" = 124 ] || fail "native timeout: exit code $rc, want 124"
grep -q 'timed out' "$tmp/err" || fail "native timeout: no message"
echo "native timeout: OK"

# 4. Not root and the interface is missing: native is unusable, and --mode native says why.
export STUB_UID=1000
"$vcan_run" --mode native --ifaces vcan7 -- true 2>"$tmp/err"
rc=$?
[ "$rc" = 125 ] || fail "forced native without vcan7: exit code $rc, want 125"
grep -q 'vcan7 does not exist' "$tmp/err" || fail "no reason given: $(cat "$tmp/err")"
if out=$("$vcan_run" --mode native --ifaces vcan7 --check); then
  fail "--check --mode native succeeded without vcan7"
fi
echo "unusable native mode is reported: OK ($out)"

# 5. No PF_CAN: auto mode picks qemu.
export STUB_UID=0 STUB_PF_CAN=0
out=$("$vcan_run" --check) || true
case $out in qemu*) ;; *) fail "without PF_CAN --check said '$out', want qemu..." ;; esac
echo "no PF_CAN means qemu: OK"
echo "vcan harness native mode: OK"
