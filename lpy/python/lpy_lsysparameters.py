# openalea.lpy.lsysparameters as Sprout provides it (being written).
__all__ = []
