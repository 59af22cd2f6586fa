#!/usr/bin/env bash
# Installs every proxyvis dependency from Debian 12 packages. Idempotent: when every package
# is already installed it only checks (no apt-get update, well under a second).
set -euo pipefail
PKGS=(
  build-essential cmake ninja-build ccache pkg-config git
  libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev
  libopenmesh-dev libembree-dev libdraco-dev
  libopenimageio-dev openimageio-tools libopencv-core-dev
  libmeshoptimizer-dev libtbb-dev
  libcli11-dev libfmt-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PKGS[@]} packages present"
  exit 0
fi
echo "setup: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
