"""LsysContext, its options and the functions on the current context (L-Py's
export_lsyscontext.cpp, export_lsysoptions.cpp), plotting and interpretation (export_plot.cpp,
export_interpretation.cpp), and the Python of openalea.lpy's package (__init__.py,
__version__.py, parameterset.py, defaultparameters.py). Written from L-Py's definition; each
case leaves the current context as it found it."""
# Index of this file:
#   [SECTION] a context's state
#   [SECTION] its namespace
#   [SECTION] the current context
#   [SECTION] the functions on the current context
#   [SECTION] options
#   [SECTION] the package's Python
#   [SECTION] plotting and interpretation

import re

from lpy_api import case


def _plain(text):
    return re.sub(r" at 0x[0-9a-fA-F]+", "", text)


# [SECTION] a context's state
@case("LsysContext", "LsysContext.empty", "LsysContext.getGroup", "LsysContext.isForward", "LsysContext.getIterationNb",
      "LsysContext.isAnimationEnabled", "LsysContext.isSelectionAlwaysRequired", "LsysContext.animation_timestep",
      "LsysContext.is_animation_timestep_to_default", "LsysContext.isCurrent", "LsysContext.InitialisationFunctionName")
def context_fresh():
    from openalea.lpy import LsysContext

    c = LsysContext()
    return [_plain(str(c)), _plain(repr(c)), c.empty(), c.getGroup(), c.isForward(), c.getIterationNb(), c.isAnimationEnabled(),
            c.isSelectionAlwaysRequired(), c.animation_timestep, c.is_animation_timestep_to_default(), c.isCurrent(),
            LsysContext.InitialisationFunctionName]


@case("LsysContext.useGroup", "LsysContext.getGroup", "LsysContext.backward", "LsysContext.forward", "LsysContext.isForward",
      "LsysContext.frameDisplay", "LsysContext.isFrameDisplayed", "LsysContext.setSelectionAlwaysRequired",
      "LsysContext.isSelectionAlwaysRequired", "LsysContext.requestSelection", "LsysContext.stop")
def context_control():
    from openalea.lpy import LsysContext

    c = LsysContext()
    out = []
    c.useGroup(3)
    c.backward()
    c.frameDisplay(True)
    out += [c.getGroup(), c.isForward(), c.isFrameDisplayed()]
    c.frameDisplay(False)
    c.forward()
    out += [c.isForward(), c.isFrameDisplayed()]
    c.frameDisplay()
    out.append(c.isFrameDisplayed())
    c.frameDisplay(False)
    out.append(c.setSelectionAlwaysRequired(True))
    out += [c.isSelectionAlwaysRequired(), c.options.find('Selection Always Required').selection]
    c.setSelectionAlwaysRequired(False)
    out += [c.isSelectionAlwaysRequired(), c.options.find('Selection Always Required').selection]
    out.append(c.requestSelection('pick one'))
    out.append(c.isFrameDisplayed())
    out.append(c.stop())
    return out


@case("LsysContext.useGroup")
def context_negative_group():
    from openalea.lpy import LsysContext

    return LsysContext().useGroup(-1)


@case("LsysContext.animation_timestep", "LsysContext.is_animation_timestep_to_default")
def context_timestep():
    from openalea.lpy import LsysContext

    c = LsysContext()
    c.animation_timestep = 0.25
    out = [c.animation_timestep, c.is_animation_timestep_to_default()]
    c.animation_timestep = 0.050001
    out += [c.is_animation_timestep_to_default()]
    return out


# [SECTION] its namespace
@case("LsysContext.__setitem__", "LsysContext.__getitem__", "LsysContext.__contains__", "LsysContext.has_key",
      "LsysContext.get", "LsysContext.__delitem__", "LsysContext.locals", "LsysContext.globals",
      "LsysContext.getNamespace", "LsysContext.updateNamespace", "LsysContext.clearNamespace", "LsysContext.clear")
