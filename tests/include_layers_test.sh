#!/bin/sh
# The include direction of docs/architecture.md's layers: no folder includes one above it.
# Each rule: FOLDER, then the include prefixes it must not use. Prints every offending line.
cd "${1:?source root}" || exit 2
status=0
rule() {
  folder=$1; shift
  for banned in "$@"; do
    hits=$(grep -rn --include='*.h' --include='*.cpp' "#include \"$banned" "$folder" 2>/dev/null)
    if [ -n "$hits" ]; then
      printf '%s must not include %s:\n%s\n' "$folder" "$banned" "$hits"
      status=1
    fi
  done
}
rule sim devices/ plant/ engine/ control/ api/
rule plant devices/ engine/ control/ api/
rule devices engine/ control/ api/ plant/
rule engine control/ api/
rule engine/loading engine/running/ engine/reporting/ engine/runner.h
rule engine/running engine/reporting/ engine/runner.h
rule engine/reporting engine/runner.h
exit $status
