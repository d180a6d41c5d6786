#!/usr/bin/env bash
# Install the Debian 12 packages mhcontact needs, only those that are missing (a second run
# installs nothing and does not touch the network). Needs root or sudo when something is missing.
set -euo pipefail
packages=(cmake make g++ libeigen3-dev pkg-config libboost-dev gemmi-dev libcli11-dev nlohmann-json3-dev catch2 python3 python3-dev python3-numpy python3-pytest pybind11-dev python3-matplotlib clang-14 libclang-rt-14-dev)
packages+=(libsundials-dev)   # SUNDIALS CVODE (BSD-3): the wheelset dynamics example (examples/wheelset_dynamics)
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