def context_namespace():
    from openalea.lpy import LsysContext

    c = LsysContext()
    c['x'] = 1
    out = ['x' in c, c.has_key('x'), c['x'], c.get('x', None), c.get('nothere', 5), 'Lsystem' in c, 'Vector3' in c,
           c.globals() is c.locals(), 'x' in c.locals()]
    d = {}
    c.getNamespace(d)
    out += ['x' in d, 'Lsystem' in d]
    c.updateNamespace({'y': 2})
    out.append(c['y'])
    del c['x']
    out.append('x' in c)
    c.clearNamespace()
    out += ['y' in c, 'Lsystem' in c]
    c['z'] = 3
    c.declare('ClearedMod')
    c.useGroup(2)
    c.clear()
    out += ['z' in c, 'Lsystem' in c, c.empty(), c.getGroup()]
    return out


@case("LsysContext.__getitem__")
def context_missing_name():
    from openalea.lpy import LsysContext

    return LsysContext()['no_such_name']


@case("LsysContext.evaluate", "LsysContext.compile")
def context_evaluate_compile():
    from openalea.lpy import LsysContext

    c = LsysContext()
    c['a'] = 20
    out = [c.evaluate('a + 1'), c.evaluate(''), c.compile('b = a * 2'), c['b'], c.compile('w', 'w = 5'), c.compile('w2', '')]
    out.append(c.evaluate('[v for v in range(3)]'))
    return out


@case("LsysContext.evaluate")
def context_evaluate_error():
    from openalea.lpy import LsysContext

    return LsysContext().evaluate('1 / 0')


@case("LsysContext.start", "LsysContext.end", "LsysContext.startEach", "LsysContext.endEach", "LsysContext.postDraw",
      "LsysContext.setStart", "LsysContext.setEnd", "LsysContext.setStartEach", "LsysContext.setEndEach",
      "LsysContext.setPostDraw")
def context_hooks():
    from openalea.lpy import LsysContext

    c = LsysContext()
    out = [c.start(), c.end(), c.startEach(), c.endEach(), c.postDraw()]
    calls = []
    c.setStart(lambda: 'started')
    c.setEnd(lambda: 'ended')
    c.setStartEach(lambda: 'each')
    c.setEndEach(lambda: calls.append('endeach') or 'endeach')
    c.setPostDraw(lambda: calls.append('post'))
    out += [c.start(), c.end(), c.startEach(), c.endEach(), c.postDraw(), calls, 'Start' in c, 'PostDraw' in c]
    return out


@case("LsysContext.initialise", "LsysContext.initialiseFrom")
def context_initialise():
    from openalea.lpy import LsysContext

    c = LsysContext()
    out = [c.initialise()]
    c['__initialiseContext__'] = lambda ctx: ctx.__setitem__('k', 7)
    out += [c.initialise(), c['k']]
    d = LsysContext()
    code = "x = 1\n###### INITIALISATION ######\ndef __initialiseContext__(context):\n    context['q'] = 9\n"
    out += [d.initialiseFrom(code), d['q'], d.initialiseFrom('no tag here')]
    return out


# [SECTION] the current context
@case("LsysContext.makeCurrent", "LsysContext.done", "LsysContext.isCurrent", "LsysContext.currentContext",
      "LsysContext.current", "context", "execContext")
def context_current():
    # A context is told by a name in its namespace: L-Py's context() gives a new Python object
    # for the same context at each call.
    from openalea.lpy import LsysContext, context, execContext

    c = LsysContext()
    c['mark'] = 'c'
    before = context()
    c.makeCurrent()
    out = [c.isCurrent(), LsysContext.currentContext().get('mark', None), LsysContext.current().get('mark', None),
           context().get('mark', None), execContext().get('mark', None), before.isCurrent(), context().isCurrent()]
    c.done()
    out += [c.isCurrent(), context().get('mark', None), before.isCurrent()]
    return out


@case("LsysContext.done")
def context_done_not_current():
    from openalea.lpy import LsysContext

    return LsysContext().done()


@case("LsysContext.defaultContext", "LsysContext.default", "LsysContext.globalContext")
def context_default_and_global():
    import sys

    from openalea.lpy import LsysContext

    d = LsysContext.defaultContext()
    d['default_mark'] = 'd'
    g = LsysContext.globalContext()
    return [LsysContext.default().get('default_mark', None), LsysContext.defaultContext().get('default_mark', None),
            g.get('default_mark', None), g.isCurrent(), g.globals() is sys.modules['__main__'].__dict__,
            'default_mark' in g.locals(), d.isCurrent(), d.done(), d.globals() is d.locals()]


