"""openalea.lpy's LsysContext, its options, the functions on the current context, plotting,
interpretation and the package's Python (issue 51), without the reference L-Py: the
differential cases of tests/reference/lpy_api_cases/context.py run here in Sprout, their results
compared with what the real L-Py gave for them (data/lpy_context_reference.json, written from the
reference; tests/reference/lpy_api.py compares the two live where the reference is built)."""
import importlib.util
import json
import os
import sys

import pytest

import sprout

sprout.use_as_openalea()

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE_TOOLS = os.path.join(HERE, '..', '..', 'tests', 'reference')
sys.path.insert(0, REFERENCE_TOOLS)
import lpy_api  # noqa: E402

sys.modules['lpy_api'] = lpy_api
_spec = importlib.util.spec_from_file_location('lpy_api_cases_context', os.path.join(REFERENCE_TOOLS, 'lpy_api_cases', 'context.py'))
CASES = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(CASES)
with open(os.path.join(HERE, 'data', 'lpy_context_reference.json')) as f:
    EXPECTED = {k: v for k, v in json.load(f).items() if not k.startswith('_')}


def test_every_case_has_the_reference_result():
    mine = {f.__name__ for name, covers, f in lpy_api._registered if f.__module__ == 'lpy_api_cases_context'}
    assert mine == set(EXPECTED)


@pytest.mark.parametrize('name', sorted(EXPECTED))
def test_case_gives_what_lpy_gives(name):
    try:
        got = {'value': lpy_api.canon(getattr(CASES, name)())}
    except Exception as e:  # a case may check the exception L-Py raises
        got = {'raises': type(e).__name__}
    assert lpy_api.case_agrees(EXPECTED[name], got), (EXPECTED[name], got)
