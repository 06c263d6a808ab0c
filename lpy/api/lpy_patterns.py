# openalea.lpy's patterns, as L-Py defines them (src/wrapper/export_patternmodule.cpp,
# export_patternstring.cpp, export_axialtree.cpp; src/cpp/patternmodule.cpp, axialtree.cpp,
# axialtree_manip.h, matching.cpp): LsysVar, PatternString, a module matched by a pattern as L-Py's
# default method matches it, what AxialTree matches with them (match, leftmatch, rightmatch,
# replace, find), and its tree read through a ConsiderFilter. PatternModule is lpy_matching.py's.

# Index of this file:
#   [SECTION] patterns
#   [SECTION] AxialTree's patterns
#   [SECTION] AxialTree through a filter

import builtins as _builtins

from _sprout_lpy import AxialTree, ParamModule, Module, _written

__all__ = ['LsysVar', 'PatternString']


# [SECTION] patterns
def _namespace():
    import openalea.lpy as lpy
    ns = lpy._state.get('ns')
    return ns if ns is not None else {}


def _parse_variable(text):
    """A pattern's parameter read as a variable ('x', '*args', '**kw', '-', 'x if x > 1'), or None."""
    import re
    m = re.match(r'^\s*(\*{0,2}[A-Za-z_]\w*|-)\s*(?:if\s+(.+?))?\s*$', text)
    return (m.group(1), m.group(2) or '') if m else None


class LsysVar:
    """A variable of a pattern (L-Py's LsysVar): its name ('x', '*args', '**kw', '-' unnamed),
    or a value the module's parameter must equal, or a condition it must meet."""

    def __init__(self, name):
        self.name, self._value, self._condition, self._text = str(name), None, None, ''

    @property
    def name(self):
        return self._name

    @name.setter
    def name(self, value):
        self._name = str(value)

    @classmethod
    def _of_value(cls, value):
        v = cls('')
        v._value, v._condition = value, 'value'
        return v

    def _set_condition(self, text):
        self._text = text
        self._value = eval('lambda %s : %s' % (self.varname(), text), _namespace())
        self._condition = 'function'

    def __str__(self):
        if self._condition == 'function':
            return self.name + ' if ' + self._text
        if self._condition == 'value':
            return str(self._value)
        return self.name

    __repr__ = __str__

    def varname(self):
        n = self.name
        return n[2:] if n.startswith('**') else n[1:] if n.startswith('*') else n

    def isArgs(self):
        return self.name.startswith('*') and not self.name.startswith('**')

    def isKwds(self):
        return self.name.startswith('**')

    def value(self):
        return self._value

    def _named(self):
        return bool(self.name) and self.name[0] != '-' and self.name not in ('*-', '**-')

    def _accepts(self, v):
        if self._condition == 'value':
            return v == self._value
        if self._condition == 'function':
            return bool(self._value(v))
        return True


def _pattern_args(argtexts):
    out = []
    for k, text in enumerate(argtexts):
        var = _parse_variable(text)
        if var is None:
            out.append(LsysVar._of_value(eval(text, _namespace())))
            continue
        v = LsysVar(var[0])
        if var[1]:
            v._set_condition(var[1])
        if (v.isKwds() and k != len(argtexts) - 1) or (v.isArgs() and k < len(argtexts) - 2):
            raise ValueError("Invalid syntax : invalid variable name '%s'" % text)
        out.append(v)
    return out


def _match_module(pattern, module, bound):
    """MatchingEngine::module_match as L-Py's default method (eWithStarNValueConstraint) reads
    it: the same class (`*` any), as many parameters (more with *args), values and conditions
    met; the variables' values appended to `bound`."""
    pvars = list(pattern.args)
    values = list(module.args)
    if pattern.name == '*':
        if not pvars:
            return True
        values = [module.name] + values
    elif pattern.mclass != module.mclass:
        return False
    kw = pvars.pop() if pvars and pvars[-1].isKwds() else None
    star = pvars.pop() if pvars and pvars[-1].isArgs() else None
    if len(values) < len(pvars) or (star is None and len(values) != len(pvars)):
        return False
    for var, v in zip(pvars, values):
        if not var._accepts(v):
            return False
        if var._named():
            bound.append(v)
    if star is not None and star._named():
        bound.append(values[len(pvars):])
    if kw is not None and kw._named():
        bound.append({})
    return True


