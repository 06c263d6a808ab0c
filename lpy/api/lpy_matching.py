# openalea.lpy's names for matching and reading, as L-Py defines them (src/wrapper/
# export_lsysrule.cpp, export_stringmatching.cpp, lsystem.h's Debugger, lpy_parser.cpp's
# LpyParsing): a rule read and matched on its own (LsysRule), the debugger an Lsystem tells of
# its matches, the map between a string's positions and its successor's, module matching
# methods, module declarations and lstrings as Python expressions. Beside lpy_lsystem.py
# (openalea.lpy._lsystem), whose Lsystem they use.
from _sprout_lpy import Lstring, _written, ParamModule
import openalea.lpy as _lpy
from openalea.lpy._lsystem import Lsystem
from openalea.lpy._strings import _enum
from openalea.lpy._patterns import _pattern_args, LsysVar

__all__ = ['LsysRule', 'LpyDebugger', 'StringMatching', 'PatternModule', 'LpyParsing', 'declare', 'undeclare',
           'lstring2py']


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


def lstring2py(text):
    """An lstring as a Python expression: the list of its modules (L-Py's lstring2py)."""
    items = []
    for name, args in _written(text):
        items.append('ParamModule(%r%s)' % (name, ''.join(',' + a for a in args)))
    return '[' + ','.join(items) + ']'


class LpyParsing:
    """L-Py's parser constants (src/cpp/lpy_parser.cpp): the file format tag and versions."""
    VersionTag = '# -*- lpy version: %f -*-'
    InitialisationBeginTag = '###### INITIALISATION ######'
    LPY_FORMAT_VERSION = 1.0
    formats = [1.0]

    @staticmethod
    def isSupportedFormat(version):
        return 1.0 <= version <= LpyParsing.LPY_FORMAT_VERSION

    @staticmethod
    def getFormatVersion(code):
        first = code.split('\n', 1)[0]
        head, tail = LpyParsing.VersionTag.split('%f')
        if first.startswith(head) and first.endswith(tail.rstrip()):
            try:
                return float(first[len(head):len(first) - len(tail.rstrip())])
            except ValueError:
                pass
        return LpyParsing.LPY_FORMAT_VERSION


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


class LpyDebugger:
    """What Lsystem.setDebugger takes: told, at each production step, of its string
    (begin), each rule that matched and produced (total_match) or produced nothing
    (partial_match), each module copied (identity) and the result (end). Positions are
    indices in the step's string; `dest` is the new string so far."""

    def __init__(self):
        pass

    def begin(self, src, direction):
        pass

    def end(self, result):
        pass

    def total_match(self, pos_beg, pos_end, dest, prod_length, rule, args):
        pass

    def partial_match(self, pos_beg, pos_end, dest, rule, args):
        pass

    def error_match(self, pos_beg, pos_end, dest, rule, args):
        return False

    def identity(self, pos, dest):
        pass

    def shouldStop(self, *args):
        return True


class LsysRule:
    """One rule, read and matched on its own (L-Py's LsysRule)."""

    def __init__(self, code=None, kind=0, group=0):
        self._lsystem, self._info = None, None
        if code:
            self.set(code)

    def set(self, code):
        self._lsystem = Lsystem()
        self._lsystem.set('production:\n' + str(code) + '\nendlsystem\n')
        s = self._lsystem._session
        if s.ruleCount() != 1:
            raise ValueError("LsysRule.set: one rule, e.g. 'F --> F[+F]F'")
        self._info = s.rule(0)

    def isCompiled(self):
        return self._info is not None

    def compile(self):
        pass

    def forwardCompatible(self):
        return not self._info['newRight']

    def backwardCompatible(self):
        return not self._info['newLeft']

    def nbContexts(self):
        return sum(1 for k in ('left', 'newLeft', 'right', 'newRight') if self._info[k])

    def isContextFree(self):
        return self.nbContexts() == 0

    def nbParameters(self):
        return self._info['parameters']

    @property
    def lineno(self):
        return self._info['line']

    def name(self):
        return self._info['header']

    def process(self, lstring):
        """The string after one step of this rule."""
        return self._lsystem.derive(Lstring(lstring) if not isinstance(lstring, Lstring) else lstring, 0, 1)

    def _match(self, lstring, pos, forward):
        s = lstring if isinstance(lstring, Lstring) else Lstring(lstring)
        if pos < 0:
            pos += len(s)
        with self._lsystem._context:
            return self._lsystem._session.match(0, s, pos, forward)

    def match(self, lstring, pos=0, dest=None):
        """(the position after the match, the values it binds), or False."""
        return self._match(lstring, pos, True)

    def reverse_match(self, lstring, pos=-1, dest=None):
        """Matched backwards from pos (the last module by default): (the position before the
        match, the values), or False."""
        return self._match(lstring, pos, False)
