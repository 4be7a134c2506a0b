#!/usr/bin/env bash
# The desktop as a student sees it, on a 1920x1080 screen with a window manager (openbox): after
# `aula run vacuum --3d` (the component, the referee and the 3D view), `aula run teletaxi` with
# its "Grid Field" window, and `aula replay` of a recorded run (the two viewers and the player),
# no two windows overlap (frames, decorations included) and every window is on the screen, when
# they open and again once the referee shows the mark; no window changed size in between. The
# replay's player names the recorded algorithm. A picture of the whole screen is taken at each
# mark ($AULA_DESKTOP_PICTURES=FOLDER keeps them).
# Usage: test_window_layout.sh BUILD_DIR
set -euo pipefail
gui_screen=1920x1080
source "$(dirname "$0")/lib.sh"
gui_test_start window-layout "$@"
start_window_manager
screen_w=1920
screen_h=1080

# Every managed window whose title matches one of the regexes, once all are open (60 s at most).
windows_of() { "$build/bin/aula-test-desktop" windows; }
all_open() {
  local listing
  listing=$(windows_of)
  for title in "$@"; do grep -Eq "^([-0-9]+ ){6}$title" <<<"$listing" || return 1; done
}

# A line's title: what follows its six numbers (mawk has no {6}).
title_of='function title(line, k) { for (k = 0; k < 6; ++k) sub(/^[-0-9]+ /, "", line); return line }'

# No two frames overlap, every frame is on the screen; prints the offence.
check_layout() {
  awk -v W=$screen_w -v H=$screen_h -v when="$1" "$title_of"'
    { x[NR] = $1; y[NR] = $2; w[NR] = $3; h[NR] = $4; t[NR] = title($0) }
    END {
      bad = 0
      for (i = 1; i <= NR; ++i) {
        if (x[i] < 0 || y[i] < 0 || x[i] + w[i] > W || y[i] + h[i] > H) {
          printf "%s: \"%s\" (%d,%d %dx%d) is not inside the %dx%d screen\n", when, t[i], x[i], y[i], w[i], h[i], W, H; bad = 1
        }
        for (j = i + 1; j <= NR; ++j) {
          ox = (x[i] + w[i] < x[j] + w[j] ? x[i] + w[i] : x[j] + w[j]) - (x[i] > x[j] ? x[i] : x[j])
          oy = (y[i] + h[i] < y[j] + h[j] ? y[i] + h[i] : y[j] + h[j]) - (y[i] > y[j] ? y[i] : y[j])
          if (ox > 0 && oy > 0) {
            printf "%s: \"%s\" (%d,%d %dx%d) and \"%s\" (%d,%d %dx%d) overlap by %dx%d px\n", when, t[i], x[i], y[i], \
                   w[i], h[i], t[j], x[j], y[j], w[j], h[j], ox, oy; bad = 1
          }
        }
      }
      exit bad
    }' "$2"
}

# Each window's own size (client area) at the mark is its size at the start.
check_sizes() {
  awk "$title_of"'
       FNR == NR { size[title($0)] = $5 "x" $6; next }
       { t = title($0)
         if (!(t in size)) { printf "\"%s\" at the mark was not open at the start\n", t; bad = 1 }
         else if (size[t] != $5 "x" $6) { printf "\"%s\" changed size: %s at the start, %dx%d at the mark\n", t, size[t], $5, $6; bad = 1 } }
       END { exit bad }' "$1" "$2"
}

# CASE: the windows open (TITLES...), then once FILE.json is finished the mark; checked and pictured.
check_desktop() {
  local name="$1" report="$2" problems=""
  shift 2
  wait_for 60 "the $name windows ($*)" all_open "$@"
  sleep 0.5  # the windows' first layout, and the WM's placement
  windows_of >"$work/$name.start.txt"
  [ -z "${press_run:-}" ] || xdotool search --name "$press_run" windowactivate --sync key F5
  wait_for 120 "the $name mark" grep -q '"finished"' "$report"
  sleep 1.5  # the referee window shows the mark
  windows_of >"$work/$name.mark.txt"
  "$build/bin/aula-test-desktop" grab "$work/$name.png" || fail "no picture of the screen"
  [ -z "${AULA_DESKTOP_PICTURES:-}" ] || cp "$work/$name.png" "$AULA_DESKTOP_PICTURES/"
  echo "$name at the start:"; cat "$work/$name.start.txt"
  echo "$name at the mark:"; cat "$work/$name.mark.txt"
  check_layout "$name at the start" "$work/$name.start.txt" >>"$work/problems.txt" || problems=1
  check_layout "$name at the mark" "$work/$name.mark.txt" >>"$work/problems.txt" || problems=1
  check_sizes "$work/$name.start.txt" "$work/$name.mark.txt" >>"$work/problems.txt" || problems=1
  [ -z "$problems" ] || echo "$name: the layout has problems" >>"$work/problems.txt"
}

stop_run() {
  kill -TERM "$1" 2>/dev/null || true
  wait "$1" || true
  wait_for 20 "the $2 windows to close" bash -c "! pgrep -f '[2]39.255.76.67:$port' >/dev/null"
}
: >"$work/problems.txt"

# 1. The vacuum with its 3D view, run from the component's window (F5) as a student does.
"$build/bin/aula" run vacuum --3d --algorithm=reference --duration=20 --rtf=4 --report="$work/vacuum.json" \
  --lcm-url="$url" >"$work/vacuum.log" 2>&1 &
run=$!
press_run='^Vacuum cleaner$' check_desktop vacuum "$work/vacuum.json" 'Vacuum cleaner' 'Vacuum cleaner referee' 'Aula 3D view'
stop_run $run vacuum

# 2. TeleTaxi with the "Grid Field" window its algorithm opens (autostart: the grid opens at once).
plugin="$build/tests/integration/plugins/libaula_test_fault_teletaxi_shows_grid.so"
[ -f "$plugin" ] || fail "no grid-showing plugin at $plugin"
"$build/bin/aula" run teletaxi --algorithm="$plugin" --TeleTaxi.Autostart=true --duration=8 --rtf=2 \
  --report="$work/teletaxi.json" --lcm-url="$url" >"$work/teletaxi.log" 2>&1 &
run=$!
check_desktop teletaxi "$work/teletaxi.json" 'TeleTaxi - Gradient Path Planning' 'TeleTaxi referee' 'Grid Field'
stop_run $run teletaxi

# 3. aula replay of a recorded vacuum run: the viewers and the player, which names the algorithm.
"$build/bin/aula" run vacuum --headless --algorithm=bounce --duration=30 --record="$work/run.lcmlog" \
  --lcm-url="$url" >"$work/recorded.log" 2>&1 || fail "the recorded run failed"
"$build/bin/aula" replay "$work/run.lcmlog" --speed=5 --report="$work/replayed.json" --lcm-url="$url" \
  >"$work/replay.log" 2>&1 &
run=$!
check_desktop replay "$work/replayed.json" 'Vacuum cleaner.*' 'Vacuum cleaner referee' 'Aula replay: .*'
grep -Eq "^([-0-9]+ ){6}Aula replay: .*bounce" "$work/replay.start.txt" ||
  echo "replay: the player's title does not name the recorded algorithm (bounce): $(grep 'Aula replay' "$work/replay.start.txt")" >>"$work/problems.txt"
stop_run $run replay

if [ -s "$work/problems.txt" ]; then fail "$(cat "$work/problems.txt")"; fi
echo "window layout: no overlap and no size change in the three desktops"
