#!/usr/bin/env bash
# Grading throughput: a class of N vacuum submissions x S seeds, graded by `aula grade` once with
# --jobs=1 and once with --jobs=2, in this one script (a ratio on one machine, so a noisy
# machine still gives a fair figure). Prints runs per minute for each and the parallel
# efficiency = throughput(jobs=2) / (2 x throughput(jobs=1)).
# Usage: bench/grade_class.sh BUILD_DIR [STUDENTS=30] [SEEDS=5] [EXTRA aula grade options...]
set -euo pipefail
build="$(cd "$1" && pwd)"; students="${2:-30}"; seeds="${3:-5}"; shift $(( $# < 3 ? $# : 3 ))
src="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-grade-bench-XXXXXX")"
trap 'rm -rf "$work"' EXIT

# The class: the reference, as students would hand it in (each its own plugin build).
for i in $(seq -w 1 "$students"); do
  mkdir -p "$work/class/student$i"
  { cat "$src/components/vacuum/reference/RoombaReference.cpp"
    printf '\nnamespace aula::vacuum {\nstd::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t seed) { return makeReferenceAlgorithm(seed); }\n}  // namespace aula::vacuum\n'
  } >"$work/class/student$i/MyAlgorithm.cpp"
done

# Compiling is not grading: a first batch builds the plugins; the measured batches reuse that
# build folder (their compile step is then a no-op of well under a second per student).
out="$work/out"
t0=$(date +%s.%N)
"$build/bin/aula" grade vacuum "$work"/class/* --seeds=1 --jobs=2 --out="$out" "$@" >/dev/null
t1=$(date +%s.%N)

measure() {  # measure JOBS [options] -> seconds of wall time for the whole batch
  local jobs="$1"; shift
  rm -rf "$out/runs" "$out/grades.csv"
  local start end
  start=$(date +%s.%N)
  "$build/bin/aula" grade vacuum "$work"/class/* --seeds=1-"$seeds" --jobs="$jobs" --out="$out" "$@" >"$work/jobs$jobs.txt"
  end=$(date +%s.%N)
  cp "$out/grades.csv" "$work/grades-jobs$jobs.csv"
  echo "$end - $start" | bc -l
}
runs=$((10#$students * seeds))
s1=$(measure 1 "$@")
s2=$(measure 2 "$@")
r1=$(echo "60 * $runs / $s1" | bc -l)
r2=$(echo "60 * $runs / $s2" | bc -l)
eff=$(echo "$r2 / (2 * $r1)" | bc -l)
same=$(cmp -s "$work/grades-jobs1.csv" "$work/grades-jobs2.csv" && echo "identical" || echo "DIFFERENT")
printf 'class: %d students x %d seeds = %d vacuum runs on %d cores (first batch incl. compiling %d plugins: %.0f s)\n' \
  "$((10#$students))" "$seeds" "$runs" "$(nproc)" "$((10#$students))" "$(echo "$t1 - $t0" | bc -l)"
printf '  --jobs=1: %6.1f s  %6.1f runs/min\n' "$s1" "$r1"
printf '  --jobs=2: %6.1f s  %6.1f runs/min\n' "$s2" "$r2"
printf '  parallel efficiency (jobs=2 / 2 x jobs=1): %.2f   grades.csv of the two: %s\n' "$eff" "$same"
