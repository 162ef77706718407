"""Numerics without physics: compiled band LU, solve and inertia (``banded``), the
linear-solver interface chosen from the pattern (``linear``), Newton with adaptive
load stepping (``static``), Newton on an energy (``minimize``), the equations of motion
with scipy's integrators (``dynamics``) and generalised-alpha, whose one compiled
march serves every system that registers its forces (beams in ``ancf.elements``,
belt drives in ``ancf.belts``).
"""
