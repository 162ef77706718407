"""Shape functions, generated code and exact mass matrices of the ANCF families.

Checks the SymPy derivation (analytic/shape_functions.py) against the shape
functions printed in the thesis (Eqs 2.12, 3.11, 4.22; Eq. 2.9 as a witness for
the correct cubic Hermite functions), the interpolation property, rigid-body
reproduction (positions, slopes and Green strain energy), that the committed
generated module is up to date, and the generated exact mass matrices.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

from analytic import shape_functions as sf
from analytic.shape_functions import FAMILIES, a, b, derive, l, x, y, z
from ancf.elements.catalogue import CONTRACT_ELEMENTS
from ancf.core.assembly import Assembly, ElementGroup
from ancf.elements import _generated as gen
from ancf.core.mesh import BeamMesh
from ancf.core.quadrature import RectangularSection
from tests.analytic.test_codegen import REGENERATE

E_MOD, NU, RHO = 2.07e11, 0.3, 7850.0
SECTION = RectangularSection(0.1, 0.2)  # b (z) = 0.1 m, h (y) = 0.2 m

xi, eta, zeta = x / l, y / l, z / l


def _dim(cls) -> int:
    """The space dimension of an element class: its own ``dim`` or its strain model's."""
    return getattr(cls, "dim", None) or cls.strain.dim


@pytest.fixture(scope="module")
def derived():
    """Scalar shape functions of every family, derived once per module."""
    return {name: derive(fam) for name, fam in FAMILIES.items()}


def _same(expr_a, expr_b) -> bool:
    return sp.simplify(sp.expand(expr_a - expr_b)) == 0


# ----------------------------------------------------------- printed shape functions
PRINTED = {
    # Eq. 2.12 (Kerkkänen linear beam)
    "linear2d": [1 - xi, l * (eta - xi * eta), xi, l * xi * eta],
    # Eq. 4.22 (3D linear beam)
    "linear3d": [1 - xi, l * (eta - xi * eta), l * zeta * (1 - xi),
                 xi, l * xi * eta, l * xi * zeta],
}

# Eq. 3.11 as it should read: S5 is the cubic Hermite function for the slope at
# node J, l(-xi^2 + xi^3).
CUBIC_CORRECT = [1 - 3 * xi**2 + 2 * xi**3, l * (xi - 2 * xi**2 + xi**3), l * (eta - xi * eta),
                 3 * xi**2 - 2 * xi**3, l * (-xi**2 + xi**3), l * xi * eta]
# Eq. 3.11 as printed in the thesis (line ~768): S5 = l(-2 xi^2 + xi^3)  -- a typo.
CUBIC_PRINTED_S5 = l * (-2 * xi**2 + xi**3)


@pytest.mark.parametrize("family", ["linear2d", "linear3d"])
def test_derived_equal_printed(derived, family):
    S = derived[family]
    assert len(S) == len(PRINTED[family])
    for k, (ours, printed) in enumerate(zip(S, PRINTED[family]), start=1):
        assert _same(ours, printed), f"{family} S{k}: derived {ours} != printed {printed}"


def test_cubic2d_equals_eq_3_11_with_corrected_s5(derived):
    S = derived["cubic2d"]
    assert len(S) == 6
    for k, (ours, ref) in enumerate(zip(S, CUBIC_CORRECT), start=1):
        assert _same(ours, ref), f"cubic2d S{k}: derived {ours} != Hermite {ref}"
    # the printed S5 differs from ours ...
    assert not _same(S[4], CUBIC_PRINTED_S5)


