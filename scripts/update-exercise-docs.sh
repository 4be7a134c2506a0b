#!/usr/bin/env bash
# Regenerates the grading settings in docs/exercises/<exercise>.md from the referees' declared
# settings (`aula config EXERCISE --markdown`), between the settings:begin and settings:end
# markers. The test Docs.ExercisePagesShowTheRefereesSettings fails when they drift.
# Usage: scripts/update-exercise-docs.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build}"
# Every exercise `aula --help` lists (the demo has no referee, hence no grading settings).
mapfile -t exercises < <("$build/bin/aula" --help | sed -n '/^exercises:/,/^[^ ]/p' | awk '/^  [a-z]/ && $1 != "demo" {print $1}')
for exercise in "${exercises[@]}"; do
  page="$here/docs/exercises/$exercise.md"
  table="$("$build/bin/aula" config "$exercise" --markdown)"
  python3 - "$page" "$table" <<'PY'
import re, sys
page, table = sys.argv[1], sys.argv[2]
text = open(page).read()
new = re.sub(r"(<!-- settings:begin[^>]*-->\n)(.*?)(<!-- settings:end -->)",
             lambda m: m.group(1) + table.rstrip("\n") + "\n" + m.group(3), text, flags=re.S)
open(page, "w").write(new)
PY
done
echo "docs/exercises: settings regenerated"
