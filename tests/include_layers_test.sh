#!/bin/sh
# The include direction of docs/architecture.md's layers: no folder includes one above it.
# Each rule: FOLDER, then the include prefixes it must not use. Prints every offending line.
cd "${1:?source root}" || exit 2
status=0
# EXCEPT (a regular expression of file paths) is left out of the next rule.
rule() {
  folder=$1; shift
  for banned in "$@"; do
    hits=$(grep -rn --include='*.h' --include='*.cpp' "#include \"$banned" "$folder" 2>/dev/null | grep -Ev "^(${EXCEPT:-^$}):")
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
# The CANopen node wires its services from above: no service includes the node that owns it.
EXCEPT='devices/canopen/node\.(h|cpp)' rule devices/canopen devices/canopen/node.h
# A product knows the Product struct (devices/product.h), not the registry that lists them all.
EXCEPT='devices/registry\.(h|cpp)|devices/configured_eds\.h' rule devices devices/registry.h
# sim/: only the one strict YAML field reader (yaml_fields.*, its own library vplant_yaml_fields)
# includes the YAML parser, so vplant_sim links none.
hits=$(grep -rn --include='*.h' --include='*.cpp' '#include <yaml-cpp/' sim | grep -Ev '^sim/yaml_fields\.(h|cpp):')
if [ -n "$hits" ]; then
  printf 'only sim/yaml_fields.* may include yaml-cpp in sim/:\n%s\n' "$hits"
  status=1
fi
exit $status
