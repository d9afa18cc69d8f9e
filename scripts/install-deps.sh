#!/usr/bin/env bash
# Installs Chute's build and run dependencies from Debian's archive (Debian 12), if any is missing.
set -euo pipefail
packages=(build-essential cmake libeigen3-dev libhypre-dev libsundials-dev libhdf5-dev libopenmpi-dev
          openmpi-bin libyaml-cpp-dev libgtest-dev libbenchmark-dev libcli11-dev
          libfccp-dev libfftw3-dev pkg-config python3-numpy python3-h5py python3-matplotlib python3-yaml chromium)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends "${missing[@]}"