@case("LsysContext.declare", "LsysContext.undeclare", "LsysContext.isDeclared", "LsysContext.declaredModules",
      "LsysContext.empty")
def context_declare():
    from openalea.lpy import LsysContext

    c = LsysContext()
    c.declare('DeclA, DeclB(x, y)')
    out = [c.isDeclared('DeclA'), c.isDeclared('DeclB'), c.isDeclared('NotDeclared'), sorted(m.name for m in c.declaredModules()),
           c.empty(), _plain(str(c))]
    c.undeclare('DeclA')
    out += [c.isDeclared('DeclA'), [m.name for m in c.declaredModules()]]
    return out


@case("LsysContext.setModuleScale")
def context_module_scale():
    from openalea.lpy import LsysContext, ModuleClass

    c = LsysContext()
    c.declare('ScaledMod')
    c.setModuleScale('ScaledMod', 2)
    c.makeCurrent()
    try:
        return ModuleClass.get('ScaledMod').scale
    finally:
        c.done()


@case("LsysContext.nproduce")
def context_nproduce_outside():
    from openalea.lpy import LsysContext, Lstring

    c = LsysContext()
    return [c.nproduce(Lstring('A B')), c.nproduce([])]


@case("LsysContext.turtle", "LsysContext.options")
def context_turtle_and_options():
    from openalea.lpy import LsysContext

    c = LsysContext()
    return [c.turtle is c.turtle, len(c.options) > 10, c.options.find('Optimization').name]


# [SECTION] the functions on the current context
@case("useGroup", "getGroup", "backward", "forward", "isForward", "frameDisplay", "isFrameDisplayed", "getIterationNb",
      "isAnimationEnabled", "isSelectionAlwaysRequired", "setSelectionAlwaysRequired", "requestSelection", "Stop",
      "nsproduce")
def functions_outside_a_run():
    from openalea.lpy import (useGroup, getGroup, backward, forward, isForward, frameDisplay, isFrameDisplayed,
                              getIterationNb, isAnimationEnabled, isSelectionAlwaysRequired, setSelectionAlwaysRequired,
                              Stop, nsproduce, context)

    out = []
    useGroup(2)
    out += [getGroup(), context().getGroup()]
    useGroup(0)
    backward()
    out.append(isForward())
    forward()
    out.append(isForward())
    frameDisplay(True)
    out.append(isFrameDisplayed())
    frameDisplay(False)
    out.append(isFrameDisplayed())
    out += [getIterationNb(), isAnimationEnabled(), isSelectionAlwaysRequired()]
    setSelectionAlwaysRequired(True)
    out.append(isSelectionAlwaysRequired())
    setSelectionAlwaysRequired(False)
    out += [Stop(), nsproduce([])]
    return out


@case("declare", "undeclare", "isDeclared")
def functions_declare():
    from openalea.lpy import declare, undeclare, isDeclared, context

    declare('GlobalDeclared')
    out = [isDeclared('GlobalDeclared'), context().isDeclared('GlobalDeclared')]
    undeclare('GlobalDeclared')
    out.append(context().isDeclared('GlobalDeclared'))
    return out


@case("pInLeftContext")
def p_in_left_context_outside():
    from openalea.lpy import pInLeftContext

    return pInLeftContext(0, {})


@case("pInRightContext")
def p_in_right_context_outside():
    from openalea.lpy import pInRightContext

    return pInRightContext(0, {})


@case("inLeftContext")
def in_left_context_outside():
    from openalea.lpy import inLeftContext

    return inLeftContext('A', {})


@case("inRightContext")
def in_right_context_outside():
    from openalea.lpy import inRightContext

    return inRightContext('A', {})


@case("getIterationNb", "getGroup", "useGroup", "isForward", "context", "LsysContext.getGroup", "LsysContext.getIterationNb")
def functions_in_a_run():
    from openalea.lpy import Lsystem

    code = '\n'.join([
        'seen = []',
        'def StartEach():',
        '    if getIterationNb() == 1: useGroup(1)',
        'def EndEach():',
        '    seen.append((getIterationNb(), getGroup(), isForward(), context().getGroup(), context().getIterationNb()))',
        'Axiom: A',
        'derivation length: 3',
        'production:',
        'A --> AB',
        'group 1:',
        'B --> C',
        'endgroup',
        'endlsystem', ''])
    lsys = Lsystem()
    lsys.setCode(code)
    result = lsys.derive()
    return [str(result), [list(t) for t in lsys.context()['seen']], lsys.context().getGroup()]


