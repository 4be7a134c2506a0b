#!/usr/bin/env bash
# What a program that paces itself by waiting on the clock costs against its time.sleep twin
# (issue 54): tests/data/python/sleep_twin (time.sleep(0.25)), busy_wait_twin (a loop on
# time.perf_counter()) and the same loop on time.time() (made from it here). On Aula every clock is
# the simulator's, and a read at the same place of the code with the clock unchanged hands the
# period back, as time.sleep does: the goal is CPU within 1.2x of the sleep's. Whole vacuum runs,
# headless, the kinds in turn (the first one rotating) ROUNDS times; CPU time = user + system of
# the run's processes (/usr/bin/time: the launcher waits for its children). Prints each kind's
# median, its ratio to the sleep's, and whether the three reports are byte-identical.
#   bench/python_clock_waits.sh [BUILD_DIR] [ROUNDS=5] [DURATION_S=900]
# Needs: cmake --build BUILD_DIR --target aula aula-sim vacuum-cleaner vacuum-cleaner-referee aula_vacuum_python
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
rounds="${2:-5}"
duration="${3:-900}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
port=$((20000 + $$ % 20000))
mkdir -p "$out/sleep" "$out/perf_counter" "$out/time"
cp "$root/tests/data/python/sleep_twin/MyAlgorithm.py" "$out/sleep/"
cp "$root/tests/data/python/busy_wait_twin/MyAlgorithm.py" "$out/perf_counter/"
sed 's/time\.perf_counter()/time.time()/g' "$root/tests/data/python/busy_wait_twin/MyAlgorithm.py" >"$out/time/MyAlgorithm.py"
grep -q 'time.time() - start' "$out/time/MyAlgorithm.py" || { echo "busy_wait_twin no longer waits on perf_counter"; exit 2; }

median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2] + a[NR/2+1]) / 2}'; }
kinds=(sleep perf_counter time)
for ((round = 0; round < rounds; ++round)); do
  for ((j = 0; j < 3; ++j)); do
    kind=${kinds[(round + j) % 3]}
    /usr/bin/time -f "%U %S %e" -o "$out/rusage" "$build/bin/aula" run vacuum --headless --seed=1 \
      --algorithm="$out/$kind/MyAlgorithm.py" --Vacuum.Referee.Duration="$duration" --report="$out/$kind.json" \
      --lcm-url="udpm://239.255.76.67:$port?ttl=0" >/dev/null 2>&1
    read -r user sys wall <"$out/rusage"
    echo "$user + $sys" | bc -l >>"$out/$kind.cpu"
    echo "$wall" >>"$out/$kind.wall"
  done
done
sleep_cpu=$(median <"$out/sleep.cpu")
for kind in "${kinds[@]}"; do
  cpu=$(median <"$out/$kind.cpu")
  printf 'vacuum %s s, waiting on %-12s CPU %.3f s (median of %d), %.3fx the sleep'"'"'s; wall %.2f s\n' \
    "$duration" "$kind:" "$cpu" "$rounds" "$(echo "$cpu / $sleep_cpu" | bc -l)" "$(median <"$out/$kind.wall")"
done
if cmp -s "$out/sleep.json" "$out/perf_counter.json" && cmp -s "$out/sleep.json" "$out/time.json"; then
  echo "reports: byte-identical"
else
  echo "reports: DIFFERENT"
  exit 1
fi
