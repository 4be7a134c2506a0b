#!/usr/bin/env bash
# A mark does not depend on the machine (issue 38): a class of slow-but-correct Python TeleTaxi
# planners graded twice, once alone with --jobs=1, once with --jobs=2 beside six busy loops, must
# give the same grades.csv marks with every run finished. Each student's planner is a tested one
# (tests/data/python/teletaxi_follow, ra_teletaxi) made slow on purpose: CPU burnt at import (numpy
# and cv2 imported too) and before it plans, from 0.5 + 1 s to 2 + 4 s (the issue's 1.5 s of
# imports and 3 s of planning among them). Prints both grades' wall times, their marks side by
# side, and exits 1 if they differ or a run did not finish.
# Usage: bench/grade_under_load.sh BUILD_DIR [SEEDS=1,2] [BUSY_LOOPS=6]
set -euo pipefail
build="$(cd "$1" && pwd)"; seeds="${2:-1,2}"; loops="${3:-6}"
src="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-grade-under-load-XXXXXX")"
busy=()
cleanup() { [ ${#busy[@]} -eq 0 ] || kill "${busy[@]}" 2>/dev/null || true; rm -rf "$work"; }
trap cleanup EXIT

# The class: one folder each. Three planners in Aula's shape (teletaxi_follow's wavefront beside them
# as a module of the student's own: a graded run sees its folder and nothing else) and three in
# RoboticsAcademy's (ra_teletaxi), each with CPU burnt at import and before it plans, and each shape
# once as it is (0 s): the slow ones must earn what it earns.
burn_function='import time as _t


def burn(cpu_s):  # real CPU time (the sim clock is time.time())
    end = _t.process_time() + cpu_s
    while _t.process_time() < end:
        pass
'
i=0
for spec in "aula 0.0 0.0" "aula 0.5 1.0" "aula 1.0 2.0" "ra 0.0 0.0" "ra 1.5 3.0" "ra 2.0 4.0"; do
  i=$((i + 1))
  read -r shape import_s plan_s <<<"$spec"
  d="$work/class/slow$i"
  mkdir -p "$d"
  if [ "$shape" = aula ]; then
    cp "$src/tests/data/python/teletaxi_follow/MyAlgorithm.py" "$d/follow.py"
    cat >"$d/MyAlgorithm.py" <<EOF
# A correct planner that computes slowly: ${import_s} s of CPU at load, ${plan_s} s more to plan.
import cv2  # noqa: F401
import numpy  # noqa: F401

import follow
${burn_function}

burn(${import_s})


class MyAlgorithm(follow.MyAlgorithm):
    def generatePath(self, api):
        burn(${plan_s})
        super().generatePath(api)
EOF
  else
    python3 - "$src/tests/data/python/ra_teletaxi/MyAlgorithm.py" "$d/MyAlgorithm.py" "$import_s" "$plan_s" "$burn_function" <<'PY'
import sys
text = open(sys.argv[1]).read()
imports_end = text.index("import cv2\n") + len("import cv2\n")
plan = text.index("free = city > 127")
text = (text[:imports_end] + sys.argv[5] + "\n\nburn(%s)\n" % sys.argv[3] + text[imports_end:plan] +
        "burn(%s)\n" % sys.argv[4] + text[plan:])
open(sys.argv[2], "w").write(text)
PY
  fi
done

grade() {  # OUT JOBS
  local t0=$SECONDS
  "$build/bin/aula" grade teletaxi "$work"/class/* --seeds="$seeds" --jobs="$2" --out="$1" --similarity=off \
    >"$1.txt" 2>&1 || { echo "aula grade failed:"; tail -20 "$1.txt"; exit 1; }
  echo "$((SECONDS - t0))"
}

# Each student's row as "student<TAB>median<TAB>failures" (a failure's text has spaces).
marks() { python3 -c 'import csv,sys; [print(r["student"], r["median"], r["failures"] or "-", sep="\t") for r in sorted(csv.DictReader(open(sys.argv[1])), key=lambda r: r["student"])]' "$1/grades.csv"; }
unfinished() { grep -L '"finished": true' "$1"/runs/*/*.json | grep -v -e '\.trace\.json$' -e '\.report\.json$' || true; }

alone_s=$(grade "$work/alone" 1)
# Each loop a session of its own: the scheduler groups a session's processes (autogroup), and one
# group of six loops would weigh as one process against the sandboxed runs (each their own session).
for _ in $(seq "$loops"); do setsid bash -c 'while :; do :; done' & busy+=($!); done
loaded_s=$(grade "$work/loaded" 2)
[ ${#busy[@]} -eq 0 ] || kill "${busy[@]}"
busy=()

echo "alone, --jobs=1: ${alone_s} s; beside ${loops} busy loops, --jobs=2: ${loaded_s} s (seeds ${seeds}, $(nproc) CPUs)"
paste <(marks "$work/alone") <(marks "$work/loaded") |
  awk -F'\t' '{ printf "%-8s alone %-10s loaded %-10s %s\n", $1, $2, $5, ($2 == $5 && $3 == $6 ? "same" : "DIFFERENT") }'
status=0
diff <(marks "$work/alone") <(marks "$work/loaded") >/dev/null || { echo "the marks differ"; status=1; }
for out in alone loaded; do
  left="$(unfinished "$work/$out")"
  [ -z "$left" ] || { echo "$out: runs that did not finish: $left"; status=1; }
done
[ $status -eq 0 ] && echo "the same marks, every run finished"
exit $status
