#!/usr/bin/env bash
# Installs what ssgraph needs to build and run, from Debian's packages (run as root, or with
# sudo): tools/debian-packages.txt. With --test, also what its tests, benchmarks and Python
# package use (tools/debian-packages-test.txt: a browser and its driver, selenium, pytest,
# matplotlib, numpy, the Python build tools, oiiotool; about 8 times the first set), which
# tools/test.sh installs itself when any is missing. The first image needs only the first.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
here=$(dirname "$0")
lists=("$here/debian-packages.txt")
case "${1:-}" in
    "") ;;
    --test) lists+=("$here/debian-packages-test.txt") ;;
    *) echo "usage: bash tools/install-deps.sh [--test]" >&2; exit 2 ;;
esac
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends $(cat "${lists[@]}")
