#!/usr/bin/env bash
# A compile error in one exercise's student file does not stop another exercise: with the vacuum
# student's MyAlgorithm.cpp broken (a broken copy mounted over it by bubblewrap, so the tree is
# never touched), `ninja aula_run_teletaxi` (what ./aula run teletaxi builds) succeeds and TeleTaxi
# runs to its mark, while `ninja aula_run_vacuum` fails on that file.
# Usage: test_broken_student_file.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir="$1"
build="$2"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-broken-student-XXXXXX")"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; cat "$work"/*.txt 2>/dev/null || true; exit 1; }

student="$source_dir/components/vacuum/student/MyAlgorithm.cpp"
{ cat "$student"; echo 'this line does not compile;'; } >"$work/MyAlgorithm.cpp"
port=$(python3 "$(dirname "$0")/../free_udp_port.py")
in_sandbox() { bwrap --dev-bind / / --ro-bind "$work/MyAlgorithm.cpp" "$student" "$@"; }

in_sandbox grep -q "this line does not compile" "$student" || fail "the broken copy is not mounted"
in_sandbox ninja -C "$build" aula_run_teletaxi >"$work/build_teletaxi.txt" 2>&1 \
  || fail "a broken vacuum student file stopped TeleTaxi's build"
in_sandbox "$build/bin/aula" run teletaxi --headless --algorithm=reference --seed=1 \
  --report="$work/teletaxi.json" --lcm-url="udpm://239.255.76.67:$port?ttl=0" >"$work/run.txt" 2>&1 \
  || fail "TeleTaxi did not run"
grep -q '"mark"' "$work/teletaxi.json" || fail "no mark for TeleTaxi"
if in_sandbox ninja -C "$build" aula_run_vacuum >"$work/build_vacuum.txt" 2>&1; then
  fail "the broken vacuum student file built"
fi
grep -q "MyAlgorithm.cpp" "$work/build_vacuum.txt" || fail "the vacuum build did not fail on the student file"
echo "a broken vacuum student file leaves TeleTaxi building and running"
