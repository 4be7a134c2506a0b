#!/usr/bin/env bash
# The grading page's players, measured in one script run (docs/performance.md):
#   1. the cost of the referee's --trace: full 900 s vacuum runs, with and without it, alternated;
#   2. a trace's size (900 s vacuum; TeleTaxi; Autopark);
#   3. a class of STUDENTS x 5 seeds x 3 worlds of 900 s vacuum runs (vacuum.world, house_3x2.world
#      and a generated 4x3 house): report.html's size, and how long headless Chromium takes to
#      load it (the page's own `load` time, and Chromium's whole wall time), and for one run's own
#      page (what report.html shows in a frame) to open its player.
# A run's three processes are started here as `aula run --headless` starts them (the launcher
# does not pass --trace to the referee yet). With --screenshots it also writes the page's pictures
# in docs/images (look at them before committing); --screenshots-only skips the measures.
# --class runs section 3 alone.
# Usage: bench/run_pages.sh BUILD_DIR [STUDENTS=30] [--screenshots|--screenshots-only|--class]
set -euo pipefail
build="$(cd "$1" && pwd)"; students="${2:-30}"; screenshots="${3:-}"
src="$(cd "$(dirname "$0")/.." && pwd)"
bin="$build/bin"; worlds="$build/share/aula/worlds"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-pages-bench-XXXXXX")"
trap 'rm -rf "$work"' EXIT

