#!/usr/bin/env bash
# Installs every Debian 12 package PaperFold needs to build, test and run.
# Idempotent and quick when everything is already there. Needs root (or sudo).
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config clang-format clang libclang-rt-14-dev
    qt6-base-dev libqt6opengl6-dev qt6-charts-dev qt6-tools-dev qt6-l10n-tools qt6-tools-dev-tools
    qt6-translations-l10n
    libeigen3-dev libpng-dev libosmesa6-dev libgl1-mesa-dri xvfb xauth fonts-dejavu-core fonts-nanum fonts-ipafont-gothic
    libtinygltf-dev libtinyobjloader-dev libassimp-dev locales
)

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages present"
    exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
