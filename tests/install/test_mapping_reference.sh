#!/usr/bin/env bash
# The vacuum's mapping reference uses the student API alone: its sources
# (components/vacuum/reference/mapping), copied into a project made by `aula new`, build against
# an installed Aula with the source and build trees hidden (bubblewrap, as test_install.sh), and
# the plugin cleans the house exactly as --algorithm=reference does (same seed, same report
# figures: the same code, and lockstep makes a run repeatable).
# Usage: test_mapping_reference.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src="$1"; build="$2"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-mapping-XXXXXX")"
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/prefix" >/dev/null
mkdir -p "$work/sources"
cp "$src"/components/vacuum/reference/mapping/*.cpp "$src"/components/vacuum/reference/mapping/*.hpp "$work/sources/"
port=$(python3 "$(dirname "$0")/../free_udp_port.py")
url="udpm://239.255.76.67:$port?ttl=0"
bwrap --dev-bind / / --tmpfs "$src" --tmpfs "$build" --die-with-parent \
  --setenv XDG_CACHE_HOME "$work/cache" --unsetenv AULA_DATA_DIR --unsetenv DISPLAY \
  bash -c "set -e
  test ! -e '$src/CMakeLists.txt' && test ! -e '$build/CMakeCache.txt'
  '$work/prefix/bin/aula' new vacuum '$work/student' >/dev/null
  rm '$work/student/MyAlgorithm.cpp'
  cp '$work'/sources/* '$work/student/'
  sed -i 's/SOURCES MyAlgorithm.cpp/SOURCES plugin.cpp scan_map.cpp coverage_planner.cpp mapping_reference.cpp/' '$work/student/CMakeLists.txt'
  cmake -S '$work/student' -B '$work/student/build' >/dev/null
  cmake --build '$work/student/build' >'$work/build.txt' 2>&1 || { cat '$work/build.txt'; exit 1; }
  cd '$work'
  '$work/prefix/bin/aula' run vacuum --headless --seed=2 --algorithm='$work/student/build/libmy_algorithm.so' \
      --report=plugin.json --lcm-url='$url' >'$work/out.txt' 2>&1 || true
"
[ -s "$work/plugin.json" ] || { echo "no report from the plugin; the run printed:"; cat "$work/out.txt"; exit 1; }
"$build/bin/aula" run vacuum --headless --seed=2 --algorithm=reference --report="$work/builtin.json" --lcm-url="$url" >/dev/null 2>&1
figure() { grep "^  \"$1\"" "$2" | sed 's/.*: \([0-9.]*\),*/\1/'; }
plugin=$(figure coverage_percent "$work/plugin.json"); builtin=$(figure coverage_percent "$work/builtin.json")
echo "mapping reference, seed 2: as a plugin from the prefix $plugin %, built in $builtin %"
grep -q '"algorithm": "libmy_algorithm.so"' "$work/plugin.json" || { echo "the report does not name the plugin"; exit 1; }
[ "$plugin" = "$builtin" ] || { echo "the plugin and the built-in reference differ"; exit 1; }
