#!/usr/bin/env bash
# The peers' job (issue 60) for two builds side by side: `aula run vacuum --headless
# --algorithm=bounce --seed=1` (900 s of the shipped house, DART contacts, the 180-beam laser, the
# bounce controller) with build A and with build B in turn, the first of each pair rotating, ROUNDS
# pairs. Measured as CPU time (user + system of all the run's processes, /usr/bin/time: the
# launcher waits for its three children, the component for the algorithm's process) and wall
# time. Prints each build's medians, the median of the pairs' ratios A / B (pairing keeps a ratio
# when the machine's load drifts), and the coverage each build's reports give.
#   bench/peers_job.sh BUILD_A BUILD_B [ROUNDS=5] [AULA RUN OPTIONS...]
#   e.g. bench/peers_job.sh build ../base/build 7
#   (a build of an older commit: git worktree add --detach ../base COMMIT, then configure and
#    `cmake --build build --target aula_run_vacuum` there)
set -euo pipefail
a="$(cd "$1" && pwd)"
b="$(cd "$2" && pwd)"
rounds="${3:-5}"
shift $(($# < 3 ? $# : 3))
options=(--algorithm=bounce --seed=1)
[ $# -gt 0 ] && options=("$@")
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2] + a[NR/2+1]) / 2}'; }

# run TAG BUILD: one run; appends "user sys cpu wall coverage" to $out/TAG.
run() {
  /usr/bin/time -f "%U %S %e" -o "$out/time" "$2/bin/aula" run vacuum --headless "${options[@]}" \
    --report="$out/report.json" >/dev/null 2>&1 || true
  local user sys wall coverage
  read -r user sys wall < <(tail -1 "$out/time")
  coverage=$(grep '^  "coverage_percent"' "$out/report.json" | sed 's/.*: \([0-9.]*\),*/\1/')
  echo "$user $sys $(echo "$user + $sys" | bc -l) $wall $coverage" >> "$out/$1"
  rm -f "$out/report.json"
}

for ((round = 0; round < rounds; ++round)); do
  if ((round % 2 == 0)); then run A "$a"; run B "$b"; else run B "$b"; run A "$a"; fi
done

column() { awk -v c="$2" '{print $c}' "$out/$1"; }
printf '%-6s %9s %9s %9s %9s  %s\n' build user_s sys_s cpu_s wall_s "coverage % (each run)"
for tag in A B; do
  printf '%-6s %9.3f %9.3f %9.3f %9.3f  %s\n' "$tag" "$(column "$tag" 1 | median)" "$(column "$tag" 2 | median)" \
    "$(column "$tag" 3 | median)" "$(column "$tag" 4 | median)" "$(column "$tag" 5 | sort -u | tr '\n' ' ')"
done
ratio() { paste <(column A "$1") <(column B "$1") | awk '{print $1 / $2}' | median; }
printf '%-6s %9.3f %9.3f %9.3f %9.3f  (median of the %d pairs)\n' "A / B" "$(ratio 1)" "$(ratio 2)" "$(ratio 3)" \
  "$(ratio 4)" "$rounds"
echo "A: $a"
echo "B: $b"
