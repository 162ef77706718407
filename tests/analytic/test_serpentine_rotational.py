"""The rotational modes of a serpentine drive (analytic/serpentine_rotational.py): two
pulleys against the closed form of two inertias on two springs; the stiffness matrix against
a finite-difference Hessian of the potential energy built here from belt_layout.wrap at the
turned arm; a three-pulley drive with a tensioner on belt_steady.solve's tensions; bad input.
Each check also shows that a perturbed input moves the answer beyond its tolerance."""
import math

import numpy as np
import pytest

from analytic import belt_steady
from analytic import serpentine_rotational as sr
from analytic.belt_layout import wrap

#: eigh on 2 x 2 and 1 x 1 problems: we see 2e-16 relative
CLOSED_FORM = 1e-12
#: finite differences of 1e-4 rad on the exact energy: we see 1.4e-8 of max |K| (the h^2
#: truncation in psi)
HESSIAN = 1e-6
#: central differences of 1e-3 relative on the arm spring: we see 7e-11 relative
SENSITIVITY = 1e-6
EA = 1e5

#: crankshaft (driver), a tensioner on the back of its slack span, an a/c compressor (m)
THREE = [
    {"name": "crank", "centre": (0.0, 0.0), "radius": 0.08, "side": 1, "law": "prescribed",
     "omega": 100.0},
    {"name": "tensioner", "centre": (0.2, 0.02), "radius": 0.03, "side": -1,
     "law": "tensioner", "pivot": (0.28, 0.0), "stiffness": 20.0, "preload": 8.0},
    {"name": "ac", "centre": (0.35, 0.2), "radius": 0.06, "side": 1, "law": "driven",
     "torque": 5.0}]
#: a tensioner on the belt's inner side between two accessories
FOUR = [
    {"name": "crank", "centre": (0.0, 0.0), "radius": 0.08, "side": 1, "law": "prescribed",
     "omega": 100.0},
    {"name": "ac", "centre": (0.3, 0.05), "radius": 0.06, "side": 1, "law": "driven",
     "torque": 5.0},
    {"name": "tensioner", "centre": (0.2, 0.3), "radius": 0.04, "side": 1, "law": "tensioner",
     "pivot": (0.1, 0.4), "stiffness": 50.0, "preload": 60.0},
    {"name": "alternator", "centre": (-0.05, 0.25), "radius": 0.03, "side": 1,
     "law": "driven", "torque": 2.0}]
ARM = {"J_arm": 5e-4, "m_t": 0.1}


def _steady(pulleys):
    """(tensions N, arm angle rad) of belt_steady.solve at 300 N installed."""
    L0 = belt_steady.path_length(pulleys) / (1 + 300.0 / EA)
    r = belt_steady.solve(pulleys, EA=EA, rhoA=0.1, L0=L0, mu=0.5)
    angle = next(p["arm_angle_rad"] for p in r["pulleys"] if p["law"] == "tensioner")
    return [s["tension_N"] for s in r["spans"]], angle


# ------------------------------------------------------------------ two pulleys, closed form
def _two(r1, r2, D=0.5):
    return [{"name": "a", "centre": (0.0, 0.0), "radius": r1, "side": 1, "law": "prescribed",
             "omega": 10.0},
            {"name": "b", "centre": (D, 0.0), "radius": r2, "side": 1, "law": "driven",
             "torque": 1.0}]


@pytest.mark.parametrize("driver", ["free", "fixed"])
def test_two_pulleys_are_two_inertias_on_two_springs(driver):
    """Both spans stretch by r2 theta2 - r1 theta1 (up to sign), so
    omega^2 = (k1 + k2) (r1^2 / J1 + r2^2 / J2) free, (k1 + k2) r2^2 / J2 with theta1 held."""
    r1, r2, J1, J2, D = 0.08, 0.05, 0.02, 0.003, 0.5
    k = 2 * EA / math.sqrt(D * D - (r1 - r2) ** 2)

    def freq(J2):
        m = sr.modes(_two(r1, r2, D), EA=EA, J=[J1, J2], T=[100.0, 300.0], driver=driver)
        assert len(m["frequencies_hz"]) == 1 and m["labels"] == ["theta_b"]
        return m["frequencies_hz"][0]

    w2 = k * ((r1 * r1 / J1 if driver == "free" else 0.0) + r2 * r2 / J2)
    assert freq(J2) == pytest.approx(math.sqrt(w2) / (2 * math.pi), rel=CLOSED_FORM)
    assert abs(freq(1.001 * J2) / freq(J2) - 1) > 100 * CLOSED_FORM


