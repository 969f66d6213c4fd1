#!/usr/bin/env bash
# Installs what ssgraph needs to build and run, from Debian's packages (run as root).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends \
    build-essential cmake pkg-config ca-certificates \
    libopenimageio-dev openimageio-tools libopenexr-dev \
    libembree-dev libtinygltf-dev nlohmann-json3-dev libstb-dev \
    libosmesa6-dev glmark2-data python3