def test_cubic2d_printed_s5_is_a_typo():
    """Eq. 3.11 prints S5 = l(-2xi^2 + xi^3).  That function cannot be the shape
    function of the node-J slope: it must vanish at node J (x = l) and have unit
    x-derivative there, but it equals -l at x = l.  The correct Hermite function
    l(-xi^2 + xi^3) satisfies all four conditions, and its x-derivative is exactly
    the coefficient of e9 printed in Eq. 2.9, (-2x/l + 3x^2/l^2)."""
    def conditions(s):
        ds = sp.diff(s, x)
        return [sp.simplify(v) for v in (s.subs(x, 0), ds.subs(x, 0), s.subs(x, l), ds.subs(x, l))]

    assert conditions(CUBIC_CORRECT[4]) == [0, 0, 0, 1]
    printed = conditions(CUBIC_PRINTED_S5)
    assert printed != [0, 0, 0, 1]
    assert printed[2] == -l  # S5(x = l) = -l instead of 0
    assert _same(sp.diff(CUBIC_CORRECT[4], x), -2 * x / l + 3 * x**2 / l**2)


def test_cubic2d_matches_eq_2_9(derived):
    """Eq. 2.9 prints eps_xx^lin = sum_k dS_k/dx e_(2k-1) - 1; its coefficients of
    e1, e3, e5, e7, e9, e11 are the x-derivatives of S1..S6 (an independent
    printing of the Omar-Shabana functions, confirming S5 above)."""
    eq_2_9 = [-6 * x / l**2 + 6 * x**2 / l**3, 1 - 4 * x / l + 3 * x**2 / l**2, -y / l,
              6 * x / l**2 - 6 * x**2 / l**3, -2 * x / l + 3 * x**2 / l**2, y / l]
    for k, (s, coef) in enumerate(zip(derived["cubic2d"], eq_2_9), start=1):
        assert _same(sp.diff(s, x), coef), f"dS{k}/dx != Eq. 2.9 coefficient {coef}"


# ----------------------------------------------------------------- interpolation
# Nodal coordinates written out independently from the thesis:
# linear2d Eq. 2.11 (r, r_y); cubic2d Eq. 2.3 (r, r_x, r_y); linear3d Eq. 4.21
# (r, r_y, r_z); cubic3d Eq. 4.25 (r, r_x, r_y, r_z); plate36 Eqs 4.14-4.15 (r, r_x, r_y at corners A, B, C, D).
NODAL_FUNCTIONALS = {
    "linear2d": [((0, 0), ()), ((0, 0), (y,)), ((l, 0), ()), ((l, 0), (y,))],
    "cubic2d": [((0, 0), ()), ((0, 0), (x,)), ((0, 0), (y,)),
                ((l, 0), ()), ((l, 0), (x,)), ((l, 0), (y,))],
    "linear3d": [((0, 0, 0), ()), ((0, 0, 0), (y,)), ((0, 0, 0), (z,)),
                 ((l, 0, 0), ()), ((l, 0, 0), (y,)), ((l, 0, 0), (z,))],
    "cubic3d": [(node, d) for node in ((0, 0, 0), (l, 0, 0)) for d in ((), (x,), (y,), (z,))],
    "plate36": [(node, d) for node in ((0, 0), (a, 0), (a, b), (0, b))
                for d in ((), (x,), (y,))],
    "cable3d": [(node, d) for node in ((0, 0, 0), (l, 0, 0)) for d in ((), (x,))],
}


@pytest.mark.parametrize("family", list(FAMILIES))
def test_kronecker_delta(derived, family):
    S = derived[family]
    coords = FAMILIES[family].coords
    functionals = NODAL_FUNCTIONALS[family]
    assert len(S) == len(functionals)
    for i, s in enumerate(S):
        for j, (node, dvars) in enumerate(functionals):
            value = sp.diff(s, *dvars) if dvars else s
            value = sp.simplify(value.subs(dict(zip(coords, node))))
            assert value == (1 if i == j else 0), f"{family}: S{i + 1} at functional {j + 1} = {value}"


# ------------------------------------------------------------- rigid-body motion
ANGLE = 0.7
C2 = np.array([0.31, -1.27])
C3 = np.array([0.31, -1.27, 2.05])


def _rotation2d(angle=ANGLE):
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s], [s, c]])


def _rotation3d(angle=ANGLE):
    """Rotation by ``angle`` about the (non-coordinate) axis (1, 2, 3)/sqrt(14)."""
    k = np.array([1.0, 2.0, 3.0]) / math.sqrt(14.0)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