# ------------------------------------------------------------- stiffness = Hessian of energy
def _energy(pulleys, T, angle, with_arcs=True):
    """V(x) = sum_j (T_j e_j + k_j e_j^2 / 2) + k_a psi^2 / 2 from the exact path at the arm
    turned by psi: e_j = the span's length less the belt between its end points, each end a
    belt point stuck to its rim (label s r (polar angle - theta)); with_arcs=False counts
    the length change alone (the tangent points' slide round the rims left out)."""
    c = np.array([p["centre"] for p in pulleys], float)
    r = np.array([p["radius"] for p in pulleys])
    sides = [p["side"] for p in pulleys]
    t = next(i for i, p in enumerate(pulleys) if p["law"] == "tensioner")
    pivot = np.array(pulleys[t]["pivot"])
    c[t] = pivot + np.hypot(*(c[t] - pivot)) * np.array([math.cos(angle), math.sin(angle)])
    names, N = [p["name"] for p in pulleys], len(pulleys)
    # an inner-side driver turning counter-clockwise runs the belt counter-clockwise
    o = 1

    def path(psi):
        cc = c.copy()
        R = np.array([[math.cos(psi), -math.sin(psi)], [math.sin(psi), math.cos(psi)]])
        cc[t] = pivot + R @ (c[t] - pivot)
        lay = wrap(cc, r, sides, names, o)
        nxt = np.roll(np.arange(N), -1)
        out = np.arctan2(*(lay.start - cc).T[::-1])
        into = np.arctan2(*(lay.end - cc[nxt]).T[::-1])
        return lay, out, into

    lay0, out0, in0 = path(0.0)
    s, k = lay0.sense, EA / lay0.span

    def V(x):
        theta, psi = x[:N], x[N]
        lay, out, into = path(psi)
        sr_ = s * r
        e = lay.span - lay0.span + np.roll(sr_ * theta, -1) - sr_ * theta
        if with_arcs:  # the polar angles' changes, each within (-pi, pi]
            turned = lambda a, a0: np.angle(np.exp(1j * (a - a0)))  # noqa: E731
            e += sr_ * turned(out, out0) - np.roll(sr_, -1) * turned(into, in0)
        return T @ e + 0.5 * k @ e ** 2 + 0.5 * pulleys[t]["stiffness"] * psi ** 2

    return V


def _hessian(V, n, h=1e-4):
    H = np.zeros((n, n))
    for a in range(n):
        for b in range(n):
            f = lambda sa, sb: V(h * (sa * np.eye(n)[a] + sb * np.eye(n)[b]))  # noqa: E731
            H[a, b] = (f(1, 1) - f(1, -1) - f(-1, 1) + f(-1, -1)) / (4 * h * h)
    return H


@pytest.mark.parametrize("pulleys", [THREE, FOUR], ids=["back-side", "inner-side"])
def test_stiffness_is_the_hessian_of_the_exact_energy(pulleys):
    T, angle = _steady(pulleys)
    K = sr.matrices(pulleys, EA=EA, J=[1e-3] * len(pulleys), T=T, arm_angle=angle, **ARM)["K"]
    n = len(K)
    H = _hessian(_energy(pulleys, np.array(T), angle), n)
    assert np.max(np.abs(K - H)) <= HESSIAN * np.max(np.abs(K))
    H_lengths = _hessian(_energy(pulleys, np.array(T), angle, with_arcs=False), n)
    assert np.max(np.abs(K - H_lengths)) > 100 * HESSIAN * np.max(np.abs(K))


# ------------------------------------------------------------ three pulleys with a tensioner
def _modes(stiffness, driver="fixed", m_t=ARM["m_t"]):
    pulleys = [dict(p) for p in THREE]
    pulleys[1]["stiffness"] = stiffness
    T, angle = _steady(THREE)  # the steady state at the nominal spring; only K changes
    return sr.modes(pulleys, EA=EA, J=[0.01, 1e-4, 0.002], T=T, arm_angle=angle,
                    driver=driver, J_arm=ARM["J_arm"], m_t=m_t)


