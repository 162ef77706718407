"""Scene registry: one declarative scene per paper example."""
from ancf.scenes import axial_bar, cantilever, pendulum, simply_supported, spinning_beam

SCENES = {s.name: s for s in (simply_supported.SCENE, cantilever.SCENE, axial_bar.SCENE,
                              pendulum.SCENE, spinning_beam.SCENE)}
