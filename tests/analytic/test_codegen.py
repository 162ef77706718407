"""The generated modules' stamps (analytic/_codegen.py): each generated module ends with
the SHA-256 of its generator's sources, the SymPy version and its own text, so that a hand
edit or a generator changed without ``--write`` fails here in milliseconds.

The full regeneration (``generate() == TARGET.read_text()``, 10-60 s per module) stays in
each element's test file, marked ``REGENERATE``: it runs with ``ANCF_REGENERATE=1``.  Since
``generate()`` returns the stamped text, the regeneration also checks the stamp; the
stamp can only match if the text was written by the same generator sources under the
same SymPy version, so the stamp test proves what the regeneration proved as long as the
SymPy derivation is deterministic (it is: regenerating reproduces the committed text).
"""
from __future__ import annotations

import os
import shutil

import pytest
import sympy as sp

from analytic import _codegen, belt3d, dufva_belt, plate_thin, shape_functions

GENERATORS = (shape_functions, dufva_belt, plate_thin, belt3d)
REGENERATE = pytest.mark.skipif(
    not os.environ.get("ANCF_REGENERATE"),
    reason="SymPy regeneration: set ANCF_REGENERATE=1 (the stamp test in "
           "tests/analytic/test_codegen.py proves the module up to date)")


def _ids(module):
    return module.__name__.rsplit(".", 1)[-1]


@pytest.mark.parametrize("gen", GENERATORS, ids=_ids)
def test_generated_module_carries_its_generators_stamp(gen):
    assert _codegen.stamp_ok(gen.TARGET, gen.SOURCES), (
        f"{gen.TARGET.name} is stale or edited by hand: run "
        f"`python -m {gen.__name__} --write`")


def _copies(gen, tmp_path):
    """Copies of the generated module and of the generator's sources under tmp_path."""
    target = tmp_path / gen.TARGET.name
    shutil.copy(gen.TARGET, target)
    srcs = []
    for i, src in enumerate(gen.SOURCES):
        (tmp_path / str(i)).mkdir()
        srcs.append(tmp_path / str(i) / src.name)
        shutil.copy(src, srcs[-1])
    return target, srcs


@pytest.mark.parametrize("gen", GENERATORS, ids=_ids)
def test_stamp_fails_on_a_hand_edit_a_stale_generator_or_another_sympy(gen, tmp_path,
                                                                       monkeypatch):
    """On copies: the untouched copy passes; one character of the body changed, one
    comment added to either source file, or another SymPy version each fail it."""
    target, srcs = _copies(gen, tmp_path)
    assert _codegen.stamp_ok(target, srcs)
    text = target.read_text()
    i = text.index("= ", text.index("def ")) + 2          # first assignment of the body
    target.write_text(text[:i] + "-" + text[i:])
    assert not _codegen.stamp_ok(target, srcs)
    target.write_text(text)
    for src in srcs:
        original = src.read_text()
        src.write_text(original + "# a change without --write\n")
        assert not _codegen.stamp_ok(target, srcs)
        src.write_text(original)
    assert _codegen.stamp_ok(target, srcs)
    monkeypatch.setattr(sp, "__version__", sp.__version__ + ".post1")
    assert not _codegen.stamp_ok(target, srcs)


def test_stamp_fails_when_the_stamp_line_is_missing_or_not_last(tmp_path):
    """Without its stamp line, or with text after it, a module fails the check."""
    target, srcs = _copies(shape_functions, tmp_path)
    text = target.read_text()
    body, _, last = text.rstrip("\n").rpartition("\n")
    target.write_text(body + "\n")
    assert not _codegen.stamp_ok(target, srcs)
    target.write_text(text + "x = 1\n")
    assert not _codegen.stamp_ok(target, srcs)
