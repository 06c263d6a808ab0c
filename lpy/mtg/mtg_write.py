# openalea.mtg's writer as Sprout provides it (openalea.mtg._write, gathered by
# openalea.mtg.io; lpy/README.md): an MTG written in the MTG format (write_mtg), shown as
# its code (display, mtg_display). Read from openalea.mtg's definition (src/openalea/mtg/io.py,
# CeCILL-C): the same header and the same code, column by column.

from string import Template
from warnings import warn

from . import traversal

_FEATURE_TYPES = ['INT', 'REAL', 'ALPHA', 'DD/MM', 'DD/MM/YY', 'DD/MM-TIME', 'DD/MM/YY-TIME', 'STRING']


def _label(s):
    from .io import get_label
    return get_label(s)


def mtg_display(g, vtx_id, tab='  ', edge_type=None, label=None):
    """The MTG below vtx_id, a line per vertex: its order in tabs, its edge and its label."""
    edge_type = edge_type or g.properties().get('edge_type', {})
    label = label or g.properties().get('label', {})
    prev, prev_scale = vtx_id, g.scale(vtx_id)
    for vid in traversal.iter_mtg(g, vtx_id):
        if prev == vid:
            continue
        name = label.get(vid, vid)
        et = edge_type[vid] if vid in edge_type else ('<' if prev == g.parent(vid) else '?')
        space, scale = '', g.scale(vid)
        if prev == g.complex(vid):
            et, space = '/', '^'
        elif prev_scale == scale and et == '<':
            space = '^'
        if scale < prev_scale:
            yield ''
        prev, prev_scale = vid, scale
        yield g.order(vid) * tab + space + et + name


