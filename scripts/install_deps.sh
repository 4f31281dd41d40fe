#!/usr/bin/env bash
# Installs the Debian packages Rigid_incidence needs, if any is missing. Idempotent.
# Run as root (or with sudo available). Extra packages can be passed as arguments.
set -euo pipefail
packages=(cmake g++ make libcgal-dev libgmp-dev libmpfr-dev libmpfi-dev libeigen3-dev
          libboost-graph-dev nlohmann-json3-dev libtbb-dev doxygen graphviz "$@")
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all Debian packages present"
  exit 0
fi
echo "install_deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
