"""SymPy derivation of the strain-energy density of Dufva's 3D belt element (thesis 4.4).

The element (``ancf.elements.belt3d``) evaluates, at each Gauss point along its
axis, the energy per unit length (J/m) integrated in closed form over the
rectangular section.  To keep the generated code small the derivation is split
in two generated pieces that the element chains (gradient and Hessian by the
chain rule):

* the section kinematics of one direction d = y or z (Eqs 4.28-4.31, 4.38-4.39 as
  read in ``ancf/elements/belt3d.py``): from ``a = r_c,x``, ``c = r_c,xx``, the
  section slope ``p = r_d`` and ``p_x = r_d,x`` on the centre line, the shear sine
  ``s`` and ``s_x = ds/dx`` (14 inputs), the vectors
  ``r_s = (unit part of p normal to t) - s t`` with ``t = a/|a|`` and
  ``r_s,x = d r_s/dx`` (chain rule through a, p, s);
* the density ``w`` in 18 variables ``a``, ``r_s^y``, ``u = r_s,x^y``, ``r_s^z``,
  ``v = r_s,x^z``, ``eps_yy``, ``eps_zz``, ``eps_yz`` with eleven coefficients ``k``:
  E alpha1, E alpha2, ks G alpha2, E, G (Pa) and the section moments A, int y^2,
  int z^2, int y^4, int z^4, int y^2 z^2 dA.  With ``D = a.a - 1``,
  ``r_x = a + y u + z v`` and ``r_x.r_x - 1 = D + Q`` (Q the y, z-dependent part)::

    w = E alpha1/8 A D^2 + E alpha2/8 int (2 D Q + Q^2) dA
        + ks G alpha2/2 int ((r_x.r_s^y)^2 + (r_x.r_s^z)^2) dA
        + E A/2 (eps_yy^2 + eps_zz^2) + 2 G A eps_yz^2,

  so that alpha1 = alpha2 = 1 is the plain Green-strain energy of Eq. 4.34 on the
  field ``r = r_c + y r_s^y + z r_s^z`` (4.37).  The section integrals map the
  monomials ``y^i z^j`` to the section moments (odd ones vanish: centroidal
  principal axes).

The nodal shear sine is ``s^K = -(r_x.r_d)/(|r_x| |r_d|)``, d = y or z
(:func:`nodal_shear_sine`).

Code generated into ``ancf/elements/_belt3d_generated.py``
(``python -m analytic.belt3d --write``): numba functions for the value, the
gradient and the Hessian of ``w``, of each component of ``r_s`` and ``r_s,x`` and
of ``s^K``; a test checks that the committed file is up to date.
"""
from __future__ import annotations

from pathlib import Path

import sympy as sp

from analytic._codegen import emit_with_derivatives, main, numba_header, sources, stamped

# kinematics of one section direction d = y or z: (a, c, p, p_x, s, s_x) -> (r_s, r_s,x)
_A = sp.symbols("a0:3", real=True)
_C = sp.symbols("c0:3", real=True)
_P = sp.symbols("p0:3", real=True)
_PX = sp.symbols("px0:3", real=True)
s, sx = sp.symbols("s sx", real=True)
KIN = _A + _C + _P + _PX + (s, sx)
# the density's variables: a, r_s^y, r_s,x^y (= u), r_s^z, r_s,x^z (= v), nodal strains
_VEC = sp.symbols("a0:3 ry0:3 u0:3 rz0:3 v0:3", real=True)
eyy, ezz, eyz = sp.symbols("eyy ezz eyz", real=True)
VARS = _VEC + (eyy, ezz, eyz)
K = sp.symbols("k0:11", real=True)  # E a1, E a2, ks G a2, E, G, A, Y2, Z2, Y4, Z4, Y2Z2
NODAL = sp.symbols("rx0 rx1 rx2 rd0 rd1 rd2", real=True)
y, z = sp.symbols("y z", real=True)


def section_vector_x():
    """(r_s, r_s,x) of one direction: r_s = (unit part of p normal to t) - s t, t = a/|a|
    (Eqs 4.28-4.31, 4.38-4.39 as read; r_s^y with p = r_y, s = s^y, r_s^z with
    p = r_z, s = s^z), written in the invariants P = a.a, m = a.p, n = p.p:
    w = p - (m/P) a, N = w.w = n - m^2/P, r_s = w/sqrt(N) - s a/sqrt(P), and
    r_s,x = d r_s/dx with a_x = c, p_x, s_x (compact; :func:`section_vector_x_chain`
    is the same by the chain rule on the vectors)."""
    a, c, p, px = (sp.Matrix(v) for v in (_A, _C, _P, _PX))
    P, m, n = a.dot(a), a.dot(p), p.dot(p)
    dP, dm, dn = 2 * a.dot(c), c.dot(p) + a.dot(px), 2 * p.dot(px)
    N = n - m**2 / P
    dN = dn - 2 * m * dm / P + m**2 * dP / P**2
    w = p - m / P * a
    wx = px - (dm / P - m * dP / P**2) * a - m / P * c
    rs = w / sp.sqrt(N) - s * a / sp.sqrt(P)
    rsx = (wx / sp.sqrt(N) - w * dN / (2 * N ** sp.Rational(3, 2)) - sx * a / sp.sqrt(P)
           - s * (c / sp.sqrt(P) - a * dP / (2 * P ** sp.Rational(3, 2))))
    return rs, rsx