def _arm_mode(m):
    return m["labels"].index("psi")


@pytest.mark.parametrize("driver", ["fixed", "free"])
def test_three_pulleys_soft_arm(driver):
    """Real positive frequencies; the lowest mode is the arm's on a soft spring; stiffening
    the spring raises it, at the rate d omega^2 / d k_a = phi_psi^2 of a mass-normalised
    shape (eq. 3: k_a enters K only at psi, psi), checked by central differences."""
    k_a = THREE[1]["stiffness"]
    m = _modes(k_a, driver)
    f = m["frequencies_hz"]
    assert len(f) == len(THREE) and np.all(np.isfinite(f)) and f[0] > 0
    assert np.all(np.diff(f) > 0) and m["labels"][0] == "psi"
    if driver == "fixed":
        assert np.all(m["shapes"][0] == 0.0)  # the crankshaft is held
    i = _arm_mode(m)
    w2 = lambda k: (2 * math.pi * _modes(k, driver)["frequencies_hz"][i]) ** 2  # noqa: E731
    dk = 1e-3 * k_a
    rate = (w2(k_a + dk) - w2(k_a - dk)) / (2 * dk)
    phi_psi = m["shapes"][-1, i]
    assert rate == pytest.approx(phi_psi ** 2, rel=SENSITIVITY)
    heavier = _modes(k_a, driver, m_t=1.01 * ARM["m_t"])["shapes"][-1, i]
    assert abs(rate / heavier ** 2 - 1) > 100 * SENSITIVITY
    stiff = _modes(10 * k_a, driver)
    assert stiff["frequencies_hz"][_arm_mode(stiff)] > f[i]


# ---------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("change, field", [
    ({"J": [0.01, -1e-4, 0.002]}, r"J\[1\] must be > 0"),
    ({"T": [300.0, 300.0]}, "T must list 3"),
    ({"EA": 0.0}, "EA must be > 0"),
    ({"J_arm": None}, "J_arm"),
    ({"m_t": -1.0}, "m_t must be >= 0"),
    ({"arm_angle": math.nan}, "arm_angle must be finite"),
    ({"driver": "held"}, "driver = 'held'"),
    ({"belt_mass": -0.1}, "belt_mass must be >= 0 kg/m"),
    ({"belt_mass": math.inf}, "belt_mass must be finite"),
    ({"belt_speed": math.nan}, "belt_speed must be finite")])
def test_bad_input_names_the_field(change, field):
    args = dict({"EA": EA, "J": [0.01, 1e-4, 0.002], "T": [300.0, 300.0, 400.0]}, **ARM)
    with pytest.raises(ValueError, match=field) as err:
        sr.modes(THREE, **dict(args, **change))
    assert "\n" not in str(err.value)


def test_an_arm_without_a_tensioner_is_refused():
    with pytest.raises(ValueError, match="J_arm = 0.001 is given but no pulley is a tensioner"):
        sr.modes(_two(0.08, 0.05), EA=EA, J=[1.0, 1.0], T=[1.0, 1.0], J_arm=1e-3)


def test_a_tension_that_buckles_the_arm_is_refused():
    """A short arm the belt pushes towards its pivot: sum_j T_j g_j'' = T a . (d_t - d_t-1)
    + T (m . Delta')^2 / l < 0 (eq. 2), about -10 N m/rad at T = 1 kN; a spring of 20 N m/rad
    holds it, none does not."""
    pulleys = [dict(p) for p in THREE]
    args = dict(EA=1.0, J=[0.01, 1e-4, 0.002], T=[1e3] * 3, **ARM)
    pulleys[1].update(pivot=(0.23, -0.025), stiffness=20.0)
    assert sr.modes(pulleys, **args)["frequencies_hz"][0] > 0
    pulleys[1]["stiffness"] = 0.0
    with pytest.raises(ValueError, match=r"pulleys.1.stiffness: the belt's tension buckles"):
        sr.modes(pulleys, **args)


# ------------------------------------------------------------------------- belt inertia
#: the belt's mass per length, kg/m, and speed, m/s
RHOA, SPEED = 0.12, 20.0
#: quadrature of the material points' velocities by central differences of 1e-5 rad: we see
#: 6e-11 of max |M_b| (the h^2 truncation and round-off / h)
QUADRATURE = 1e-9


