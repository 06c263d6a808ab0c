# openalea.lpy's names for matching and reading, as L-Py defines them (src/wrapper/
# export_stringmatching.cpp, export_parser.cpp, lpy_parser.cpp's LpyParsing): the map between a
# string's positions and its successor's, module matching methods, module declarations, the
# parser's constants and lstrings as L-Py's Python, the values a rule's header binds (ArgList). Rules and the debugger are in
# lpy_rules.py (openalea.lpy._rules).
from _sprout_lpy import Lstring, _written, ParamModule
import openalea.lpy as _lpy
from openalea.lpy._lsystem import Lsystem
from openalea.lpy._strings import _enum
from openalea.lpy._patterns import _pattern_args, LsysVar

__all__ = ['StringMatching', 'PatternModule', 'LpyParsing', 'ArgList', 'declare', 'undeclare', 'lstring2py']


def declare(names):
    """Declares modules ('A, B(x), C') for the strings read outside a model."""
    _lpy.context().declare(names)


def undeclare(names):
    _lpy.context().undeclare(names)


_set_args = ParamModule.args.__set__  # `m.args = ...` writes m.__dict__, as in L-Py


def _variable(value, member):
    if not isinstance(value, LsysVar):
        raise TypeError('PatternModule.%s: an LsysVar, not a %s' % (member, type(value).__name__))
    return value


class _MatchingMethod(type(ParamModule)):
    @property
    def matchingMethod(cls):
        """The option 'Module matching' of the current context."""
        chosen = _lpy._state.get('options', {}).get('Module matching')
        return eMatchingMethod.values[2 if chosen is None else int(chosen)]


eMatchingMethod = _enum('eMatchingMethod', ['eSimple', 'eWithStar', 'eWithStarNValueConstraint'])


class PatternModule(ParamModule, metaclass=_MatchingMethod):
    """A module of a rule's header (L-Py's PatternModule): its parameters are variables
    (LsysVar: names, `*args`, conditions) or values the module matched must have. Sprout matches
    as eWithStarNValueConstraint, L-Py's default, whichever method is chosen."""
    eSimple, eWithStar, eWithStarNValueConstraint = eMatchingMethod.eSimple, eMatchingMethod.eWithStar, \
        eMatchingMethod.eWithStarNValueConstraint
    eMatchingMethod = eMatchingMethod
    eDefaultMatchingMethod = eMatchingMethod.eWithStarNValueConstraint

    def __init__(self, name, params=None, lineno=-1):
        if isinstance(name, PatternModule):
            ParamModule.__init__(self, name.name)
            _set_args(self, list(name.args))
            return
        if isinstance(name, ParamModule):  # a module of a PatternString
            ParamModule.__init__(self, name)
            return
        if isinstance(name, int):  # PatternModule(id, params[, lineno])
            text = '%s(%s)' % (_lpy.ModuleClassTable.get().find(name).name, params or '')
        else:
            text, lineno = name, (lineno if params is None else params)
        written = _written(text)
        if len(written) != 1:
            raise ValueError('Invalid query module ' + text)
        mname, args = written[0]
        ParamModule.__init__(self, mname)
        _set_args(self, _pattern_args(args))

    def __str__(self):
        return self.name + ('(%s)' % ','.join(str(a) for a in self.args) if len(self) else '')

    # Its parameters are LsysVars (L-Py's PatternModule holds nothing else).
    def setParameter(self, name, value):
        ParamModule.setParameter(self, name, _variable(value, 'setParameter'))

    def __setitem__(self, i, value):
        ParamModule.__setitem__(self, i, _variable(value, '__setitem__'))

    def append(self, value):
        ParamModule.append(self, _variable(value, 'append'))

    def prepend(self, value):
        ParamModule.prepend(self, _variable(value, 'prepend'))

    __repr__ = __str__

    def getVarNb(self):
        return len(self.varnames())

    def varnames(self):
        return [a.varname() for a in self.args if isinstance(a, LsysVar) and a._named()]


def lstring2py(lstring):
    """An lstring as a Python expression, the list of its modules (L-Py's lstring2py), which
    AxialTree reads back. L-Py writes each module as its class's id and its arguments; Sprout's
    ids are not L-Py's, and Sprout writes ParamModule(name, arguments)."""
    items = []
    for name, args in _written(str(lstring)):
        items.append('ParamModule(%r%s)' % (name, ''.join(',' + a for a in args)))
    return '[' + ','.join(items) + ']'


