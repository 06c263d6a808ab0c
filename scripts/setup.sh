#!/usr/bin/env bash
# Sprout's set-up on a fresh Debian 12 machine: installs the Debian packages that are missing,
# builds, then either opens Sprout (default) or runs the whole test suite.
#
#   scripts/setup.sh         install, build, open the viewer on the default plant
#   scripts/setup.sh test    install, build, run every test (what CI runs)
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-run}"

packages=(
  build-essential cmake pkg-config python3 python3-glad
  libglm-dev libglfw3-dev libimgui-dev libgl1-mesa-dev libosmesa6-dev libpng-dev libjpeg-dev
  libgtest-dev libgmock-dev libbenchmark-dev xvfb xauth
  libtinyobjloader-dev libxml2-utils
  python3-dev pybind11-dev
  # L-Py models import numpy as often as math (the corpus test counts on it), and scipy,
  # matplotlib and pandas often enough: the scientific Python they take for granted
  python3-numpy python3-scipy python3-matplotlib python3-pandas
  # the editor shows pasted notation (δ ω → − p₁) with DejaVu Sans Mono's glyphs
  fonts-dejavu-core
)
# The test suite checks exports with the Khronos glTF validator, from the npm registry.
if [ "$mode" = test ] && ! command -v npm >/dev/null; then packages+=(nodejs npm); fi
# Growth and turntable videos are encoded by ffmpeg (without it Sprout writes PNG frames);
# the tests check the videos with ffprobe.
if [ "$mode" = test ]; then packages+=(ffmpeg); fi
# The install and package tests read what they check with the tools that use it.
if [ "$mode" = test ]; then packages+=(lintian desktop-file-utils shared-mime-info man-db dpkg-dev file); fi
# The documentation site, built and checked by the tests (mkdocs build --strict).
if [ "$mode" = test ]; then packages+=(mkdocs mkdocs-material mkdocstrings mkdocstrings-python-handlers); fi
# `import sprout`: its pytest suite, the notebook's slider, and the Dask sweep example.
if [ "$mode" = test ]; then packages+=(python3-pytest python3-ipywidgets python3-dask python3-distributed); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "Installing: ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"

case "$mode" in
  test)
    npm ci --prefix tests/tools --no-audit --no-fund --loglevel=error
    # Not the tests against the real L-Py (label reference: they need it built beside the project).
    ctest --test-dir build --output-on-failure -j"$jobs" -LE reference
    ;;
  run)
    exec ./build/sprout "${@:2}"
    ;;
  *)
    echo "usage: scripts/setup.sh [run|test]" >&2
    exit 2
    ;;
esac
