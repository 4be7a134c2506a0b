#!/usr/bin/env bash
# Installs every build, test and run dependency of Aula with apt (Debian 12).
# Idempotent: quiet and fast when everything is already there.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libdart-all-dev libdart-collision-bullet-dev libdart-utils-dev libdart-gui-osg-dev
  libdart-external-lodepng-dev libdart-external-imgui-dev libgl1-mesa-dri
  libsdformat-dev
  liblcm-dev liblcm-bin libglib2.0-dev
  libompl-dev
  qtbase5-dev libqt5charts5-dev
  libopencv-dev
  libeigen3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth xdotool
  iproute2 procps python3 python3-pip bc
  dpkg-dev bubblewrap libseccomp-dev ccache
  nlohmann-json3-dev libssl-dev
  slurmctld slurmd slurm-client munge
  chromium
  python3-dev pybind11-dev python3-numpy python3-opencv
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${#missing[@]} package(s): ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# python-lcm, the independent LCM client of tests/integration/test_stock_lcm_client.sh: Debian
# packages LCM's C, C++ and Java parts but not its Python module; PyPI has LCM's own wheel. It goes
# to the python3 on PATH, the one the test runs.
if ! python3 -c 'import lcm' 2>/dev/null; then
  echo "install-deps: installing python-lcm (PyPI: lcm==1.5.0)"
  python3 -m pip install --quiet 'lcm==1.5.0' 2>/dev/null ||
    python3 -m pip install --quiet --break-system-packages 'lcm==1.5.0'
fi
echo "install-deps: done"