@pytest.mark.parametrize("driver", ["free", "fixed"])
def test_no_belt_mass_is_the_massless_model(driver):
    """belt_mass = 0 (any belt_speed) returns the model of eqs. (1)-(4) bit for bit."""
    T, angle = _steady(THREE)
    args = dict(EA=EA, J=[0.01, 1e-4, 0.002], T=T, arm_angle=angle, driver=driver, **ARM)
    old = sr.modes(THREE, **args)
    new = sr.modes(THREE, belt_mass=0.0, belt_speed=SPEED, **args)
    for key in ("frequencies_hz", "shapes"):
        assert np.array_equal(new[key], old[key])
    assert new["labels"] == old["labels"]
    light = sr.modes(THREE, belt_mass=1e-9, **args)["frequencies_hz"]
    assert not np.array_equal(light, old["frequencies_hz"])


@pytest.mark.parametrize("driver", ["free", "fixed"])
def test_two_pulleys_with_belt_mass(driver):
    """Two pulleys, one span of length l each way: the belt on pulley i (wrap w_i) adds
    m r_i^3 w_i to J_i, each span (a bar whose ends move at r_1 theta_1', r_2 theta_2')
    m l (r_1^2 theta_1'^2 + r_1 r_2 theta_1' theta_2' + r_2^2 theta_2'^2) / 6 to the kinetic
    energy.  Held driver: omega^2 = k r_2^2 / (J_2 + m r_2^3 w_2 + 2 m l r_2^2 / 3), k the
    two spans' EA / l; free: omega^2 = k v^T M^-1 v, v = (-r_1, r_2) (K = k v v^T)."""
    r1, r2, J1, J2, D = 0.08, 0.05, 0.02, 0.003, 0.5
    l = math.sqrt(D * D - (r1 - r2) ** 2)
    w1 = math.pi + 2 * math.asin((r1 - r2) / D)
    w2 = 2 * math.pi - w1
    k = 2 * EA / l

    def closed(m, lumped=False):
        share = 1 / 2 if lumped else 1 / 3
        M11 = J1 + m * r1 ** 3 * w1 + 2 * m * l * r1 * r1 * share
        M22 = J2 + m * r2 ** 3 * w2 + 2 * m * l * r2 * r2 * share
        M12 = 0.0 if lumped else m * l * r1 * r2 / 3
        if driver == "fixed":
            w_sq = k * r2 * r2 / M22
        else:
            w_sq = k * (r1 * r1 * M22 + 2 * r1 * r2 * M12 + r2 * r2 * M11) / (M11 * M22 - M12 ** 2)
        return math.sqrt(w_sq) / (2 * math.pi)

    f = sr.modes(_two(r1, r2, D), EA=EA, J=[J1, J2], T=[100.0, 300.0], driver=driver,
                 belt_mass=RHOA)["frequencies_hz"]
    assert len(f) == 1 and f[0] == pytest.approx(closed(RHOA), rel=CLOSED_FORM)
    # the consistent bar mass matters: lumped span masses (l / 2 at each end) miss it
    assert abs(closed(RHOA, lumped=True) / f[0] - 1) > 100 * CLOSED_FORM
    assert abs(closed(1.001 * RHOA) / f[0] - 1) > 100 * CLOSED_FORM


