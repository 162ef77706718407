"""Scenes: one declarative scene per paper example, each in one file on the scene API
(``base``: ``Scene``, ``SceneResult``); ``analytic`` exposes the references of
``analytic/`` the same way (``ancf analytic NAME``); ``accuracy`` the per-scene
accuracy warnings; ``beam_static``, ``beam_dynamic`` and ``belt_common`` the builders
the scenes share; ``frames`` the deformed geometry of a finished run per output step and
``vtk`` its ParaView output (``--vtk``).

``SCENES`` is built on first use, so that importing ``ancf.scenes.base`` loads no
scene, solver or element.
"""
from __future__ import annotations


def __getattr__(name):
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
