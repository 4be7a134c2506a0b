#!/usr/bin/env bash
# Every header an installed Aula puts in include/ compiles on its own: installed into a prefix,
# each one is the only line of a .cpp, built by a project that knows nothing but the prefix's
# package (find_package(Aula) and its API targets: the installed include folder, OpenCV, Eigen).
# A header that includes one that is not installed fails here (proxies.hpp did: aula/lcm/bus.hpp).
# Usage: test_headers.sh BUILD_DIR
set -euo pipefail
build="$1"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-headers-XXXXXX")"
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/prefix" >/dev/null
mkdir -p "$work/project/src"
headers=$(cd "$work/prefix/include" && find aula -name '*.hpp' | sort)
[ -n "$headers" ] || { echo "no header installed under $work/prefix/include/aula"; exit 1; }
sources=""
n=0
for h in $headers; do
  n=$((n + 1))
  echo "#include <$h>" >"$work/project/src/h$n.cpp"
  sources="$sources src/h$n.cpp"
done
cat >"$work/project/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.16)
project(aula_headers CXX)
set(CMAKE_CXX_STANDARD 17)
find_package(Aula REQUIRED PATHS "$work/prefix" NO_DEFAULT_PATH)
add_library(each_header OBJECT $sources)
target_link_libraries(each_header PRIVATE Aula::vacuum_api Aula::teletaxi_api Aula::autopark_api)
CMAKE
cmake -S "$work/project" -B "$work/project/build" -G Ninja >"$work/configure.txt" 2>&1 || { cat "$work/configure.txt"; exit 1; }
if ! cmake --build "$work/project/build" -- -k 0 >"$work/build.txt" 2>&1; then
  echo "installed headers that do not compile on their own:"
  for i in $(seq 1 "$n"); do
    grep -q "src/h$i.cpp.o" <(grep FAILED "$work/build.txt") && echo "  $(cat "$work/project/src/h$i.cpp")"
  done
  grep -m 20 "error" "$work/build.txt"
  exit 1
fi
echo "ok: the $n installed headers each compile on their own"
