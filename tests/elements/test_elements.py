"""Planar ANCF elements: derivatives, symmetry, zero-energy modes, input checks.

The contract tests run over ``CONTRACT_ELEMENTS`` (the beam catalogue and the belt
elements; a 3D element, ``dim = 3``, gets a 3D mesh, perturbation and rotation about
(1, 2, 3)).  Finite-difference tolerance: the continuum beams' strain energy is a
polynomial of degree 4 in the nodal coordinates (Green strains are quadratic), so
the central difference (f(e + h) - f(e - h)) / 2h has the exact error h^2/6 f'''
(no higher terms), and round-off adds ~ eps_machine |f| / h.  With h = 1e-6 (m for
positions, 1 for slopes, against element lengths ~0.7 m) both are ~1e-10 relative
or less, so a relative tolerance of 1e-6 leaves a wide margin yet catches any
wrong term.  The belt element's energy is rational in the slopes (t = r_x/|r_x|,
the nodal shear sines), with third derivatives of the same order as the
polynomial ones near the reference (|r_x|, |r_y| ~ 1), so its truncation error is
again ~h^2 relative and the same tolerance holds (seen: <= 1e-9).
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.core.assembly import Assembly, ElementGroup
from ancf.elements.catalogue import CONTRACT_ELEMENTS
from ancf.elements.linear2d import LinearBeam2D
from ancf.elements.omar_shabana import OmarShabana2D
from ancf.core.mesh import BeamMesh
from ancf.core.quadrature import RectangularSection

E_MOD, RHO = 2.07e11, 7850.0
SECTION = RectangularSection(0.1, 0.1)
L = 2.0
H = 1e-6
RTOL = 1e-6

CASES = list(CONTRACT_ELEMENTS.values())  # every element, every variant
IDS = list(CONTRACT_ELEMENTS)


def _dim(cls) -> int:
    """The space dimension of an element class: its own ``dim`` or its strain model's."""
    return getattr(cls, "dim", None) or cls.strain.dim


def _build(cls, kw, n_el=3, nu=0.3, section=SECTION):
    """Mesh, reference and element ``cls(..., **kw)``; kw a dict or an integration scheme."""
    kw = kw if isinstance(kw, dict) else {"integration": kw}
    m = BeamMesh(L, n_el, cls.slots, dim=_dim(cls))
    q0 = m.reference()
    el = cls(m.lengths, q0[m.dofmap], section, E=E_MOD, nu=nu, rho=RHO, **kw)
    return m, q0, el


def _perturbed(m, q0, seed=0, size=1e-2):
    """Reference + random perturbation of relative size ``size``: positions by
    size * element length, slopes by size."""
    rng = np.random.default_rng(seed)
    scale = np.array([m.lengths[0] if s == "r" else 1.0 for s in m.slots])
    d = rng.standard_normal((m.n_nodes, len(m.slots), m.dim)) * scale[None, :, None]
    return q0 + size * d.ravel()


def _close_columns(approx, exact, rtol):
    """Column-wise relative comparison ||a_j - x_j|| <= rtol ||x_j||."""
    err = np.linalg.norm(approx - exact, axis=-2)
    ref = np.linalg.norm(exact, axis=-2)
    return err, ref, np.all(err <= rtol * ref)


@pytest.mark.parametrize("nu", [0.0, 0.3])
@pytest.mark.parametrize("cls,kw", CASES, ids=IDS)
def test_gradient_matches_energy_differences(cls, kw, nu):
    m, q0, el = _build(cls, kw, nu=nu)
    e = _perturbed(m, q0)[m.dofmap]
    g, _ = el.gradient(e)
    fd = np.zeros_like(g)
    for j in range(el.ndof):  # elements are independent: perturb dof j of all at once
        ep, em = e.copy(), e.copy()
        ep[:, j] += H
        em[:, j] -= H
        fd[:, j] = (el.energy(ep) - el.energy(em)) / (2 * H)
    err = np.linalg.norm(fd - g, axis=1)
    assert np.all(err <= RTOL * np.linalg.norm(g, axis=1)), (err, np.linalg.norm(g, axis=1))