class Writer(object):
    """An MTG as the MTG format's header parts and code."""

    def __init__(self, g, header=''):
        self.g = g
        self._header = header

    def _place(self, vtx, tab, nb_tab, sym_at_col):
        """The edge written before vtx and its column, from the vertices written in each column."""
        g = self.g
        et = g.property('edge_type').get(vtx, '/')
        parent, cur_scale = g.parent(vtx), g.scale(vtx)
        possible_et = possible_tab = None
        for i in range(tab, -1, -1):
            vc = v = sym_at_col[i]
            vscale = g.scale(v)
            parent_proj = parent
            if vscale > cur_scale:
                for _ in range(vscale - cur_scale):
                    vc = g.complex(vc)
                parent_proj = g.parent(next(g.component_roots_at_scale_iter(vtx, scale=vscale)))
            if vc == parent and v == parent_proj:
                if et == '<' or i + 1 >= nb_tab:
                    return '^' + et, i
                return et, i + 1
            if vc == parent:
                if et == '<':
                    possible_et, possible_tab = '^' + et, i
                elif i + 1 < nb_tab:
                    possible_tab = i + 1
                else:
                    possible_et, possible_tab = '^' + et, i
            elif i == 0 and g.complex(vc) == g.complex(vtx) == g.root and not possible_et:
                return et, 0
        if possible_et and possible_tab:
            return possible_et, possible_tab
        raise ValueError('Error in the MTG for vertex %d: it cannot be written in the MTG code' % vtx)

    def code(self, property_names, nb_tab=None, display_id=False, display_scale=False, filter=None):
        """The MTG: section, ENTITY-CODE's line and a line per vertex."""
        g = self.g
        if nb_tab is None:
            from .algo import orders
            nb_tab = max(orders(g)) + 1  # as openalea.mtg counts them: the largest vertex id
        head = ['MTG :', '\t'.join(['ENTITY-CODE'] + (nb_tab - 1) * [''] + list(property_names))]
        labels, properties = g.property('label'), g.properties()
        current, tab, sym_at_col = g.root, 0, []
        for vtx in traversal.iter_mtg2(g, current):
            if filter and not filter(g, vtx):
                continue
            if vtx == current:
                sym_at_col.append(vtx)
                continue
            if current == g.complex(vtx):
                et = '/' if current == g.root else '^/'
            else:
                et, tab = self._place(vtx, tab, nb_tab, sym_at_col)
            if tab >= nb_tab:
                raise ValueError('There is not enough tabs to store the MTG code.\n'
                                 'Increase the nb_tab variable to at least %d' % (tab + 1))
            name = et + _label(labels.get(vtx, str(vtx)))
            if display_id and display_scale:
                name += '\t\t\t(id=%d, scale=%d)' % (vtx, g.scale(vtx))
            elif display_id:
                name += '\t\t\t(id=%d)' % vtx
            elif display_scale:
                name += '\t\t\t(scale=%d)' % g.scale(vtx)
            line = [''] * nb_tab
            line[tab] = name
            line += [str(properties[p][vtx]) if vtx in properties[p] else '' for p in property_names]
            head.append('\t'.join(line))
            current = vtx
            if len(sym_at_col) == tab:
                sym_at_col.append(vtx)
            else:
                sym_at_col = sym_at_col[:tab + 1]
                sym_at_col[tab] = vtx
        return head

    @staticmethod
    def _code(code='A'):
        return 'CODE :  \tFORM-%s' % (code if code in ['A', 'B'] else 'A')

    @staticmethod
    def _classes(symbols):
        klass = ['CLASSES :', '\t'.join(['SYMBOL', 'SCALE', 'DECOMPOSITION', 'INDEXATION', 'DEFINITION'])]
        default = dict(decomposition='FREE', indexation='FREE', definition='EXPLICIT')
        template = Template('\t'.join(['$symbol', '$scale', '$decomposition', '$indexation', '$definition']))
        klass.append(template.substitute(dict(default, symbol='$', scale='0', definition='IMPLICIT')))
        for sdict in symbols:
            klass.append(template.substitute(dict(default, **sdict)))
        return '\n'.join(klass)

    @staticmethod
    def _description(scale_symbol):
        desc = ['DESCRIPTION :', '\t'.join(['LEFT', 'RIGHT', 'RELTYPE', 'MAX'])]
        for scale in sorted(scale_symbol.keys()):
            symbols = scale_symbol[scale]
            for s in symbols:
                for edge_type in ['<', '+']:
                    desc.append('\t'.join([s, ','.join(symbols), edge_type, '?']))
        return '\n'.join(desc)

    @staticmethod
    def _features(name_type):
        features = ['FEATURES :', '\t'.join(['NAME', 'TYPE'])]
        for name, type_ in name_type:
            if type_ not in _FEATURE_TYPES:
                warn('The type %s for the feature %s is not allow' % (type_, name), SyntaxWarning)
                continue
            features.append('\t'.join([name, type_]))
        return '\n'.join(features)

    @staticmethod
    def _scale2symbol(scales):
        return [dict(scale=str(s), symbol=c) for s, classes in scales.items() for c in classes]


def write_mtg(g, properties=[], class_at_scale=None, nb_tab=None, display_id=False):
    """The MTG as the text of an MTG file: `properties` a list of (name, type) written as
    feature columns, `class_at_scale` each class's scale (by default from the labels)."""
    from .io import get_name
    w = Writer(g)
    if not class_at_scale:
        class_at_scale = dict((get_name(lab), g.scale(vid)) for vid, lab in g.property('label').items())
    scales = {}
    for class_, scale in class_at_scale.items():
        scales.setdefault(scale, []).append(class_)
    header = [w._code(), '', w._classes(w._scale2symbol(scales)), '', w._description(scales), '',
              w._features(properties), '']
    header += w.code([p[0] for p in properties], nb_tab=nb_tab, display_id=display_id,
                     filter=lambda g, v: g.scale(v) <= 4)
    header.append('')
    return '\n'.join(header)


def display(g, max_scale=0, display_id=True, display_scale=False, nb_tab=None, **kwds):
    """The MTG's code as text (MTG.display prints it)."""
    f = (lambda g, v: g.scale(v) <= max_scale) if max_scale else None
    code = Writer(g).code([], nb_tab=nb_tab, display_id=display_id, display_scale=display_scale, filter=f)
    return '\n'.join(code[2:])