class LpyParsing:
    """L-Py's parser constants (src/cpp/lpy_parser.cpp): the file format tag and versions."""
    InitialisationBeginTag = '###### INITIALISATION ######'
    VersionTag = '# -*- lpy version: %f -*-'
    formats = [1.0]
    DefaultFormat = 1.0
    lstring2py = staticmethod(lstring2py)

    @staticmethod
    def isSupportedFormat(version):
        """Whether L-Py reads files of this format (1.0)."""
        return 1.0 <= _float32(version) <= 1.0

    @staticmethod
    def _version(code):
        head, tail = LpyParsing.VersionTag.split('%f')
        if not code.startswith(head):
            return None
        rest = code[len(head):]
        end = 0
        while end < len(rest) and rest[end] not in ' \t\n':
            end += 1
        if not rest[end:].startswith(tail) or not rest[end + len(tail):].startswith('\n'):
            return None
        return _atof(rest[:end])

    @staticmethod
    def getFormatVersion(code):
        """The format a file's first line gives ('# -*- lpy version: 1.1 -*-'), else 1.0."""
        found = LpyParsing._version(str(code))
        return _float32(1.0 if found is None else found)

    @staticmethod
    def isFormatDefined(code):
        """Whether the code starts with a format line."""
        return LpyParsing._version(str(code)) is not None


def _float32(x):
    import struct
    return struct.unpack('f', struct.pack('f', float(x)))[0]


def _atof(text):
    """C's atof: the longest number at the start of the text (0.0 when none)."""
    import re
    m = re.match(r'\s*[-+]?(\d+\.?\d*([eE][-+]?\d+)?|\.\d+([eE][-+]?\d+)?|inf(inity)?|nan)', text, re.I)
    return float(m.group(0)) if m else 0.0


class ArgList:
    """The values a rule's header binds (L-Py's ArgList, a C++ vector of Python objects):
    ArgList(), ArgList(size[, value])."""

    def __init__(self, size=0, value=None):
        if isinstance(size, bool) or not isinstance(size, int) or size < 0:
            raise TypeError("ArgList(size[, value]): a size from 0 on")
        self._items = [value] * size

    def append(self, value):
        self._items.append(value)

    def extend(self, values):
        self._items.extend(values)

    def __len__(self):
        return len(self._items)

    def __getitem__(self, i):
        return ArgList._of(self._items[i]) if isinstance(i, slice) else self._items[i]

    def __setitem__(self, i, value):
        self._items[i] = value

    def __delitem__(self, i):
        del self._items[i]

    def __iter__(self):
        return iter(self._items)

    def __contains__(self, value):
        return value in self._items

    def __repr__(self):
        return repr(self._items)

    def __str__(self):
        return str(self._items)

    @classmethod
    def _of(cls, values):
        out = cls()
        out._items = list(values)
        return out


class StringMatching:
    """Which position of an original string each position of a target string comes from
    (L-Py's StringMatching): marks (original, target, policy), where from a mark on either
    both positions increase together ('increasing') or the original stays ('fixed': what a
    rule made of one module)."""
    INCREASING, FIXED = 0, 1

    def __init__(self):
        self._marks = [[0, 0, StringMatching.INCREASING]]

    def clear(self):
        self.__init__()

    def addIdentity(self, length):
        """`length` modules copied as they are."""
        last = self._marks[-1]
        if len(self._marks) > 1 and self._marks[-2][2] == StringMatching.INCREASING:
            last[0] += length
            last[1] += length
        else:
            last[2] = StringMatching.INCREASING
            self._marks.append([last[0] + length, last[1] + length, StringMatching.INCREASING])

    def append(self, original, target):
        """`original` modules became `target` modules."""
        if original == 1 and target == 1:
            return self.addIdentity(1)
        last = self._marks[-1]
        last[2] = StringMatching.FIXED
        self._marks.append([last[0] + original, last[1] + target, StringMatching.INCREASING])

    def isIdentity(self):
        return all(m[2] != StringMatching.FIXED for m in self._marks)

    def begin(self):
        it = StringMatching.const_iterator(self._marks, 0)
        while it._at + 1 < len(self._marks) and self._marks[it._at + 1][1] == self._marks[0][1]:
            it._at += 1
        it._original, it._target = self._marks[it._at][0], self._marks[it._at][1]
        return it

    def end(self):
        it = StringMatching.const_iterator(self._marks, len(self._marks))
        it._original, it._target = self._marks[-1][0], self._marks[-1][1]
        return it

    class const_iterator:
        """A position of the target string and the original's it comes from."""

        def __init__(self, marks, at):
            self._marks, self._at = marks, at

        def increment(self):
            marks = self._marks
            self._target += 1
            if self._at >= len(marks):
                self._original += 1
            elif self._at + 1 >= len(marks):
                if marks[self._at][2] == StringMatching.INCREASING:
                    self._original += 1
            elif self._target == marks[self._at + 1][1]:
                while self._at + 1 < len(marks) and self._target == marks[self._at + 1][1]:
                    self._at += 1
                    self._original = marks[self._at][0]
            elif marks[self._at][2] == StringMatching.INCREASING:
                self._original += 1

        def original(self):
            return self._original

        def target(self):
            return self._target

        def next(self):
            self.increment()
            return self._original

        def values(self):
            return (self._original, self._target)

        def nextValues(self):
            self.increment()
            return self.values()