RIGID_CASES = {
    # family: (dimension of r, element lengths)
    "linear2d": (2, {"l": 1.7}),
    "cubic2d": (2, {"l": 1.7}),
    "linear3d": (3, {"l": 1.7}),
    "cubic3d": (3, {"l": 1.7}),
    "plate36": (3, {"a": 1.3, "b": 0.8}),
    "cable3d": (3, {"l": 1.7}),  # a line: points on the axis, the one slope r_x
}
LINES = ("cable3d",)


@pytest.mark.parametrize("family", list(FAMILIES))
def test_rigid_body_motion_reproduced(family):
    dim, lengths = RIGID_CASES[family]
    fam = FAMILIES[family]
    R, c = (_rotation2d(), C2) if dim == 2 else (_rotation3d(), C3)
    subs = {l: lengths.get("l", 1.0), a: lengths.get("a", 1.0), b: lengths.get("b", 1.0)}
    # nodal coordinates of the rotated and translated reference configuration
    rows = []
    for node, dvars in NODAL_FUNCTIONALS[family]:
        if not dvars:
            X = np.zeros(dim)
            X[:len(node)] = [float(sp.sympify(v).subs(subs)) for v in node]
            rows.append(R @ X + c)
        else:
            rows.append(R[:, {x: 0, y: 1, z: 2}[dvars[0]]])
    Enod = np.array(rows)  # (nshape, dim)

    rng = np.random.default_rng(1)
    npts = 50
    ncoords = len(fam.coords)
    if family == "plate36":
        P = rng.uniform(0, 1, (npts, 2)) * [lengths["a"], lengths["b"]]
    else:  # interior of a beam: 0 < x < l, |y|, |z| up to half a section (0 on a line)
        P = np.column_stack([rng.uniform(0, lengths["l"], npts),
                             rng.uniform(-0.1, 0.1, (npts, ncoords - 1))
                             * (family not in LINES)])
    lens = [lengths["a"], lengths["b"]] if family == "plate36" else [lengths["l"]]
    args = [P[:, i] for i in range(ncoords)] + lens
    X = np.zeros((npts, dim))
    X[:, :ncoords] = P

    r = getattr(gen, f"{family}_S")(*args) @ Enod
    np.testing.assert_allclose(r, X @ R.T + c, rtol=0, atol=1e-12)
    # the position gradient is the rotation: r_x = R[:, 0], r_y = R[:, 1] (r_z = R[:, 2])
    for k, name in enumerate(str(v) for v in fam.coords[:1 if family in LINES else None]):
        rk = getattr(gen, f"{family}_{name}")(*args) @ Enod
        np.testing.assert_allclose(rk, np.broadcast_to(R[:, k], rk.shape), rtol=0, atol=1e-12)


CLASSES = list(dict.fromkeys(cls for cls, _ in CONTRACT_ELEMENTS.values()))  # every element


def _rigid(mesh: BeamMesh, q, R, c):
    """Apply r -> R r + c to the positions and R to the slopes of a global vector."""
    Q = q.reshape(mesh.n_nodes, len(mesh.slots), mesh.dim).copy()
    for s, slot in enumerate(mesh.slots):
        Q[:, s, :] = Q[:, s, :] @ R.T + (c if slot == "r" else 0.0)
    return Q.ravel()


@pytest.mark.parametrize("cls,kw", CONTRACT_ELEMENTS.values(), ids=list(CONTRACT_ELEMENTS))
def test_rigid_body_motion_has_no_strain_energy(cls, kw):
    L = 2.0
    m = BeamMesh(L, 3, cls.slots, dim=_dim(cls))
    q0 = m.reference()
    el = cls(m.lengths, q0[m.dofmap], SECTION, E=E_MOD, nu=NU, rho=RHO, **kw)
    q = _rigid(m, q0, *((_rotation3d(), C3) if _dim(cls) == 3 else (_rotation2d(), C2)))
    U = el.energy(q[m.dofmap])
    scale = E_MOD * SECTION.area * L
    # brief asked for 1e-6 E A L; the exact value is zero and round-off gives ~1e-30
    assert np.all(np.abs(U) <= 1e-12 * scale), U
    g, _ = el.gradient(q[m.dofmap])  # and no elastic forces
    assert np.abs(g).max() <= 1e-9 * E_MOD * SECTION.area