@pytest.mark.parametrize("nu", [0.0, 0.3])
@pytest.mark.parametrize("cls,kw", CASES, ids=IDS)
def test_tangent_matches_gradient_differences(cls, kw, nu):
    m, q0, el = _build(cls, kw, nu=nu)
    e = _perturbed(m, q0, seed=1)[m.dofmap]
    g, K = el.gradient(e, tangent=True)
    g_only, none = el.gradient(e)
    assert none is None
    np.testing.assert_array_equal(g, g_only)
    fd = np.zeros_like(K)
    for j in range(el.ndof):
        ep, em = e.copy(), e.copy()
        ep[:, j] += H
        em[:, j] -= H
        fd[:, :, j] = (el.gradient(ep)[0] - el.gradient(em)[0]) / (2 * H)
    err, ref, ok = _close_columns(fd, K, RTOL)
    assert ok, (err / ref).max()


@pytest.mark.parametrize("cls,kw", CASES, ids=IDS)
def test_tangent_symmetric(cls, kw):
    m, q0, el = _build(cls, kw)
    for q in (q0, _perturbed(m, q0, seed=2)):
        _, K = el.gradient(q[m.dofmap], tangent=True)
        np.testing.assert_allclose(K, np.swapaxes(K, 1, 2), rtol=0, atol=1e-12 * np.abs(K).max())


def _rotate(m, v, angle, shift=(0.0, 0.0)):
    """r -> R r + shift on positions, R on slopes, of a global vector; in 3D the
    rotation is about the axis (1, 2, 3) and the shift gains z = 0.3."""
    c, s = np.cos(angle), np.sin(angle)
    R = np.array([[c, -s], [s, c]])
    if m.dim == 3:
        k = np.array([1.0, 2.0, 3.0]) / np.sqrt(14.0)
        Kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
        R, shift = np.eye(3) + s * Kx + (1 - c) * Kx @ Kx, (*shift, 0.3)
    V = v.reshape(m.n_nodes, len(m.slots), m.dim) @ R.T
    V[:, [k for k, sl in enumerate(m.slots) if sl == "r"], :] += np.asarray(shift)
    return V.ravel()


@pytest.mark.parametrize("cls,kw", CASES, ids=IDS)
def test_energy_invariant_under_rigid_motion_of_deformed_state(cls, kw):
    m, q0, el = _build(cls, kw)
    q = _perturbed(m, q0, seed=3)
    U = el.energy(q[m.dofmap])
    np.testing.assert_allclose(el.energy(_rotate(m, q, 0.7, (0.4, -0.2))[m.dofmap]), U, rtol=1e-10)


def _rotated_reference_ratio(cls, scheme, angle, **kw):
    """U(R q; reference R q0) / U(q; reference q0) - 1, per element."""
    m = BeamMesh(L, 3, cls.slots)
    q0 = m.reference()
    q = _perturbed(m, q0, seed=3)
    kw = {"E": E_MOD, "nu": 0.3, "rho": RHO, "integration": scheme, **kw}
    el = cls(m.lengths, q0[m.dofmap], SECTION, **kw)
    el_r = cls(m.lengths, _rotate(m, q0, angle)[m.dofmap], SECTION, **kw)
    return el_r.energy(_rotate(m, q, angle)[m.dofmap]) / el.energy(q[m.dofmap]) - 1.0


@pytest.mark.parametrize("cls,scheme,angle,kw", [
    (OmarShabana2D, "thesis", 0.7, {}),            # isotropic Lame matrix
    (OmarShabana2D, "exact", 0.7, {}),
    (LinearBeam2D, "exact", 0.7, {"nu": 0.0, "ks": 1.0}),  # diag(E, E, E/2) is isotropic
    (LinearBeam2D, "thesis", np.pi / 2, {}),       # diag(E, E, ks G) is invariant under 90 deg
    (LinearBeam2D, "report-selective", np.pi, {}),
])
def test_energy_invariant_for_rotated_reference(cls, scheme, angle, kw):
    """Reference and deformed states both rotated (exercises J0 != I)."""
    assert np.abs(_rotated_reference_ratio(cls, scheme, angle, **kw)).max() < 1e-10