# [SECTION] options
@case("LsysOptions", "LsysOptions.__len__", "LsysOptions.__getitem__", "LsysOption", "LsysOption.name", "LsysOption.comment",
      "LsysOption.category", "LsysOption.global", "LsysOption.default_value_id", "LsysOption.selection",
      "LsysOption.currentValue", "LsysOption.__len__", "LsysOption.__getitem__", "LsysOption.isToDefault",
      "LsysOptionValue", "LsysOptionValue.name", "LsysOptionValue.comment")
def options_table():
    from openalea.lpy import LsysContext

    c = LsysContext()  # kept: its options live as long as it does
    o = c.options
    out = []
    for i in range(len(o)):
        opt = o[i]
        out.append([opt.name, opt.comment, opt.category, getattr(opt, 'global'), opt.default_value_id, opt.selection,
                    opt.currentValue(), opt.isToDefault(), len(opt), [[opt[k].name, opt[k].comment] for k in range(len(opt))]])
    return out


@case("LsysOption.setSelection", "LsysOption.selection", "LsysOption.isToDefault", "LsysOption.activate",
      "LsysOption.activateSelection", "LsysOptions.setSelection", "LsysOptions.find", "LsysOptions.activate",
      "LsysOptions.activateSelection", "LsysOptionValue.activate", "LsysOption.__getitem__")
def options_select():
    from openalea.lpy import LsysContext

    c = LsysContext()  # kept: its options live as long as it does
    o = c.options
    opt = o.find('Optimization')
    out = [opt.setSelection(0), opt.selection, opt.currentValue(), opt.isToDefault(), opt.setSelection('Level 2'),
           opt.currentValue(), opt.setSelection('bogus'), opt.setSelection(10), opt.selection]
    out += [o.setSelection('Optimization', 1), opt.isToDefault(), o.setSelection('Optimization', 'Level 0'), opt.selection,
            o.setSelection('No such option', 1), o.find('No such option')]
    out += [opt.activate('Level 2'), opt.selection, opt.activate('bogus'), opt.activateSelection(), opt[0].activate(),
            opt.selection, opt[-1].name]
    out += [o.activate('Optimization', 'Level 1'), opt.selection, o.activate('No such option', 'x'),
            o.activateSelection('Optimization'), o.activateSelection('No such option')]
    opt.selection = 2
    out.append(opt.currentValue())
    return out


@case("LsysOption.selection")
def option_invalid_selection():
    from openalea.lpy import LsysContext

    c = LsysContext()
    c.options.find('Optimization').selection = 7


@case("LsysOptions.__getitem__")
def options_index_out_of_range():
    from openalea.lpy import LsysContext

    c = LsysContext()
    return c.options[100]


@case("LsysOption.__getitem__")
def option_index_out_of_range():
    from openalea.lpy import LsysContext

    c = LsysContext()
    return c.options.find('Optimization')[3]


@case("LsysOption", "LsysOptions", "LsysOption.setSelection", "LsysOptions.find")
def options_standalone():
    from openalea.lpy import LsysOption, LsysOptions

    opt = LsysOption('myopt', 'a comment', 'a category')
    bare = LsysOption('bare')
    opts = LsysOptions()
    return [opt.name, opt.comment, opt.category, len(opt), opt.selection, opt.default_value_id, getattr(opt, 'global'),
            opt.setSelection(0), opt.isToDefault(), bare.comment, bare.category, len(opts), opts.find('myopt')]


# [SECTION] the package's Python
@case("LPY_VERSION_MAJOR", "LPY_VERSION_MINOR", "LPY_VERSION_REV", "LPY_VERSION_STR", "get_major", "get_minor",
      "get_revision", "get_version_majorminor", "version_string")
