#!/usr/bin/env bash
# Install the Debian 12 packages mhcontact needs, only those that are missing (a second run
# installs nothing and does not touch the network). Needs root or sudo when something is missing.
set -euo pipefail
packages=(cmake make g++ libeigen3-dev pkg-config libboost-dev gemmi-dev libcli11-dev nlohmann-json3-dev catch2 python3 python3-dev python3-numpy python3-pytest pybind11-dev python3-matplotlib clang-14 libclang-rt-14-dev)
packages+=(libsundials-dev)   # SUNDIALS CVODE (BSD-3): the wheelset dynamics example (examples/wheelset_dynamics)
packages+=(
  slurm-wlm            # tests/cluster/slurm.sh: the Slurm route on a private single-node cluster (docs/cluster.md)
  munge                # Slurm's authentication daemon, started by that test
  python3-distributed  # mhcontact.fleet on Dask and its test (python/tests/test_fleet_dask.py)
  python3-skbuild      # pip install . builds the module through CMake (pyproject.toml, setup.py)
  python3-wheel        # pip's wheel build without network (--no-build-isolation)
  python3-venv         # the fresh virtual environment of tests/repo/pip_install.sh
)
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if ((${#missing[@]} == 0)); then
  exit 0
fi
echo "deps.sh: installing ${missing[*]}" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