# --------------------------------------------------------------- generated module
@pytest.mark.slow
@REGENERATE  # the stamp test in tests/analytic/test_codegen.py runs always
def test_generated_module_up_to_date():
    committed = sf.TARGET.read_text()
    assert sf.generate() == committed, (
        "ancf/elements/_generated.py is stale: run `python -m analytic.shape_functions --write`")


# ------------------------------------------------------------------------- mass
def _gauss(n, lo, hi):
    t, w = np.polynomial.legendre.leggauss(n)
    return lo + (t + 1) * (hi - lo) / 2, w * (hi - lo) / 2


def _straight_e0(lengths, slots, dim=2):
    X = np.concatenate([[0.0], np.cumsum(lengths)])
    ref = {"r_x": [1.0, 0.0, 0.0], "r_y": [0.0, 1.0, 0.0], "r_z": [0.0, 0.0, 1.0]}
    nodes = np.array([[([Xi, 0.0, 0.0] if s == "r" else ref[s])[:dim] for s in slots] for Xi in X])
    return np.stack([np.concatenate([nodes[i].ravel(), nodes[i + 1].ravel()])
                     for i in range(len(lengths))])


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_mass_equals_gauss_integration(cls):
    """Consistent mass against 6 x 6 Gauss points over (x, y) times the width b (2D),
    or 6 x 6 x 6 over (x, y, z) (3D elements)."""
    dim = _dim(cls)
    lengths = np.array([0.7, 1.3])
    el = cls(lengths, _straight_e0(lengths, cls.slots, dim), SECTION, E=E_MOD, nu=NU, rho=RHO)
    M = el.mass()
    Sfun = getattr(gen, f"{cls.family}_S")
    h, bw = SECTION.h, SECTION.b
    for e, le in enumerate(lengths):
        xs, wx = _gauss(6, 0.0, le)
        ys, wy = _gauss(6, -h / 2, h / 2)
        if dim == 3:
            zs, wz = _gauss(6, -bw / 2, bw / 2)
            XX, YY, ZZ = (g.reshape(6, -1) for g in np.meshgrid(xs, ys, zs, indexing="ij"))
            W = np.einsum("p,q,r->pqr", wx, wy, wz).reshape(6, -1)
            S = Sfun(XX, YY, ZZ, le)
        else:
            XX, YY = np.meshgrid(xs, ys, indexing="ij")
            W = np.outer(wx, wy) * bw  # section integrated over z: width b
            S = Sfun(XX, YY, le)  # (6, 6, nshape)
        ns = S.shape[-1]
        Sfull = np.zeros(S.shape[:2] + (dim, dim * ns))
        for d in range(dim):
            Sfull[..., d, d::dim] = S
        Mnum = RHO * np.einsum("pq,pqdi,pqdj->ij", W, Sfull, Sfull)
        np.testing.assert_allclose(M[e], Mnum, rtol=0, atol=1e-12 * np.abs(Mnum).max())
        np.testing.assert_allclose(M[e], M[e].T, rtol=0, atol=0)