def section_vector_x_chain():
    """(r_s, r_s,x) from the vectors: t = a/|a|, r_s = w/|w| - s t with w = p - (t.p) t,
    r_s,x by the chain rule through a, p, s (large expressions: for checks only)."""
    a, p = sp.Matrix(_A), sp.Matrix(_P)
    t = a / sp.sqrt(a.dot(a))
    w = p - t.dot(p) * t
    rs = w / sp.sqrt(w.dot(w)) - s * t
    rsx = rs.jacobian(a) * sp.Matrix(_C) + rs.jacobian(p) * sp.Matrix(_PX)
    return rs, rsx + rs.diff(s) * sx


_MOMENT = {(0, 0): 5, (2, 0): 6, (0, 2): 7, (4, 0): 8, (0, 4): 9, (2, 2): 10}


def integrate_section(expr):
    """int expr dA over a centroidal rectangle for a polynomial in y, z (moments K[5:])."""
    poly = sp.Poly(sp.expand(expr), y, z)
    out = 0
    for (i, j), coef in poly.terms():
        if i % 2 or j % 2:
            continue
        out += coef * K[_MOMENT[(i, j)]]
    return out


def density():
    """w (J/m) in the variables VARS; see the module docstring."""
    a, ry, u, rz, v = (sp.Matrix(_VEC[3 * i: 3 * i + 3]) for i in range(5))
    D = a.dot(a) - 1
    Q = 2 * y * a.dot(u) + 2 * z * a.dot(v) + y**2 * u.dot(u) + 2 * y * z * u.dot(v) + z**2 * v.dot(v)
    r_x = a + y * u + z * v
    bend = integrate_section(2 * D * Q + Q**2)
    shear = integrate_section(r_x.dot(ry) ** 2 + r_x.dot(rz) ** 2)
    return (K[0] / 8 * K[5] * D**2 + K[1] / 8 * bend + K[2] / 2 * shear
            + K[3] / 2 * K[5] * (eyy**2 + ezz**2) + 2 * K[4] * K[5] * eyz**2)


def nodal_shear_sine():
    """s^K = -(r_x.r_d)/(|r_x| |r_d|) of a node's slopes (rx0..2, rd0..2)."""
    rx, rd = sp.Matrix(NODAL[:3]), sp.Matrix(NODAL[3:])
    return -rx.dot(rd) / sp.sqrt(rx.dot(rx) * rd.dot(rd))


# ----------------------------------------------------------------- code generation
def generate() -> str:
    """Text of ``ancf/elements/_belt3d_generated.py``."""
    w = density().subs({K[i]: sp.Symbol(f"k[{i}]") for i in range(len(K))})
    lines = numba_header("Strain-energy density of the 3D Dufva belt element, its section "
                         "vectors and nodal shear sine:", "belt3d")
    lines += emit_with_derivatives("density", "w (J/m) at (a, r_s^y, r_s,x^y, r_s^z, r_s,x^z, eyy, "
                                   "ezz, eyz), k (11,)", w, VARS, [str(v) for v in VARS] + ["k"])
    rs, rsx = section_vector_x()
    kargs = [str(v) for v in KIN]
    for name, vec in (("section_vector", rs), ("section_vector_x", rsx)):
        for i in range(3):
            lines += emit_with_derivatives(f"{name}{i}", f"component {i} of {name.replace('_x', ',x')} "
                                           "at (a, c, p, px, s, sx)", vec[i], KIN, kargs)
    node = "s^K = -(r_x.r_d)/(|r_x| |r_d|) of (rx0, rx1, rx2, rd0, rd1, rd2)"
    lines += emit_with_derivatives("shear_sine", node, nodal_shear_sine(), NODAL,
                                   [str(v) for v in NODAL])
    return stamped("\n".join(lines).rstrip() + "\n", SOURCES)


TARGET = Path(__file__).resolve().parent.parent / "ancf" / "elements" / "_belt3d_generated.py"
SOURCES = sources(__file__)  # what the generated text depends on (its stamp)


if __name__ == "__main__":
    raise SystemExit(main(generate, TARGET, __doc__.splitlines()[0]))
