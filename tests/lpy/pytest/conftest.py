# L-Py's own pytest suite run against Sprout (issue 37): loaded with `-p conftest` from this
# folder (tests/lpy/pytest/run.py), so the suite's files run unmodified, their
# `from openalea.lpy import *` giving Sprout's.
import sprout

sprout.use_as_openalea()
