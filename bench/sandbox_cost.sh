#!/usr/bin/env bash
# What the graded run's sandbox costs: 900 s vacuum runs of the reference, headless, with and
# without --sandbox (bubblewrap with exact binds, its own user and network namespaces, prlimit),
# alternating in this one script so that a noisy machine weighs on both alike. Prints the median
# wall time of each and their ratio. Usage: bench/sandbox_cost.sh BUILD_DIR [SEEDS="1 2 3 4 5"]
set -euo pipefail
build="$(cd "$1" && pwd)"; seeds="${2:-1 2 3 4 5}"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-sandbox-bench-XXXXXX")"
trap 'rm -rf "$work"' EXIT
run() {  # run SEED [--sandbox] -> wall seconds
  local start end
  start=$(date +%s.%N)
  "$build/bin/aula" run vacuum --headless --algorithm=reference --seed="$1" ${2:-} --report="$work/r.json" >/dev/null 2>&1
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
: >"$work/open"; : >"$work/sandboxed"
for seed in $seeds; do
  run "$seed" >>"$work/open"
  run "$seed" --sandbox >>"$work/sandboxed"
done
open=$(median <"$work/open"); sandboxed=$(median <"$work/sandboxed")
printf 'vacuum 900 s, median wall: open %.3f s, sandboxed %.3f s, ratio %.3f\n' "$open" "$sandboxed" \
  "$(echo "$sandboxed / $open" | bc -l)"
