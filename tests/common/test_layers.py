"""The layer rule (``ancf.common.layers``): every module belongs to a layer and imports
nothing from a layer above its own, at module level or inside a function; the
layout table of docs/architecture.md is the one generated from the tree."""
from __future__ import annotations

import pytest

from ancf.common import layers

FILES = layers.project_files()


def test_every_module_belongs_to_a_layer():
    orphans = [f for f in FILES if f not in layers.PACKAGE_FILES
               and layers.layer_of(layers.module_name(f)) is None]
    assert orphans == []


def test_no_module_imports_from_a_layer_above_its_own():
    found = [line for f in FILES for line in layers.upward_imports(f, (layers.ROOT / f).read_text())]
    assert found == [], "\n".join(found)


def test_the_package_init_imports_only_the_top_layer_lazily():
    for f in layers.PACKAGE_FILES:
        assert layers.package_init_violations((layers.ROOT / f).read_text()) == []


@pytest.mark.parametrize("source, bad", [
    ("import os\n", False),
    ("def __getattr__(name):\n    from ancf import api\n    return getattr(api, name)\n", False),
    ("def __getattr__(name):\n    import ancf.api\n", False),
    ("from ancf import api\n", True),                      # eager: every import pays for it
    ("import ancf.api\n", True),
    ("def __getattr__(name):\n    from ancf.scenes import SCENES\n", True),  # not the top layer
    ("def __getattr__(name):\n    from ancf.common import params\n", True),
    ("def helper():\n    from ancf import api\n", True),  # lazy, but not in __getattr__
    ("if True:\n    from ancf import cli\n", True),
])
def test_the_package_init_rule_can_fail(source, bad):
    assert bool(layers.package_init_violations(source)) is bad


@pytest.mark.parametrize("rel, source, bad", [
    ("ancf/core/mesh.py", "def f():\n    from ancf.scenes import SCENES\n", True),
    ("ancf/solvers/static.py", "from ancf.elements import green2d\n", True),
    ("ancf/solvers/static.py", "import ancf.belts.contact2d\n", True),
    ("analytic/bechtel.py", "from ancf.core.quadrature import gauss01\n", True),
    ("ancf/common/inputs.py", "from analytic import bechtel\n", True),
    ("ancf/belts/path.py", "from . import contact2d\nfrom ..core import mesh\n", False),
    ("ancf/belts/path.py", "from ..scenes import base\n", True),
    ("analytic/bechtel.py", "from ancf.common.params import Param\nimport ancf\n", False),
    ("ancf/cli.py", "from ancf.reports import output\n", False),
    ("ancf/api.py", "def f():\n    from ancf.study.sweep import run_sweep\n", False),
    ("ancf/scenes/vtk.py", "from ancf import api\n", True),
    ("ancf/study/sweep.py", "def f():\n    import ancf.api\n", True),
    ("ancf/__init__.py", "from ancf import api\n", True),
    ("ancf/__init__.py", "def __getattr__(name):\n    from ancf import api\n", False),
])
def test_the_rule_sees_upward_imports_at_any_depth(rel, source, bad):
    assert bool(layers.upward_imports(rel, source)) is bad


def test_the_architecture_layout_table_is_generated_from_the_tree():
    text = layers.PAGE.read_text()
    assert layers.BEGIN in text and layers.END in text
    assert text == layers.page_with_table(text), "run: python -m ancf.common.layers"


def test_the_checkout_folders_are_found_wherever_a_module_sits(monkeypatch):
    from ancf.common import paths
    from ancf.study import references
    monkeypatch.delenv("ANCF_CACHE", raising=False)
    assert (paths.REPO / "ancf" / "common" / "paths.py").is_file()
    assert (paths.REPORTS / "README.md").is_file()
    assert references.cache_root() == paths.REPORTS / ".cache"
