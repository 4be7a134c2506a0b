#!/usr/bin/env bash
# What the algorithm's own process costs (Component.OwnProcess, issue 39): each exercise's
# reference headless, `aula run EXERCISE --headless --algorithm=... --seed=N`, with the algorithm
# in its own process (on) and inside the component (off), in turn (the first one rotating), ROUNDS
# times. Measured as CPU time (user + system of the run's processes, /usr/bin/time: the launcher
# waits for the component, the component for the algorithm's process), so a loaded machine
# weighs on both alike; wall time beside it. Prints each kind's median, the ratio on / off, the
# cost per control period ((on - off) / periods), and whether the two reports are byte-identical.
#   bench/algorithm_process.sh [BUILD_DIR] [ROUNDS=5] [EXERCISES="vacuum teletaxi autopark"] [SEED=1]
set -euo pipefail
build="$(cd "${1:-build}" && pwd)"
rounds="${2:-5}"
exercises="${3:-vacuum teletaxi autopark}"
seed="${4:-1}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2] + a[NR/2+1]) / 2}'; }
algorithm_of() { case "$1" in autopark) echo planner ;; *) echo reference ;; esac; }
period_of() { case "$1" in vacuum) echo Vacuum ;; teletaxi) echo TeleTaxi ;; autopark) echo Autopark ;; esac; }

for ex in $exercises; do
  kinds=(on off)
  for ((round = 0; round < rounds; ++round)); do
    for ((j = 0; j < 2; ++j)); do
      kind=${kinds[(round + j) % 2]}
      /usr/bin/time -f "%U %S %e" -o "$out/time" "$build/bin/aula" run "$ex" --headless --algorithm="$(algorithm_of "$ex")" \
        --seed="$seed" --Component.OwnProcess="$kind" --report="$out/$ex-$kind.json" >/dev/null 2>&1
      read -r user sys wall <"$out/time"
      echo "$user + $sys" | bc -l >>"$out/$ex-$kind.cpu"
      echo "$wall" >>"$out/$ex-$kind.wall"
    done
  done
  sim_s=$(grep -m1 '"sim_time_s"' "$out/$ex-on.json" | sed 's/.*: *\([0-9.]*\).*/\1/')
  config=$("$build/bin/aula" config "$ex" 2>/dev/null)  # whole: a pipe closed early would end the script (pipefail)
  period_s=$(sed -n "s/^ *$(period_of "$ex").Period = *\([0-9.]*\).*/\1/p" <<<"$config")
  periods=$(echo "$sim_s / $period_s" | bc)
  on=$(median <"$out/$ex-on.cpu"); off=$(median <"$out/$ex-off.cpu")
  same=$(cmp -s "$out/$ex-on.json" "$out/$ex-off.json" && echo identical || echo DIFFERENT)
  printf '%-9s %s x %d: CPU on %.3f s, off %.3f s (medians), on/off %.3f, %.1f us a control period (%d periods); wall on %.2f s, off %.2f s; reports %s\n' \
    "$ex" "$(algorithm_of "$ex")" "$rounds" "$on" "$off" "$(echo "$on / $off" | bc -l)" \
    "$(echo "($on - $off) * 1000000 / $periods" | bc -l)" "$periods" \
    "$(median <"$out/$ex-on.wall")" "$(median <"$out/$ex-off.wall")" "$same"
done