def version():
    from openalea.lpy import (LPY_VERSION_MAJOR, LPY_VERSION_MINOR, LPY_VERSION_REV, LPY_VERSION_STR, get_major, get_minor,
                              get_revision, get_version_majorminor, version_string)
    from openalea.lpy.__version__ import __version_number__

    return [LPY_VERSION_MAJOR, LPY_VERSION_MINOR, LPY_VERSION_REV, LPY_VERSION_STR, get_major(0), get_minor(0), get_revision(0),
            get_version_majorminor(__version_number__), version_string(0), version_string(0, '$Rev: 1234 $')]


@case("ParameterSet", "parameterset", "ParameterSet.get", "ParameterSet.hasattr", "ParameterSet.set", "ParameterSet.setdefault",
      "ParameterSet.parameter_names", "ParameterSet.rename", "ParameterSet.copy")
def parameter_set():
    from openalea.lpy import ParameterSet, parameterset

    p = ParameterSet(a=1, b=2)
    out = [repr(p), p.get('a'), p.get('c', 5), p.hasattr('a'), p.hasattr('c')]
    p.set(c=3)
    p.setdefault(c=10, d=4)
    out += [sorted(p.parameter_names()), p.c, p.d]
    p.rename('a', 'z')
    out += ['z' in p, 'a' in p, p['z']]
    p['y'] = 8
    del p['b']
    out += [repr(p), repr(p.copy()), repr(p.copy(False)), parameterset.ParameterSet is ParameterSet]
    return out


@case("ParameterSet.setdefault")
def parameter_set_setdefault_odd():
    from openalea.lpy import ParameterSet

    return ParameterSet().setdefault('e')


@case("ParameterSet.setdefault")
def parameter_set_setdefault_pairs():
    from openalea.lpy import ParameterSet

    return ParameterSet().setdefault('e', 1)


@case("extern")
def extern_values():
    ns = {}
    exec('\n'.join(['from openalea.lpy import extern', 'b = 20', 'extern(a=1, b=2)', 'extern("b")', '']), ns)
    from openalea.lpy.defaultparameters import extern as extern2
    import openalea.lpy as lpy
    return [ns['a'], ns['b'], sorted(ns['__externs__']), extern2 is lpy.extern]


@case("defaultparameters")
def default_parameters():
    # L-Py's calls inspect.getargspec, which Python 3.11 no longer has: given back here as
    # getfullargspec (the same .args) for the reference; Sprout's does not call it.
    import inspect
    if not hasattr(inspect, 'getargspec'):
        inspect.getargspec = inspect.getfullargspec
    ns = {}
    exec('\n'.join(['from openalea.lpy import defaultparameters', 'b = 20',
                    '@defaultparameters', 'def p():', '    a = 1', '    b = 2', '',
                    '@defaultparameters', 'def q(i):', '    c = 3 * i', '    b = 0', '    return c + 1', '',
                    'r = q(4)', '']), ns)
    return [ns['a'], ns['b'], ns['c'], ns['r'], ns['p'].__name__, callable(ns['q'])]


@case("extern")
def extern_missing():
    ns = {}
    exec("from openalea.lpy import extern\nextern('not_given')\n", ns)


@case("determine_lpymodule_path")
def lpymodule_path():
    import os
    import sys
    import tempfile

    from openalea.lpy import determine_lpymodule_path

    root = tempfile.mkdtemp()
    os.makedirs(os.path.join(root, 'lpymodpkg'))
    open(os.path.join(root, 'lpymodpkg', '__init__.py'), 'w').close()
    open(os.path.join(root, 'lpymodpkg', 'growth.lpy'), 'w').close()
    sys.path.insert(0, root)
    try:
        found = determine_lpymodule_path('lpymodpkg.growth.lpy')
        return [os.path.relpath(found, root), os.path.relpath(determine_lpymodule_path('lpymodpkg.growth'), root)]
    finally:
        sys.path.remove(root)


@case("determine_lpymodule_path")
def lpymodule_path_missing():
    from openalea.lpy import determine_lpymodule_path

    return determine_lpymodule_path('json.no_such_model')


@case("deprecated", "ModuleType")
def deprecated_and_module_type():
    import types
    import warnings

    from openalea.lpy import deprecated, ModuleType

    def old(x):
        """an old function"""
        return x + 1

    f = deprecated(old)
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter('always')
        value = f(1)
    return [value, f.__name__, f.__doc__, f.__deprecated__, w[0].category.__name__, str(w[0].message),
            ModuleType is types.ModuleType]


