"""Sprout's L-system engine for Python programs and notebooks.

    import sprout
    plant = sprout.open("fractal_plant")        # a file of any kind Sprout opens, or a preset
    s = plant.derive(3)                          # step 3: a read-only sequence of modules
    picture = plant.render(width=400, height=300)   # numpy (300, 400, 4), headless
    plant.export("plant.glb")

A plant shows itself in Jupyter (its picture), and `sprout.slider(plant)` steps through its
growth with ipywidgets when they are installed.
"""
import builtins as _builtins
import os as _os
import tempfile as _tempfile

from ._sprout import (LString, Plant, __version__, lpy_curves, lpy_materials, lpy_patches, lpy_scalars,  # noqa: F401
                      lsys_curves, open, parse, presets, set_lpy_curve, set_lpy_material, set_lpy_patch, set_lpy_scalar,
                      set_lsys_curve)


class GrammarError(ValueError):
    """A grammar that cannot be read: `line` and `col` of the first error, every problem in
    `diagnostics` as (line, col, 'error'|'warning', message)."""

    def __init__(self, message, line=0, col=0, diagnostics=()):
        super().__init__(message)
        self.line, self.col, self.diagnostics = line, col, list(diagnostics)


def _png_bytes(plant, n=None, width=480, height=360, seed=None):
    fd, path = _tempfile.mkstemp(suffix=".png")
    _os.close(fd)
    try:
        plant.render(n=n, width=width, height=height, seed=seed, path=path)
        with _builtins.open(path, "rb") as f:
            return f.read()
    finally:
        _os.unlink(path)


def _repr_png_(self):
    """The plant's picture at its own n, for Jupyter."""
    return _png_bytes(self)


def _steps(self, n=None, seed=None):
    """Each step's string, from the axiom to step n (default: the grammar's n)."""
    last = self.n if n is None else n
    for k in range(last + 1):
        yield self.derive(k, seed=seed)


Plant._repr_png_ = _repr_png_
Plant.steps = _steps
Plant.png = _png_bytes

from .parameters import Parameters as _Parameters, editor  # noqa: E402,F401  (after _png_bytes, which it uses)

Plant.parameters = property(lambda self: _Parameters(self), doc="The model's objects by name, as the viewer's editors edit them")


def use_as_openalea():
    """Makes `import openalea.lpy` and `import openalea.plantgl.all` give Sprout's in this
    interpreter, so scripts written for L-Py run unchanged (`Lsystem`, `Lstring`, ...). Where a
    real openalea.lpy is installed, says so and changes nothing. Returns openalea.lpy."""
    import importlib.util
    import sys
    import warnings

    mod = sys.modules.get("openalea.lpy")
    if mod is not None and str(getattr(mod, "__file__", "")).startswith("<sprout>"):
        return mod
    try:
        real = mod is not None or importlib.util.find_spec("openalea.lpy") is not None
    except (ImportError, ValueError):
        real = False
    if real:
        warnings.warn("sprout.use_as_openalea(): a real openalea.lpy is installed here; it is left as it is")
        return importlib.import_module("openalea.lpy")
    from ._sprout import _install_openalea

    _install_openalea()
    return sys.modules["openalea.lpy"]


def slider(plant, width=480, height=360, seed=None):
    """A step slider over the plant's growth (ipywidgets), its picture redrawn at each step."""
    import ipywidgets as widgets

    image = widgets.Image(value=_png_bytes(plant, plant.n, width, height, seed), format="png", width=width, height=height)
    step = widgets.IntSlider(value=plant.n, min=0, max=plant.n, description="step")

    def redraw(change):
        image.value = _png_bytes(plant, change["new"], width, height, seed)

    step.observe(redraw, names="value")
    box = widgets.VBox([step, image])
    box.step, box.image = step, image
    return box