@pytest.mark.parametrize("scheme", ["thesis", "report-selective"])
def test_linear_beam_energy_invariant_for_reference_at_angle(scheme):
    """Strains are measured in the element's local frame, so a beam whose reference is
    rotated by 0.7 rad stores the same energy as the same beam along x (this failed by
    ~50 % when strains were measured in the global axes)."""
    assert np.abs(_rotated_reference_ratio(LinearBeam2D, scheme, 0.7)).max() < 1e-10


@pytest.mark.parametrize("cls,scheme,reference", [
    (LinearBeam2D, "exact", "normal=8x8,shear=8x8"),
    (LinearBeam2D, "thesis", "normal=1x8,shear=1x8"),
    (OmarShabana2D, "exact", "all=9x8"),
    (OmarShabana2D, "thesis", "all=4x8"),
])
def test_exact_section_rule_is_exact(cls, scheme, reference):
    """'e' (closed form across y) and the 'exact' scheme equal high-order Gauss rules."""
    m, q0, el = _build(cls, scheme)
    _, _, el_ref = _build(cls, reference)
    e = _perturbed(m, q0, seed=4)[m.dofmap]
    np.testing.assert_allclose(el.energy(e), el_ref.energy(e), rtol=1e-11)


# ------------------------------------------------------------------ zero-energy modes
def _zero_modes(cls, kw, n_el, nu=0.3):
    m, q0, el = _build(cls, kw, n_el=n_el, nu=nu)
    K = Assembly(m.n_dofs, [ElementGroup(el, m.dofmap)]).gradient_tangent(q0)[1].toarray()
    w = np.linalg.eigvalsh(K)
    # (near-)zero: |lambda| < 1e-9 * max|lambda|; the smallest physical eigenvalue
    # here is ~3e-5 * max, round-off zeros are ~1e-16 * max
    return int(np.sum(np.abs(w) < 1e-9 * np.abs(w).max()))


ZERO_MODES = {}  # recorded counts, printed with -s


@pytest.mark.parametrize("n_el", [1, 4])
@pytest.mark.parametrize("name", ["LinearBeam2D-thesis", "LinearBeam2D-exact",
                                  "LinearBeam2D-report-fix", "OmarShabana2D-thesis",
                                  "OmarShabana2D-exact", "DufvaBelt2D", "DufvaBelt2D-alpha"])
def test_only_rigid_body_zero_energy_modes(name, n_el):
    """Free-free mesh at the reference: 2 translations + 1 rotation.  The belt
    element has no more: linearised about the straight reference its energy vanishes
    only for u' = 0, v'' + s_x = 0, nodal sin(gamma) = 0 and nodal eps_yy = 0, which
    leave 3 of an element's 12 coordinates free (also with nx = 3, which integrates
    u'^2, a quartic, exactly)."""
    n = _zero_modes(*CONTRACT_ELEMENTS[name], n_el)
    ZERO_MODES[(name, n_el)] = n
    print(f"{name} {n_el} element(s): {n} zero-energy modes")
    assert n == 3


@pytest.mark.parametrize("n_el", [1, 4])
@pytest.mark.parametrize("name", ["DufvaBelt3D", "DufvaBelt3D-alpha"])
def test_spatial_belt_has_only_rigid_body_zero_energy_modes(name, n_el):
    """Free-free 3D belt mesh at the reference: 3 translations + 3 rotations.  Twist
    is not free: a twist rate phi' gives r_x.r_s^y = -z phi', r_x.r_s^z = y phi', i.e.
    the torsional stiffness ks G alpha2 (I_y + I_z) of the shear terms."""
    n = _zero_modes(*CONTRACT_ELEMENTS[name], n_el)
    print(f"{name} {n_el} element(s): {n} zero-energy modes")
    assert n == 6


@pytest.mark.parametrize("n_el", [1, 4])
def test_report_selective_zero_energy_modes(n_el):
    """'report-selective' (normal 2x2, shear 1x1) has NO spurious mode at the
    reference configuration: the count is exactly 3.  Linearised about the
    straight reference, r = r0 + u with u = a0 + a1 x + a2 y + a3 xy (likewise v
    with b0..b3) gives eps_xx = a1 + a3 y, eps_yy = b2 + b3 x and
    gamma = a2 + b1 + a3 x + b3 y.  eps_xx and eps_yy vanishing at the 2x2 points
    force a1 = a3 = b2 = b3 = 0, and gamma at the single point (l/2, 0) then forces
    a2 + b1 = 0: 8 - 5 = 3 zero modes per element (rigid body only).  The report's
    'No convergence' (Table 4) is therefore not a zero-energy mode of the
    reference stiffness."""
    n = _zero_modes(LinearBeam2D, "report-selective", n_el)
    ZERO_MODES[("LinearBeam2D", "report-selective", n_el)] = n
    print(f"LinearBeam2D report-selective {n_el} element(s): {n} zero-energy modes")
    assert n == 3


