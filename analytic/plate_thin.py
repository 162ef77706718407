"""SymPy derivation of the strain-energy density of the thin ANCF plate (thesis 4.3).

The element (``ancf.elements.plate36``) evaluates, at each Gauss point of its mid
surface, the energy per unit area (J/m^2) as a function of fifteen point variables

    r_x, r_y (3 each, -), r_xx, r_xy, r_yy (3 each, 1/m),

and of three material coefficients ``k = (E h / (2 (1 - nu^2)) (N/m), D / 2 (N m),
nu (-))`` with ``D = E h^3 / (12 (1 - nu^2))`` (the element's choice; the
thesis prints ``E h^3 / 12``).

Membrane part, Eq. 4.16, from the mid-surface Green strains of a reference that is
flat and aligned with the local axes (``r_x = e_x``, ``r_y = e_y``)::

    eps_xx = (r_x.r_x - 1)/2,  eps_yy = (r_y.r_y - 1)/2,  gamma_xy = r_x.r_y,
    w_m = k0 ((eps_xx + eps_yy)^2 - 2 (1 - nu) (eps_xx eps_yy - gamma_xy^2 / 4)).

The printed Eq. 4.16 puts the square outside the bracket and writes ``eps_xy/4``;
it is read here as the plane-stress energy, ``gamma_xy`` the engineering shear
strain (then w_m = E h / (2 (1 - nu^2)) (eps_xx^2 + eps_yy^2 + 2 nu eps_xx eps_yy
+ (1 - nu)/2 gamma_xy^2), :func:`check`).

Bending part, Eqs 4.17-4.18, with ``n = r_x x r_y``::

    kappa_ij = r_ij.n / (|n| |r_i| |r_j|),
    w_b = k1 ((kappa_xx + kappa_yy)^2 - 2 (1 - nu) (kappa_xx kappa_yy - kappa_xy^2)).

Code generated into ``ancf/elements/_plate_generated.py``
(``python -m analytic.plate_thin --write``): numba functions for the value, the
gradient and the Hessian of ``w_m`` in (r_x, r_y) and of ``w_b`` in all fifteen
variables; a test checks that the committed file is up to date.
"""
from __future__ import annotations

from pathlib import Path

import sympy as sp

from analytic._codegen import emit_with_derivatives, main, numba_header, sources, stamped

RX = sp.symbols("rx0:3", real=True)
RY = sp.symbols("ry0:3", real=True)
RXX = sp.symbols("rxx0:3", real=True)
RXY = sp.symbols("rxy0:3", real=True)
RYY = sp.symbols("ryy0:3", real=True)
MEMBRANE = RX + RY
POINT = RX + RY + RXX + RXY + RYY
K = sp.symbols("k0:3", real=True)


def membrane_density():
    """w_m (J/m^2), Eq. 4.16 read as the plane-stress energy of the Green strains."""
    rx, ry = sp.Matrix(RX), sp.Matrix(RY)
    exx, eyy, gxy = (rx.dot(rx) - 1) / 2, (ry.dot(ry) - 1) / 2, rx.dot(ry)
    return K[0] * ((exx + eyy) ** 2 - 2 * (1 - K[2]) * (exx * eyy - gxy**2 / 4))


def curvatures():
    """kappa_xx, kappa_yy, kappa_xy (1/m), Eq. 4.18."""
    rx, ry = sp.Matrix(RX), sp.Matrix(RY)
    n = rx.cross(ry)
    nn, lx, ly = (sp.sqrt(v.dot(v)) for v in (n, rx, ry))
    return (sp.Matrix(RXX).dot(n) / (nn * lx * lx), sp.Matrix(RYY).dot(n) / (nn * ly * ly),
            sp.Matrix(RXY).dot(n) / (nn * lx * ly))


def bending_density():
    """w_b (J/m^2), Eq. 4.17."""
    kxx, kyy, kxy = curvatures()
    return K[1] * ((kxx + kyy) ** 2 - 2 * (1 - K[2]) * (kxx * kyy - kxy**2))


def check() -> None:
    """w_m equals the plane-stress form in the strains (ValueError otherwise)."""
    rx, ry = sp.Matrix(RX), sp.Matrix(RY)
    exx, eyy, gxy = (rx.dot(rx) - 1) / 2, (ry.dot(ry) - 1) / 2, rx.dot(ry)
    nu = K[2]
    plane = K[0] * (exx**2 + eyy**2 + 2 * nu * exx * eyy + (1 - nu) / 2 * gxy**2)
    diff = sp.expand(membrane_density() - plane)
    if diff != 0:
        raise ValueError(f"membrane density is not the plane-stress energy: {diff}")


def generate() -> str:
    """Text of ``ancf/elements/_plate_generated.py``."""
    check()
    kk = {K[i]: sp.Symbol(f"k[{i}]") for i in range(3)}
    wm, wb = membrane_density().subs(kk), bending_density().subs(kk)
    margs = [str(v) for v in MEMBRANE] + ["k"]
    bargs = [str(v) for v in POINT] + ["k"]
    lines = numba_header("Strain-energy density of the thin ANCF plate (membrane and bending):",
                         "plate_thin")
    mdoc = "w_m (J/m^2) at (r_x, r_y) with coefficients k (3,)"
    lines += emit_with_derivatives("membrane", mdoc, wm, MEMBRANE, margs)
    bdoc = "w_b (J/m^2) at (r_x, r_y, r_xx, r_xy, r_yy) with coefficients k (3,)"
    lines += emit_with_derivatives("bending", bdoc, wb, POINT, bargs)
    return stamped("\n".join(lines).rstrip() + "\n", SOURCES)


TARGET = Path(__file__).resolve().parent.parent / "ancf" / "elements" / "_plate_generated.py"
SOURCES = sources(__file__)  # what the generated text depends on (its stamp)


if __name__ == "__main__":
    raise SystemExit(main(generate, TARGET, __doc__.splitlines()[0]))
