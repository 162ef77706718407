"""A scene describes itself: the scene list, the result keys and the study specs are
collected from the scene files (``ORDER``, ``SCENE``, ``results``, ``study``), and the
analytic references from their own files."""
from __future__ import annotations

import pytest

import ancf.scenes as scenes
from ancf.scenes.analytic import DYNAMIC_REFERENCES, REFERENCES
from ancf.common.paths import declared


def test_declared_lists_the_files_that_declare_a_place_in_their_order(tmp_path):
    (tmp_path / "late.py").write_text("ORDER = 20\nSCENE = Scene()\n")
    (tmp_path / "early.py").write_text('"""doc"""\nORDER = 10\n')
    (tmp_path / "helper.py").write_text("X = 1  # ORDER = 5 in a comment is no declaration\n")
    (tmp_path / "freq.py").write_text("ORDER = 30\nFREQUENCY_ORDER = 1\n")
    assert list(declared(tmp_path).items()) == [("early", 10), ("late", 20), ("freq", 30)]
    assert declared(tmp_path, "FREQUENCY_ORDER") == {"freq": 1}


@pytest.mark.parametrize("name, module", [
    ("axial-bar", "axial_bar"), ("belt-drive", "belt_drive"), ("axial_bar", None),
    ("base", None), ("spec", None), ("nope", None), ("../base", None), (3, None)])
def test_a_name_finds_its_module_by_the_naming_convention(name, module):
    assert scenes.module_of(name) == module


def test_every_scene_declares_its_results_and_its_study():
    for name, sc in scenes.SCENES.items():
        assert sc.results, name
        assert sc.study is not None and sc.study().scene == name
        assert all(set(f) == {"kind", "doc", "nullable", "required", "items", "keys"}
                   for f in sc.results.values()), name


def test_every_reference_declares_its_results():
    assert list(REFERENCES)[:2] == ["timoshenko", "reissner"]
    assert set(DYNAMIC_REFERENCES) == {"spinning-extension", "rigid-pendulum"}
    assert all(ref.results for ref in REFERENCES.values())
