# openalea.lpy's rules and what reads or follows them, as L-Py defines them (src/wrapper/
# export_lsysrule.cpp, export_debugger.cpp, export_lsystem.cpp's enums,
# src/cpp/lsysrule.cpp, lsystem.h's Debugger, __init__.py's LsystemIterator): a rule read,
# matched and applied on its own or one of an Lsystem's (LsysRule), the debugger an Lsystem
# tells of its matches (LpyDebugger), the derivation's directions and rule types (eDirection,
# eRuleType), an Lsystem's derivation step by step (LsystemIterator). Beside lpy_lsystem.py
# (openalea.lpy._lsystem), whose Lsystem they use.

# Index of this file:
#   [SECTION] enums
#   [SECTION] LpyDebugger
#   [SECTION] LsysRule
#   [SECTION] LsystemIterator

from _sprout_lpy import Lstring, _written
import openalea.lpy as _lpy
from openalea.lpy._lsystem import Lsystem
from openalea.lpy._matching import ArgList

__all__ = ['LsysRule', 'LpyDebugger', 'LsystemIterator', 'eDirection', 'eForward', 'eBackward',
           'eRuleType', 'eProduction', 'eDecomposition', 'eInterpretation']


# [SECTION] enums
class _Enum(int):
    """A Boost.Python enum: an int; its named values are the class's attributes (with a
    `name`), listed by `names` and `values`; a value made by calling the class has no name."""
    __slots__ = ()

    def _own(self):
        return type(self).values.get(int(self)) is self

    @property
    def name(self):
        if not self._own():
            raise AttributeError("'%s' object has no attribute 'name'" % type(self).__name__)
        return type(self)._names[int(self)]

    def __repr__(self):
        kind = 'openalea.lpy.__lpy_kernel__.' + type(self).__name__
        return kind + '.' + self.name if self._own() else '%s(%d)' % (kind, int(self))

    def __str__(self):
        return self.name if self._own() else repr(self)

    def __reduce__(self):
        return (getattr, (type(self), self.name)) if self._own() else (type(self), (int(self),))


def _enum(name, *items):
    cls = type(name, (_Enum,), {'__slots__': (), 'names': {}, 'values': {}, '_names': {},
                                '__module__': 'openalea.lpy.__lpy_kernel__'})
    for value, item in enumerate(items):
        obj = int.__new__(cls, value)
        cls.names[item], cls.values[value], cls._names[value] = obj, obj, item
        setattr(cls, item, obj)
    return cls


eDirection = _enum('eDirection', 'eForward', 'eBackward')
eForward, eBackward = eDirection.eForward, eDirection.eBackward
eRuleType = _enum('eRuleType', 'eProduction', 'eDecomposition', 'eInterpretation')
eProduction, eDecomposition, eInterpretation = eRuleType.eProduction, eRuleType.eDecomposition, eRuleType.eInterpretation


# [SECTION] LpyDebugger
class LpyDebugger:
    """What Lsystem.setDebugger takes (L-Py's Lsystem::Debugger), to derive from: told, at each
    production step, of its string (begin), each rule that matched and produced (total_match),
    matched and produced nothing (partial_match), each module copied (identity) and the result
    (end). Positions are indices in the step's string; `dest` is the new string so far. With
    alwaysStop False, only the matches at a breakpoint are told: a code line within a rule, a
    position of the string. (L-Py's binding never calls error_match: a rule's error goes on.)"""

    def __init__(self):
        self.alwaysStop = True

    def _breaks(self, kind):
        return self.__dict__.setdefault('_' + kind, [])

    alwaysStop = property(lambda self: self.__dict__.get('_alwaysStop', True),
                          lambda self, v: self.__dict__.__setitem__('_alwaysStop', bool(v)))

    def begin(self, src, direction):
        pass

    def end(self, result):
        pass

    def total_match(self, pos_beg, pos_end, dest, prod_length, rule, args):
        pass

    def partial_match(self, pos_beg, pos_end, dest, rule, args):
        pass

    def error_match(self, pos_beg, pos_end, dest, rule, args, trace=None):
        return False

    def identity(self, pos, dest):
        pass

    def insertCodeBreakPointAt(self, line):
        self._breaks('code').append(_uint(line))

    def _remove(self, kind, v):
        if _uint(v) not in self._breaks(kind):
            raise ValueError("Cannot remove %s break point." % kind)
        self._breaks(kind).remove(_uint(v))

    def removeCodeBreakPointAt(self, line):
        self._remove('code', line)

    def hasCodeBreakPointAt(self, line):
        return _uint(line) in self._breaks('code')

    def insertLstringBreakPointAt(self, pos):
        self._breaks('lstring').append(_uint(pos))

    def removeLstringBreakPointAt(self, pos):
        self._remove('lstring', pos)

    def hasLstringBreakPointAt(self, pos):
        _uint(pos)  # L-Py's binding tells nothing (it returns None)

    def clearBreakPoints(self):
        self.clearCodeBreakPoints()
        self.clearLstringBreakPoints()

    def clearCodeBreakPoints(self):
        self._breaks('code').clear()

    def clearLstringBreakPoints(self):
        self._breaks('lstring').clear()

    def clearPyError(self):
        """Python's pending error cleared (none is pending between Python calls)."""


