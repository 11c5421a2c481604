#!/bin/sh
# Installs the build tree to a temporary prefix, copies examples/cylinder_master out of the
# source tree, configures and builds it there against the prefix (find_package(vplant)), runs its
# GoogleTest, runs the installed CLI on the installed reference plant, and removes everything.
#   example-against-install.sh BUILD_DIR SOURCE_DIR [COMPILER_LAUNCHER]
set -eu
build=$1 src=$2 launcher=${3:-}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vplant-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
cp -r "$src/examples/cylinder_master" "$tmp/example"
set -- -S "$tmp/example" -B "$tmp/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="-Wall -Wextra -Werror"
[ -n "$launcher" ] && set -- "$@" -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher"
cmake "$@" >/dev/null
cmake --build "$tmp/build" -j2
ctest --test-dir "$tmp/build" --output-on-failure
# The installed CLI finds everything it needs under the prefix (its outputs go to the cwd).
cd "$tmp"
"$prefix/bin/vplant" run "$prefix/share/vplant/scenarios/reference-plant.yaml" --quiet
echo "example built and passed against $prefix; the installed CLI ran the reference plant"