def test_generated_mass_offset_sections():
    """The generated mass functions with non-zero first moments (a section not
    centred on the axis) against 6x6(x6) Gauss integration, for the 2D and 3D
    beams, and the plate (per unit thickness)."""
    le, (y0, y1), (z0, z1) = 1.3, (-0.03, 0.11), (0.02, 0.09)
    xs, wx = _gauss(6, 0.0, le)
    ys, wy = _gauss(6, y0, y1)
    zs, wz = _gauss(6, z0, z1)
    # 2D families: int over z gives the width (z1 - z0)
    Q = {f"Q{p}": (z1 - z0) * (y1**(p + 1) - y0**(p + 1)) / (p + 1) for p in range(3)}
    XX, YY = np.meshgrid(xs, ys, indexing="ij")
    W = np.outer(wx, wy) * (z1 - z0)
    for fam in ("linear2d", "cubic2d"):
        S = getattr(gen, f"{fam}_S")(XX, YY, le)
        num = np.einsum("pq,pqi,pqj->ij", W, S, S)
        got = getattr(gen, f"{fam}_mass")(**Q, l=le)
        np.testing.assert_allclose(got, num, rtol=0, atol=1e-12 * np.abs(num).max())
    # linear3d: Q_p_q = int y^p z^q dA
    Q3 = {f"Q{p}_{q}": (y1**(p + 1) - y0**(p + 1)) / (p + 1) * (z1**(q + 1) - z0**(q + 1)) / (q + 1)
          for p in range(3) for q in range(3 - p)}
    Q3 = {k: v for k, v in Q3.items() if k in gen.LINEAR3D_MASS_ARGS}
    XX, YY, ZZ = np.meshgrid(xs, ys, zs, indexing="ij")
    W = wx[:, None, None] * wy[None, :, None] * wz[None, None, :]
    S = gen.linear3d_S(XX, YY, ZZ, le)
    num = np.einsum("pqr,pqri,pqrj->ij", W, S, S)
    np.testing.assert_allclose(gen.linear3d_mass(**Q3, l=le), num, rtol=0,
                               atol=1e-12 * np.abs(num).max())
    # plate36 over [0, a] x [0, b]
    pa, pb = 1.3, 0.8
    xs, wx = _gauss(6, 0.0, pa)
    ys, wy = _gauss(6, 0.0, pb)
    XX, YY = np.meshgrid(xs, ys, indexing="ij")
    S = gen.plate36_S(XX, YY, pa, pb)
    num = np.einsum("pq,pqi,pqj->ij", np.outer(wx, wy), S, S)
    np.testing.assert_allclose(gen.plate36_mass(pa, pb), num, rtol=0,
                               atol=1e-12 * np.abs(num).max())


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_total_mass_of_rigid_translation(cls):
    L = 2.0
    dim = _dim(cls)
    m = BeamMesh(L, 4, cls.slots, dim=dim)
    q0 = m.reference()
    el = cls(m.lengths, q0[m.dofmap], SECTION, E=E_MOD, nu=NU, rho=RHO)
    M = Assembly(m.n_dofs, [ElementGroup(el, m.dofmap)]).mass().toarray()
    total = RHO * SECTION.area * L
    for comp in range(dim):
        u = np.zeros(m.n_dofs)
        for node in range(m.n_nodes):
            u[m.dof(node, "r", comp)] = 1.0
        assert u @ M @ u == pytest.approx(total, rel=1e-12)
    # the scalar mass integrals of every family sum to the volume (area) over the
    # position shape functions, since those add up to one
    mass_args = {"Q0": 0.02, "Q1": 0.0, "Q2": 0.02 * 0.2**2 / 12, "l": 1.7}
    for fam, positions in (("linear2d", [0, 2]), ("cubic2d", [0, 3])):
        mm = getattr(gen, f"{fam}_mass")(**mass_args)
        assert mm[np.ix_(positions, positions)].sum() == pytest.approx(0.02 * 1.7, rel=1e-12)
    mm = gen.linear3d_mass(Q0_0=0.02, Q0_1=0.0, Q0_2=1e-5, Q1_0=0.0, Q1_1=0.0, Q2_0=2e-5, l=1.7)
    assert mm[np.ix_([0, 3], [0, 3])].sum() == pytest.approx(0.02 * 1.7, rel=1e-12)
    mm = gen.cubic3d_mass(Q0_0=0.02, Q0_1=0.0, Q0_2=1e-5, Q1_0=0.0, Q1_1=0.0, Q2_0=2e-5, l=1.7)
    assert mm[np.ix_([0, 4], [0, 4])].sum() == pytest.approx(0.02 * 1.7, rel=1e-12)
    mm = gen.plate36_mass(1.3, 0.8)
    pos = [0, 3, 6, 9]
    assert mm[np.ix_(pos, pos)].sum() == pytest.approx(1.3 * 0.8, rel=1e-12)
