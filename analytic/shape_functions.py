"""SymPy derivation of ANCF shape functions and exact mass integrals.

Every element family is declared by its polynomial displacement field (a list of
monomials in the local coordinates x, y[, z]) and its nodal coordinates (a node
position plus the derivative taken there: none for the position ``r``, ``x`` for
the slope ``dr/dx`` ...).  Requiring ``r = S e`` to reproduce each nodal
coordinate gives a square linear system for the polynomial coefficients; its
inverse yields the scalar shape functions ``S_k``, so that ``S = [S_1 I, S_2 I, ...]``.

Families (thesis equation numbers):

* ``linear2d``     Eqs 2.10-2.12 (Kerkkänen linear beam, 8 DOF)
* ``cubic2d``      Eqs 2.2-2.3 (Omar-Shabana, 12 DOF) = Eq. 3.11 (Dufva belt element)
* ``linear3d``     Eq. 4.22 (3D linear beam, 18 DOF)
* ``cubic3d``      Eq. 4.25 (Dufva 3D belt element, 24 DOF: cubic in x, linear in y, z)
* ``plate36``      Eqs 4.14-4.15 (thin plate, 36 DOF, incomplete cubic of Dmitrochenko)
* ``cable3d``      the gradient-deficient cable of Gerstmayr and Shabana (2006), Chrono's
  ``ChElementCableANCF`` (12 DOF: r, r_x per node, cubic in x)

The numeric code used at run time is generated from these derivations into
``ancf/elements/_generated.py`` (``python -m analytic.shape_functions --write``);
a test regenerates it and checks that the committed file is up to date.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import sympy as sp

from analytic._codegen import main, sources, stamped

x, y, z = sp.symbols("x y z", real=True)
l, a, b = sp.symbols("l a b", positive=True)  # element length; plate sides a (x), b (y)


@dataclass(frozen=True)
class Family:
    """Declaration of an ANCF element family.

    ``nodes``: node positions in local coordinates; ``node_dofs``: the derivative
    variables of each nodal coordinate (``()`` is the position itself).
    ``section``: the local coordinates integrated over the cross-section (beams)
    and ``length_symbols``: the symbols the local coordinates are scaled by.
    """

    name: str
    dim: int
    coords: tuple
    monomials: tuple
    nodes: tuple
    node_dofs: tuple
    axial: tuple  # coordinates integrated along the element (with their ranges)
    section: tuple  # coordinates integrated in closed form over a cross-section


FAMILIES = {
    "linear2d": Family(
        "linear2d", 2, (x, y), (1, x, y, x * y),
        nodes=((0, 0), (l, 0)), node_dofs=((), (y,)),
        axial=((x, 0, l),), section=(y,)),
    "cubic2d": Family(
        "cubic2d", 2, (x, y), (1, x, x**2, x**3, y, x * y),
        nodes=((0, 0), (l, 0)), node_dofs=((), (x,), (y,)),
        axial=((x, 0, l),), section=(y,)),
    "linear3d": Family(
        "linear3d", 3, (x, y, z), (1, x, y, z, x * y, x * z),
        nodes=((0, 0, 0), (l, 0, 0)), node_dofs=((), (y,), (z,)),
        axial=((x, 0, l),), section=(y, z)),
    "cubic3d": Family(
        "cubic3d", 3, (x, y, z), (1, x, x**2, x**3, y, x * y, z, x * z),
        nodes=((0, 0, 0), (l, 0, 0)), node_dofs=((), (x,), (y,), (z,)),
        axial=((x, 0, l),), section=(y, z)),
    "plate36": Family(
        "plate36", 3, (x, y),
        (1, x, y, x**2, x * y, y**2, x**3, x**2 * y, x * y**2, y**3, x**3 * y, x * y**3),
        nodes=((0, 0), (a, 0), (a, b), (0, b)), node_dofs=((), (x,), (y,)),
        axial=((x, 0, a), (y, 0, b)), section=()),
    "cable3d": Family(
        "cable3d", 3, (x, y, z), (1, x, x**2, x**3),
        nodes=((0, 0, 0), (l, 0, 0)), node_dofs=((), (x,)),
        axial=((x, 0, l),), section=(y, z)),
}


def derive(family: Family) -> list:
    """Scalar shape functions S_k(x, y[, z]) of a family, in nodal-coordinate order."""
    rows = []
    for node in family.nodes:
        at = dict(zip(family.coords, node))
        for dvars in family.node_dofs:
            rows.append([sp.diff(m, *dvars).subs(at) if dvars else sp.sympify(m).subs(at)
                         for m in family.monomials])
    A = sp.Matrix(rows)
    if A.shape[0] != A.shape[1]:
        raise ValueError(f"{family.name}: {A.shape[0]} nodal coordinates for "
                         f"{A.shape[1]} polynomial coefficients")
    basis = sp.Matrix([list(family.monomials)])
    return [sp.simplify(s) for s in basis * A.inv()]


def section_moment_symbols(family: Family, degree: int) -> dict:
    """Symbols Q_p (or Q_p_q in 3D) for the section integrals  int y^p z^q dA."""
    if len(family.section) == 1:
        return {(p,): sp.Symbol(f"Q{p}") for p in range(degree + 1)}
    return {(p, q): sp.Symbol(f"Q{p}_{q}") for p in range(degree + 1)
            for q in range(degree + 1 - p)}


def integrate_exact(expr, family: Family):
    """Exact integral of a polynomial over the element volume (or plate area).

    The cross-section is integrated in closed form through its moments
    ``Q_p = int y^p dA`` (``Q_p_q = int y^p z^q dA`` in 3D), so any section shape
    is covered; the axial coordinate(s) are integrated symbolically.
    """
    expr = sp.expand(expr)
    if family.section:
        poly = sp.Poly(expr, *family.section)
        deg = poly.total_degree()
        Q = section_moment_symbols(family, deg)
        expr = sum(coef * Q[powers] for powers, coef in poly.terms())
    for var, lo, hi in family.axial:
        expr = sp.integrate(expr, (var, lo, hi))
    return sp.expand(expr)


def mass_scalar(family: Family) -> sp.Matrix:
    """m_ij = int S_i S_j dV (the mass matrix is rho * kron(m, I_dim), Eq. 2.26)."""
    S = derive(family)
    n = len(S)
    return sp.Matrix(n, n, lambda i, j: integrate_exact(S[i] * S[j], family))


# ----------------------------------------------------------------- code generation
_DERIVS = {2: ("", "x", "y", "xx", "xy", "yy"), 3: ("", "x", "y", "z")}
#: r_xx: the belt element's centre-line curvature r_c,xx, the cable's curvature
_EXTRA = {"cubic3d": ("xx",), "cable3d": ("xx",)}


def _lengths(family: Family) -> tuple:
    return (a, b) if family.name == "plate36" else (l,)


def _emit_family(family: Family) -> list:
    S = derive(family)
    coords = family.coords
    args = ", ".join(str(c) for c in coords + _lengths(family))
    names = _DERIVS[len(coords)] + _EXTRA.get(family.name, ())
    out = []
    for d in names:
        dvars = [dict(x=x, y=y, z=z)[c] for c in d]
        exprs = [sp.diff(s, *dvars) if d else s for s in S]
        body = ", ".join(f"_b({sp.pycode(e)})" for e in exprs)
        fname = f"{family.name.replace('-', '_')}_{d or 'S'}"
        out += [f"def {fname}({args}):", f"    _b = _broadcaster({args})",
                f"    return np.stack([{body}], axis=-1)", ""]
    m = mass_scalar(family)
    syms = sorted(m.free_symbols, key=str)
    margs = ", ".join(str(s) for s in syms)
    rows = ",\n        ".join("[" + ", ".join(sp.pycode(m[i, j]) for j in range(m.shape[1])) + "]"
                              for i in range(m.shape[0]))
    out += [f"def {family.name}_mass({margs}):",
            '    """Exact scalar mass integrals m_ij = int S_i S_j dV (multiply by rho)."""',
            f"    return np.array([\n        {rows}])", ""]
    out += [f"{family.name.upper()}_MASS_ARGS = {tuple(str(s) for s in syms)!r}", ""]
    return out


def generate() -> str:
    """Text of ``ancf/elements/_generated.py``."""
    lines = ['"""Shape functions and exact mass integrals: GENERATED by',
             "``python -m analytic.shape_functions --write`` from the SymPy derivation in",
             '``analytic/shape_functions.py``. Do not edit by hand."""',
             "", "import numpy as np", "", "",
             "def _broadcaster(*args):",
             "    shape = np.broadcast(*args).shape",
             "    return lambda v: np.broadcast_to(np.asarray(v, dtype=float), shape)",
             "", ""]
    for fam in FAMILIES.values():
        lines += _emit_family(fam) + [""]
    return stamped("\n".join(lines).rstrip() + "\n", SOURCES)


TARGET = Path(__file__).resolve().parent.parent / "ancf" / "elements" / "_generated.py"
SOURCES = sources(__file__)  # what the generated text depends on (its stamp)


if __name__ == "__main__":
    raise SystemExit(main(generate, TARGET, __doc__.splitlines()[0]))
