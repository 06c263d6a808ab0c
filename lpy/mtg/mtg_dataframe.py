# openalea.mtg.dataframe as Sprout provides it where the real openalea.mtg is not installed
# (lpy/README.md): an MTG's properties as a pandas DataFrame, a row per vertex, with its parent,
# complex, scale and order (src/openalea/mtg/dataframe.py, CeCILL-C). pandas from Debian
# (python3-pandas, which scripts/setup.sh installs).

import pandas as pd

from .algo import orders


def to_dataframe(g):
    """The MTG's properties and structure as a DataFrame (columns: each property, parent,
    complex, scale, order). As openalea.mtg does, the columns are added to g.properties()."""
    d = g.properties()
    d['parent'] = g._parent
    d['complex'] = {vid: g.complex(vid) for vid in g if g.complex(vid)}
    d['scale'] = g._scale
    d['order'] = orders(g)
    return pd.DataFrame.from_dict(d)
