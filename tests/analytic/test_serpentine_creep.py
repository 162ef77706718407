"""The discrete model with creeping wraps (analytic/serpentine_creep.py): a wrap's port
against a finite-difference solution of its boundary-value problem, the chaining of zones,
the sticking model (analytic/serpentine_rotational.py) as the creep factor grows, the
damping against a quadratic eigenproblem solved directly, the tangent stiffness against
differences of the force law, bad input.  Each check shows that a perturbed input moves
the answer beyond its tolerance."""
import math

import numpy as np
import pytest
from scipy.linalg import eig
from scipy.sparse import diags
from scipy.sparse.linalg import spsolve

from analytic import belt_steady
from analytic import serpentine_creep as sc
from analytic import serpentine_rotational as sr

EA, C, V, MU = 2e4, 1e5, 3.6, 0.8
S = 2j * math.pi * 80.0
#: second-order differences on 4001 points over 5 cm: we see 2e-6 relative
BVP = 1e-4
#: the identity of chaining two parts of one zone: we see 1e-15
CHAIN = 1e-12
#: the sticking limit at c = 1e12 kg/(m s): the lag sqrt(EA / (omega c)) is 6e-6 of a span;
#: we see 1e-5 relative
STICK = 1e-4
THREE = [
    {"name": "crank", "centre": (0.0, 0.0), "radius": 0.08, "side": 1, "law": "prescribed",
     "omega": 40.0},
    {"name": "tensioner", "centre": (0.2, 0.02), "radius": 0.03, "side": -1,
     "law": "tensioner", "pivot": (0.28, 0.0), "stiffness": 20.0, "preload": 8.0},
    {"name": "ac", "centre": (0.35, 0.2), "radius": 0.06, "side": 1, "law": "driven",
     "torque": 3.0}]


def _fd_port(a, b, L, n=4001):
    """[w'(0), w'(L)] for w(0) = 1, w(L) = 0 of w'' = a w' + b w by central differences."""
    h = L / (n - 1)
    lower = np.full(n - 1, 1 / h ** 2 + a / (2 * h), complex)
    main = np.full(n, -2 / h ** 2 - b, complex)
    upper = np.full(n - 1, 1 / h ** 2 - a / (2 * h), complex)
    main[[0, -1]], upper[0], lower[-1] = 1, 0, 0
    rhs = np.zeros(n, complex)
    rhs[0] = 1
    w = spsolve(diags([lower, main, upper], [-1, 0, 1], format="csc"), rhs)
    return np.array([(-3 * w[0] + 4 * w[1] - w[2]) / (2 * h),
                     (3 * w[-1] - 4 * w[-2] + w[-3]) / (2 * h)])


@pytest.mark.parametrize("a, b", [(C * V / EA, C * S / EA), (-MU / 0.05, 0.0)])
def test_zone_port_solves_its_boundary_value_problem(a, b):
    L = 0.05
    D = sc.zone_port(EA, L, a, b)
    fd = _fd_port(a, b, L)
    assert np.max(np.abs(D[:, 0] - fd)) <= BVP * np.max(np.abs(fd))
    moved = _fd_port(1.1 * a + 1.0, 1.1 * b, L)
    assert np.max(np.abs(D[:, 0] - moved)) > 100 * BVP * np.max(np.abs(fd))


def test_chained_parts_equal_the_whole_zone():
    a, b = C * V / EA, C * S / EA
    whole = sc.zone_port(EA, 0.08, a, b)
    parts = sc.chain(sc.zone_port(EA, 0.03, a, b), sc.zone_port(EA, 0.05, a, b))
    assert np.max(np.abs(parts - whole)) <= CHAIN * np.max(np.abs(whole))
    other = sc.chain(sc.zone_port(EA, 0.03, a, b), sc.zone_port(EA, 0.05, 0.0, 0.0))
    assert np.max(np.abs(other - whole)) > 1e-3 * np.max(np.abs(whole))


def _drive():
    """Inertias, the steady tensions at 200 N installed and the arm's steady angle."""
    L0 = belt_steady.path_length(THREE) / (1 + 200.0 / EA)
    st = belt_steady.solve(THREE, EA=EA, rhoA=0.12, L0=L0, mu=MU)
    T = [s["tension_N"] for s in st["spans"]]
    angle = next(p["arm_angle_rad"] for p in st["pulleys"] if p["law"] == "tensioner")
    return {"J": [1.0, 5e-5, 3e-4], "T": T, "J_arm": 1e-3, "arm_angle": angle}