def _uint(v):
    if isinstance(v, bool) or not isinstance(v, int) or not 0 <= v < 1 << 32:
        raise TypeError("a position or line: an int from 0 to 2**32 - 1")
    return v


class _Told:
    """What the engine calls for an Lsystem's debugger: L-Py's Debugger::shouldStop decides
    which matches it is told of (all with alwaysStop, else those at a breakpoint)."""

    def __init__(self, debugger):
        self.d = debugger

    def _stop(self, beg, end, rule=None):
        d = self.d
        if getattr(d, 'alwaysStop', True):
            return True
        breaks = d._breaks('lstring') if isinstance(d, LpyDebugger) else []
        if any(beg <= b < max(end, beg + 1) for b in breaks):
            return True
        if rule is not None and isinstance(d, LpyDebugger):
            return any(0 <= line - rule.lineno < rule.codelength for line in d._breaks('code'))
        return False

    def begin(self, src, direction):
        self.d.begin(src, eDirection.values[direction])

    def end(self, result):
        self.d.end(result)

    def total_match(self, beg, end, dest, n, rule, args):
        if self._stop(beg, end, rule):
            self.d.total_match(beg, end, dest, n, rule, args)

    def partial_match(self, beg, end, dest, rule, args):
        if self._stop(beg, end, rule):
            self.d.partial_match(beg, end, dest, rule, args)

    def identity(self, pos, dest):
        if self._stop(pos, pos):
            self.d.identity(pos, dest)

# [SECTION] LsysRule
def _next_token(text, i):
    """L-Py's next_token: past a quoted string or a parenthesised group, else one character."""
    n = len(text)
    if text[i] in '"\'':
        j = text.find(text[i], i + 1)
        return n if j < 0 else j + 1
    if text[i] == '(':
        depth, i = 1, i + 1
        while i < n and depth:
            if text[i] in '"\'':
                i = _next_token(text, i)
                continue
            depth += {'(': 1, ')': -1}.get(text[i], 0)
            i += 1
        return i
    return i + 1


def _split_rule(code):
    """L-Py's LsysRule::set: the header, the definition (' --> ...' for an arrow), and whether
    the rule is static (-static->, : @static)."""
    for i, c in enumerate(code):
        if c == ':':
            body = code[i + 1:].lstrip(' \t')
            if body.startswith('@static'):
                return code[:i], body[len('@static'):], True
            return code[:i], code[i + 1:], False
        if c == '-' and (i == 0 or code[i - 1] != '-'):
            if code.startswith('-->', i):
                return code[:i], ' --> ' + code[i + 3:], False
            if code.startswith('-static->', i):
                return code[:i], ' --> ' + code[i + 9:], True
    raise ValueError("Ill-formed Rule : unfound delimiter ':' in " + code)


