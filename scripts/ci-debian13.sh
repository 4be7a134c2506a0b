#!/usr/bin/env bash
# CI's Debian 13 ("trixie") stage (.ci/run calls it after the Debian 12 stages): this checkout's
# HEAD, cloned into a Debian 13 root, with its dependencies from scripts/install-deps.sh, built
# with AULA_WERROR, its unit tests (ctest -L unit), and one headless run of each exercise's
# reference. Needs root (debootstrap, and the namespaces and mounts each command in the root runs in).
#
# The root is made once with `debootstrap --variant=minbase trixie` and kept, with its installed
# packages and its own ccache, in AULA_DEBIAN13_ROOT (default /var/cache/aula-ci/trixie): a warm
# stage installs nothing and rebuilds from the cache. Delete that folder to start cold.
#   scripts/ci-debian13.sh              the whole stage
#   scripts/ci-debian13.sh --all-tests  the same, but `./aula test` (every test, unit and
#                                       integration, with the test set of packages) for the unit tests
#   scripts/ci-debian13.sh --ctest REGEX  only `./aula test -R REGEX` in the root (everything built,
#                                       the test set installed; each test's output shown, no
#                                       exercise runs): one test, or a few, again after a fix
#   scripts/ci-debian13.sh --marks SEEDS  only bench/marks_across_releases.sh in the root (the
#                                       exercises built, no tests): the references' marks over
#                                       SEEDS (1-5), to diff with the same script on Debian 12
#   AULA_DEBIAN13_ROOT=DIR scripts/ci-debian13.sh
set -euo pipefail
usage() { echo "usage: scripts/ci-debian13.sh [--all-tests | --ctest REGEX | --marks SEEDS]" >&2; exit 2; }
args=("$@")
all_tests=0
ctest_regex=""
marks_seeds=""
while [ $# -gt 0 ]; do
  case "$1" in
    --marks) [ $# -ge 2 ] && [[ "$2" =~ ^[0-9]+-[0-9]+$ ]] || usage; marks_seeds="$2"; shift ;;
    --all-tests) all_tests=1 ;;
    --ctest) [ $# -ge 2 ] && [ -n "$2" ] || usage; ctest_regex="$2"; all_tests=1; shift ;;
    --ctest=?*) ctest_regex="${1#--ctest=}"; all_tests=1 ;;
    *) usage ;;
  esac
  shift
done
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
root="${AULA_DEBIAN13_ROOT:-/var/cache/aula-ci/trixie}"
start_s=$SECONDS
say() { echo "ci-debian13 [$((SECONDS - start_s)) s]: $*"; }

if [ "$(id -u)" -ne 0 ]; then
  # As install-deps.sh does: sudo when it asks for no password, else say what is needed.
  if command -v sudo >/dev/null && sudo -n true 2>/dev/null; then exec sudo -n "$0" "${args[@]}"; fi
  echo "ci-debian13: needs root (debootstrap, namespaces and mount); run it as root or with sudo" >&2
  exit 2
fi

# 1. The root: made once (about 2 minutes), then reused. A half-made one is made again.
if [ ! -f "$root/.aula-debian13-ready" ]; then
  command -v debootstrap >/dev/null || { apt-get update -qq && apt-get install -y -qq debootstrap >/dev/null; }
  rm -rf "$root.partial"
  mkdir -p "$(dirname "$root")"
  say "making a Debian 13 root in $root (debootstrap --variant=minbase trixie)"
  debootstrap --variant=minbase trixie "$root.partial" >"$(dirname "$root")/debootstrap.log" 2>&1 ||
    { tail -20 "$(dirname "$root")/debootstrap.log"; exit 1; }
  rm -rf "$root"
  mv "$root.partial" "$root"
  touch "$root/.aula-debian13-ready"
else
  say "reusing the Debian 13 root in $root"
fi

# 2. Every command in the root runs as in a container rather than a chroot: in mount and PID
# namespaces of its own, the root made "/" with pivot_root. Why: the kernel refuses a chrooted
# process a user namespace (unshare(CLONE_NEWUSER) fails with EPERM), which the sandbox
# (bubblewrap) needs, so the sandbox's tests could not run in a chroot; and the root's /proc, /sys
# and /dev exist only in that mount namespace, so none is left on the host when the command ends,
# fails or is killed. --kill-child and the PID namespace end whatever the command started.
# The root shares the host's network and name (no network or UTS namespace of its own), so it
# resolves names as the host does: its resolv.conf and its hosts file, which names this machine.
# debootstrap's hosts file names only localhost, and a program that looks up its own host name
# failed (a Slurm daemon could not find its controller, `hostname -s`, and retried until the
# Slurm test's timeout).
cp /etc/resolv.conf "$root/etc/resolv.conf"
cp /etc/hosts "$root/etc/hosts"
# 3. This checkout's HEAD as a clean clone inside the root (the build folder is kept between
# stages: ccache does the rest).
commit="$(git -C "$here" rev-parse HEAD)"
src="$root/src/aula"
if [ ! -d "$src/.git" ]; then
  rm -rf "$src"
  mkdir -p "$root/src"
  git clone --quiet --no-checkout "$here" "$src"
