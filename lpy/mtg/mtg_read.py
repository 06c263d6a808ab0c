# openalea.mtg's Reader as Sprout provides it (openalea.mtg._read, gathered by
# openalea.mtg.io; lpy/README.md): an MTG file's header checked (CODE, CLASSES, DESCRIPTION,
# FEATURES) and its code, one vertex a line with tabs for branches and feature columns,
# rewritten as the brackets form that multiscale_edit builds the MTG from. Read from
# openalea.mtg's definition (src/openalea/mtg/io.py, CeCILL-C); what it finds wrong is
# printed as its warnings are, each with its line.

_DECOMPOSITIONS = ['NONE', 'FREE', 'CONNECTED', 'NOTCONNECTED', 'LINEAR', 'PURELINEAR', '<-LINEAR', '+-LINEAR']


class Reader(object):
    """An MTG text parsed: its header, then its code into the MTG."""

    def __init__(self, string, has_line_as_param=True, mtg=None, has_date=False, verbose=True):
        self.mtg = mtg
        self.txt = string
        self.lines = string.splitlines()
        self._code = ''
        self._symbols = {}
        self._description = None
        self._features = {}
        self.has_date = has_date
        self._no_line = 0
        self.warnings = []
        self.has_line_as_param = has_line_as_param
        self.verbose = verbose

    def parse(self):
        self.header()
        self.code()
        if self.verbose:
            self.errors()
        return self.mtg

    def header(self):
        self._no_line = -1
        self.code_form()
        self.classes()
        self.description()
        self.features()

    def check(self):
        return True

    def _warn(self, message):
        self.warnings.append((self._no_line, message))

    def code_form(self):
        """CODE : FORM-A or FORM-B."""
        code = self._next_line().split('#')[0].split(':')
        if len(code) == 2 and 'CODE' in code[0] and 'FORM-' in code[1]:
            self._code = code[1]
        else:
            self._warn('Code form error')

    def classes(self):
        """CLASSES: SYMBOL SCALE DECOMPOSITION INDEXATION DEFINITION, a class a line."""
        l = self._next_line()
        if not l.startswith('CLASSES'):
            self._warn('CLASSES section not found.')
        l = self._next_line().split('#')[0]
        if l.split() != ['SYMBOL', 'SCALE', 'DECOMPOSITION', 'INDEXATION', 'DEFINITION']:
            self._warn('CLASS header error.')
        while l:
            l = self._next_line()
            if l.startswith('DESCRIPTION'):
                break
            line = l.split('#')[0].split()
            if len(line) != 5:
                self._warn('CLASS error.')
                break
            symbol, scale, decomposition, indexation, definition = line
            if not symbol.isalpha() and symbol != '$':
                self._warn('Bad symbol %s.' % symbol)
            if not scale.isdigit():
                self._warn('Bad scale %s.' % scale)
            if decomposition not in _DECOMPOSITIONS:
                self._warn('Bad decomposition id %s.' % decomposition)
            if definition not in ['IMPLICIT', 'EXPLICIT']:
                self._warn('Bad definition %s.' % definition)
            if symbol != '$':
                if not scale.isdigit():
                    raise ValueError('MTG file, line %d: the scale of class %s is %r, not a number' % (self._no_line + 1, symbol, scale))
                self._symbols[symbol] = int(scale)
        if l.startswith('DESCRIPTION'):
            self._no_line -= 1

    def description(self):
        """DESCRIPTION: LEFT RIGHT RELTYPE MAX, the relations allowed (checked, not kept)."""
        if not self._next_line().startswith('DESCRIPTION'):
            self._warn('DESCRIPTION section not found.')
        l = self._next_line().split('#')[0]
        if l.split() != ['LEFT', 'RIGHT', 'RELTYPE', 'MAX']:
            self._warn('DESCRIPTION header error.')
        while l:
            l = self._next_line()
            if l.startswith('FEATURES'):
                break
            line = l.split('#')[0].split()
            if len(line) < 2:
                self._warn('Class description error.')
                continue
            if line[0] not in self._symbols:
                self._warn('Unknown left symbol %s.' % line[0])
            rights = [x.strip() for x in ''.join(line[1:-2]).split(',')]
            bad = [x for x in rights if x not in self._symbols]
            if bad:
                self._warn('Unknown right symbols %s.' % bad)
            reltype, _max = line[-2:]
            if reltype not in ['+', '<']:
                self._warn('Unknown relation type %s.' % reltype)
            if _max != '?' and not _max.isdigit():
                self._warn('Error in the maximum number of relationships (%s).Give a number or ?' % _max)
        if l.startswith('FEATURES'):
            self._no_line -= 1

    def features(self):
        """FEATURES: NAME TYPE, a feature a line (INT, REAL, ALPHA, a date)."""
        if not self._next_line().startswith('FEATURES'):
            self._warn('FEATURES section not found.')
        l = self._next_line().split('#')[0]
        if l.split() != ['NAME', 'TYPE']:
            self._warn('FEATURES header error.')
        while l:
            l = self._next_line()
            if not l or l.startswith('MTG'):
                break
            line = l.split('#')[0].split()
            if len(line) != 2:
                self._warn('FEATURE description error.')
                continue
            name, _type = line
            if '/' in _type and 'date' in name.lower():
                self.has_date = True
            self._features[name] = _type
        if l.startswith('MTG'):
            self._no_line -= 1
        if self.has_line_as_param:
            self._features['_line'] = 'INT'

    def _next_line(self):
        """The next line that is neither blank nor a comment ('' at the end)."""
        while True:
            self._no_line += 1
            if self._no_line >= len(self.lines):
                self._no_line = len(self.lines) - 1
                return ''
            l = self.lines[self._no_line]
            if l.strip() and l.strip()[0] != '#':
                return l

    def next_line_iter(self):
        l = self._next_line()
        while l:
            yield l
            l = self._next_line()

    def errors(self):
        for no, warning in self.warnings:
            if no < len(self.lines):
                print('== Line %d: %s' % (no, self.lines[no]))
                print(warning)
            else:
                print(no, ' ', warning)

    def code(self):
        """MTG: then ENTITY-CODE (or TOPO) and the feature columns, then the vertices."""
        if not self._next_line().startswith('MTG'):
            self._warn('MTG section not found.')
        l = self._next_line()
        if not l.startswith('ENTITY-CODE') and not l.startswith('TOPO'):
            self._warn('ENTITY-CODE or TOPO not found.')
        l = l.split('#')[0]
        features = l.split()[1:]
        self._nb_features = len(features)
        self._feature_head = []
        for feature in features:
            if feature not in self._features:
                self._warn('Error in ENTITY-CODE: Feature %s is unknown.' % feature)
            else:
                self._feature_head.append(feature)
        code_topo = l[:l.find(features[0])] if features else l
        nb_cols = len(code_topo.split('\t'))
        self._feature_slice = slice(nb_cols - 1, nb_cols - 1 + self._nb_features)
        self.preprocess_code()
        self.build_mtg()

    def preprocess_line(self, s, diff_space, indent, nb_spaces, edge_type):
        """One line's node with the brackets its indentation opens or closes."""
        if diff_space > 0:
            indent.append(nb_spaces)
            edge_type.append(s[0])
            return ('[' + s if s[0] in ['+', '/'] else s), edge_type
        brackets = []
        if diff_space < 0:
            while nb_spaces - indent[-1] < 0:
                indent.pop()
                if edge_type and edge_type.pop() in ['+', '/']:
                    brackets.append(']')
            if nb_spaces != indent[-1]:
                raise ValueError('MTG file, line %d: its indentation matches no line above' % (self._no_line + 1))
        if s.startswith('^') or (diff_space == 0 and s.startswith('*')):
            s = s[1:]
        elif edge_type:
            close = ']' if edge_type[-1] in ['+', '/'] else ''
            if s[0] in ['+', '/']:
                if close:
                    edge_type.pop()
                edge_type.append(s[0])
                s = close + '[' + s
        elif diff_space == 0 and s[0] == '+':
            edge_type.append(s[0])
        return ''.join(brackets + [s]), edge_type

    def preprocess_code(self):
        indent, edge_type, new_code = [0], [], []
        for l in self.next_line_iter():
            s = l.strip().split()[0]
            args = l.split('\t')[self._feature_slice]
            params = ['%s=%s' % (k, v) for k, v in zip(self._feature_head, args) if v.strip()]
            if self.has_line_as_param:
                params.append('_line=%d' % self._no_line)
            if params:
                s = s + '(' + ','.join(params) + ')'
            nb_spaces = len(l) - len(l.lstrip('\t'))
            s, edge_type = self.preprocess_line(s, nb_spaces - indent[-1], indent, nb_spaces, edge_type)
            new_code.append(s)
        while edge_type:
            if edge_type.pop() in ['+', '/']:
                new_code.append(']')
        self._new_code = ''.join(new_code)

    def build_mtg(self):
        from .io import multiscale_edit
        self.mtg = multiscale_edit(self._new_code, self._symbols, self._features, self.has_date, mtg=self.mtg)
