#!/usr/bin/env bash
# An installed Aula, used the way a student uses it: install into a prefix, then - with the
# source and build trees hidden (an empty folder mounted over each, bubblewrap) - scaffold a
# project with `aula new`, build it against the prefix only, run it headless and get a report;
# and the installed MyAlgorithm.py template, run as it is (nothing to build), gives one too.
# Usage: test_install.sh SOURCE_DIR BUILD_DIR EXERCISE
set -euo pipefail
src="$1"; build="$2"; exercise="$3"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-install-XXXXXX")"
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/prefix" >/dev/null
# Nothing but the prefix from here on: the trees are empty folders inside the sandbox.
port=$(python3 "$(dirname "$0")/../free_udp_port.py")
case "$exercise" in
  vacuum) short="--Vacuum.Referee.Duration=20" ;;
  teletaxi) short="--TeleTaxi.Referee.Timeout=20" ;;
  autopark) short="--Autopark.Referee.Timeout=20" ;;
esac
# A slow machine is waited for: the default backstop (the episode x 1.5 + 60 s, 90 s here) ran
# out on a loaded 2-core machine before the Python template's process had started.
short="$short --timeout=900"
# Every header the exercise's API installs must compile from the prefix alone (each one may
# include others: they must be installed too). They go first in the student's file.
extra=""
[ "$exercise" = teletaxi ] && extra="aula/world/map_transform.hpp"  # the old path, kept for plugins
(cd "$work/prefix/include" && for h in aula/"$exercise"/*.hpp $extra; do echo "#include <$h>"; done) >"$work/api_headers.inc"
run() {
  bwrap --dev-bind / / --tmpfs "$src" --tmpfs "$build" --die-with-parent \
    --setenv XDG_CACHE_HOME "$work/cache" --unsetenv AULA_DATA_DIR --unsetenv DISPLAY \
    bash -c "$1"
}
run "set -e
  test ! -e '$src/CMakeLists.txt' && test ! -e '$build/CMakeCache.txt'
  '$work/prefix/bin/aula' new $exercise '$work/student'
  cat '$work/api_headers.inc' '$work/student/MyAlgorithm.cpp' >'$work/with_headers.cpp'
  mv '$work/with_headers.cpp' '$work/student/MyAlgorithm.cpp'
  cmake -S '$work/student' -B '$work/student/build' >/dev/null
  cmake --build '$work/student/build' >'$work/build.txt' 2>&1 || { cat '$work/build.txt'; exit 1; }
  test -f '$work/student/build/libmy_algorithm.so'
  cd '$work'
  '$work/prefix/bin/aula' run $exercise --headless --algorithm='$work/student/build/libmy_algorithm.so' \
      --report=r.json --lcm-url='udpm://239.255.76.67:$port?ttl=0' \
      $short >'$work/out.txt' 2>&1 || true
  '$work/prefix/bin/aula' new $exercise '$work/student_py' --python >'$work/new_py.txt' 2>&1
  '$work/prefix/bin/aula' run $exercise --headless --algorithm='$work/student_py/MyAlgorithm.py' \
      --report=py.json --lcm-url='udpm://239.255.76.67:$port?ttl=0' \
      $short >'$work/py_out.txt' 2>&1 || true
"
if [ ! -s "$work/r.json" ]; then
  echo "no report; the run printed:"; cat "$work/out.txt"; exit 1
fi
grep -q "\"exercise\": \"$exercise\"" "$work/r.json" || { echo "report is not $exercise's:"; cat "$work/r.json"; exit 1; }
grep -q '"algorithm": "libmy_algorithm.so"' "$work/r.json" || { echo "report does not name the plugin:"; cat "$work/r.json"; exit 1; }
if [ ! -s "$work/py.json" ] || ! grep -q '"algorithm": "MyAlgorithm.py"' "$work/py.json" || grep -q '"algorithm_error"' "$work/py.json"; then
  echo "the installed MyAlgorithm.py template gave no clean report; the run printed:"; cat "$work/py_out.txt"
  cat "$work/py.json" 2>/dev/null; exit 1
fi
for stub in "aula_$exercise.pyi" aula_devices.pyi; do
  test -s "$work/prefix/share/aula/templates/$exercise/$stub" || { echo "no $stub installed"; exit 1; }
  test -s "$work/student_py/$stub" || { echo "aula new --python wrote no $stub:"; cat "$work/new_py.txt"; exit 1; }
done
# The README aula new writes carries the exercise's student page, as installed.
grep -q "a student's page" "$work/student_py/README.md" || { echo "aula new's README lacks the student page:"; cat "$work/student_py/README.md"; exit 1; }
if grep -rq -- "$src\|$build" "$work/prefix/bin" "$work/prefix/lib/aula"; then
  echo "an installed binary names the source or build tree:"; grep -rl -- "$src\|$build" "$work/prefix/bin" "$work/prefix/lib/aula"; exit 1
fi
echo "ok: $exercise from the prefix alone"; cat "$work/r.json"
