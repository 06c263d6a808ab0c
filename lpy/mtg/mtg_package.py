# The package openalea.mtg as Sprout provides it where the real one is not installed
# (lpy/README.md): the MTG and its kin (mtg_mtg.py) at the package's top, as openalea.mtg's
# __init__ gathers them. Its plant frame (an MTG's geometry from dressing data, the
# plantframe package) is not in Sprout's: PlantFrame and DressingData say so when called.

from .mtg import *

__version__ = '2.4.0 (Sprout)'


def _without_plantframe(name):
    def missing(*args, **kwds):
        raise NotImplementedError("openalea.mtg's %s (plantframe: an MTG's geometry from dressing data) is not in "
                                  "Sprout's openalea.mtg; install openalea.mtg to use it" % name)
    missing.__name__ = name
    return missing


PlantFrame = _without_plantframe('PlantFrame')
DressingData = _without_plantframe('DressingData')
