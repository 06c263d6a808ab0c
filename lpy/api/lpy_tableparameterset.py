# openalea.lpy.tableparameterset as Sprout provides it, written from L-Py's definition
# (src/openalea/lpy/tableparameterset.py): parameter sets whose values live in one table for
# the whole model, a row per set and a column per parameter, so that a model can read every
# module's parameters at once (get_table(), a pandas DataFrame). A TableParameterSet reads and
# writes its row as a ParameterSet reads and writes its attributes.
#
#   init_table()       a table kept as a DataFrame (pandas)
#   init_dict_table()  a table kept as a dict of columns (a DataFrame only when asked for)
#   get_table()        the table as a DataFrame
#
# Each run of a model imports this module afresh (openalea.lpy._begin): no table is left from
# an earlier run.

_table = None


def _dataframe(columns=None):
    try:
        from pandas import DataFrame
    except ImportError as e:  # pandas is not one of Sprout's own dependencies
        raise ImportError("openalea.lpy.tableparameterset keeps its table in pandas, which is not "
                          "installed (Debian: python3-pandas)") from e
    return DataFrame(columns if columns is not None else {})


class ParamDictTable:
    """The table as a dict of columns: {parameter: {row: value}}."""

    def __init__(self):
        self.id = 0
        self.data = {}

    def dataframe(self):
        return _dataframe(self.data)

    def pnames(self):
        return list(self.data.keys())

    def get_new_id(self, values):
        uid = self.id
        self.id += 1
        for name, value in values.items():
            self.setattr(uid, name, value)
        return uid

    def hasattr(self, uid, name):
        return uid in self.data.get(name, {})

    def setattr(self, uid, name, value):
        self.data.setdefault(name, {})[uid] = value

    def getattr(self, uid, name):
        try:
            return self.data[name][uid]
        except KeyError:
            raise AttributeError(name) from None

    def delattr(self, uid, name):
        self.data.get(name, {}).pop(uid, None)

    def rename(self, old, new):
        self.data[new] = self.data.pop(old)


class ParamTable(ParamDictTable):
    """The table as a pandas DataFrame, made at each change (L-Py's ParamTable)."""

    def dataframe(self):
        return _dataframe({name: [column.get(uid) for uid in range(self.id)] for name, column in self.data.items()})


def init_table(value=None):
    global _table
    _table = ParamTable() if value is None else value


def init_dict_table(value=None):
    init_table(ParamDictTable() if value is None else value)


def _get_table():
    if _table is None:
        init_table()
    return _table


def get_table():
    return _get_table().dataframe()


class TableParameterSet:
    """A set of parameters kept as a row of the model's table."""

    def __init__(self, **values):
        self.__dict__['uid'] = _get_table().get_new_id(values)

    def rename(self, old, new):
        _get_table().rename(old, new)

    def setdefault(self, *args, **values):
        if args and values:
            raise ValueError('setdefault takes names and values, or name=value, not both')
        if len(args) % 2:
            raise ValueError('setdefault takes a list of names and values')
        pairs = list(zip(args[0::2], args[1::2])) + list(values.items())
        for name, value in pairs:
            if not _get_table().hasattr(self.uid, name):
                _get_table().setattr(self.uid, name, value)

    def hasattr(self, name):
        return _get_table().hasattr(self.uid, name)

    def get(self, name, default=None):
        return _get_table().getattr(self.uid, name) if _get_table().hasattr(self.uid, name) else default

    def set(self, **values):
        for name, value in values.items():
            _get_table().setattr(self.uid, name, value)

    def parameter_names(self):
        return _get_table().pnames()

    def __repr__(self):
        table = _get_table()
        return '%s(%s,%s)' % (type(self).__name__, self.uid,
                              ','.join('%s=%r' % (n, table.getattr(self.uid, n)) for n in table.pnames() if table.hasattr(self.uid, n)))

    def __getattr__(self, name):
        if name == 'uid':
            return self.__dict__['uid']
        return _get_table().getattr(self.uid, name)

    def __setattr__(self, name, value):
        if name == 'uid':
            self.__dict__['uid'] = value
        else:
            _get_table().setattr(self.uid, name, value)

    def __delattr__(self, name):
        _get_table().delattr(self.uid, name)

    def __contains__(self, name):
        return _get_table().hasattr(self.uid, name)
