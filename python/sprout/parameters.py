"""A model's graphical objects from Python (issue 52): `plant.parameters`, what the viewer's
panel edits. Each is read from the model's text and written back into it the way the viewer's
editors write it (L-Py Studio's INITIALISATION part, a .lsys grammar's `function:` and
`contour:` lines), and the plant is made again from the new text:

    plant = sprout.open("lsystem9.lpy")
    list(plant.parameters)                        # ['branchpath', ...]
    p = plant.parameters["branchpath"]
    p.points = [(x, y + 0.1, w) for x, y, w in p.points]
    plant.parameters["material 1"].ambient = (200, 40, 40)
    plant.parameters["H"].value = 4               # an L-Py scalar
    sprout.editor(plant, "branchpath")            # a notebook widget (ipywidgets), else a picture
"""
import collections.abc as _abc
import io as _io

from . import _sprout

_MATERIAL_FIELDS = ("ambient", "diffuse", "specular", "emission", "shininess", "transparency")


class Parameter:
    """One object of a model: `kind` is curve, function, patch, material, texture (a material
    with an `image` file), scalar, category (a heading of L-Py Studio's scalars, no value)
    (L-Py) or function, contour (.lsys); `points` (curves, functions, contours, patches), `value`
    (scalars) and a material's fields read the model's text now and write into it."""

    def __init__(self, plant, kind, name, key):
        object.__setattr__(self, "_plant", plant)
        object.__setattr__(self, "kind", kind)
        object.__setattr__(self, "name", name)
        object.__setattr__(self, "_key", key)

    def _entry(self):
        text = self._plant.text
        if self._key[0] == "curve":
            return [c for c in _sprout.lpy_curves(text) if c["key"] == self.name][-1]
        if self._key[0] == "patch":
            return [p for p in _sprout.lpy_patches(text) if p["name"] == self.name][-1]
        if self._key[0] == "material":
            return [m for m in _sprout.lpy_materials(text) if m["index"] == self._key[1]][-1]
        if self._key[0] == "scalar":
            return [s for s in _sprout.lpy_scalars(text) if s["name"] == self.name][-1]
        return [c for c in _sprout.lsys_curves(text) if c["name"] == self.name][-1]

    def _write(self, text):
        self._plant._set_text(text)

    @property
    def points(self):
        """The control points: (x, y, w) for an L-Py curve or function, (x, y) for a .lsys
        function or contour, rows of (x, y, z, w) for a patch."""
        e = self._entry()
        if "points" not in e:
            raise AttributeError("a %s has no points" % self.kind)
        return [tuple(p) if not isinstance(p[0], (list, tuple)) else [tuple(q) for q in p] for p in e["points"]]

    @points.setter
    def points(self, points):
        text = self._plant.text
        if self._key[0] == "curve":
            pts = [tuple(p) + (1.0,) * (3 - len(p)) for p in points]
            self._write(_sprout.set_lpy_curve(text, self.name, pts))
        elif self._key[0] == "patch":
            self._write(_sprout.set_lpy_patch(text, self.name, [[tuple(q) + (1.0,) * (4 - len(q)) for q in row] for row in points]))
        elif self._key[0] == "lsys":
            self._write(_sprout.set_lsys_curve(text, self.name, [tuple(p)[:2] for p in points]))
        else:
            raise AttributeError("a %s has no points" % self.kind)

    @property
    def value(self):
        """A scalar's value."""
        if self._key[0] != "scalar" or self.kind == "category":
            raise AttributeError("a %s has no value" % self.kind)
        return self._entry()["value"]

    @value.setter
    def value(self, v):
        if self._key[0] != "scalar" or self.kind == "category":
            raise AttributeError("a %s has no value" % self.kind)
        self._write(_sprout.set_lpy_scalar(self._plant.text, self.name, float(v)))

    def __getattr__(self, field):
        if field in _MATERIAL_FIELDS and self.kind == "material":
            return self._entry()[field]
        if field == "image" and self.kind == "texture":
            return self._entry()["texture"]
        raise AttributeError(field)

    def __setattr__(self, field, v):
        if (field in _MATERIAL_FIELDS and self.kind == "material") or (field == "image" and self.kind == "texture"):
            return self._write(_sprout.set_lpy_material(self._plant.text, self._key[1], field, v))
        if field in ("points", "value"):
            return object.__setattr__(self, field, v)
        raise AttributeError("%s cannot be set on a %s" % (field, self.kind))

    def __repr__(self):
        return "<sprout parameter %s (%s)>" % (self.name, self.kind)

    def png(self, width=360, height=260):
        """A picture of the curve or function and its control polygon (matplotlib)."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(width / 100, height / 100), dpi=100)
        pts = self.points
        if self._key[0] == "patch":
            for row in pts:
                ax.plot([q[0] for q in row], [q[1] for q in row], "o-", color="0.5")
        else:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", color="0.6")
            if self._key[0] == "curve":  # the curve as PlantGL evaluates it
                e = self._entry()
                line = _sprout._lpy_curve_samples(e["kind"], e["degree"], [tuple(p) for p in pts], 120)
                ax.plot([q[0] for q in line], [q[1] for q in line], "-", color="tab:green", linewidth=2)
        ax.set_title("%s (%s)" % (self.name, self.kind))
        ax.set_aspect("equal" if self.kind != "function" else "auto")
        out = _io.BytesIO()
        fig.savefig(out, format="png")
        plt.close(fig)
        return out.getvalue()

    def _repr_png_(self):
        try:
            return self.png()
        except ImportError:
            return None


class Parameters(_abc.Mapping):
    """The objects of a plant's model by name (a material: "material N")."""

    def __init__(self, plant):
        self._plant = plant

    def _keys(self):
        text, out = self._plant.text, {}
        for c in _sprout.lpy_curves(text):  # an earlier panel's version of a name: "NAME#k"
            out[c["key"]] = ("function" if c["function"] else "curve", ("curve",))
        for p in _sprout.lpy_patches(text):
            out[p["name"]] = ("patch", ("patch",))
        for s in _sprout.lpy_scalars(text):
            out[s["name"]] = ("category" if s["kind"] == "Category" else "scalar", ("scalar",))
        for m in _sprout.lpy_materials(text):
            out["material %d" % m["index"]] = ("texture" if "texture" in m else "material", ("material", m["index"]))
        for c in _sprout.lsys_curves(text):
            out[c["name"]] = (c["kind"], ("lsys",))
        return out

    def __getitem__(self, name):
        keys = self._keys()
        if name not in keys:
            raise KeyError(name)
        kind, key = keys[name]
        return Parameter(self._plant, kind, name, key)

    def __iter__(self):
        return iter(self._keys())

    def __len__(self):
        return len(self._keys())


