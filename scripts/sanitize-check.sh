#!/usr/bin/env bash
# The sanitizer run CI makes after `./aula test` (issue 15): Aula built with AddressSanitizer and
# UndefinedBehaviorSanitizer (the `sanitize` preset, into build-sanitize/), then its unit tests
# and one headless run of each exercise under them. Any sanitizer report in any process fails it:
# UBSan halts at its first error, ASan at its first, LeakSanitizer at exit. Third-party leaks that
# are not Aula's are in tests/sanitize/lsan.supp, each with its reason.
#   scripts/sanitize-check.sh
set -euo pipefail
cd "$(dirname "$0")/.."
root="$(pwd)"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=0:detect_stack_use_after_return=0"
export LSAN_OPTIONS="suppressions=$root/tests/sanitize/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"

if [ ! -f build-sanitize/build.ninja ]; then
  cmake --preset sanitize >/dev/null
fi
# Only what the run needs: the unit tests (their discovery runs them under the sanitizers too),
# and the programs and student plugins of every exercise.
cmake --build build-sanitize -j"$(nproc)" --target aula_unit_tests aula_all_exercises
ctest --test-dir build-sanitize -L unit -j"$(nproc)" --output-on-failure

out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
port=$((30000 + $$ % 20000))
status=0
run() {  # run NAME aula-run-arguments...
  local name="$1"; shift
  local log="$out/$name.log"
  if ! build-sanitize/bin/aula run "$@" --headless --report="$out/$name.json" \
      --lcm-url="udpm://239.255.76.67:$port?ttl=0" >"$log" 2>&1; then
    echo "sanitize: $name: the run failed" >&2
    status=1
  fi
  if grep -qE "ERROR: (Address|Leak)Sanitizer|runtime error:|SUMMARY: (Address|UndefinedBehavior|Leak)Sanitizer" "$log"; then
    echo "sanitize: $name: a sanitizer reported an error" >&2
    status=1
  fi
  if [ "$status" -ne 0 ]; then cat "$log" >&2; fi
  echo "sanitize: $name: $(grep -h '"mark"' "$out/$name.json" 2>/dev/null | tr -d ' ,')"
}
# Each exercise's runs as it declares them (RUNS and SANITIZE_ARGS of its aula_exercise()).
while read -r label exercise args <&3; do  # fd 3: the runs keep the script's stdin
  case "$label" in ''|'#'*) continue ;; esac
  # shellcheck disable=SC2086  # the declared arguments, one word each
  run "$label" "$exercise" $args
done 3<build-sanitize/exercises/sanitize-runs.txt
exit "$status"