def test_sticking_limit_is_the_sticking_model():
    """c -> infinity at V = 0 (at V != 0 the entering belt's creep stays: docstring)."""
    d = _drive()
    stick = sr.modes(THREE, EA=EA, driver="fixed", **d)
    for c, close in ((1e12, True), (1e5, False)):
        got = sc.modes(THREE, EA=EA, creep=c, mu=MU, transport_speed=0.0, **d)
        err = np.max(np.abs(np.array(got["frequencies_hz"]) / stick["frequencies_hz"] - 1))
        assert (err <= STICK) == close, (c, err)
        assert got["labels"] == stick["labels"]


def test_damping_equals_the_quadratic_eigenproblem():
    """Sticking limit with bearing and arm damping: s of det(s^2 M + s C + K) = 0 by
    scipy's generalized eigensolver on the companion pencil, to 1e-5 (V = 0; the layer's
    lag at c = 1e14 leaves 1.3e-6)."""
    d = _drive()
    damping, arm = [0.0, 1e-5, 1e-3], 0.05
    got = sc.modes(THREE, EA=EA, creep=1e14, mu=MU, transport_speed=0.0, damping=damping,
                   arm_damping=arm, **d)
    mat = sr.matrices(THREE, EA=EA, **d)
    Q = np.delete(np.eye(4), 0, axis=1)
    M, K = Q.T @ mat["M"] @ Q, Q.T @ mat["K"] @ Q
    Cm = Q.T @ np.diag(damping + [arm]) @ Q
    Z, I = np.zeros((3, 3)), np.eye(3)
    s = eig(np.block([[Z, I], [-K, -Cm]]), np.block([[I, Z], [Z, M]]), right=False)
    s = np.sort_complex(s[s.imag > 0])
    ref = np.sort(np.abs(s.imag)) / (2 * math.pi)
    zeta = (-s.real / np.abs(s))[np.argsort(np.abs(s.imag))]
    np.testing.assert_allclose(got["frequencies_hz"], ref, rtol=1e-5)  # seen 1.3e-6
    np.testing.assert_allclose(got["damping_ratios"], zeta, rtol=0, atol=1e-5)  # seen 1.3e-6
    assert got["damping_ratios"][0] > 0.01
    undamped = sc.modes(THREE, EA=EA, creep=1e14, mu=MU, transport_speed=0.0, **d)
    assert abs(undamped["damping_ratios"][0]) < 1e-6


@pytest.mark.parametrize("strain", sc.STRAINS)
def test_tangent_stiffness_is_the_force_laws_slope(strain):
    def force(lam):
        return EA * (lam - 1) if strain == "engineering" else EA * lam * (lam * lam - 1) / 2
    lam, h = 1.012, 1e-6
    T = force(lam)
    slope = lam * (force(lam + h) - force(lam - h)) / (2 * h)
    got = float(sc.tangent_stiffness(EA, T, strain))
    assert got == pytest.approx(slope, rel=1e-8)
    assert got != pytest.approx(EA, rel=1e-3)


def test_saturated_zone_softens_the_drive():
    d = _drive()
    free = sc.modes(THREE, EA=EA, creep=C, mu=MU, transport_speed=V, **d)
    L = THREE[2]["radius"] * sr.matrices(THREE, EA=EA, **d)["layout"].wrap[2]
    zones = [[], [], [(0.8 * L, L, -1)]]
    sat = sc.modes(THREE, EA=EA, creep=C, mu=MU, transport_speed=V, zones=zones, **d)
    k = free["labels"].index("theta_ac")
    assert sat["frequencies_hz"][k] < 0.995 * free["frequencies_hz"][k]


@pytest.mark.parametrize("kwargs, field", [
    ({"creep": 0.0}, "creep"), ({"mu": -0.1}, "mu"), ({"zones": [[], []]}, "zones"),
    ({"zones": [[], [], [(0.0, 9.0, 1)]]}, "zones[2]"),
    ({"zones": [[], [], [(0.0, 0.01, 2)]]}, "zones[2]"),
    ({"damping": [0.0, -1.0, 0.0]}, "damping[1]"), ({"arm_damping": -1.0}, "arm_damping"),
    ({"belt_damping": -1.0}, "belt_damping"), ({"EA": [EA, EA]}, "EA"),
    ({"transport_speed": float("nan")}, "transport_speed")])
def test_bad_input_names_the_field(kwargs, field):
    args = {"EA": EA, "creep": C, "mu": MU, "transport_speed": V, **_drive(), **kwargs}
    with pytest.raises(ValueError, match=field.replace("[", r"\[").replace("]", r"\]")):
        sc.modes(THREE, **args)


def test_bad_strain_law():
    with pytest.raises(ValueError, match="strain"):
        sc.tangent_stiffness(EA, 100.0, "hencky")