fi
git -C "$src" fetch --quiet "$here" "$commit"
git -C "$src" checkout --quiet --force --detach "$commit"
git -C "$src" clean --quiet -fdx -e build/
say "cloned $commit into $src"

in_root() {  # in_root COMMAND: runs COMMAND with bash in the root's /src/aula
  unshare --mount --propagation private --pid --fork --kill-child -- /bin/bash -c '
    set -e
    mount --bind "$1" "$1"  # pivot_root needs the new root to be a mount point
    mount -t proc proc "$1/proc"
    mount --rbind /sys "$1/sys"
    mount --rbind /dev "$1/dev"
    cd "$1"
    mkdir -p .aula-host
    pivot_root . .aula-host
    cd /
    umount -l /.aula-host
    exec /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 \
      CCACHE_DIR=/var/cache/ccache TMPDIR=/tmp /bin/bash -c "cd /src/aula && $2"' in_root "$root" "$1"
}

# 4. Dependencies: only what the stage builds and runs (`build`), from Debian 13's own packages.
in_root "scripts/install-deps.sh build"
say "dependencies installed"

# 5. Build with warnings as errors, through the root's own ccache: what the unit tests and the
# exercises' runs need (as scripts/sanitize-check.sh builds), or everything with --all-tests.
targets="--target aula_unit_tests aula_all_exercises"
[ "$all_tests" = 1 ] && targets=""
in_root "cmake --preset default -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache >/dev/null &&
  cmake --build build -j\$(nproc) $targets >build/ci-build.log 2>&1 || { tail -60 build/ci-build.log; exit 1; }"
say "built ($(in_root "ccache -s 2>/dev/null | grep -E '^ *Hits' | head -1 | tr -s ' '"))"

if [ -n "$marks_seeds" ]; then
  in_root "bench/marks_across_releases.sh build $marks_seeds"
  exit 0
fi

# 6. The unit tests, or with --all-tests every test (./aula test installs the test set first), or
# with --ctest only the tests it names (and then nothing else: no exercise runs).
if [ -n "$ctest_regex" ]; then
  in_root "./aula test --timeout 1200 -R $(printf '%q' "$ctest_regex") 2>&1 | tee build/ci-ctest.log; exit \${PIPESTATUS[0]}"
  say "the tests matching '$ctest_regex' passed"
  exit 0
elif [ "$all_tests" = 1 ]; then
  in_root "./aula test --timeout 1200 >build/ci-test.log 2>&1 ||
    { grep -E 'tests passed|Failed|\\*\\*\\*|Not Run|Skipped' build/ci-test.log | tail -60; exit 1; }
    grep -E 'tests passed|Total Test time' build/ci-test.log"
  say "every test passed"
else
  in_root "ctest --test-dir build -L unit -j\$(nproc) --output-on-failure --timeout 600 >build/ci-unit.log 2>&1 ||
    { grep -E 'tests passed|Failed|\\*\\*\\*' build/ci-unit.log | tail -40; exit 1; }; grep 'tests passed' build/ci-unit.log"
  say "unit tests passed"
fi

# 7. Each exercise's headless runs as it declares them (RUNS of its aula_exercise(), the build's
# exercises/runs.txt; scripts/sanitize-check.sh runs the same), on a port of its own; the mark
# must be in the report.
# (fd 3: the programs run keep the stage's stdin)
while read -r name exercise args <&3; do
  case "$name" in ''|'#'*) continue ;; esac
  in_root "build/bin/aula run $exercise --headless $args --seed=1 \
    --lcm-url='udpm://239.255.76.67:0?ttl=0' --report=/tmp/ci-$name.json >/tmp/ci-$name.log 2>&1 ||
    { tail -30 /tmp/ci-$name.log; exit 1; }
    grep -q '\"mark\"' /tmp/ci-$name.json || { echo 'no mark in the report'; cat /tmp/ci-$name.json; exit 1; }"
  say "$name: $(in_root "grep -E '\"(mark|coverage_percent)\"' /tmp/ci-$name.json | tr -d ' \n'")"
done 3<"$src/build/exercises/runs.txt"
say "Debian 13 stage passed in $((SECONDS - start_s)) s"
