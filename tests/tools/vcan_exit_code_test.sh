#!/bin/bash
# vcan-run passes the command's exit code, stdout, stderr, arguments, working directory and
# environment through (one guest boot in qemu mode).
# usage: vcan_exit_code_test.sh /path/to/vcan-run
# shellcheck disable=SC2016 # single-quoted $ is what these tests send through
set -u
vcan_run=${1:?usage: $0 /path/to/vcan-run}

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/work dir"
cd "$tmp/work dir" || fail "cd"

export VPLANT_HARNESS_PROBE="spaces and 'quotes' and \$dollar"
"$vcan_run" -- sh -c '
  echo "out-marker"
  echo "err-marker" >&2
  printf "arg=<%s>\n" "$@"
  echo "pwd=$(pwd)"
  echo "probe=$VPLANT_HARNESS_PROBE"
  echo "home=$HOME"
  ip link show vcan0 >/dev/null || exit 99
  exit 7' sh "a b" 'c"d' '' '$HOME' >"$tmp/out" 2>"$tmp/err"
rc=$?
echo "--- stdout"; cat "$tmp/out"
echo "--- stderr"; cat "$tmp/err"
echo "--- exit code $rc"

[ "$rc" = 7 ] || fail "exit code $rc, want 7"
grep -qx 'out-marker' "$tmp/out" || fail "stdout lacks out-marker"
grep -q 'out-marker' "$tmp/err" && fail "stdout leaked into stderr"
grep -qx 'err-marker' "$tmp/err" || fail "stderr lacks err-marker"
grep -q 'err-marker' "$tmp/out" && fail "stderr leaked into stdout"
want=$(printf 'arg=<%s>\n' "a b" 'c"d' '' '$HOME')
[ "$(grep '^arg=' "$tmp/out")" = "$want" ] || fail "arguments changed on the way"
grep -qxF "pwd=$tmp/work dir" "$tmp/out" || fail "working directory not kept"
grep -qxF "probe=$VPLANT_HARNESS_PROBE" "$tmp/out" || fail "environment not passed"
grep -qxF "home=$HOME" "$tmp/out" || fail "HOME not passed"
echo "vcan harness exit code: OK"