class PatternString(AxialTree):
    """A string of patterns (L-Py's PatternString): modules whose parameters are variables."""

    def __init__(self, text='', lineno=-1):
        AxialTree.__init__(self)
        if isinstance(text, PatternString):
            AxialTree.append(self, text)
        elif isinstance(text, Module):
            AxialTree.append(self, text)
        elif text:
            for name, args in _written(str(text)):
                AxialTree.append(self, _lpy().PatternModule(name + ('(%s)' % ','.join(args) if args else '')))

    def __getitem__(self, i):
        m = AxialTree.__getitem__(self, i)
        return m if isinstance(i, slice) else _lpy().PatternModule(m)

    def __iter__(self):
        return (self[i] for i in range(len(self)))

    def __repr__(self):
        return 'PatternString(%s)' % str(self)

    def varnames(self):
        out = []
        for m in self:
            out += m.varnames()
        return out

    def getVarNb(self):
        return sum(m.getVarNb() for m in self)


def _lpy():
    import openalea.lpy
    return openalea.lpy


# [SECTION] AxialTree's patterns
def _pattern_string(p):
    if isinstance(p, PatternString):
        return list(p)
    if isinstance(p, _lpy().PatternModule):
        return [p]
    return list(PatternString(p))


def _exact(s, patterns, at):
    """string_exact_match: the patterns, one module each, from position `at` on; the end, or -1."""
    if at < 0 or at + len(patterns) > len(s):
        return -1
    for k, p in enumerate(patterns):
        if not _match_module(p, s[at + k], []):
            return -1
    return at + len(patterns)


def _position(s, pos):
    n = len(s)
    if pos < 0:
        pos += n
    if pos < 0 or pos > n:
        raise IndexError('index out of range')
    return pos


def _tree_match(self, pattern, pos):
    return _exact(self, _pattern_string(pattern), _position(self, pos)) >= 0


def _tree_reverse_match(self, pattern, pos):
    pos = _position(self, pos)
    if pos >= len(self):
        return False
    ps = _pattern_string(pattern)
    return _exact(self, ps, pos - len(ps) + 1) >= 0


def _tree_rightmatch(self, pattern, pos):
    """A right context: the modules after `pos`, branches the pattern does not open passed
    over, a ']' of the string the end of what follows (a ']' of the pattern: the rest of the
    branch passed over)."""
    ps = _pattern_string(pattern)
    j = _position(self, pos) + 1
    for p in ps:
        if p.name == '[':
            if j >= len(self) or self[j].name != '[':
                return False
            j += 1
            continue
        if p.name == ']':
            e = self.endBracket(j, True) if j < len(self) else None
            if e is None:
                return False
            j = e + 1
            continue
        while j < len(self) and self[j].name == '[':
            e = self.endBracket(j)
            if e is None:
                return False
            j = e + 1
        if j >= len(self) or self[j].name == ']' or not _match_module(p, self[j], []):
            return False
        j += 1
    return True


def _tree_leftmatch(self, pattern, pos):
    """A left context: the modules before `pos` towards the root, branches passed over."""
    ps = _pattern_string(pattern)
    j = _position(self, pos) - 1
    for p in reversed(ps):
        while j >= 0 and self[j].name in '[]':
            if self[j].name == ']':
                b = self.beginBracket(j)
                if b is None:
                    return False
                j = b
            j -= 1
        if j < 0 or not _match_module(p, self[j], []):
            return False
        j -= 1
    return True


def _tree_find(self, pattern, start=0, end=2147483647):
    if isinstance(pattern, _lpy().PatternModule):
        a, b = _position(self, start), len(self) if end == 2147483647 else _position(self, end)
        for i in range(a, b):
            if self[i].name == pattern.name and len(self[i]) == len(pattern):
                return i
        return None
    return _find_name(self, pattern, start, end)


def _replacement(b):
    if isinstance(b, tuple):
        return AxialTree([ParamModule(b)])
    if isinstance(b, Module):
        return AxialTree([b])
    return AxialTree(b)


def _tree_replace(self, a, b):
    by = _replacement(b)
    out = AxialTree()
    if isinstance(a, _lpy().PatternModule):
        for m in self:
            out += by if _match_module(a, m, []) else AxialTree([m])
        return out
    ps, i = _pattern_string(a), 0
    while i < len(self):
        e = _exact(self, ps, i) if ps else -1
        if e > i:
            out += by
            i = e
        else:
            out.append(self[i])
            i += 1
    return out


_find_name = AxialTree.find
AxialTree.match = _tree_match
AxialTree.reverse_match = _tree_reverse_match
AxialTree.leftmatch = _tree_leftmatch
AxialTree.rightmatch = _tree_rightmatch
AxialTree.find = _tree_find
AxialTree.replace = _tree_replace


# [SECTION] AxialTree through a filter
# The tree's members given a ConsiderFilter (src/cpp/axialtree_manip.h): the modules it ignores
# are passed over. Without one, the C++ members (lpy/api/types_lstring.cpp).
def _ignored(s, i, f):
    return f.isIgnored(s[i])


