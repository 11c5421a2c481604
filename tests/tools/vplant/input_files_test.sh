#!/bin/sh
# `vplant node` and `vplant run` on input files that are not regular files: a FIFO (open() would
# block forever), /dev/zero (reading never ends) and a directory. Each is refused at once with
# exit 2 and "file: not a regular file (...)"; every command runs under a timeout, so a hang
# fails the test instead of stalling ctest. Then SIGTERM stops a real-time `vplant node` within a
# second. Usage: input_files_test.sh VPLANT DATA_DIR
set -u
vplant=$1
data=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0

# expect_refusal NAME EXPECTED_TEXT COMMAND...: exit 2 within 10 s and the text on stderr.
expect_refusal() {
  name=$1 text=$2
  shift 2
  timeout 10 "$@" >"$tmp/out" 2>&1
  rc=$?
  if [ $rc -ne 2 ] || ! grep -qF "$text" "$tmp/out"; then
    echo "FAIL $name: exit $rc (want 2), output:"
    cat "$tmp/out"
    failures=$((failures + 1))
  else
    echo "ok   $name"
  fi
}

mkfifo "$tmp/fifo.eds" "$tmp/fifo.yaml" "$tmp/fifo.store"
eds="$data/eds/quirk_none.eds"
scenario_with_store() {
  cat >"$tmp/$1.yaml" <<YAML
buses: [{name: main, transport: virtual}]
nodes:
  - {name: io, device: eds, eds: $eds, node_id: 5, bus: main, store: $2}
clock: {duration: 100ms}
YAML
}
scenario_with_eds() {
  cat >"$tmp/$1.yaml" <<YAML
buses: [{name: main, transport: virtual}]
nodes:
  - {name: io, device: eds, eds: $2, node_id: 5, bus: main}
clock: {duration: 100ms}
YAML
}

expect_refusal "node --eds FIFO" "$tmp/fifo.eds: not a regular file (a FIFO)" \
  "$vplant" node --eds "$tmp/fifo.eds" --virtual --duration 0.1
expect_refusal "node --eds /dev/zero" "/dev/zero: not a regular file (a character device)" \
  "$vplant" node --eds /dev/zero --virtual --duration 0.1
expect_refusal "node --eds DIR" "$tmp: not a regular file (a directory)" \
  "$vplant" node --eds "$tmp" --virtual --duration 0.1
expect_refusal "node --store FIFO" "$tmp/fifo.store: not a regular file (a FIFO)" \
  "$vplant" node --eds "$eds" --store "$tmp/fifo.store" --virtual --duration 0.1
expect_refusal "node --store /dev/zero" "/dev/zero: not a regular file (a character device)" \
  "$vplant" node --eds "$eds" --store /dev/zero --virtual --duration 0.1
expect_refusal "node --store DIR" "$tmp: not a regular file (a directory)" \
  "$vplant" node --eds "$eds" --store "$tmp" --virtual --duration 0.1
expect_refusal "run FIFO" "$tmp/fifo.yaml: not a regular file (a FIFO)" "$vplant" run "$tmp/fifo.yaml"
expect_refusal "run /dev/zero" "/dev/zero: not a regular file (a character device)" "$vplant" run /dev/zero
scenario_with_eds eds_fifo "$tmp/fifo.eds"
expect_refusal "run eds: FIFO" "not a regular file (a FIFO)" "$vplant" run "$tmp/eds_fifo.yaml"
scenario_with_eds eds_zero /dev/zero
expect_refusal "run eds: /dev/zero" "not a regular file (a character device)" "$vplant" run "$tmp/eds_zero.yaml"
scenario_with_store store_fifo "$tmp/fifo.store"
expect_refusal "run store: FIFO" "store: $tmp/fifo.store: not a regular file (a FIFO)" "$vplant" run "$tmp/store_fifo.yaml"
scenario_with_store store_dir "$tmp"
expect_refusal "run store: DIR" "store: $tmp: not a regular file (a directory)" "$vplant" run "$tmp/store_dir.yaml"
scenario_with_store store_zero /dev/zero
expect_refusal "run store: /dev/zero" "store: /dev/zero: not a regular file (a character device)" "$vplant" run "$tmp/store_zero.yaml"

# SIGTERM stops a real-time node within a second, with its summary and exit 0.
"$vplant" node --eds "$eds" >"$tmp/node.out" 2>&1 &
pid=$!
sleep 1
kill -TERM $pid
start=$(date +%s%N)
( sleep 3; kill -KILL $pid 2>/dev/null ) &
killer=$!
wait $pid
rc=$?
elapsed_ms=$(( ($(date +%s%N) - start) / 1000000 ))
kill $killer 2>/dev/null
if [ $rc -ne 0 ] || [ $elapsed_ms -gt 1000 ] || ! grep -q "s simulated" "$tmp/node.out"; then
  echo "FAIL node SIGTERM: exit $rc after $elapsed_ms ms, output:"
  cat "$tmp/node.out"
  failures=$((failures + 1))
else
  echo "ok   node SIGTERM ($elapsed_ms ms)"
fi

exit $failures
