#!/usr/bin/env bash
# Sprout against the real cpfg, timed side by side on every VLab object of the manuals (issue 50):
# each object's `cpfg -g -str` (its cpfg line's options) and `sprout expand FOLDER`, the best of
# --repeat runs of each (process start, reading the object's files and deriving, for both), and
# the median ratio cpfg / Sprout. Usage: bench/cpfg_vs_reference.sh CPFG_BIN [--repeat 3] [--only NAME]
# CPFG_BIN: ROOT/bin of ../shared/tools/build-cpfg-reference.sh (WITH_ENVIRO=1).
exec /usr/bin/python3 "$(dirname "$0")/../tests/reference/cpfg_compare.py" "$1" --time "${@:2}"