def _is(s, i, name):
    return s[i].name == name


def _end_bracket(s, i):
    e = s.endBracket(i)
    return len(s) if e is None else e


def _parent(s, pos, f):
    if pos == 0:
        return None
    pos -= 1
    while pos > 0 and (s[pos].isBracket() or _ignored(s, pos, f)):
        while pos > 0 and (_is(s, pos, '[') or _ignored(s, pos, f)):
            pos -= 1
        while pos > 0 and _is(s, pos, ']'):
            b = s.beginBracket(pos)
            if b is None:
                return None
            pos = b - 1 if b > 0 else 0
    if pos == 0 and (_is(s, 0, '[') or _ignored(s, 0, f)):
        return None
    return pos


def _branches(s, pos, f, direct):
    """children (direct: with the direct child), lateral_children: from module pos."""
    out, n = [], len(s)
    if pos >= n or _is(s, pos, ']'):
        return out
    pos += 1
    if pos >= n or _is(s, pos, ']'):
        return out
    while pos < n and (_is(s, pos, '[') or _ignored(s, pos, f)):
        while pos < n and not s[pos].isBracket() and _ignored(s, pos, f):
            pos += 1
        while pos < n and _is(s, pos, '['):
            out += _branches(s, pos, f, True)
            pos = _end_bracket(s, pos)
            if pos >= n:
                return out
            pos += 1
    if direct and pos < n and not _is(s, pos, ']'):
        out.append(pos)
    return out


def _direct_child(s, pos, f):
    n = len(s)
    if pos >= n or _is(s, pos, ']'):
        return None
    pos += 1
    while pos < n and (_is(s, pos, '[') or _ignored(s, pos, f)):
        while pos < n and not _is(s, pos, '[') and _ignored(s, pos, f):
            pos += 1
        while pos < n and _is(s, pos, '['):
            pos = _end_bracket(s, pos)
            if pos >= n:
                return None
            pos += 1
    return None if pos >= n or _is(s, pos, ']') else pos


def _roots(s, f):
    out, n = [], len(s)
    if n == 0 or _is(s, 0, ']'):
        return out
    i = 0
    if _is(s, 0, '['):
        while i < n and (s[i].isBracket() or _ignored(s, i, f)):
            while i < n and _is(s, i, '['):
                out += _branches(s, i, f, True)
                i = _end_bracket(s, i)
                if i >= n:
                    return out
                i += 1
            while i < n and not s[i].isBracket() and _ignored(s, i, f):
                i += 1
            if i < n and _is(s, i, ']'):
                break
        if i < n and not _is(s, i, ']'):
            out.append(i)
    elif _ignored(s, 0, f):
        out += _branches(s, 0, f, True)
    else:
        out.append(0)
    return out


def _positions(v):
    return None if not v else v[0] if len(v) == 1 else v


def _index(s, pos):
    n = len(s)
    if pos < 0:
        pos += n
    if pos < 0 or pos >= n:
        raise IndexError('index out of range')
    return pos


def _filtered(name, with_filter):
    native = getattr(AxialTree, name)

    def member(self, *args, **kwds):
        f = kwds.pop('filter', None)
        if f is None and args and not isinstance(args[-1], (int, str)) and args[-1] is not None:
            f, args = args[-1], args[:-1]
        elif args and args[-1] is None and len(args) > (0 if name == 'roots' else 1):
            args = args[:-1]
        if f is None:
            return native(self, *args, **kwds)
        return with_filter(self, f, *args, **kwds)

    member.__name__ = name
    member.__doc__ = native.__doc__
    return member


def _children(s, f, pos, edge_type=None):
    pos = _index(s, pos)
    if edge_type is None:
        return _positions(_branches(s, pos, f, True))
    if edge_type == '<':
        return _direct_child(s, pos, f)
    if edge_type == '+':
        return _positions(_branches(s, pos, f, False))
    raise ValueError('invalid edge type')


AxialTree.roots = _filtered('roots', lambda s, f: _positions(_roots(s, f)))
AxialTree.parent = _filtered('parent', lambda s, f, pos: _parent(s, _index(s, pos), f))
AxialTree.children = _filtered('children', _children)
AxialTree.lateral_children = _filtered('lateral_children',
                                       lambda s, f, pos: _positions(_branches(s, _index(s, pos), f, False)))
AxialTree.direct_child = _filtered('direct_child', lambda s, f, pos: _direct_child(s, _index(s, pos), f))
AxialTree.father, AxialTree.sons = AxialTree.parent, AxialTree.children
AxialTree.lateralSons, AxialTree.directSon = AxialTree.lateral_children, AxialTree.direct_child
