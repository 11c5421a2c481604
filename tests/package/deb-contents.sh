#!/bin/sh
# Builds the Debian package with CPack from the build tree into a temporary directory and checks
# its name, its file list (dpkg-deb -c), its Depends (dpkg-deb -f: the runtime packages of the
# CLI's shared libraries), that the packaged CLI runs the packaged reference plant and that the
# example master builds against the unpacked package and passes.
#   deb-contents.sh BUILD_DIR VERSION
set -eu
build=$1 version=$2
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vplant-deb.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
cpack --config "$build/CPackConfig.cmake" -B "$tmp" >"$tmp/cpack.out" 2>&1 || { cat "$tmp/cpack.out"; exit 1; }
deb=$tmp/vplant_${version}_$(dpkg --print-architecture).deb
[ -f "$deb" ] || { echo "no $deb"; ls "$tmp"; exit 1; }
dpkg-deb -c "$deb" | awk '{print $6}' >"$tmp/files"
fail=0
for f in ./usr/bin/vplant ./usr/include/vplant/simulation.h ./usr/include/vplant/frame.h ./usr/include/vplant/error.h \
         ./usr/lib/libvplant_api.a ./usr/lib/libvplant_engine.a ./usr/lib/cmake/vplant/vplantConfig.cmake \
         ./usr/lib/cmake/vplant/vplantConfigVersion.cmake ./usr/lib/cmake/vplant/vplantTargets.cmake \
         ./usr/share/vplant/eds/WAGDSVC1.eds ./usr/share/vplant/eds/hlt1100.eds ./usr/share/vplant/eds/vtvpcd.eds \
         ./usr/share/vplant/scenarios/reference-plant.yaml ./usr/share/vplant/exercises/nmt.yaml ./usr/share/doc/vplant/README.md \
         ./usr/share/doc/vplant/embedding.md; do
  grep -qx "$f" "$tmp/files" || { echo "missing from the package: $f"; fail=1; }
done
# Nothing private: only the public headers.
if grep -E '^\./usr/include/' "$tmp/files" | grep -v -E '^\./usr/include/(vplant/.*)?$'; then
  echo "headers outside include/vplant/"; fail=1
fi
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for p in libc6 libstdc++6 libyaml-cpp0.7 libode8 libfmt9 libmicrohttpd12; do
  echo "$depends" | tr ',' '\n' | sed 's/^ *//; s/ .*//' | grep -qxF "$p" || { echo "Depends lacks $p"; fail=1; }
done
[ "$(dpkg-deb -f "$deb" Package)" = vplant ] && [ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || { echo "bad Package/Version"; fail=1; }
# The packaged CLI, unpacked, on the packaged reference plant.
dpkg-deb -x "$deb" "$tmp/root"
(cd "$tmp" && "$tmp/root/usr/bin/vplant" run "$tmp/root/usr/share/vplant/scenarios/reference-plant.yaml" --quiet) || fail=1
# The packaged (debug-stripped) libraries link: the example against the unpacked tree.
src=$(cd "$(dirname "$0")/../.." && pwd)
cp -r "$src/examples/cylinder_master" "$tmp/example"
{ cmake -S "$tmp/example" -B "$tmp/example-build" -DCMAKE_PREFIX_PATH="$tmp/root/usr" -DCMAKE_BUILD_TYPE=Release >/dev/null &&
  cmake --build "$tmp/example-build" -j2 >/dev/null && "$tmp/example-build/cylinder_master_test" --gtest_brief=1; } || fail=1
[ $fail -eq 0 ] && echo "$(basename "$deb"): $(wc -l <"$tmp/files") entries, $(du -h "$deb" | cut -f1)"
exit $fail