# run3 SECTION COMPONENT REFEREE WORLD SEED STEM [REFEREE_OPTION...] [-- SIM_SETTING...]: one
# headless run in lockstep as fast as possible, the exercise's .cfg and its algorithm $ALGORITHM
# (reference; Autopark: reactive); prints its wall time and the CPU time of its three processes.
run3() {
  local section="$1" component="$2" referee="$3" world="$4" seed="$5" stem="$6"
  shift 6
  case "$world" in /*) ;; *) world="$worlds/$world" ;; esac  # a world of the data folder, or a path
  local cfg algorithm="${ALGORITHM:-reference}"
  case "$section" in
    Vacuum) cfg=vacuumCleaner.cfg ;; TeleTaxi) cfg=teleTaxi.cfg ;; Autopark) cfg=autopark.cfg; algorithm="${ALGORITHM:-reactive}" ;;
  esac
  cfg="$build/share/aula/config/$cfg"
  local referee_args=() sim_args=()
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do referee_args+=("$1"); shift; done
  [ $# -gt 0 ] && shift && sim_args=("$@")
  local url="udpm://239.255.76.67:$((20000 + RANDOM % 20000))?ttl=0&recv_buf_size=4194304"
  local t0 cpu0; t0=$(date +%s.%N); children_cpu >"$work/cpu0"; cpu0=$(cat "$work/cpu0")
  "$bin/aula-sim" "$world" --lockstep --Simulator.Lockstep.WaitForClients=2 --rtf=0 --Simulator.Seed="$seed" \
    --lcm-url="$url" ${sim_args[@]+"${sim_args[@]}"} >"$stem.sim.txt" 2>&1 &
  local sim=$!
  "$bin/$referee" --config="$cfg" --headless --lcm-url="$url" "--$section.World=$world" ${referee_args[@]+"${referee_args[@]}"} \
    >"$stem.referee.txt" 2>&1 &
  local ref=$!
  "$bin/$component" --config="$cfg" --headless --lcm-url="$url" "--$section.World=$world" "--$section.Autostart=true" \
    "--$section.Algorithm=$algorithm" \
    >"$stem.component.txt" 2>&1 &
  local comp=$!
  wait "$ref"
  local t1; t1=$(date +%s.%N)
  kill -TERM "$comp" "$sim" 2>/dev/null || true
  wait "$comp" "$sim" 2>/dev/null || true
  children_cpu >"$work/cpu1"
  echo "$(echo "$t1 - $t0" | bc -l) $(echo "$(cat "$work/cpu1") - $cpu0" | bc -l)"
}

# The CPU seconds (user + system) of this shell's waited-for children so far.
# `times` itself, not in a pipe or $(...): a subshell's children are not this shell's.
children_cpu() {
  times >"$work/times"
  tail -1 "$work/times" | tr -d s | awk '{ n = 0; for (i = 1; i <= 2; ++i) { split($i, p, "m"); n += p[1] * 60 + p[2] } print n }'
}

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }

# Chromium, headless, a fresh profile, nothing in the background.
chrome() {
  local profile; profile="$(mktemp -d "$work/profile-XXXXXX")"
  /usr/bin/chromium --headless --no-sandbox --disable-gpu --disable-background-networking --disable-component-update \
    --disable-sync --no-first-run --user-data-dir="$profile" --hide-scrollbars "$@" 2>/dev/null
}

if [ "$screenshots" != "--screenshots-only" ] && [ "$screenshots" != "--class" ]; then
echo "== 1. the cost of --trace: 900 s vacuum runs (reference), seeds 1-5 twice, each without and with it, alternated"
mkdir -p "$work/cost"
: >"$work/cost/without"; : >"$work/cost/with"
for round in 1 2; do
  for seed in 1 2 3 4 5; do
    run3 Vacuum vacuum-cleaner vacuum-cleaner-referee vacuum.world "$seed" "$work/cost/a$seed" \
      --report="$work/cost/a$seed.json" >>"$work/cost/without"
    run3 Vacuum vacuum-cleaner vacuum-cleaner-referee vacuum.world "$seed" "$work/cost/b$seed" \
      --report="$work/cost/b$seed.json" --trace="$work/cost/b$seed.trace.json" >>"$work/cost/with"
    cmp -s "$work/cost/a$seed.json" "$work/cost/b$seed.json" || { echo "seed $seed: the report changed with --trace"; exit 1; }
  done
done
for what in without with; do
  wall=$(cut -d' ' -f1 "$work/cost/$what" | median); cpu=$(cut -d' ' -f2 "$work/cost/$what" | median)
  printf '%-8s --trace: wall %s s, CPU %s s (medians of 10; each run: %s)\n' "$what" "$(printf '%.3f' "$wall")" \
    "$(printf '%.3f' "$cpu")" "$(cut -d' ' -f1 "$work/cost/$what" | xargs printf '%.2f ')"
  eval "wall_$what=$wall cpu_$what=$cpu"
done
echo "cost of --trace: wall $(echo "100 * ($wall_with - $wall_without) / $wall_without" | bc -l | xargs printf '%+.1f') %," \
     "CPU $(echo "100 * ($cpu_with - $cpu_without) / $cpu_without" | bc -l | xargs printf '%+.1f') %"

echo "== 2. trace sizes"
for seed in 1 2 3 4 5; do printf 'vacuum 900 s seed %s: %s bytes\n' "$seed" "$(stat -c %s "$work/cost/b$seed.trace.json")"; done
run3 TeleTaxi teletaxi teletaxi-referee cityLarge.world 1 "$work/taxi" --trace="$work/taxi.trace.json" >/dev/null
run3 Autopark autopark autopark-referee autopark.world 1 "$work/park" --trace="$work/park.trace.json" >/dev/null
grep -q "mark" "$work/taxi.referee.txt" && grep -q "mark" "$work/park.referee.txt" || { echo "a run did not end with a mark"; exit 1; }
echo "teletaxi: $(stat -c %s "$work/taxi.trace.json") bytes; autopark: $(stat -c %s "$work/park.trace.json") bytes"

fi

if [ "$screenshots" != "--screenshots-only" ]; then
echo "== 3. a class of $students x 5 seeds x 3 worlds: report.html"
# Each student's fifteen runs are the fifteen runs made here (report, trace, picture): the page's
# size and load time depend on the runs' files, not on who ran them.
mkdir -p "$work/class-runs"
python3 "$src/worlds/tools/make_house.py" --out "$work/house_g7.world" --seed 7 --rooms-x 4 --rooms-y 3 >/dev/null
for world in vacuum house_3x2 house_g7; do
  world_file="$world.world"; [ "$world" = house_g7 ] && world_file="$work/house_g7.world"
  for seed in 1 2 3 4 5; do
    stem="$work/class-runs/$world-seed$seed"
    run3 Vacuum vacuum-cleaner vacuum-cleaner-referee "$world_file" "$seed" "$stem" \
      --report="$stem.report.json" --picture="$stem.png" --trace="$stem.trace.json" >/dev/null
  done
done
class="$work/class"
for i in $(seq -w 1 "$students"); do
  mkdir -p "$class/runs/student$i"
  for report in "$work"/class-runs/*.report.json; do
    from="${report%.report.json}"; name="$(basename "$from")"
    stem="$class/runs/student$i/$name"
    python3 - "$report" "$stem" "student$i" "${name%-seed*}.world" <<'EOF2'
import json, sys
report = json.load(open(sys.argv[1]))
report.update({"student": sys.argv[3], "log": sys.argv[2] + ".log", "graded_world": sys.argv[4]})
json.dump(report, open(sys.argv[2] + ".json", "w"), indent=2)
EOF2
    cp "$from.trace.json" "$stem.trace.json"
    cp "$from.png" "$stem.png"
  done
done
t0=$(date +%s.%N)
"$bin/aula" grade --collect "$class" >/dev/null
t1=$(date +%s.%N)
echo "aula grade --collect: $(echo "$t1 - $t0" | bc -l | xargs printf '%.2f') s"
echo "report.html: $(stat -c %s "$class/report.html") bytes ($(ls "$class"/runs/*/*.json | grep -vc 'trace') runs);" \
     "a run's page: $(stat -c %s "$class/runs/student01/vacuum-seed3.html") bytes;" \
     "the folder: $(du -sb "$class" | cut -f1) bytes"
