"""Scene registry: one declarative scene per paper example."""
from ancf.scenes import axial_bar, cantilever, simply_supported

SCENES = {s.name: s for s in (simply_supported.SCENE, cantilever.SCENE, axial_bar.SCENE)}