def editor(plant, name, width=480, height=360):
    """A notebook editor of one curve, function or contour: a slider for each control point's
    x and y, the curve's picture and the plant's, redrawn as they move (ipywidgets). Without
    ipywidgets, the curve's picture."""
    p = plant.parameters[name]
    try:
        import ipywidgets as widgets
    except ImportError:
        from IPython.display import Image

        return Image(data=p.png())
    from . import _png_bytes

    curve = widgets.Image(value=p.png(), format="png")
    picture = widgets.Image(value=_png_bytes(plant, None, width, height), format="png", width=width, height=height)
    rows = []
    for k, q in enumerate(p.points):
        sliders = []
        for axis in (0, 1):
            lo, hi = min(-1.0, q[axis] * 2), max(1.0, q[axis] * 2)
            s = widgets.FloatSlider(value=q[axis], min=lo, max=hi, step=0.01, description="%d %s" % (k, "xy"[axis]))

            def moved(change, k=k, axis=axis):
                pts = [list(t) for t in p.points]
                pts[k][axis] = change["new"]
                p.points = pts
                curve.value = p.png()
                picture.value = _png_bytes(plant, None, width, height)

            s.observe(moved, names="value")
            sliders.append(s)
        rows.append(widgets.HBox(sliders))
    box = widgets.VBox([widgets.HBox([curve, picture])] + rows)
    box.curve, box.picture, box.rows = curve, picture, rows
    return box
