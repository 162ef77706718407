"""Scenes: one declarative scene per paper example, each in one file on the scene API
(``base``: ``Scene``, ``SceneResult``); ``analytic`` exposes the references of
``analytic/`` the same way (``ancf analytic NAME``); ``accuracy`` the per-scene
accuracy warnings and ``sense`` the physical-sense checks (issue 22); ``beam_static``, ``beam_dynamic`` and ``belt_common`` the builders
the scenes share; ``beam3d_published`` the published data of the 3D beam benchmarks
(``princeton-beam``, ``beam3d-bending``); ``frames`` the deformed geometry of a finished
run per output step and ``vtk`` its ParaView output (``--vtk``); ``modes`` the natural
frequencies and mode shapes of the static scenes (``ancf modes NAME``).

``SCENES`` is built on first use, so that importing ``ancf.scenes.base`` loads no
scene, solver or element; :func:`scene` loads one scene's module only (``ancf run
NAME`` imports the kernels of that scene and no other); :data:`MODULES` names the
module of each scene, in the order of ``SCENES``.
The package is callable: ``ancf.scenes()`` is :func:`catalogue`, the Python API's
listing of the scenes and references.
"""
from __future__ import annotations

import importlib
import sys
import types

#: scene name -> its module below ancf.scenes (the order of SCENES)
MODULES = {"simply-supported": "simply_supported", "cantilever": "cantilever",
           "axial-bar": "axial_bar", "pendulum": "pendulum", "spinning-beam": "spinning_beam",
           "belt-free-static": "belt_free_static", "belt2d": "belt2d",
           "plate-square": "plate_square", "plate-strip": "plate_strip",
           "beam3d-cantilever": "beam3d_cantilever", "belt3d": "belt3d",
           "princeton-beam": "princeton_beam", "beam3d-bending": "beam3d_bending",
           "belt-drive": "belt_drive"}


def scene(name: str):
    """The Scene called ``name``, importing its module only (KeyError if unknown)."""
    return importlib.import_module(f"ancf.scenes.{MODULES[name]}").SCENE


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
    if name == "SCENES" and "SCENES" in globals():
        return globals()["SCENES"]
    if name != "SCENES":
        raise AttributeError(name)
    scenes = {n: scene(n) for n in MODULES}
    globals()["SCENES"] = scenes
    return scenes
