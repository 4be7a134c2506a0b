#!/usr/bin/env bash
# Installs Aula's dependencies with apt (Debian 12 "bookworm" or Debian 13 "trixie", told apart by
# /etc/os-release), by set, so each command installs only its own:
#   scripts/install-deps.sh build   to build and run Aula (what `./aula run` and `./aula build` need)
#   scripts/install-deps.sh test    the above, plus what the tests drive: Xvfb, openbox, Chromium, lintian,
#                                   the python-lcm wheel, and a single-node Slurm (the Slurm tests)
#   scripts/install-deps.sh slurm   the above's Slurm part alone: to grade with --engine=slurm
#   scripts/install-deps.sh all     every set (the default)
# Idempotent: quiet and fast when everything is already there.
set -euo pipefail

build_packages=(
  build-essential cmake ninja-build pkg-config git ccache dpkg-dev
  libdart-all-dev libdart-collision-bullet-dev libdart-utils-dev libdart-gui-osg-dev
  libdart-external-lodepng-dev libdart-external-imgui-dev
  libtinyxml2-dev libassimp-dev
  liblcm-dev liblcm-bin libglib2.0-dev
  libompl-dev
  qtbase5-dev libqt5charts5-dev
  libopencv-dev
  libeigen3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libssl-dev libseccomp-dev
  # aula grade: students' zips and LMS exports (the same name on Debian 12 and 13)
  libminizip-dev
  # to run: the sandbox, a run's private network, the generators
  libgl1-mesa-dri bubblewrap iproute2 procps python3
  # the embedded Python of a student's MyAlgorithm.py
  python3-dev pybind11-dev python3-numpy python3-opencv python3-greenlet
)
test_packages=(xvfb xauth xdotool openbox bc python3-pip chromium lintian)

# What differs between the releases. Aula reads SDF with its own reader (libs/world, on tinyxml2)
# on both; Debian 12's libsdformat is only the oracle of that reader's test (WorldSdfOracle), and
# Debian 13 has no libsdformat at all. Everything else has the same package names on both.
release_id="unknown"
if [ -r /etc/os-release ]; then release_id="$(. /etc/os-release && echo "${ID:-unknown}-${VERSION_ID:-unknown}")"; fi
case "$release_id" in
  debian-12) test_packages+=(libsdformat-dev) ;;
  debian-13) ;;
  *) echo "install-deps: $release_id is neither Debian 12 nor 13; trying Debian 13's package names" >&2 ;;
esac
slurm_packages=(slurmctld slurmd slurm-client munge)

set_name="${1:-all}"
case "$set_name" in
  build) wanted=("${build_packages[@]}") ;;
  slurm) wanted=("${slurm_packages[@]}") ;;
  test|all) wanted=("${build_packages[@]}" "${test_packages[@]}" "${slurm_packages[@]}") ;;
  *) echo "usage: scripts/install-deps.sh [build|test|slurm|all]" >&2; exit 2 ;;
esac

missing=()
for p in "${wanted[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps ($set_name): installing ${#missing[@]} package(s): ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# python-lcm, the independent LCM client of tests/integration/test_stock_lcm_client.sh: Debian
# packages LCM's C, C++ and Java parts but not its Python module; PyPI has LCM's own wheel. It goes
# to the python3 on PATH, the one the test runs. Tests only.
if [ "$set_name" = test ] || [ "$set_name" = all ]; then
  if ! python3 -c 'import lcm' 2>/dev/null; then
    echo "install-deps: installing python-lcm (PyPI: lcm==1.5.0)"
    python3 -m pip install --quiet 'lcm==1.5.0' 2>/dev/null ||
      python3 -m pip install --quiet --break-system-packages 'lcm==1.5.0'
  fi
fi
echo "install-deps ($set_name): done"
