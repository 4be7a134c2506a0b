# What the GUI tests share (source it, then call gui_test_start NAME BUILD_DIR): the test runs
# under a virtual display of its own (xvfb-run, re-executing the script; $gui_screen, 1400x1000
# unless the script sets it first), on a private LCM port, in a scratch folder; its processes are
# ended and the folder removed at exit.
#   $build $work $port $url   set by gui_test_start
#   start_window_manager      openbox on the display, once it manages windows (decorations, placement)
#   fail MESSAGE              prints the run's logs and exits 1
#   wait_for SECONDS WHAT COMMAND...   until COMMAND succeeds, or fails naming WHAT
#   find_window TITLE_REGEX   the window's id, once it is mapped (30 s at most)

gui_test_start() {
  local name="$1"
  build="$2"
  if [ -z "${AULA_GUI_TEST_DISPLAY:-}" ]; then
    AULA_GUI_TEST_DISPLAY=1 exec xvfb-run -a -s "-screen 0 ${gui_screen:-1400x1000}x24" bash "$0" "$build"
  fi
  work="$(mktemp -d "${TMPDIR:-/tmp}/aula-$name-XXXXXX")"
  port=$(python3 "$(dirname "${BASH_SOURCE[0]}")/../../free_udp_port.py")
  url="udpm://239.255.76.67:$port?ttl=0"
  export XDG_CACHE_HOME="$work/cache" XDG_RUNTIME_DIR="$work/runtime"
  mkdir -m 700 -p "$XDG_RUNTIME_DIR"
  trap gui_test_cleanup EXIT
}

gui_test_cleanup() {
  pkill -TERM -f "239.255.76.67:$port" 2>/dev/null || true
  [ -z "${window_manager:-}" ] || kill -TERM "$window_manager" 2>/dev/null || true
  sleep 0.3
  rm -rf "$work"
}

fail() {
  echo "FAIL: $*"
  for log in "$work"/*.log; do
    [ -f "$log" ] || continue
    echo "--- $(basename "$log"):"
    tail -n 40 "$log"
  done
  exit 1
}

wait_for() {
  local deadline=$((SECONDS + $1)) what="$2"
  shift 2
  until "$@" >/dev/null 2>&1; do
    [ $SECONDS -lt $deadline ] || fail "timed out waiting for $what"
    sleep 0.2
  done
}

find_window() {
  local id
  id=$(timeout 30 xdotool search --sync --name "$1" | head -1) || true
  [ -n "$id" ] || fail "no window named /$1/"
  echo "$id"
}

start_window_manager() {
  command -v openbox >/dev/null || fail "no openbox (scripts/install-deps.sh test installs it)"
  openbox --sm-disable >"$work/openbox.log" 2>&1 &
  window_manager=$!
  wait_for 20 "openbox to manage the display" "$build/bin/aula-test-desktop" windows
}
