#!/usr/bin/env bash
# Sprout against the real L-Py, timed on every model of ../shared/corpus/lpy (issue 41); see
# bench/lpy_vs_reference.py for what is timed.  Usage: bench/lpy_vs_reference.sh REF_PYTHON [options]
exec /usr/bin/python3 "$(dirname "$0")/lpy_vs_reference.py" "$@"
