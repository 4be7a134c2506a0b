#!/usr/bin/env bash
# cpack -G DEB gives aula_<version>_amd64.deb, with Depends from dpkg-shlibdeps, listing the
# programs, the student API headers, the worlds, the CMake package, the Python hosts and stubs,
# the Debian Python packages a student's MyAlgorithm.py runs on, and the documentation that
# `aula --help` names; lintian finds no error in it.
# Usage: test_package.sh BUILD_DIR
set -euo pipefail
build="$1"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-deb-XXXXXX")"
trap 'rm -rf "$work"' EXIT
(cd "$work" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work" >/dev/null)
deb="$(ls "$work"/aula_*_amd64.deb)"
contents="$(dpkg-deb -c "$deb")"
for path in ./usr/bin/aula ./usr/bin/aula-sim ./usr/bin/vacuum-cleaner ./usr/bin/teletaxi-referee \
    ./usr/include/aula/vacuum/vacuum_algorithm.hpp ./usr/include/aula/component/devices.hpp \
    ./usr/include/aula/episode_t.hpp ./usr/share/aula/worlds/vacuum.world ./usr/share/aula/config/vacuumCleaner.cfg \
    ./usr/lib/cmake/Aula/AulaConfig.cmake ./usr/lib/aula/algorithms/libaula_vacuum_student.so \
    ./usr/share/aula/templates/teletaxi/MyAlgorithm.cpp ./usr/lib/aula/python/libaula_vacuum_python.so \
    ./usr/lib/aula/python/libaula_teletaxi_python.so ./usr/lib/aula/python/libaula_autopark_python.so \
    ./usr/share/aula/templates/vacuum/MyAlgorithm.py ./usr/share/aula/templates/vacuum/aula_vacuum.pyi \
    ./usr/share/aula/templates/vacuum/aula_devices.pyi ./usr/share/aula/references/vacuum/classic/RoombaReference.cpp \
    ./usr/share/aula/references/teletaxi/reference/GppReference.cpp; do
  grep -q " $path\$" <<<"$contents" || { echo "missing from $deb: $path"; exit 1; }
done
depends="$(dpkg-deb -f "$deb" Depends)"
for lib in libdart liblcm libqt5widgets libopencv-core "libpython3\.[0-9]*" python3-numpy python3-opencv python3-greenlet binutils; do
  grep -q "$lib" <<<"$depends" || { echo "Depends lacks $lib (dpkg-shlibdeps): $depends"; exit 1; }
done
grep -q "cmake" <<<"$depends" || { echo "Depends lacks what a plugin build needs: $depends"; exit 1; }
# The docs `aula --help` points to are in the package, at the path it names.
docs="$("$build/bin/aula" --help | sed -n 's/^docs: \([^ ]*\) .*/\1/p')"
[ "$(basename "$docs")" = aula ] && [ "$(basename "$(dirname "$docs")")" = doc ] || { echo "aula --help names no doc folder: $docs"; exit 1; }
for doc in grading.md worlds.md exercises/vacuum.md exercises/teletaxi.md exercises/autopark.md copyright changelog.Debian.gz; do
  grep -q " ./usr/share/doc/aula/$doc\$" <<<"$contents" || { echo "missing from $deb: /usr/share/doc/aula/$doc (aula --help names it)"; exit 1; }
done
# Debian's own checks: no error (warnings are listed, not fatal).
if command -v lintian >/dev/null; then
  lintian --no-tag-display-limit "$deb" >"$work/lintian.txt" 2>&1 || true
  if grep -q "^E: " "$work/lintian.txt"; then echo "lintian errors:"; grep "^E: " "$work/lintian.txt"; exit 1; fi
  echo "lintian: $(grep -c "^W: " "$work/lintian.txt" || true) warning(s), no error"
else
  echo "lintian is not installed (scripts/install-deps.sh test installs it)"; exit 1
fi
echo "ok: $(basename "$deb")"; echo "Depends: $depends"
