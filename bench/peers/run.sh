#!/usr/bin/env bash
# The peers' job side by side: Aula's `aula run vacuum --headless --algorithm=bounce --seed=SEED`
# (900 s of the shipped house: DART contacts, a 180-beam laser, the bounce controller) and the same
# job modelled in MuJoCo from Aula's own world and settings (mujoco_vacuum.py). N pairs, alternated
# Aula, MuJoCo, Aula, MuJoCo..., each whole process timed by /usr/bin/time (wall; CPU = user +
# system with the processes it waited for); prints the medians, their ratio and each one's coverage.
# MuJoCo comes from PyPI into a bench virtual environment outside the source tree, created on the
# first call: it is never a dependency of Aula. The model's laser and coverage count can be checked
# against a run Aula recorded: "$venv/bin/python" bench/peers/compare_with_aula.py SETTINGS RUN.lcmlog.
#   bench/peers/run.sh BUILD [N] [SEED]     e.g. bench/peers/run.sh build 5
set -euo pipefail
if [ $# -lt 1 ] || [ ! -x "$1/bin/aula" ]; then
  echo "usage: bench/peers/run.sh BUILD [N] [SEED]   (BUILD/bin/aula must exist)" >&2
  exit 2
fi
build="$(cd "$1" && pwd)"
pairs="${2:-5}"
seed="${3:-1}"
here="$(cd "$(dirname "$0")" && pwd)"
mujoco_version=4.0.1
lcm_version=1.5.3  # for compare_with_aula.py, which reads Aula's recorded runs
venv="${XDG_CACHE_HOME:-$HOME/.cache}/aula-bench-peers/venv"

installed="import lcm, mujoco, sys; sys.exit(mujoco.__version__ != '$mujoco_version')"
if ! "$venv/bin/python" -c "$installed" 2>/dev/null; then
  echo "peers: installing mujoco==$mujoco_version and lcm==$lcm_version into $venv" >&2
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet "mujoco==$mujoco_version" "lcm==$lcm_version"
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# The settings the run would use, as Aula prints them: read once, outside the timings.
"$build/bin/aula" config vacuum --Simulator.Seed="$seed" --Vacuum.Algorithm=bounce > "$work/settings.txt"

load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
for pair in $(seq 1 "$pairs"); do
  /usr/bin/time -f "%e %U %S" -o "$work/aula.time" \
    "$build/bin/aula" run vacuum --headless --algorithm=bounce --seed="$seed" --report="$work/aula.json" \
    > "$work/aula.out" 2>&1 ||
    { cat "$work/aula.out" >&2; exit 1; }
  echo "aula $(cat "$work/aula.time") $(tr -d '\n' < "$work/aula.json")" >> "$work/runs"
  /usr/bin/time -f "%e %U %S" -o "$work/mujoco.time" \
    "$venv/bin/python" "$here/mujoco_vacuum.py" "$work/settings.txt" "$seed" > "$work/mujoco.json"
  echo "mujoco $(cat "$work/mujoco.time") $(cat "$work/mujoco.json")" >> "$work/runs"
  echo "peers: pair $pair of $pairs done" >&2
done
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"

"$venv/bin/python" "$here/summary.py" "$work/runs" "$build" "$seed" "$load_before" "$load_after"