def _split_header(header):
    """L-Py's LsysRule::parseHeader: left < newleft << predecessor >> newright > right."""
    def ill(why=''):
        return ValueError("Ill-formed Rule Header : " + why + header)
    cg = ncg = pred = ncd = cd = ''
    beg, i, n, begncd = 0, 0, len(header), False
    while i < n:
        c = header[i]
        if c == '<':
            if pred:
                raise ill()
            if header[i + 1:i + 2] == '<':
                if ncg:
                    raise ill()
                ncg, i = header[beg:i], i + 1
            elif cg:
                raise ill()
            else:
                cg = header[beg:i]
            beg = i + 1
        elif c == '>':
            if header[i + 1:i + 2] == '>':
                if begncd or ncd:
                    raise ill("Two new left contexts found : ")
                if pred:
                    raise ill("Two Predecessors found : ")
                pred, begncd, i = header[beg:i], True, i + 1
            elif begncd:
                ncd, begncd = header[beg:i], False
            elif pred:
                raise ill("Two Predecessors found : ")
            else:
                pred = header[beg:i]
            if not pred:
                raise ill("No Predecessor found : ")
            beg = i + 1
        i = _next_token(header, i)
    if not pred:
        pred = header[beg:]
        if not pred:
            raise ill("No Predecessor found : ")
    elif beg != n:
        if begncd:
            ncd = header[beg:]
        else:
            cd = header[beg:]
    if ncg and ncd:
        raise ill("New left and right contexts found : ")
    return [cg, ncg, pred, ncd, cd]


def _pattern_text(text):
    """A pattern as L-Py's PatternString writes it: each module's name and its arguments."""
    if not text.strip():
        return ''
    return ''.join(name + ('(%s)' % ','.join(a.strip() for a in args) if args else '') for name, args in _written(text))


def _constant(arg):
    import ast
    try:
        ast.literal_eval(arg.strip())
        return True
    except (ValueError, SyntaxError):
        return False


def _rule_text(code, line):
    """The text of the rule whose header is at `line` (1-based) of `code`: its header line and
    the indented lines of its body."""
    lines = code.split('\n')
    out = [lines[line - 1]]
    for more in lines[line:]:
        if more[:1] not in (' ', '\t') and more.strip():
            break
        out.append(more)
    while len(out) > 1 and not out[-1].strip():
        out.pop()
    return '\n'.join(out) + '\n'


