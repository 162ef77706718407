"""Scenes: one declarative scene per paper example, each in one file on the scene API
(``base``: ``Scene``, ``SceneResult``); ``analytic`` exposes the references of
``analytic/`` the same way (``ancf analytic NAME``); ``accuracy`` the per-scene
accuracy warnings; ``beam_static``, ``beam_dynamic`` and ``belt_common`` the builders
the scenes share; ``frames`` the deformed geometry of a finished run per output step and
``vtk`` its ParaView output (``--vtk``).

``SCENES`` is built on first use, so that importing ``ancf.scenes.base`` loads no
scene, solver or element.  The package is callable: ``ancf.scenes()`` is
:func:`catalogue`, the Python API's listing of the scenes and references.
"""
from __future__ import annotations

import sys
import types


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
    from ancf.scenes import (axial_bar, beam3d_cantilever, belt2d, belt3d, belt_free_static,
                             cantilever, pendulum, plate_square, plate_strip, simply_supported,
                             spinning_beam)
    scenes = {s.name: s for s in (simply_supported.SCENE, cantilever.SCENE, axial_bar.SCENE,
                                  pendulum.SCENE, spinning_beam.SCENE, belt_free_static.SCENE,
                                  belt2d.SCENE, plate_square.SCENE, plate_strip.SCENE,
                                  beam3d_cantilever.SCENE, belt3d.SCENE)}
    globals()["SCENES"] = scenes
    return scenes
