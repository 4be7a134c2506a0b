#!/usr/bin/env bash
# Grading throughput: a class of N vacuum submissions x S seeds, all measured in this one script
# (a ratio on one machine, so a noisy machine still gives a fair figure).
# --compare=jobs (the default): graded by `aula grade` once with --jobs=1 and once with --jobs=2;
#   prints runs per minute for each and the parallel efficiency
#   = throughput(jobs=2) / (2 x throughput(jobs=1)).
# --compare=sandbox: the grade's runs three ways:
#   - sandboxed: as `aula grade` runs them (exact binds, a user, process and network namespace of
#     their own, seccomp, limits);
#   - previous: the sandbox before issue 28 (`bwrap --ro-bind / / --dev /dev --proc /proc --tmpfs
#     /var/tmp --unshare-pid --unshare-ipc --unshare-uts --die-with-parent --new-session` and the
#     same seccomp program: no exact binds, no user namespace, no limits). Aula has no switch
#     back to it, so this script puts a `prlimit` of its own first on the runs' PATH (the
#     launcher starts the sandbox as `prlimit ... -- bwrap ... -- COMPONENT`) that starts the
#     component that way instead; the run's private network stays (the launcher makes it);
#   - unsandboxed: the same runs' commands less --sandbox.
#   All through `aula grade-task` (each run of the manifest, as a Slurm task runs it), JOBS at
#   once, each worker on a CPU of its own as `aula grade` places its runs, each kind into an out
#   folder of its own. The class goes by slices of SLICE runs, each slice run by the three kinds
#   in turn (the first one rotating), ROUNDS times, so that a machine whose load changes weighs
#   on the three alike. Prints each kind's throughput, the ratios and whether the three kinds'
#   grades.csv are identical (the differing rows when not); and first one batch of `aula grade`.
# --compare=build: the class compiled and graded by `aula grade` with each submission's build in
#   its sandbox (--build-sandbox=on, the default: bubblewrap, limits, no network) and out of it
#   (--build-sandbox=off), each time into a fresh out folder (so every plugin is compiled; no
#   calibration: --calibration-seeds=off), the two
#   in turn (the first one rotating), ROUNDS times; prints each kind's compile time (until the
#   grade says how many runs it plans), whole grade time, plugins compiled per minute and runs
#   per minute, the ratios, and whether the two kinds' grades.csv are identical (the differing
#   rows when not). (Not CPU time: a process in bubblewrap's own PID namespace is reaped there,
#   and its time never reaches the grade's rusage.)
# --compare=process: the same two grades with the build in its sandbox both times, and the
#   student's algorithm in a process of its own (--Component.OwnProcess=on) or
#   inside the component (off): the same figures and the same check of grades.csv.
# Usage: bench/grade_class.sh BUILD_DIR [STUDENTS=30] [SEEDS=5] [--compare=jobs|sandbox|build|process]
#        [--rounds=1] [--slice=10] [--jobs=2] [EXTRA aula grade options...]
set -euo pipefail
build="$(cd "$1" && pwd)"; students="${2:-30}"; seeds="${3:-5}"; shift $(( $# < 3 ? $# : 3 ))
compare=jobs; rounds=1; jobs=2; slice=10
while [ $# -gt 0 ]; do
  case "$1" in
    --compare=*) compare="${1#*=}" ;;
    --rounds=*) rounds="${1#*=}" ;;
    --jobs=*) jobs="${1#*=}" ;;
    --slice=*) slice="${1#*=}" ;;
    *) break ;;
  esac
  shift
done
case "$compare" in jobs|sandbox|build|process) ;; *) echo "grade_class.sh: --compare=$compare: jobs, sandbox, build or process" >&2; exit 2 ;; esac
src="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-grade-bench-XXXXXX")"
trap 'rm -rf "$work"' EXIT

# The class: the reference, as students would hand it in (each its own plugin build).
for i in $(seq -w 1 "$students"); do
  mkdir -p "$work/class/student$i"
  cp "$src/components/vacuum/reference/roomba_steps.hpp" "$work/class/student$i/"  # the reference's steps, beside it
  { cat "$src/components/vacuum/reference/RoombaReference.cpp"
    printf '\nnamespace aula::vacuum {\nstd::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t seed) { return makeReferenceAlgorithm(seed); }\n}  // namespace aula::vacuum\n'
  } >"$work/class/student$i/MyAlgorithm.cpp"
done

