#!/usr/bin/env bash
# A student's algorithm in Python against the same algorithm in C++, whole vacuum runs
# (headless, lockstep: simulator + component + referee): the deterministic bounce
# (tests/data/plugins/vacuum_bounce.cpp) and its line-by-line Python port
# (tests/data/python/vacuum_bounce/MyAlgorithm.py), which earn the same report. Alternated, so
# that both share the machine's moods. 900 s runs give the ratio; 1 s runs (13 execute() calls)
# give the start-up, the Python host's included; the rest, over 11,250 calls, is what an
# execute() in Python costs more than in C++.
#   bench/python_vs_cpp.sh [BUILD_DIR] [RUNS]
# Needs the test plugin: cmake --build BUILD_DIR --target aula_test_vacuum_bounce aula_vacuum_python
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
runs="${2:-7}"
cpp="$build/tests/integration/plugins/libaula_test_vacuum_bounce.so"
python="$root/tests/data/python/vacuum_bounce/MyAlgorithm.py"
[ -f "$cpp" ] || { echo "no $cpp: cmake --build $build --target aula_test_vacuum_bounce"; exit 2; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
port=$((20000 + $$ % 20000))
median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2] + a[NR/2+1]) / 2}'; }
# wall LANGUAGE ALGORITHM DURATION: one run's wall seconds, appended to $out/LANGUAGE-DURATION
wall() {
  local start end
  start=$(date +%s.%N)
  "$build/bin/aula" run vacuum --headless --algorithm="$2" --Vacuum.Referee.Duration="$3" \
    --report="$out/$1.json" --lcm-url="udpm://239.255.76.67:$port?ttl=0" >/dev/null 2>&1
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l >> "$out/$1-$3"
}
for _ in $(seq "$runs"); do
  for duration in 900 1; do
    wall cpp "$cpp" $duration
    wall python "$python" $duration
  done
done
cmp -s <(grep -v '"algorithm"' "$out/cpp.json") <(grep -v '"algorithm"' "$out/python.json") ||
  { echo "the two reports differ: not the same algorithm"; exit 1; }
cpp900=$(median < "$out/cpp-900"); py900=$(median < "$out/python-900")
cpp1=$(median < "$out/cpp-1"); py1=$(median < "$out/python-1")
printf 'vacuum 900 s, median of %s runs each: C++ bounce %.2f s, Python bounce %.2f s: Python/C++ = %.2f\n' \
  "$runs" "$cpp900" "$py900" "$(echo "$py900 / $cpp900" | bc -l)"
printf 'vacuum 1 s (start-up): C++ %.3f s, Python %.3f s: the Python host starts in %.0f ms more\n' \
  "$cpp1" "$py1" "$(echo "($py1 - $cpp1) * 1000" | bc -l)"
printf 'per execute() call, Python more than C++: %.1f us (over 11,237 calls more)\n' \
  "$(echo "(($py900 - $cpp900) - ($py1 - $cpp1)) * 1000000 / 11237" | bc -l)"