for n in 1 2 3; do
  t0=$(date +%s.%N)
  dom="$(chrome --virtual-time-budget=30000 --dump-dom "file://$class/report.html")"
  t1=$(date +%s.%N)
  echo "load $n: the page's load event at $(grep -o 'data-loaded-ms="[0-9]*"' <<<"$dom" | grep -o '[0-9]*') ms;" \
       "Chromium's whole run (start, load, dump, quit) $(echo "$t1 - $t0" | bc -l | xargs printf '%.2f') s"
done
# A run's player is its own page (report.html shows it in a frame): how long that page takes to open it.
dom="$(chrome --virtual-time-budget=30000 --dump-dom "file://$class/runs/student15/vacuum-seed3.html#t=450")"
echo "opening one run's player (its page): $(grep -o 'data-open-ms="[0-9]*"' <<<"$dom" | grep -o '[0-9]*') ms"
fi

if [ "$screenshots" = "--screenshots" ] || [ "$screenshots" = "--screenshots-only" ]; then
  echo "== screenshots in docs/images"
  out="$src/docs/images"
  mkdir -p "$work/alice/runs/alice" "$work/shots"
  # A vacuum player mid-run (seed 3, at 450 s), with its timeline.
  run3 Vacuum vacuum-cleaner vacuum-cleaner-referee vacuum.world 3 "$work/shots/v" --report="$work/alice/runs/alice/vacuum-seed3.report.json" \
    --picture="$work/alice/runs/alice/vacuum-seed3.png" --trace="$work/alice/runs/alice/vacuum-seed3.trace.json" >/dev/null
  # An Autopark run that touches a parked car when it sets off, stopped at that contact.
  run3 Autopark autopark autopark-referee autopark.world 1 "$work/shots/p" --report="$work/alice/runs/alice/autopark-seed1.report.json" \
    --picture="$work/alice/runs/alice/autopark-seed1.png" --trace="$work/alice/runs/alice/autopark-seed1.trace.json" \
    -- --Simulator.StartPose.car=-7,-1.5,0 >/dev/null
  # An Autopark run that did not park: 12 s are not enough (the page's breakdown, at its end).
  run3 Autopark autopark autopark-referee autopark.world 2 "$work/shots/q" --report="$work/alice/runs/alice/autopark-seed2.report.json" \
    --picture="$work/alice/runs/alice/autopark-seed2.png" --trace="$work/alice/runs/alice/autopark-seed2.trace.json" \
    --Autopark.Referee.Timeout=12 >/dev/null
  # A small class whose marks differ: six students, two seeds, each student's episode shorter or
  # longer (the reference as everyone's algorithm; the overview's histograms and spreads are real).
  i=0
  for duration in 150 300 420 540 700 900; do
    i=$((i + 1))
    mkdir -p "$work/shots/runs/student$i"
    for seed in 1 2; do
      stem="$work/shots/runs/student$i/vacuum-seed$seed"
      run3 Vacuum vacuum-cleaner vacuum-cleaner-referee vacuum.world "$seed" "$stem" --report="$stem.report.json" \
        --picture="$stem.png" --trace="$stem.trace.json" --Vacuum.Referee.Duration="$duration" >/dev/null
    done
  done
  for report in "$work"/shots/runs/*/*.report.json; do
    stem="${report%.report.json}"
    python3 - "$stem" "$(basename "$(dirname "$stem")")" <<'EOF'
import json, sys
report = json.load(open(sys.argv[1] + ".report.json"))
report.update({"student": sys.argv[2], "log": sys.argv[1] + ".log"})
json.dump(report, open(sys.argv[1] + ".json", "w"), indent=2)
EOF
    rm "$report"
  done
  "$bin/aula" grade --collect "$work/shots" >/dev/null
  for report in "$work"/alice/runs/alice/*.report.json; do
    stem="${report%.report.json}"
    python3 - "$stem" alice <<'EOF'
import json, sys
report = json.load(open(sys.argv[1] + ".report.json"))
report.update({"student": sys.argv[2], "log": sys.argv[1] + ".log"})
json.dump(report, open(sys.argv[1] + ".json", "w"), indent=2)
EOF
  done
  "$bin/aula" grade --collect "$work/alice" >/dev/null
  contact=$(python3 -c "import json,sys; t=json.load(open(sys.argv[1])); print([e['t_s'] for e in t['events'] if e['kind']=='contact'][0])" \
            "$work/alice/runs/alice/autopark-seed1.trace.json")
  chrome --window-size=1280,760 --virtual-time-budget=5000 --screenshot="$out/player_vacuum.png" \
    "file://$work/alice/runs/alice/vacuum-seed3.html#t=450"
  chrome --window-size=1280,620 --virtual-time-budget=5000 --screenshot="$out/player_autopark_contact.png" \
    "file://$work/alice/runs/alice/autopark-seed1.html#t=$contact"
  chrome --window-size=1280,760 --virtual-time-budget=5000 --screenshot="$out/player_autopark_not_parked.png" \
    "file://$work/alice/runs/alice/autopark-seed2.html#t=99999"
  chrome --window-size=400,1400 --virtual-time-budget=5000 --screenshot="$out/player_phone.png" \
    "file://$work/alice/runs/alice/vacuum-seed3.html#t=450"
  # Zoomed 4x and following the robot: the player's own controls, set by a line added to a copy.
  python3 - "$work/alice/runs/alice/vacuum-seed3.html" "$work/alice/zoom.html" <<'EOF2'
import sys
page = open(sys.argv[1]).read()
end = page.rindex("</body>")
set_zoom = ("<script>setTimeout(() => { const p = document.querySelector('.player').player; p.zoomSelect.value = 4; "
            "p.zoomSelect.dispatchEvent(new Event('change')); p.followBox.checked = true; "
            "p.followBox.dispatchEvent(new Event('change')); }, 300);</script>")
open(sys.argv[2], "w").write(page[:end] + set_zoom + page[end:])
EOF2
  chrome --window-size=1280,760 --virtual-time-budget=5000 --screenshot="$out/player_zoom_follow.png" "file://$work/alice/zoom.html#t=450"
  # The trace's layers, each switched on by #layers= (player_layers.js): the vacuum's laser rays and
  # published belief, TeleTaxi's plan, Autopark's three lasers, a RoboticsAcademy program's prints.
  mkdir -p "$work/layers"
  "$bin/aula" run vacuum --headless --algorithm=reference --seed=1 --report-html="$work/layers/vacuum.html" >/dev/null 2>&1
  "$bin/aula" run teletaxi --headless --algorithm=reference --seed=1 --report-html="$work/layers/teletaxi.html" >/dev/null 2>&1
  "$bin/aula" run autopark --headless --algorithm=planner --seed=1 --report-html="$work/layers/autopark.html" >/dev/null 2>&1
  "$bin/aula" run vacuum --headless --algorithm="$src/tests/data/python/ra_vacuum/MyAlgorithm.py" --seed=1 \
    --Vacuum.Referee.Duration=120 --report-html="$work/layers/printed.html" >/dev/null 2>&1
  chrome --window-size=1280,800 --virtual-time-budget=5000 --screenshot="$out/player_layers_vacuum.png" \
    "file://$work/layers/vacuum.html#t=450&layers=laser,belief"
  chrome --window-size=1280,800 --virtual-time-budget=5000 --screenshot="$out/player_layers_teletaxi.png" \
    "file://$work/layers/teletaxi.html#t=6&layers=plan"
  chrome --window-size=1280,560 --virtual-time-budget=5000 --screenshot="$out/player_layers_autopark.png" \
    "file://$work/layers/autopark.html#t=10&layers=laser"
  chrome --window-size=1280,820 --virtual-time-budget=5000 --screenshot="$out/player_layers_printed.png" \
    "file://$work/layers/printed.html#t=60&layers=console"
  # The pictures load after the page's load: the compositor's last frame has them.
  chrome --window-size=1280,1500 --virtual-time-budget=20000 --run-all-compositor-stages-before-draw --screenshot="$out/report_overview.png" "file://$work/shots/report.html"
  echo "written: $out/{player_vacuum,player_autopark_contact,player_autopark_not_parked,player_phone,player_zoom_follow,report_overview}.png" \
       "and $out/player_layers_{vacuum,teletaxi,autopark,printed}.png: look at each"
fi
