#!/bin/sh
# `vplant test`: which files are scenarios, shards that are disjoint and whole, a three-value
# sweep as three named cases with different outcomes (also through `vplant run` and `--case`), a
# hanging case stopped by --timeout while the others finish, a broken file reported with its
# file:line:col while the others run, and the exit codes. Usage: test_command_test.sh VPLANT SRC
set -u
vplant=$1
src=$2
data=$src/tests/data/scenarios/suite
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
failures=0

# check NAME COMMAND...: the command must succeed.
check() {
  name=$1
  shift
  if "$@"; then
    echo "ok   $name"
  else
    echo "FAIL $name"
    failures=$((failures + 1))
  fi
}
# run_rc WANT OUTFILE COMMAND...: run the command (output to OUTFILE); true when it exits WANT.
run_rc() {
  want=$1 out=$2
  shift 2
  "$@" >"$out" 2>&1
  rc=$?
  [ $rc -eq "$want" ] || { echo "exit $rc, want $want:"; cat "$out"; return 1; }
}
has() { grep -qF -- "$1" "$2" || { echo "'$1' not in $2:"; cat "$2"; return 1; }; }

# Folders: every *.yaml except *.plant.yaml, in sorted order; a sweep lists each combination.
check "folder lists the scenarios, not the plant file" run_rc 0 list.txt "$vplant" test "$data/cases" --list
printf '%s\n' 'cylinder-sweep[plant.pump.initial_swivel_angle=0.2]' 'cylinder-sweep[plant.pump.initial_swivel_angle=0.3]' \
  'cylinder-sweep[plant.pump.initial_swivel_angle=0.4]' quick >want.txt
check "the four cases, in order" cmp list.txt want.txt

# Shards: disjoint, and together the whole suite (here and on the regression folder).
for dir in "$data/cases" "$src/scenarios"; do
  "$vplant" test "$dir" --list | sort >all.txt
  : >union.txt
  for k in 1 2 3; do
    "$vplant" test "$dir" --shard $k/3 --list | sort >shard$k.txt
    check "shard $k/3 of $dir is not empty" test -s shard$k.txt
    cat shard$k.txt >>union.txt
  done
  sort union.txt >union-sorted.txt
  check "shards of $dir together are the suite, each case once" cmp all.txt union-sorted.txt
done
check "--filter on case names" run_rc 0 filtered.txt "$vplant" test "$src/scenarios" --filter 'fault-wire-*' --list
check "--filter keeps the four wire-fault cases" test "$(wc -l <filtered.txt)" -eq 4

# A three-value sweep: three named cases, one passes, two fail at the slope's line.
line=$(grep -n 'slope: 0.164' "$data/cases/cylinder-sweep.yaml" | cut -d: -f1)
check "sweep exits 1" run_rc 1 sweep.txt "$vplant" test "$data/cases/cylinder-sweep.yaml" -j 2 --junit sweep.xml
check "sweep 0.3 passes" has "PASS    cylinder-sweep[plant.pump.initial_swivel_angle=0.3]" sweep.txt
check "sweep 0.2 fails" has "FAIL    cylinder-sweep[plant.pump.initial_swivel_angle=0.2]" sweep.txt
check "sweep 0.4 fails" has "FAIL    cylinder-sweep[plant.pump.initial_swivel_angle=0.4]" sweep.txt
check "sweep JUnit: a testsuite per case" test "$(grep -c '<testsuite ' sweep.xml)" -eq 3
check "sweep JUnit: the failures with file:line:col" \
  test "$(grep -c "cylinder-sweep.yaml:$((line - 1)):5: at t=" sweep.xml)" -eq 2
# Each case: its assertion plus one test case per rule of the verdict on the master (docs/masters.md).
check "sweep JUnit: two failures counted" has '<testsuites tests="36" failures="2" errors="0"' sweep.xml
check "sweep JUnit: a testsuite per case" test "$(grep -c '^  <testsuite name=' sweep.xml)" -eq 3
check "vplant run runs every combination" run_rc 1 run.txt "$vplant" run "$data/cases/cylinder-sweep.yaml"
check "vplant run: three summaries" test "$(grep -c '^vplant run: cylinder-sweep\[' run.txt)" -eq 3
check "vplant run --case runs one" run_rc 0 case.txt "$vplant" run "$data/cases/cylinder-sweep.yaml" --quiet \
  --case 'cylinder-sweep[plant.pump.initial_swivel_angle=0.3]'
check "vplant run --case with an unknown name exits 2" run_rc 2 nocase.txt "$vplant" run "$data/cases/quick.yaml" --case nope
check "... and names the file" has "quick.yaml: no case named 'nope'" nocase.txt

# A case that hangs is stopped by its timeout and reported; the other one finishes.
start=$(date +%s)
check "hanging case: exit 1" run_rc 1 hang.txt "$vplant" test "$data/hangs.yaml" "$data/cases/quick.yaml" -j 2 --timeout 2s \
  --junit hang.xml
check "hanging case: stopped within seconds" test $(($(date +%s) - start)) -lt 30
check "hanging case: TIMEOUT" has "TIMEOUT hangs" hang.txt
check "hanging case: the other passes" has "PASS    quick" hang.txt
check "hanging case: an error suite in the JUnit" has '<error message="TIMEOUT: stopped after the --timeout of 2s">' hang.xml

# A file that does not load: exit 2 with its file:line:col; the others still run.
check "broken file: exit 2" run_rc 2 broken.txt "$vplant" test "$data/broken.yaml" "$data/cases/quick.yaml"
check "broken file: file:line:col" has "$data/broken.yaml:6:1: unknown key 'colck'" broken.txt
check "broken file: the other passes" has "PASS    quick" broken.txt

# Bad options and paths: exit 2 with a reason.
check "--shard 3/2" run_rc 2 o.txt "$vplant" test "$data/cases" --shard 3/2
check "--timeout not a duration" run_rc 2 o.txt "$vplant" test "$data/cases" --timeout soon
check "a missing path" run_rc 2 o.txt "$vplant" test "$data/nothing-here"
check "... named" has "nothing-here: no such file or folder" o.txt
check "--filter matching nothing" run_rc 2 o.txt "$vplant" test "$data/cases" --filter 'zz*'

[ $failures -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