# [SECTION] plotting and interpretation
@case("generateScene")
def generate_scene():
    from openalea.lpy import Lstring, generateScene

    return [len(generateScene(Lstring('F'))), len(generateScene(Lstring('F[+F]F'))), len(generateScene(Lstring('+f')))]


@case("registerPlotter", "cleanPlotter", "plot")
def plotter():
    from openalea.lpy import Lstring, registerPlotter, cleanPlotter, plot

    seen = []

    class Plotter:
        def plot(self, scene):
            seen.append(len(scene))

        def selection(self):
            return []

    registerPlotter(Plotter())
    try:
        plot(Lstring('FF'))
        plot(Lstring('F[+F]'))
    finally:
        cleanPlotter()
    return seen


@case("turtle_interpretation", "turtle_partial_interpretation")
def turtle_interpretations():
    from openalea.lpy import LsysContext, Lstring, turtle_interpretation, turtle_partial_interpretation

    c = LsysContext()  # kept: its turtle lives as long as it does
    t = c.turtle
    out = [turtle_interpretation(Lstring('FF'), t), len(t.getScene())]
    turtle_partial_interpretation(Lstring('F'), t)
    out.append(len(t.getScene()))
    turtle_interpretation(Lstring('F'), t)
    out.append(len(t.getScene()))
    return out


@case("turtle_interpretation")
def turtle_interpretation_unbalanced():
    from openalea.lpy import LsysContext, Lstring, turtle_interpretation

    import os
    import sys

    c = LsysContext()
    # L-Py's C++ prints the turtle's stack size to the process's stdout (file 1), where the
    # cases' results go: sent elsewhere for the call.
    sys.stdout.flush()
    kept = os.dup(1)
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)
    try:
        return turtle_interpretation(Lstring('F[F'), c.turtle)
    finally:
        os.dup2(kept, 1)
        os.close(kept)
        os.close(devnull)


@case("pproduce")
def pproduce_without_id():
    from openalea.lpy import pproduce

    return pproduce()


@case("helpTurtle")
def help_turtle():
    from openalea.lpy import helpTurtle

    return [helpTurtle(), helpTurtle('F'), helpTurtle('+'), helpTurtle('Left'), helpTurtle('@Gc'), helpTurtle('NoSuchModule')]


@case("LsysContext.useGroup", "LsysContext.getIterationNb", "LsysContext.isFrameDisplayed", "LsysContext.backward",
      "LsysContext.isForward")
def context_control_around_a_run():
    # What is set on an Lsystem's context before a derivation steers it; what the derivation
    # leaves is read from the context after it.
    from openalea.lpy import Lsystem

    lsys = Lsystem()
    lsys.setCode('Axiom: A\nproduction:\nA --> AB\ngroup 1:\nB --> C\nendgroup\nendlsystem\n')
    plain = str(lsys.derive(lsys.axiom, 0, 2))
    lsys.context().useGroup(1)
    grouped = str(lsys.derive(lsys.axiom, 0, 3))
    out = [plain, grouped, lsys.context().getGroup(), lsys.context().getIterationNb(), lsys.context().isFrameDisplayed()]
    lsys.context().useGroup(0)
    lsys.context().backward()
    out += [str(lsys.derive(lsys.axiom, 0, 2)), lsys.context().isForward()]
    return out


@case("LsysContext.get")
def context_get_needs_a_default():
    from openalea.lpy import LsysContext

    c = LsysContext()
    c['x'] = 1
    return c.get('x')


@case("LsysContext")
def context_takes_no_argument():
    from openalea.lpy import LsysContext

    return LsysContext(1)


@case("LsysContext.evaluate")
def context_evaluate_indented():
    from openalea.lpy import LsysContext

    return LsysContext().evaluate(' 3')


@case("LsysContext.undeclare")
def context_undeclare_predefined():
    from openalea.lpy import LsysContext

    return LsysContext().undeclare('F')


