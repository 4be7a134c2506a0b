#!/usr/bin/env bash
# An exercise is its own folders: the short way of docs/adding-an-exercise.md, step by step. Copy
# every file whose path names the vacuum exercise (its tests, bench scripts and pictures included)
# under a new name, with the name replaced inside those copies only, and nothing else edited. The
# copy must build, pass its own unit tests and the docs check (scripts/update-doc-lists.py
# --check), be listed by `aula --help`, be in CI's lists of runs, and its reference must cover what
# vacuum's covers on the same world and seed. It builds what those checks run, not the whole tree
# (the page's step 3 builds all): the tree is over twice the steps (603 against 255), too long for
# CI's budget on a fresh machine, and the rest is built and tested by the tree's own build. The
# clone sits at a fixed path in the build folder, so ccache makes the next run's compiles quick.
# Usage: test_clone_exercise.sh SOURCE_DIR BUILD_DIR (BUILD_DIR: the tree's own build, for vacuum's run)
set -euo pipefail
source_dir="$(cd "$1" && pwd)"
build_dir="$(cd "$2" && pwd)"
name=sweeper
work="$build_dir/clone_exercise"  # a fixed path: the next run's compiles are ccache's hits
rm -rf "$work"
mkdir -p "$work"
trap 'rm -rf "$work"' EXIT
clone="$work/src"

# 1. The tree as it is (tracked files and new ones git does not ignore), without its build.
mkdir -p "$clone"
(cd "$source_dir" && git ls-files -z --cached --others --exclude-standard) |
  (cd "$source_dir" && xargs -0 cp --parents -P -t "$clone" || true)  # a file deleted but not yet committed: said, not fatal
[ -f "$clone/CMakeLists.txt" ] || { echo "FAIL: could not copy the tree"; exit 1; }

# 2. The clone (the page's steps 1 and 2): each path naming vacuum copied under the new name; text
# files get the name replaced (vacuum, Vacuum, VACUUM), pictures are copied as they are.
copied=0
while IFS= read -r -d '' path; do
  target="${path//vacuum/$name}"
  target="${target//Vacuum/${name^}}"
  mkdir -p "$clone/$(dirname "$target")"
  if [ -L "$source_dir/$path" ]; then
    cp -P "$source_dir/$path" "$clone/$target"
  elif grep -Iq . "$source_dir/$path" 2>/dev/null; then
    sed -e "s/vacuum/$name/g" -e "s/Vacuum/${name^}/g" -e "s/VACUUM/${name^^}/g" "$source_dir/$path" >"$clone/$target"
  else
    cp "$source_dir/$path" "$clone/$target"
  fi
  copied=$((copied + 1))
done < <(cd "$source_dir" && git ls-files -z --cached --others --exclude-standard | grep -z -i vacuum)
echo "copied $copied files naming vacuum as $name"
[ "$copied" -gt 10 ] || { echo "FAIL: too few files name vacuum ($copied)"; exit 1; }

# 3. Its build (the page's step 3), bounded to what the checks below run: `./aula run $name`'s
# programs and plugins (aula_run_$name), its unit tests (aula_unit_tests_$name), and the docs
# check's grades.csv columns (aula-test-grades-columns). The docs check reads the other programs'
# --help only when built: their lines in the docs are the tree's, checked by docs.ListsMatchTheCode.
# ccache when the machine has it.
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$clone" -B "$clone/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DAULA_WERROR=ON "${launcher[@]}" \
  >"$work/configure.log" 2>&1 || { tail -30 "$work/configure.log"; echo "FAIL: the clone does not configure"; exit 1; }
cmake --build "$clone/build" -j"$(nproc)" --target "aula_run_$name" "aula_unit_tests_$name" aula-test-grades-columns \
  >"$work/build.log" 2>&1 ||
  { grep -E 'error|FAILED' "$work/build.log" | head -30; echo "FAIL: the clone does not build"; exit 1; }
echo "the clone builds aula_run_$name and aula_unit_tests_$name"

# Its own unit tests (components/$name/tests/, added from tests/unit), and the docs check.
[ -f "$clone/components/$name/tests/CMakeLists.txt" ] || { echo "FAIL: the copy has no tests of its own"; exit 1; }
ctest --test-dir "$clone/build/tests/unit/$name" -j"$(nproc)" --output-on-failure >"$work/ctest.log" 2>&1 ||
  { grep -E 'tests passed|Failed|\*\*\*' "$work/ctest.log" | tail -30; echo "FAIL: the copy's unit tests fail"; exit 1; }
grep -q "tests passed, 0 tests failed out of [1-9]" "$work/ctest.log" ||
  { tail -5 "$work/ctest.log"; echo "FAIL: the copy ran no unit test"; exit 1; }
echo "the copy's unit tests pass: $(grep 'tests passed' "$work/ctest.log")"
(cd "$clone" && python3 scripts/update-doc-lists.py --check build) >"$work/docs.log" 2>&1 ||
  { cat "$work/docs.log"; echo "FAIL: the docs check fails in the clone"; exit 1; }
echo "scripts/update-doc-lists.py --check passes in the clone"
# CI's lists (scripts/sanitize-check.sh, scripts/ci-debian13.sh read them) run the copy.
grep -q "^$name $name " "$clone/build/exercises/runs.txt" ||
  { cat "$clone/build/exercises/runs.txt"; echo "FAIL: CI's runs leave $name out"; exit 1; }
echo "CI's runs include $name"

# 4. Listed by the front door.
"$clone/build/bin/aula" --help >"$work/help.txt"
grep -q "^  $name " "$work/help.txt" || { cat "$work/help.txt"; echo "FAIL: aula --help does not list $name"; exit 1; }
echo "aula --help lists $name"

# 5. Its reference covers what vacuum's covers (same world, same seed), each run on a bus of its own.
"$clone/build/bin/aula" run "$name" --headless --algorithm=reference --seed=1 --report="$work/$name.json" \
  >"$work/$name.log" 2>&1 || { tail -20 "$work/$name.log"; echo "FAIL: aula run $name failed"; exit 1; }
"$build_dir/bin/aula" run vacuum --headless --algorithm=reference --seed=1 --report="$work/vacuum.json" \
  >"$work/vacuum.log" 2>&1 || { tail -20 "$work/vacuum.log"; echo "FAIL: aula run vacuum failed"; exit 1; }
field() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])' "$1" "$2"; }
clone_coverage="$(field "$work/$name.json" coverage_percent)"
vacuum_coverage="$(field "$work/vacuum.json" coverage_percent)"
echo "coverage: $name $clone_coverage %, vacuum $vacuum_coverage %"
[ "$clone_coverage" = "$vacuum_coverage" ] || { echo "FAIL: the clone covers $clone_coverage %, vacuum $vacuum_coverage %"; exit 1; }
[ "$(field "$work/$name.json" mark)" = "$(field "$work/vacuum.json" mark)" ] || { echo "FAIL: the marks differ"; exit 1; }
echo "the clone $name covers what vacuum covers"