@pytest.mark.parametrize("spec,n_el,expected", [
    # all terms at the single point (l/2, 0): eps_xx = a1, eps_yy = b2 + b3 l/2,
    # gamma = a2 + b1 + a3 l/2 -> 8 - 3 = 5 zero modes per element
    ("normal=1x1,shear=1x1", 1, 5),
    ("normal=1x1,shear=1x1", 4, 8),
    # normal exact across y but shear at y = 0 only: one hourglass mode
    ("normal=1xe,shear=1x1", 1, 4),
    ("normal=1xe,shear=1x1", 4, 4),
])
def test_reduced_integration_shows_spurious_modes(spec, n_el, expected):
    """The mode counter does detect spurious modes when integration is reduced."""
    n = _zero_modes(LinearBeam2D, spec, n_el)
    print(f"LinearBeam2D {spec} {n_el} element(s): {n} zero-energy modes")
    assert n == expected


# -------------------------------------------------------------------- invalid input
@pytest.mark.parametrize("cls", [LinearBeam2D, OmarShabana2D])
@pytest.mark.parametrize("name", ["bogus", "Thesis", "report_fix", ""])
def test_unknown_integration_raises(cls, name):
    with pytest.raises(ValueError) as info:
        _build(cls, name)
    msg = str(info.value)
    assert "integration" in msg
    for allowed in cls.schemes:
        assert repr(allowed) in msg or allowed in msg, (allowed, msg)


@pytest.mark.parametrize("spec", ["normal=2x0,shear=1x1", "normal=0x2,shear=1x1",
                                  "normal=2x2,shear=1xq", "normal=2x2x2,shear=1x1",
                                  "bending=2x2"])
def test_malformed_integration_spec_raises(spec):
    with pytest.raises(ValueError, match="integration"):
        _build(LinearBeam2D, spec)


@pytest.mark.parametrize("value", [None, 3])
def test_non_string_integration_raises_value_error(value):
    with pytest.raises(ValueError, match="integration"):
        _build(LinearBeam2D, value)


@pytest.mark.parametrize("cls,kw", CASES, ids=IDS)
def test_energy_of_stacked_states_is_each_states_energy(cls, kw):
    """The energy history's one call over all samples (``Assembly.energy_samples``, and
    an element's own ``energy_samples`` where it has one) gives each state's energies
    bit for bit."""
    m, q0, el = _build(cls, kw)
    Q = np.array([_perturbed(m, q0, seed=s, size=0.02 * s) for s in range(4)])
    asm = Assembly(m.n_dofs, [ElementGroup(el, m.dofmap)])
    each = np.array([np.concatenate(asm.energies(q)) for q in Q])
    np.testing.assert_array_equal(asm.energy_samples(Q), each)
    assert np.ptp(each, axis=0).min() > 0  # the states differ: a row mix-up would show


@pytest.mark.parametrize("cls", [LinearBeam2D, OmarShabana2D])
def test_gravity_potential_of_stacked_states_is_each_states(cls):
    """Gravity's potential of states side by side (the energy history's one call) is each
    state's, bit for bit."""
    from ancf.core.forces import Gravity
    m, q0, el = _build(cls, "thesis" if cls is LinearBeam2D else {})
    Q = np.array([_perturbed(m, q0, seed=s, size=0.1 * s) for s in range(5)])
    grav = Gravity(Assembly(m.n_dofs, [ElementGroup(el, m.dofmap)]), (0.3, -9.81))
    each = np.array([np.concatenate(grav.element_potential(q)) for q in Q])
    np.testing.assert_array_equal(np.concatenate(grav.element_potential(Q), axis=1), each)
    assert np.ptp(each, axis=0).min() > 0
