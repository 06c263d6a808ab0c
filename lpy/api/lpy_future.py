# openalea.lpy.__lpyfuture__ as Sprout provides it: L-Py's experimental string controls, used
# from EndEach. Written from L-Py's definition (src/openalea/lpy/__lpyfuture__.py): the
# decorated EndEach returns the string the step should leave, which the engine takes in place
# of the one just derived.
#
#   DiscardNewString()          this step's string is dropped: the one kept after the step
#                               before comes back (called from EndEach or from any rule)
#   @enable_string_discard      on EndEach: makes the above happen
#   pushString(name)            the string after this step is kept under `name`
#   popString(name)             it comes back at the end of this step (and is returned now)
#   @enable_string_pushpop      on EndEach: makes those happen
#
# Importing * brings an EndEach already decorated for discarding, so a model that only calls
# DiscardNewString() in a rule needs nothing else (as in L-Py). Each run of a model imports
# this module afresh (openalea.lpy._begin), so nothing is remembered from an earlier run.
import openalea.lpy as lpy

_discard = False
_kept = None
_push = None
_pop = None
_stack = {}


def DiscardNewString():
    global _discard
    _discard = True


def _arity(fn):
    n = fn.__code__.co_argcount
    if n > 2:
        raise ValueError('EndEach should be defined with at most 2 arguments (lstring, lscene)')
    return n


def _call(fn, n, lstring, lscene):
    return fn() if n == 0 else fn(lstring) if n == 1 else fn(lstring, lscene)


def _with_arity(wrapped, n):
    # The engine reads the hook's arity from __code__: give it back the decorated one's,
    # at least the string (a wrapper with none could not return the kept string).
    if n == 2:
        return lambda lstring, lscene: wrapped(lstring, lscene)
    return lambda lstring: wrapped(lstring, None)


def enable_string_discard(endeach):
    n = _arity(endeach)

    def wrapped(lstring, lscene):
        global _discard, _kept
        if not _discard:
            result = _call(endeach, n, lstring, lscene)
        if _discard:
            _discard = False
            return _kept
        _kept = lpy.Lstring(lstring)
        return result

    return _with_arity(wrapped, n)


@enable_string_discard
def EndEach():
    pass


def pushString(name):
    global _push
    _push = name


def popString(name):
    global _pop
    if name not in _stack:
        raise ValueError('no string was pushed under the name ' + repr(name))
    _pop = name
    return _stack[name]


def enable_string_pushpop(endeach):
    n = _arity(endeach)

    def wrapped(lstring, lscene):
        global _push, _pop
        result = _call(endeach, n, lstring, lscene)
        if _push is not None:
            _stack[_push] = lpy.Lstring(lstring)
            _push = None
        if _pop is not None:
            result = _stack.pop(_pop)
            _pop = None
        return result

    return _with_arity(wrapped, n)
