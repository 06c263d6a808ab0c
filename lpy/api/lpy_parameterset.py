# openalea.lpy.parameterset as Sprout provides it: L-Py's ParameterSet, the class openalea.lpy
# holds (lpy/api/lpy.py), for models that import it from here.
from openalea.lpy import ParameterSet  # noqa: F401