@case("LsysContext.nproduce", "nsproduce")
def context_production_buffer():
    from openalea.lpy import LsysContext, Lstring, nsproduce

    c = LsysContext()
    c.nproduce('A B')
    c.nproduce(Lstring('C(1)'))
    out = [str(c.__production_buffer__)]
    c.makeCurrent()
    try:
        nsproduce('D')
        out.append(str(c.__production_buffer__))
    finally:
        c.done()
    return out


def _error_of(call):
    """The exception a call raises, by name (Boost.Python's ArgumentError is Python's TypeError)."""
    try:
        call()
    except Exception as e:  # the error is the result
        name = type(e).__name__
        return 'TypeError' if name == 'ArgumentError' else name
    return None


@case("LsysContext.declare", "LsysContext.undeclare", "LsysContext.isDeclared", "LsysContext.setModuleScale",
      "LsysContext.frameDisplay", "LsysContext.setSelectionAlwaysRequired", "LsysContext.requestSelection",
      "LsysContext.__setitem__", "LsysContext.__getitem__", "LsysContext.__contains__", "LsysContext.evaluate",
      "LsysContext.compile", "LsysContext.initialiseFrom", "LsysContext.updateNamespace", "LsysContext.getNamespace",
      "LsysContext.animation_timestep", "LsysContext.useGroup", "LsysContext.nproduce", "declare")
def context_bad_arguments():
    from openalea.lpy import LsysContext, declare

    c = LsysContext()
    calls = [lambda: c.declare(5), lambda: c.undeclare(5), lambda: c.isDeclared(5), lambda: c.setModuleScale('A', 'x'),
             lambda: c.setModuleScale('A', 2.5), lambda: c.frameDisplay('x'), lambda: c.frameDisplay(None),
             lambda: c.frameDisplay(1), lambda: c.setSelectionAlwaysRequired('x'), lambda: c.requestSelection(5),
             lambda: c.__setitem__(5, 1), lambda: c.__getitem__(5), lambda: 5 in c, lambda: c.evaluate(5), lambda: c.compile(5),
             lambda: c.initialiseFrom(5), lambda: c.updateNamespace(5), lambda: c.getNamespace(5),
             lambda: setattr(c, 'animation_timestep', 'x'), lambda: c.useGroup(2.0), lambda: c.useGroup(True),
             lambda: c.nproduce(5), lambda: declare('A(')]
    return [_error_of(call) for call in calls]


@case("LsysOptions.setSelection", "LsysOptions.find", "LsysOptions.__getitem__", "LsysOption", "LsysOption.setSelection",
      "helpTurtle", "generateScene", "turtle_interpretation", "nsproduce")
def options_and_functions_bad_arguments():
    from openalea.lpy import LsysContext, LsysOption, Lstring, helpTurtle, generateScene, turtle_interpretation, nsproduce

    c = LsysContext()
    o = c.options
    calls = [lambda: o.setSelection('Optimization', 1.5), lambda: o.find(5), lambda: o[1.5], lambda: o['Optimization'],
             lambda: o.find('Optimization').setSelection(None), lambda: LsysOption(5), lambda: helpTurtle(5),
             lambda: generateScene('F'), lambda: turtle_interpretation('F', c.turtle), lambda: nsproduce(5)]
    return [_error_of(call) for call in calls]


@case("inLeftContext", "inRightContext")
def in_context_made_at_run_time():
    # Patterns a rule's body makes while it runs: each test goes on from where the last ended.
    from openalea.lpy import Lsystem

    code = '\n'.join([
        'seen = []',
        'right = "B(y)"',
        'Axiom: C(1) A B(2) B(3) D',
        'derivation length: 1',
        'production:',
        'A:',
        '    d = {}',
        '    seen.append((inRightContext(right, d), dict(d)))',
        '    d = {}',
        '    seen.append((inRightContext(right, d), dict(d)))',
        '    d = {}',
        '    seen.append((inRightContext(right, d), dict(d)))',
        '    d = {}',
        '    left = "C(" + "z)"',
        '    seen.append((inLeftContext(left, d), dict(d)))',
        '    seen.append(inLeftContext("E", {}))',
        '    produce A',
        'endlsystem', ''])
    lsys = Lsystem()
    lsys.setCode(code)
    lsys.derive()
    return [list(x) if isinstance(x, tuple) else x for x in lsys.context()['seen']]
