"""Scenes: one declarative scene per paper example, each in one file on the scene API
(``base``: ``Scene``, ``SceneResult``, result keys) with its references, errors and
grids (``spec``: ``SceneSpec``, ``Reference``); ``analytic/`` exposes the references of
``analytic/`` the same way, one file each (``ancf analytic NAME``); ``accuracy`` the per-scene
accuracy warnings and ``sense`` the physical-sense checks (issue 22); ``beam_static``, ``beam_dynamic`` and ``belt_common`` the builders
the scenes share; ``beam3d_published`` the published data of the 3D beam benchmarks
(``princeton-beam``, ``beam3d-bending``); ``frames`` the deformed geometry of a finished
run per output step and ``vtk`` its ParaView output (``--vtk``); ``modes`` the natural
frequencies and mode shapes of the static scenes (``ancf modes NAME``); ``belt_steady`` a
drive file's steady running state (``ancf steady belt-drive``).

A scene is one module ``ancf/scenes/<name with _ for ->.py`` that declares ``SCENE =
Scene(...)`` and its place in the scene list, ``ORDER = <int>`` (``ancf scenes``,
``SCENES``, ``reports/schemas.md``); its results, references, errors and grids are
declared in the same file (:mod:`ancf.scenes.base`, :mod:`ancf.scenes.spec`), and the
study layer collects them from ``SCENES``.  Adding a scene is adding its file.

``SCENES`` and :data:`MODULES` are built on first use, so that importing
``ancf.scenes.base`` loads no scene, solver or element; :data:`MODULES` names the module
of each scene, in the order of ``SCENES``, from a listing of this folder's files that
declare an ``ORDER`` (no scene imported); :func:`scene` loads one scene's module only
(``ancf run NAME`` imports the kernels of that scene and no other, and reads no other
scene's file).
The package is callable: ``ancf.scenes()`` is :func:`catalogue`, the Python API's
listing of the scenes and references.
"""
from __future__ import annotations

import importlib
import re
import sys
import types
from pathlib import Path

#: this folder: the scene modules
FOLDER = Path(__file__).parent


def module_of(name) -> str | None:
    """The module of the scene called ``name``: the one named after it (``-`` as ``_``)
    if that declares an ``ORDER``, else None; reads that file only."""
    module = name.replace("-", "_") if isinstance(name, str) else ""
    path = FOLDER / f"{module}.py"
    if not module.isidentifier() or "_" in name or not path.is_file():
        return None
    return module if re.search(r"^ORDER = \d+", path.read_text(), flags=re.M) else None


def scene(name: str):
    """The Scene called ``name``, importing its module only (KeyError if unknown)."""
    module = module_of(name)
    if module is None:
        raise KeyError(name)
    return importlib.import_module(f"ancf.scenes.{module}").SCENE


def catalogue() -> list[dict]:
    """Every scene (``command`` ``"run"``) and analytic reference (``"analytic"``) with its
    one-line description and parameters ``{name: {default, depends_on_others, unit,
    allowed, doc}}`` (``default`` is None where it depends on other parameters), as
    ``ancf scenes`` lists them."""
    from ancf.scenes.analytic import REFERENCES
    out = []
    for command, registry in (("run", __getattr__("SCENES")), ("analytic", REFERENCES)):
        for name, sc in registry.items():
            out.append({"command": command, "name": name, "doc": sc.doc, "params": {
                p.name: {"default": None if callable(p.default) else p.default,
                         "depends_on_others": callable(p.default), "unit": p.unit,
                         "allowed": p.allowed(), "doc": p.doc} for p in sc.params}})
    return out


class _CallablePackage(types.ModuleType):
    """The package ``ancf.scenes``, callable: ``ancf.scenes()`` lists the scenes
    (:func:`catalogue`), so the name serves both the package and the Python API."""

    def __call__(self) -> list[dict]:
        return catalogue()


sys.modules[__name__].__class__ = _CallablePackage


def __getattr__(name):
    if name not in ("SCENES", "MODULES"):
        raise AttributeError(name)
    if name == "MODULES":
        #: scene name -> its module below ancf.scenes (the order of SCENES)
        from ancf.common.paths import declared
        value = {module.replace("_", "-"): module for module in declared(FOLDER)}
    else:
        value = {n: scene(n) for n in __getattr__("MODULES")}
    globals()[name] = value
    return value
