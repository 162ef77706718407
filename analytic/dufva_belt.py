"""SymPy derivation of the strain-energy density of Dufva's belt element (thesis 3.1).

The element (``ancf.elements.dufva2d``) evaluates, at each Gauss point along its
axis, the energy per unit length (J/m) integrated in closed form over the
rectangular section, as a function of seven point variables

    a = r_c,x (2),  c = r_c,xx (2),  s = sin(gamma),  s_x = d sin(gamma)/dx (1/m),
    eps_yy (interpolated transverse strain),

and of six section-and-material coefficients ``k`` (N, N m^2, N m^4, N, N m^2, N).
The kinematics follow the thesis word for word: ``t = a/|a|`` (Eq. 3.4),
``r_s = (I + Ĩ s) Ĩ t`` (Eq. 3.10), ``r_s,x`` by differentiating ``r_s`` along x
(``t_x = dt/da c``), and the density is Eqs 3.18 + 3.19 + the transverse term of
Eq. 2.18 after the section integrals (``int y^2 dA = I2``, ``int y^4 dA = I4``)::

    w = k0 (a.a - 1)^2 + k1 ((a.r_s,x)^2 + 1/2 (a.a - 1) r_s,x.r_s,x) + k2 (r_s,x.r_s,x)^2
        + k3 (a.r_s)^2 + k4 (r_s,x.r_s)^2 + k5 eps_yy^2

with k0 = E alpha1 A/8, k1 = E alpha2 I2/2, k2 = E alpha2 I4/8, k3 = ks G alpha2 A/2,
k4 = ks G alpha2 I2/2, k5 = E A/2.  In the invariants ``P = a.a``,
``k = (a x c)/P`` (the rate of turn of t) the dot products reduce to
``a.r_s = -s sqrt(P)``, ``a.r_s,x = -sqrt(P) (k + s_x)``,
``r_s,x.r_s,x = (k + s_x)^2 + s^2 k^2`` and ``r_s,x.r_s = s s_x``
(:func:`density_invariant`; :func:`check` proves it equal to the vector form).

The nodal shear sine is ``s^K = -(r_x.r_y)/(|r_x| |r_y|)`` (:func:`nodal_shear_sine`).

The belt's strain-rate damping (``ancf.elements.dufva2d.damping_forces``) acts on two
strain measures of the same point variables (:func:`strain_measures`): the axial strain
``eps = sqrt(P) - 1`` (the stretch |r_x|/|r_o,x| less one of ``ancf.belts.strains``;
Exudyn's ANCFCable2D axial strain) and the bending strain ``kappa = k + s_x`` (the rate
of turn of the section r_s whose square the k1 term holds; Exudyn's curvature
``(r_x x r_xx)/|r_x|^2`` when the shear is zero).

Code generated into ``ancf/elements/_dufva_generated.py``
(``python -m analytic.dufva_belt --write``): numba functions for the value, the
gradient and the Hessian of ``w`` in the seven point variables and of ``s^K`` in
the four nodal slope components; a test checks that the committed file is up to date.
"""
from __future__ import annotations

from pathlib import Path

import sympy as sp

from analytic._codegen import emit, emit_with_derivatives, main, numba_header, sources, stamped

a0, a1, c0, c1, s, sx, ey = POINT = sp.symbols("a0 a1 c0 c1 s sx ey", real=True)
K = sp.symbols("k0:6", real=True)
NODAL = sp.symbols("rx0 rx1 ry0 ry1", real=True)
ITILDE = sp.Matrix([[0, -1], [1, 0]])  # Eq. 3.6


def density_vector():
    """w from the vectors of Eqs 3.4, 3.10, 3.18, 3.19 (a, c, s, s_x, eps_yy)."""
    a, c = sp.Matrix([a0, a1]), sp.Matrix([c0, c1])
    t = a / sp.sqrt(a.dot(a))                                  # Eq. 3.4
    r_s = (sp.eye(2) + ITILDE * s) * ITILDE * t                # Eq. 3.10
    r_sx = r_s.jacobian(a) * c + r_s.diff(s) * sx              # d r_s / dx
    P = a.dot(a)
    return (K[0] * (P - 1) ** 2 + K[1] * (a.dot(r_sx) ** 2 + (P - 1) * r_sx.dot(r_sx) / 2)
            + K[2] * r_sx.dot(r_sx) ** 2 + K[3] * a.dot(r_s) ** 2 + K[4] * r_s.dot(r_sx) ** 2
            + K[5] * ey**2)


