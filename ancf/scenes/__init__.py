"""Scenes: one declarative scene per paper example, each in one file on the scene API
(``base``: ``Scene``, ``SceneResult``); ``analytic`` exposes the references of
``analytic/`` the same way (``ancf analytic NAME``); ``accuracy`` the per-scene
accuracy warnings; ``beam_static``, ``beam_dynamic`` and ``belt_common`` the builders
the scenes share.

``SCENES`` is built on first use, so that importing ``ancf.scenes.base`` loads no
scene, solver or element; :func:`scene` loads one scene's module only (``ancf run
NAME`` imports the kernels of that scene and no other); :data:`MODULES` names the
module of each scene, in the order of ``SCENES``.
"""
from __future__ import annotations

import importlib

#: scene name -> its module below ancf.scenes (the order of SCENES)
MODULES = {"simply-supported": "simply_supported", "cantilever": "cantilever",
           "axial-bar": "axial_bar", "pendulum": "pendulum", "spinning-beam": "spinning_beam",
           "belt-free-static": "belt_free_static", "belt2d": "belt2d",
           "plate-square": "plate_square", "plate-strip": "plate_strip",
           "beam3d-cantilever": "beam3d_cantilever", "belt3d": "belt3d"}


def scene(name: str):
    """The Scene called ``name``, importing its module only (KeyError if unknown)."""
    return importlib.import_module(f"ancf.scenes.{MODULES[name]}").SCENE


def __getattr__(name):
    if name != "SCENES":
        raise AttributeError(name)
    scenes = {n: scene(n) for n in MODULES}
    globals()["SCENES"] = scenes
    return scenes
