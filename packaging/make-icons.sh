#!/usr/bin/env bash
# Sprout's icon, drawn by Sprout: packaging/icon.lsys rendered at the hicolor theme's sizes
# (transparent PNGs) and exported as SVG into packaging/icons/. Run after a build when the
# icon's grammar changes; the results are kept in the repository and installed by CMake.
#
#   packaging/make-icons.sh [path/to/sprout]      (default build/sprout)
set -euo pipefail
cd "$(dirname "$0")/.."
sprout="${1:-build/sprout}"
mkdir -p packaging/icons
for size in 16 24 32 48 64 128 256 512; do
  "$sprout" render packaging/icon.lsys -o "packaging/icons/sprout-$size.png" --size "${size}x${size}" \
    --no-ground --no-shadows --view front --transparent
done
"$sprout" export packaging/icon.lsys -o packaging/icons/sprout.svg