def density_invariant():
    """The same density in the invariants P = a.a and k = (a x c)/P."""
    P = a0**2 + a1**2
    k = (a0 * c1 - a1 * c0) / P
    b = k + sx
    rsx2 = b**2 + s**2 * k**2
    return (K[0] * (P - 1) ** 2 + K[1] * (P * b**2 + (P - 1) * rsx2 / 2) + K[2] * rsx2**2
            + K[3] * s**2 * P + K[4] * s**2 * sx**2 + K[5] * ey**2)


def nodal_shear_sine():
    """s^K = -(r_x.r_y)/(|r_x| |r_y|) of a node's slopes (rx0, rx1, ry0, ry1)."""
    rx0, rx1, ry0, ry1 = NODAL
    return -(rx0 * ry0 + rx1 * ry1) / sp.sqrt((rx0**2 + rx1**2) * (ry0**2 + ry1**2))


def strain_measures():
    """(eps, kappa): the axial strain sqrt(P) - 1 and the bending strain k + s_x, 1/m."""
    P = a0**2 + a1**2
    return sp.sqrt(P) - 1, (a0 * c1 - a1 * c0) / P + sx


def check() -> None:
    """The invariant density equals the vector one (ValueError otherwise)."""
    diff = sp.simplify(density_vector() - density_invariant())
    if diff != 0:
        raise ValueError(f"invariant density differs from Eqs 3.18-3.19: {diff}")


# ----------------------------------------------------------------- code generation
def generate() -> str:
    """Text of ``ancf/elements/_dufva_generated.py``."""
    check()
    w, sk = density_invariant(), nodal_shear_sine()
    pargs = [str(v) for v in POINT] + ["k"]
    kk = {K[i]: sp.Symbol(f"k[{i}]") for i in range(6)}
    w = w.subs(kk)
    nargs = [str(v) for v in NODAL]
    lines = numba_header("Strain-energy density of the Dufva belt element and its nodal shear sine:",
                         "dufva_belt")
    point = "w (J/m) at (a0, a1, c0, c1, s, sx, ey) with coefficients k (6,)"
    lines += emit_with_derivatives("density", point, w, POINT, pargs)
    node = "s^K = -(r_x.r_y)/(|r_x| |r_y|) of (rx0, rx1, ry0, ry1)"
    lines += emit_with_derivatives("shear_sine", node, sk, NODAL, nargs)
    for name, m in zip(("axial_strain", "bending_strain"), strain_measures()):
        doc = f"{name.replace('_', ' ')} at (a0, a1, c0, c1, s, sx, ey)"
        lines += emit(f"{name}_grad", doc + "; gradient into grad (7,)", m, POINT, pargs[:-1], 1)
        lines += emit(f"{name}_hess", doc + "; gradient into grad (7,), Hessian into hess (7, 7)",
                      m, POINT, pargs[:-1], 2, f"{name}_grad")
    slopes, doc = POINT[:2], "axial strain at (a0, a1): its derivatives by the slopes alone"
    lines += emit("axial_slope_grad", doc + "; gradient into grad (2,)", strain_measures()[0],
                  slopes, ["a0", "a1"], 1)
    lines += emit("axial_slope_hess", doc + "; gradient into grad (2,), Hessian into hess (2, 2)",
                  strain_measures()[0], slopes, ["a0", "a1"], 2, "axial_slope_grad")
    return stamped("\n".join(lines).rstrip() + "\n", SOURCES)


TARGET = Path(__file__).resolve().parent.parent / "ancf" / "elements" / "_dufva_generated.py"
SOURCES = sources(__file__)  # what the generated text depends on (its stamp)


if __name__ == "__main__":
    raise SystemExit(main(generate, TARGET, __doc__.splitlines()[0]))