class LsysRule:
    """One rule, read, matched and applied on its own (L-Py's LsysRule(id, group, prefix):
    prefix 'p' production, 'd' decomposition, 'h' interpretation), or one of an Lsystem's
    (Lsystem.productionRule...)."""

    def __init__(self, id=0, group=0, prefix='p'):
        self.clear()
        self._id, self._gid, self._prefix = _uint(id), _uint(group), str(prefix)[:1]

    def clear(self):
        """Forgets the rule (and its id, group and prefix)."""
        self._id, self._gid, self._prefix = 0, 0, 'p'
        self._parts, self._definition, self._source = [''] * 5, '', ''
        self._lsystem, self._index, self._names, self._static, self._compiled = None, 0, [], False, False
        self.__dict__['lineno'], self._codelength, self._consider = -1, 0, None

    @classmethod
    def _of(cls, lsystem, index):
        """Rule `index` of an Lsystem's translation."""
        s = lsystem._session
        info = s.rule(index)
        kind, group = info['kind'], info['group']
        rank = sum(1 for i in range(index) if s.rule(i)['kind'] == kind and s.rule(i)['group'] == group)
        r = cls(rank, group, 'pdh'[kind])
        r._read(_rule_text(lsystem._fullcode, info['line']))
        r._lsystem, r._index, r._names, r._compiled = lsystem, index, list(info['names']), True
        r.__dict__['lineno'] = info['line']
        r._settle()
        return r

    def _read(self, code):
        code = str(code)
        header, definition, static = _split_rule(code)
        parts = [_pattern_text(p) for p in _split_header(header)]
        self._source, self._definition, self._parts, self._static = code, definition, parts, static
        self._codelength = code.count('\n')

    def _settle(self):
        """L-Py's optimisation level 1: an arrow rule whose production has only constant
        arguments is static (its production made once): its header's variables are unnamed
        ('-'). Gives whether that changed the rule's function name."""
        d, named = self._definition, self.functionName()
        if not self._static and d.startswith(' --> ') and '$' not in d:
            self._static = all(_constant(a) for _, args in _written(d[5:]) for a in args)
        if self._static:
            self._names = []
            self._parts = [''.join(name + ('(%s)' % ','.join('-' if a.strip().isidentifier() else a for a in args) if args else '')
                                   for name, args in _written(p)) if p else '' for p in self._parts]
        return self.functionName() != named

    def set(self, code):
        """Reads the rule's text ('A(x) < B(y) --> C(x+y)', or a header ':' and a body) and
        compiles it."""
        self._read(code)
        self._names, self._compiled, self._lsystem = [], False, None
        self.compile()

    def _need(self):
        if self._lsystem is None:
            raise ValueError("Python code of rule not compiled")
        return self._lsystem

    def compile(self, namespace=None):
        """Compiles the rule's Python (L-Py warns when it already is)."""
        if self._compiled:
            import warnings
            warnings.warn("Python code already imported.")
            return
        self.recompile()

    def recompile(self):
        section = {'p': 'production', 'd': 'decomposition', 'h': 'interpretation'}.get(self._prefix, 'production')
        lsys = Lsystem()
        filter = '' if self._consider is None else '%s: %s\n' % self._consider
        head = 'production:\n' + (section + ':\n' if section != 'production' else '')
        lsys.set('%s%s%s\nendlsystem\n' % (filter, head, self._source.rstrip('\n')))
        if lsys._session.ruleCount() != 1:
            raise ValueError("LsysRule.set: one rule, e.g. 'F --> F[+F]F'")
        self._names = list(lsys._session.rule(0)['names'])
        if self._settle():  # L-Py looks its function up by the name it had before
            raise ValueError("Compilation failed.")
        self._lsystem, self._index, self._compiled = lsys, 0, True

    def isCompiled(self):
        return self._compiled

    # -- what the rule is ----------------------------------------------------------------
    id = property(lambda self: self._id, lambda self, v: setattr(self, '_id', _uint(v)))
    groupId = property(lambda self: self._gid, lambda self, v: setattr(self, '_gid', _uint(v)))
    codelength = property(lambda self: self._codelength)
    static = property(lambda self: self._static)
    lineno = property(lambda self: self.__dict__['lineno'])

    @property
    def __static_production__(self):
        return self() if self._static else Lstring('')

    def _pattern(self, k):
        # openalea.lpy's PatternString where there is one (a pattern's variables are no Python
        # values: not an Lstring); its text otherwise.
        return _lpy.PatternString(self._parts[k]) if hasattr(_lpy, 'PatternString') else self._parts[k]

    def leftContext(self):
        return self._pattern(0)

    def newLeftContext(self):
        return self._pattern(1)

    def predecessor(self):
        return self._pattern(2)

    def newRightContext(self):
        return self._pattern(3)

    def rightContext(self):
        return self._pattern(4)

    def definition(self):
        # L-Py's binding gives a C++ string by reference, which it cannot convert.
        raise TypeError("No Python class registered for C++ class std::__cxx11::basic_string<char, std::char_traits<char>, "
                        "std::allocator<char> >")

    def nbContexts(self):
        return sum(1 for k in (0, 1, 3, 4) if self._parts[k])

    def isContextFree(self):
        return self.nbContexts() == 0

    def forwardCompatible(self):
        return not self._parts[3]

    def backwardCompatible(self):
        return not self._parts[1]

    def hasQuery(self):
        return any(name.startswith('?') for p in self._parts if p for name, _ in _written(p))

    def nbParameters(self):
        return len(self._names)

    def parameterNames(self):
        return list(self._names)

    def name(self):
        cg, ncg, pred, ncd, cd = self._parts
        return ((cg + ' < ') if cg else '') + ((ncg + ' << ') if ncg else '') + pred + \
            ((' >> ' + ncd) if ncd else '') + ((' > ' + cd) if cd else '')

    def functionName(self):
        tail = ''.join(c if c.isalpha() else '_' for p in self._parts for c in p)
        return '__%s_%d_%d_%s' % (self._prefix, self._gid, self._id, tail)

    def function(self):
        """The Python function the rule's body became (None before it is compiled)."""
        if not self._compiled:
            return None
        lsys = self._lsystem
        return lsys._context._state['ns'].get(lsys._session.rule(self._index)['function'])

    def code(self):
        """The rule as a Python function: its head as L-Py names it, then its body."""
        body = self._definition
        if body.startswith(' --> '):
            body = '\n\treturn ' + body[5:].strip() + '\n'
        return 'def %s(%s) :%s' % (self.functionName(), ','.join(self._names), body if body.strip() else '\t\tpass\n')

    def __str__(self):
        return (self.name() or '(none)') + ' : \n' + (self._definition or '\t(none)')

    # -- matching and applying -----------------------------------------------------------
    def __call__(self, args=None):
        """The rule's production, or None when it produces nothing. L-Py's binding reads no
        value from `args` (it iterates them with Python 2's next): a rule with parameters
        says it was given none."""
        return self._apply([], args is not None)

    def _apply(self, values, listed):
        lsys = self._need()
        if self._static:
            values = [None] * lsys._session.rule(self._index)['parameters']
        elif len(values) != len(self._names):
            raise ValueError("%s takes exactly %d argument(s) (%d given).\n" % (self.name(), len(self._names), len(values))
                             + (str(list(values)) if listed else ''))
        with lsys._context:
            return lsys._session.apply(self._index, tuple(values))

    def _lstring(self, lstring):
        return lstring if isinstance(lstring, Lstring) else Lstring(lstring)

    def _match(self, lstring, pos, forward):
        s = self._lstring(lstring)
        if pos < 0:
            pos += len(s)
        if not (0 <= pos < len(s)) and not (pos == 0 and not len(s)):
            raise IndexError("index out of range")
        lsys = self._need()
        with lsys._context:
            found = lsys._session.match(self._index, s, pos, forward)
        return found if found is False else (found[0], ArgList._of(found[1]))

    def match(self, lstring, pos=0, dest=None):
        """(the position after the match, the values it binds), or False."""
        return self._match(lstring, pos, True)

    def reverse_match(self, lstring, pos=-1, dest=None):
        """Matched backwards from pos (the last module by default): (the position before the
        match, the values), or False."""
        return self._match(lstring, pos, False)

    def applyTo(self, lstring, args):
        """Appends the production for these values (an ArgList, as match gives them) to
        `lstring`; whether the rule produced."""
        if not isinstance(args, ArgList) or not isinstance(lstring, Lstring):
            raise TypeError("LsysRule.applyTo(Lstring, ArgList)")
        out = self._apply(list(args), True)
        if out is None:
            return False
        if len(out) and out[0].name in ('*', 'None'):
            return True
        lstring += out
        return True

    def process(self, lstring):
        """The string with the rule applied wherever it matches, from left to right."""
        src, out, i = self._lstring(lstring), Lstring(''), 0
        while i < len(src):
            found = self.match(src, i)
            if found is False:
                out.append(src[i])
                i += 1
            else:  # as L-Py's: a rule that produces nothing drops what it matched
                self.applyTo(out, found[1])
                i = max(found[0], i + 1)
        return out

    def consider(self, modules):
        """Only these modules count in the rule's contexts."""
        self._consider = ('consider', str(modules))
        self._compiled = False
        self.recompile()

    def ignore(self, modules):
        """These modules are passed over in the rule's contexts."""
        self._consider = ('ignore', str(modules))
        self._compiled = False
        self.recompile()

    considerFilter = property(lambda self: self._consider and _consider_filter(*self._consider), consider)