if [ "$compare" = build ] || [ "$compare" = process ]; then
  # What differs between the two grades: the build's sandbox, or the algorithm's own process.
  option=--build-sandbox; [ "$compare" = process ] && option=--Component.OwnProcess
  runs=$((10#$students * seeds))
  printf 'class: %d students x %d seeds = %d vacuum runs on %d cores, --jobs=%d, compiled anew each time\n' \
    "$((10#$students))" "$seeds" "$runs" "$(nproc)" "$jobs"
  declare -A compile_s=([on]=0 [off]=0) grade_s=([on]=0 [off]=0)
  kinds=(on off)
  for ((round = 0; round < rounds; ++round)); do
    for ((j = 0; j < 2; ++j)); do
      kind=${kinds[(round + j) % 2]}
      out="$work/build-$kind"
      rm -rf "$out"
      start=$(date +%s.%N)
      # Each line of the grade's output with the seconds since the start: the compile step ends
      # where the grade says how many runs it plans.
      "$build/bin/aula" grade vacuum "$work"/class/* --seeds=1-"$seeds" --jobs="$jobs" --out="$out" \
        "$option=$kind" --calibration-seeds=off "$@" | while IFS= read -r line; do
          printf '%s %s\n' "$(echo "$(date +%s.%N) - $start" | bc -l)" "$line"
        done >"$work/build-$kind.txt"
      end=$(date +%s.%N)
      compiled=$(grep -m1 ' [0-9]* runs: ' "$work/build-$kind.txt" | cut -d' ' -f1)
      failed=$(grep -c 'did not compile\|refused' "$out/grades.csv" || true)
      [ "$failed" = 0 ] || { echo "grade_class.sh: $failed submission(s) did not build with $option=$kind" >&2; exit 1; }
      compile_s[$kind]=$(echo "${compile_s[$kind]} + $compiled" | bc -l)
      grade_s[$kind]=$(echo "${grade_s[$kind]} + $end - $start" | bc -l)
      cp "$out/grades.csv" "$work/grades-build-$kind.csv"
    done
  done
  for kind in on off; do
    printf '  %s=%-3s: compile %6.1f s (%5.1f plugins/min), whole grade %6.1f s (%5.1f runs/min) over %d round(s)\n' \
      "$option" "$kind" "${compile_s[$kind]}" "$(echo "60 * $students * $rounds / ${compile_s[$kind]}" | bc -l)" \
      "${grade_s[$kind]}" "$(echo "60 * $runs * $rounds / ${grade_s[$kind]}" | bc -l)" "$rounds"
  done
  same=$(cmp -s "$work/grades-build-on.csv" "$work/grades-build-off.csv" && echo "identical" || echo "DIFFERENT")
  printf '  boxed / unboxed: compile time %.3f, whole grade time %.3f   grades.csv of the two: %s\n' \
    "$(echo "${compile_s[on]} / ${compile_s[off]}" | bc -l)" "$(echo "${grade_s[on]} / ${grade_s[off]}" | bc -l)" "$same"
  [ "$same" = identical ] || diff "$work/grades-build-on.csv" "$work/grades-build-off.csv" | sed 's/^/    /' | cut -c1-300
  exit 0
fi

# Compiling is not grading: a first batch builds the plugins; the measured batches reuse that
# build folder (their compile step is then a no-op of well under a second per student).
out="$work/out"
t0=$(date +%s.%N)
"$build/bin/aula" grade vacuum "$work"/class/* --seeds=1 --jobs=2 --out="$out" "$@" >/dev/null
t1=$(date +%s.%N)
runs=$((10#$students * seeds))
printf 'class: %d students x %d seeds = %d vacuum runs on %d cores (first batch incl. compiling %d plugins: %.0f s)\n' \
  "$((10#$students))" "$seeds" "$runs" "$(nproc)" "$((10#$students))" "$(echo "$t1 - $t0" | bc -l)"

measure() {  # measure JOBS [options] -> seconds of wall time for the whole batch of `aula grade`
  local jobs="$1"; shift
  rm -rf "$out/runs" "$out/grades.csv"
  local start end
  start=$(date +%s.%N)
  "$build/bin/aula" grade vacuum "$work"/class/* --seeds=1-"$seeds" --jobs="$jobs" --out="$out" "$@" >"$work/jobs$jobs.txt"
  end=$(date +%s.%N)
  cp "$out/grades.csv" "$work/grades-jobs$jobs.csv"
  echo "$end - $start" | bc -l
}

# tasks MANIFEST FIRST LAST -> seconds of wall time: runs FIRST..LAST of MANIFEST by `aula grade-task`,
# $jobs workers, worker k on CPU k (of those allowed) taking every jobs-th run.
tasks() {
  local manifest="$1" first="$2" last="$3" start end k
  mapfile -t cpus < <(taskset -cp $$ | sed 's/.*: //' | tr ',' '\n' |
                      awk -F- '{ if (NF == 2) for (c = $1; c <= $2; ++c) print c; else print $1 }')
  start=$(date +%s.%N)
  for ((k = 0; k < jobs; ++k)); do
    ( for ((i = first + k; i <= last; i += jobs)); do
        taskset -c "${cpus[k % ${#cpus[@]}]}" "$build/bin/aula" grade-task "$manifest" "$i" >/dev/null
      done ) &
  done
  wait
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}

if [ "$compare" = jobs ]; then
  s1=$(measure 1 "$@")
  s2=$(measure 2 "$@")
  r1=$(echo "60 * $runs / $s1" | bc -l)
  r2=$(echo "60 * $runs / $s2" | bc -l)
  eff=$(echo "$r2 / (2 * $r1)" | bc -l)
  same=$(cmp -s "$work/grades-jobs1.csv" "$work/grades-jobs2.csv" && echo "identical" || echo "DIFFERENT")
  printf '  --jobs=1: %6.1f s  %6.1f runs/min\n' "$s1" "$r1"
  printf '  --jobs=2: %6.1f s  %6.1f runs/min\n' "$s2" "$r2"
  printf '  parallel efficiency (jobs=2 / 2 x jobs=1): %.2f   grades.csv of the two: %s\n' "$eff" "$same"
  exit 0
fi

# The whole class's manifest (every seed), as `aula grade` writes it, and the same less --sandbox.
s_grade=$(measure "$jobs" "$@")
printf '  aula grade --jobs=%d (sandboxed, its own pool): %6.1f s  %6.1f runs/min\n' "$jobs" "$s_grade" \
  "$(echo "60 * $runs / $s_grade" | bc -l)"
cp "$out/manifest.json" "$work/sandboxed.json"
grep -q -- '"--sandbox"' "$work/sandboxed.json" || { echo "grade_class.sh: the manifest's runs are not sandboxed" >&2; exit 1; }
jq '.runs[].command |= map(select(. != "--sandbox"))' "$work/sandboxed.json" >"$work/unsandboxed.json"
cp "$work/sandboxed.json" "$work/previous.json"

# The previous sandbox: a prlimit first on PATH that takes the launcher's
# `prlimit LIMITS -- bwrap OPTIONS --seccomp FD -- COMPONENT...` and runs COMPONENT as before.
mkdir -p "$work/previous-sandbox"
cat >"$work/previous-sandbox/prlimit" <<'SHIM'
#!/usr/bin/env bash
set -euo pipefail
seccomp=""
while [ "$1" != "--" ]; do shift; done; shift    # the limits
bwrap="$1"; shift
while [ "$1" != "--" ]; do [ "$1" = --seccomp ] && seccomp="$2"; shift; done; shift
[ -n "$seccomp" ] || { echo "previous-sandbox prlimit: no --seccomp in the launcher's command" >&2; exit 1; }
exec "$bwrap" --ro-bind / / --dev /dev --proc /proc --tmpfs /var/tmp --setenv TMPDIR /var/tmp --unshare-pid \
  --unshare-ipc --unshare-uts --die-with-parent --new-session --seccomp "$seccomp" -- "$@"
SHIM
chmod +x "$work/previous-sandbox/prlimit"

# Each kind writes into an out folder of its own; the class goes by slices of SLICE runs, each
# slice run by the three kinds in turn (the first kind rotating), so a machine whose load changes
# weighs on all three alike.
kinds=(unsandboxed previous sandboxed)
for kind in "${kinds[@]}"; do
  # The runs' files (runs/) move; the plugins (build/) stay where the first batch built them.
  jq --arg from "$out/runs/" --arg to "$work/out-$kind/runs/" --arg dir "$work/out-$kind" \
     'walk(if type == "string" then (if startswith($from) then $to + ltrimstr($from) else gsub("=" + $from; "=" + $to) end) else . end)
      | .out_dir = $dir' "$work/$kind.json" >"$work/$kind.manifest.json"
  mkdir -p "$work/out-$kind/runs"
done
count=$(jq '.runs | length' "$work/sandboxed.json")
declare -A total=([unsandboxed]=0 [previous]=0 [sandboxed]=0)
turn=0
for ((round = 1; round <= rounds; ++round)); do
  for kind in "${kinds[@]}"; do rm -rf "$work/out-$kind/runs"; done
  for ((first = 0; first < count; first += slice)); do
    last=$((first + slice - 1 < count - 1 ? first + slice - 1 : count - 1))
    for ((j = 0; j < 3; ++j)); do
      kind=${kinds[(turn + j) % 3]}
      if [ "$kind" = previous ]; then
        s=$(PATH="$work/previous-sandbox:$PATH" tasks "$work/$kind.manifest.json" "$first" "$last")
      else
        s=$(tasks "$work/$kind.manifest.json" "$first" "$last")
      fi
      total[$kind]=$(echo "${total[$kind]} + $s" | bc -l)
    done
    turn=$((turn + 1))
  done
done
rate() { echo "60 * $count * $rounds / ${total[$1]}" | bc -l; }
for kind in "${kinds[@]}"; do
  "$build/bin/aula" grade --collect="$work/out-$kind" >/dev/null
  printf '  %-11s: %6.1f s for %d runs x %d rounds  %6.1f runs/min\n' "$kind" "${total[$kind]}" "$count" "$rounds" "$(rate "$kind")"
done
same=identical
for kind in unsandboxed previous; do
  if ! cmp -s "$work/out-$kind/grades.csv" "$work/out-sandboxed/grades.csv"; then
    same=DIFFERENT
    diff "$work/out-$kind/grades.csv" "$work/out-sandboxed/grades.csv" | sed "s/^/    $kind vs sandboxed: /" | cut -c1-300
  fi
done
printf '  sandboxed / previous sandbox: %.3f   sandboxed / unsandboxed: %.3f   grades.csv of the three: %s\n' \
  "$(echo "$(rate sandboxed) / $(rate previous)" | bc -l)" "$(echo "$(rate sandboxed) / $(rate unsandboxed)" | bc -l)" "$same"
