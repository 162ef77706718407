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

Code generated into ``ancf/elements/_dufva_generated.py``
(``python -m analytic.dufva_belt --write``): numba functions for the value, the
gradient and the Hessian of ``w`` in the seven point variables and of ``s^K`` in
the four nodal slope components; a test checks that the committed file is up to date.
"""
from __future__ import annotations

import argparse
from pathlib import Path

import sympy as sp

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


def check() -> None:
    """The invariant density equals the vector one (ValueError otherwise)."""
    diff = sp.simplify(density_vector() - density_invariant())
    if diff != 0:
        raise ValueError(f"invariant density differs from Eqs 3.18-3.19: {diff}")


# ----------------------------------------------------------------- code generation
def _emit(name, doc, expr, variables, args, order, first=None):
    """Lines of a numba function returning expr and, by order, its gradient into ``grad``
    and its Hessian into ``hess``.  A Hessian function takes value and gradient from
    the gradient function ``first`` so that both give bit-identical gradients."""
    n = len(variables)
    if order == 2:
        outs = [expr.diff(variables[i], variables[j]) for i in range(n) for j in range(i, n)]
    else:
        outs = [expr] + [expr.diff(v) for v in variables] * order
    subs, red = sp.cse(outs, symbols=sp.numbered_symbols("x"), optimizations="basic")
    sig = ", ".join(args + ["grad"] * (order >= 1) + ["hess"] * (order >= 2))
    lines = ["@njit(cache=True)", f"def {name}({sig}):", f'    """{doc}"""']
    if order == 2:
        lines.append(f"    value = {first}({', '.join(args)}, grad)")
    lines += [f"    {sym} = {sp.pycode(e)}" for sym, e in subs]
    if order == 2:
        it = iter(red)
        for i in range(n):
            for j in range(i, n):
                e = sp.pycode(next(it))
                lines.append(f"    hess[{i}, {j}] = {e}" if i == j else
                             f"    hess[{i}, {j}] = hess[{j}, {i}] = {e}")
        return lines + ["    return value", "", ""]
    lines += [f"    grad[{i}] = {sp.pycode(e)}" for i, e in enumerate(red[1:])]
    return lines + [f"    return {sp.pycode(red[0])}", "", ""]


def generate() -> str:
    """Text of ``ancf/elements/_dufva_generated.py``."""
    check()
    w, sk = density_invariant(), nodal_shear_sine()
    pargs = [str(v) for v in POINT] + ["k"]
    kk = {K[i]: sp.Symbol(f"k[{i}]") for i in range(6)}
    w = w.subs(kk)
    nargs = [str(v) for v in NODAL]
    lines = ['"""Strain-energy density of the Dufva belt element and its nodal shear sine:',
             "GENERATED by ``python -m analytic.dufva_belt --write`` from the SymPy derivation",
             'in ``analytic/dufva_belt.py``. Do not edit by hand."""', "",
             "import math", "",
             "from numba import njit", "", ""]
    point = "w (J/m) at (a0, a1, c0, c1, s, sx, ey) with coefficients k (6,)"
    lines += _emit("density", point, w, POINT, pargs, 0)
    lines += _emit("density_grad", point + "; gradient into grad (7,)", w, POINT, pargs, 1)
    lines += _emit("density_hess", point + "; gradient into grad (7,), Hessian into hess (7, 7)",
                   w, POINT, pargs, 2, "density_grad")
    node = "s^K = -(r_x.r_y)/(|r_x| |r_y|) of (rx0, rx1, ry0, ry1)"
    lines += _emit("shear_sine", node, sk, NODAL, nargs, 0)
    lines += _emit("shear_sine_grad", node + "; gradient into grad (4,)", sk, NODAL, nargs, 1)
    lines += _emit("shear_sine_hess", node + "; gradient into grad (4,), Hessian into hess (4, 4)",
                   sk, NODAL, nargs, 2, "shear_sine_grad")
    return "\n".join(lines).rstrip() + "\n"


TARGET = Path(__file__).resolve().parent.parent / "ancf" / "elements" / "_dufva_generated.py"


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--write", action="store_true", help=f"write {TARGET.name}")
    args = p.parse_args(argv)
    text = generate()
    if args.write:
        TARGET.write_text(text)
        print(f"wrote {TARGET}")
    else:
        print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
