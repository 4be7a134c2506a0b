# What the benches on generated houses share (bench/vacuum_noise_houses.sh,
# bench/vacuum_large_floors.sh): their arguments, BUILD_DIR and SEEDS and then options for
# `aula run`; a scratch folder removed at the end; a private LCM port; a house drawn by
# worlds/tools/make_house.py; a run of the reference on it; a number from its report.
# Sourced by them, after `set -euo pipefail`; it takes BUILD_DIR and SEEDS off their arguments.
build="${1:-build}"
seeds="${2:-1 2 3}"
shift $(( $# < 2 ? $# : 2 ))
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
port=$((20000 + $$ % 20000))

# house NAME MAKE_HOUSE_ARGUMENTS: writes $out/NAME.world.
house() {
  local name="$1"
  # shellcheck disable=SC2086
  python3 "$here/worlds/tools/make_house.py" --out "$out/$name.world" $2 >/dev/null
}

# run_reference WORLD SEED REPORT [AULA RUN OPTIONS...]: the reference, headless (a run that
# fails writes no report, and the bench stops at it).
run_reference() {
  local world="$1" seed="$2" report="$3"
  shift 3
  "$build/bin/aula" run vacuum --headless --world="$world" --algorithm=reference --seed="$seed" --report="$report" \
    --lcm-url="udpm://239.255.76.67:$port?ttl=0" "$@" >/dev/null 2>&1 || true
}

# field NAME REPORT: a number of the report's top level.
field() { grep "^  \"$1\"" "$2" | head -1 | sed 's/.*: \([0-9.]*\),*/\1/'; }
