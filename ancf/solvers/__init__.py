"""Numerics without physics: compiled band LU, solve and inertia (``banded``), the
linear-solver interface chosen from the pattern (``linear``), Newton with adaptive
load stepping (``static``), Newton on an energy (``minimize``), the lowest eigenpairs of
K phi = omega^2 M phi (``eigen``: dense, or shift-invert Lanczos on the band or sparse LU),
the equations of motion with scipy's integrators (``dynamics``) and generalised-alpha (``generalized_alpha``)
with its one compiled march (``alpha_march``), which serves every system whose
residual, factorisation and solve are registered for its record type
(``ancf.common.dispatch``): the beams' elimination form (``alpha_compiled``, its element
assembly from ``ancf.elements``), the belt drives (``ancf.belts.system``); the memory a model
would need, estimated before it is built (``cost``).
"""