def _quadrature(lay, m, t, pivot, n, h=1e-5, points=24):
    """M_b = sum m ds J^T J over the belt's material points, J = dx / dq by central
    differences of the points moved rigidly with their pulley (the tensioner's centre
    turning about the pivot by psi, the last coordinate): on each wrap, Gauss-Legendre in the
    polar angle; on each span, x linear between its end points' (Gauss in the fraction)."""
    N = len(lay.span)

    def moved(i, x0, q):
        c = lay.centres[i]
        R = lambda a: np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])  # noqa
        centre = pivot + R(q[-1]) @ (c - pivot) if i == t else c
        return centre + R(q[i]) @ (x0 - c)

    def jac(i, x0):
        return np.stack([(moved(i, x0, h * e) - moved(i, x0, -h * e)) / (2 * h)
                         for e in np.eye(n)], axis=1)

    out = np.zeros((n, n))
    xg, wg = np.polynomial.legendre.leggauss(points)
    for i in range(N):
        x_in = lay.end[i - 1] - lay.centres[i]
        a0, sweep = math.atan2(x_in[1], x_in[0]), lay.sense[i] * lay.wrap[i]
        for x, w in zip(xg, wg):
            a = a0 + sweep * (x + 1) / 2
            Jx = jac(i, lay.centres[i] + lay.radii[i] * np.array([math.cos(a), math.sin(a)]))
            out += m * lay.radii[i] * lay.wrap[i] * w / 2 * Jx.T @ Jx
        Ja, Jb = jac(i, lay.start[i]), jac((i + 1) % N, lay.end[i])
        xs, ws = np.polynomial.legendre.leggauss(3)  # exact for the quadratic integrand
        for x, w in zip(xs, ws):
            Jx = (1 - x) / 2 * Ja + (1 + x) / 2 * Jb
            out += m * lay.span[i] * w / 2 * Jx.T @ Jx
    return out


@pytest.mark.parametrize("pulleys", [THREE, FOUR], ids=["back-side", "inner-side"])
def test_belt_inertia_is_the_material_points_kinetic_energy(pulleys):
    """M with belt_mass less M without = the quadrature of eqs. (5)-(6)'s kinetic energy;
    at an arm turned by 1e-3 rad the quadrature differs beyond the tolerance."""
    T, angle = _steady(pulleys)
    args = dict(EA=EA, J=[1e-3] * len(pulleys), T=T, **ARM)
    mat = sr.matrices(pulleys, arm_angle=angle, belt_mass=RHOA, **args)
    Mb = mat["M"] - sr.matrices(pulleys, arm_angle=angle, **args)["M"]
    t, n = mat["tensioner"], len(Mb)
    pivot = np.array(pulleys[t]["pivot"], float)
    Q = _quadrature(mat["layout"], RHOA, t, pivot, n)
    assert np.max(np.abs(Mb - Q)) <= QUADRATURE * np.max(np.abs(Mb))
    assert abs(Mb[t, -1]) > 100 * QUADRATURE * np.max(np.abs(Mb))  # the wrap's cross term
    turned = sr.matrices(pulleys, arm_angle=angle + 1e-3, **args)["layout"]
    Q_turned = _quadrature(turned, RHOA, t, pivot, n)
    assert np.max(np.abs(Q_turned - Q)) > 100 * QUADRATURE * np.max(np.abs(Mb))


@pytest.mark.parametrize("driver", ["free", "fixed"])
def test_belt_mass_lowers_every_frequency(driver):
    """M_b is positive semi-definite and K does not change at belt_speed = 0, so every
    omega^2 = min-max of the Rayleigh quotient falls; more mass, lower still."""
    T, angle = _steady(THREE)
    args = dict(EA=EA, J=[0.01, 1e-4, 0.002], T=T, arm_angle=angle, driver=driver, **ARM)
    f0 = sr.modes(THREE, **args)["frequencies_hz"]
    f1 = sr.modes(THREE, belt_mass=RHOA, **args)["frequencies_hz"]
    f2 = sr.modes(THREE, belt_mass=2 * RHOA, **args)["frequencies_hz"]
    assert np.all(f1 < f0 * (1 - 1e-3)) and np.all(f2 < f1 * (1 - 1e-3))


def test_belt_speed_lowers_the_tensions_on_the_arm():
    """K at belt_speed c equals K at speed 0 on the tensions T_j - m c^2 (the g_j'' term of
    eq. 3, the spans' k_j kept); beyond the tolerance from K at the full tensions."""
    T, angle = _steady(THREE)
    args = dict(EA=EA, J=[0.01, 1e-4, 0.002], arm_angle=angle, belt_mass=RHOA, **ARM)
    K = sr.matrices(THREE, T=T, belt_speed=SPEED, **args)["K"]
    K_low = sr.matrices(THREE, T=np.array(T) - RHOA * SPEED ** 2, **args)["K"]
    K_full = sr.matrices(THREE, T=T, **args)["K"]
    assert np.max(np.abs(K - K_low)) <= CLOSED_FORM * np.max(np.abs(K))
    assert np.max(np.abs(K - K_full)) > 100 * CLOSED_FORM * np.max(np.abs(K))
