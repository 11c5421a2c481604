#!/bin/sh
# The `vplant test` command lines of docs/ci.md, taken from the page word for word and run on
# scenarios/regression as the CI jobs run them (from a checkout with the binary in build/): the
# GitHub Actions line as shard 1 of 2, the GitLab line with CI_NODE_INDEX=2 CI_NODE_TOTAL=2. Both
# pass; together their JUnit files hold every regression scenario as a testsuite, each once. Then
# the external master's lines: the plant on socketcand, and a python-can client on it.
# Usage: ci_commands_test.sh VPLANT SRC
set -u
vplant=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() {
  echo "FAIL $1"
  failures=$((failures + 1))
}

github=$(sed -n 's/^ *- run: \(build\/tools\/vplant\/vplant test .*\)$/\1/p' "$src/docs/ci.md")
gitlab=$(sed -n 's/^ *- \(build\/tools\/vplant\/vplant test .*\)$/\1/p' "$src/docs/ci.md")
[ -n "$github" ] || fail "docs/ci.md has no GitHub Actions 'vplant test' line"
[ -n "$gitlab" ] || fail "docs/ci.md has no GitLab CI 'vplant test' line"
[ $failures -eq 0 ] || exit 1
github=$(printf '%s' "$github" | sed 's/\${{ matrix.shard }}/1/')

# A checkout as CI has it: scenarios/ and the binary at build/tools/vplant/vplant.
for job in github gitlab; do
  mkdir -p "$tmp/$job/build/tools/vplant"
  ln -s "$src/scenarios" "$tmp/$job/scenarios"
  ln -s "$vplant" "$tmp/$job/build/tools/vplant/vplant"
done
(cd "$tmp/github" && sh -c "$github") >"$tmp/github.txt" 2>&1 || { cat "$tmp/github.txt"; fail "the GitHub Actions line: $github"; }
(cd "$tmp/gitlab" && CI_NODE_INDEX=2 CI_NODE_TOTAL=2 sh -c "$gitlab") >"$tmp/gitlab.txt" 2>&1 ||
  { cat "$tmp/gitlab.txt"; fail "the GitLab CI line: $gitlab"; }

(cd "$src" && "$vplant" test scenarios/regression --list) | sort >"$tmp/all.txt"
cat "$tmp/github/out/junit.xml" "$tmp/gitlab/out/junit.xml" | sed -n 's/^  <testsuite name="\([^"]*\)".*/\1/p' | sort >"$tmp/suites.txt"
cmp "$tmp/all.txt" "$tmp/suites.txt" || { diff "$tmp/all.txt" "$tmp/suites.txt"; fail "the two shards' JUnit suites are not the suite, each once"; }
[ "$(wc -l <"$tmp/all.txt")" -eq "$(ls "$src"/scenarios/regression/*.yaml | wc -l)" ] || fail "not one case per regression file"
for job in github gitlab; do [ -s "$tmp/$job/out/report/index.html" ] || fail "$job: no out/report/index.html"; done

# The external master's lines: the plant served over socketcand (no vcan, no root), the wait for
# its "is up" line, then a python-can client (the master's stand-in) reads the HLT 1100's 1000h by
# SDO over bus main.
plant=$(grep '^vplant run scenarios/reference-plant.yaml .*--can main=socketcand:127.0.0.1:29536 .*&$' "$src/docs/ci.md")
wait_up=$(grep "^until grep -q ' is up:' plant.log" "$src/docs/ci.md")
if [ -z "$plant" ] || [ -z "$wait_up" ]; then
  fail "docs/ci.md has no socketcand plant line and wait line"
else
  mkdir -p "$tmp/socketcand/bin"
  ln -s "$vplant" "$tmp/socketcand/bin/vplant"
  ln -s "$src/scenarios" "$tmp/socketcand/scenarios"
  cd "$tmp/socketcand" || exit 1
  PATH="$tmp/socketcand/bin:$PATH" sh -c "$plant
echo \$! >plant.pid"
  if timeout 20 sh -c "$wait_up"; then
    /usr/bin/python3 -c 'import can, time
bus = can.Bus(interface="socketcand", host="127.0.0.1", port=29536, channel="main")
bus.send(can.Message(arbitration_id=0x605, data=[0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0], is_extended_id=False))
end = time.monotonic() + 5
answer = None
while answer is None and time.monotonic() < end:
    frame = bus.recv(0.5)
    if frame is not None and frame.arbitration_id == 0x585:
        answer = frame
bus.shutdown()
raise SystemExit(0 if answer is not None else "no SDO answer from the HLT 1100 (0x585)")' ||
      fail "the plant over socketcand: no SDO answer to python-can"
  else
    cat plant.log
    fail "the socketcand plant did not come up"
  fi
  kill -INT "$(cat plant.pid)" 2>/dev/null
  cd "$tmp" || exit 1
fi

[ $failures -eq 0 ] && echo "ok   docs/ci.md's command lines" || exit 1