def _consider_filter(how, modules):
    make = getattr(_lpy, 'ConsiderFilter', None)
    if make is None:
        return '%s: %s' % (how, modules)
    return make(modules, getattr(_lpy, 'eIgnore', 1) if how == 'ignore' else getattr(_lpy, 'eConsider', 0))


# [SECTION] LsystemIterator
class LsystemIterator:
    """The strings of an Lsystem's derivation, step by step (L-Py's LsystemIterator)."""

    def __init__(self, lsystem, start=0, stop=None, step=1):
        assert step >= 1 and start >= 0 and (stop is None or start <= stop)
        self.lsystem, self.start, self.step = lsystem, start, step
        self.axiom = lsystem.axiom
        self.stop = lsystem.derivationLength if stop is None else stop
        self.currentstep = -1

    def __next__(self):
        if self.currentstep == -1:
            self.axiom = self.lsystem.axiom
            if self.start != 0:
                self.axiom = self.lsystem.derive(self.axiom, 0, self.start)
            self.currentstep = self.start
            return self.axiom
        if self.currentstep + self.step > self.stop:
            raise StopIteration()
        self.axiom = self.lsystem.derive(self.axiom, self.currentstep, self.step)
        self.currentstep += self.step
        return self.axiom

    next = __next__

    def __iter__(self):
        return self
