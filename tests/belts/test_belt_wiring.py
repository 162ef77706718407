"""How the belt scenes are wired: what the scenes hand their kernels, the sense of every
prescribed motion, the laid belt's path, the driven pulley's equation of motion.

The unit tests check each law, kernel and Jacobian alone; the acceptance checks compare
runs with references built from the scene's own parameters.  Neither sees a parameter
altered on its way from the scene into the compiled drive record, or a prescribed motion
of the wrong sense.  Here the records of the belt2d and belt3d scenes at their defaults
are held against Table 3.1 and Table 4.1 as printed (Kerkkänen 2006,
the papers folder beside the project, shared/papers/000_*.txt l. 907-925 and l. 1071-1089), written down below, not
read from the package; the laws the march evaluates against Eqs 3.29, 4.46 and 4.47
written out; the laid belt against the two-pulley path written out (a stadium); and a
short Model 2 run against I dw/dt = M_friction - T_a with the table's I.  Each runs in
seconds (tests/mutations.py plants the wiring bugs these catch).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from ancf.belts.drive2d import BeltDrive
from ancf.belts.drive3d import Belt3DDrive
from ancf.belts.friction import PARAMS
from ancf.belts.post3d import pulley_moments
from ancf.scenes import SCENES, belt2d, belt3d

#: Table 3.1 (thesis l. 910-925)
TABLE_3_1 = dict(R1=0.08125, R2=0.08125, l_s=0.382882, O1=(-0.191441, 0.0), O2=(0.191441, 0.0),
                 rho=1036.0, side=0.01, E=1.0e8, nu=0.3, k_p=1.0e7, c_p=10.0, mu=1.2, I=0.1,
                 nu_s=1.0e5, alpha1=1.0, alpha2=0.01, belt_length=1.2727)
#: Table 4.1 (thesis l. 1073-1089) with section 4.6's E, u0 and bending (l. 1318, 1322)
TABLE_4_1 = {
    1: dict(R=0.10, w=0.08, h=0.01, k_p=1.0e7, c_p=2000.0, nu_s=1.0e5, mu=1.2, rho=1036.0,
            nu=0.3, t0=0.05, t1=0.60, omega0=12.0, I=0.25, E=1.0e7, u0=0.0025, n_elements=16),
    2: dict(R=0.05, w=0.04, h=0.003, k_p=8.0e7, c_p=2000.0, nu_s=2.0e5, mu=0.6, rho=166.667,
            nu=0.3, t0=0.05, t1=1.00, omega0=500.0, I=0.00025, E=1.6667e6, u0=0.0, n_elements=20),
}


def _friction(prm) -> dict:
    """k_p, c_p and the creep-rate law's values by name from a kernel's contact record."""
    return {name: prm[name] for name in ("k_p", "c_p", *(p.name for p in PARAMS["creep-rate"]))}


def _belt_mass(element, n_per_node: int, dim: int) -> float:
    """Sum over elements of u^T M_e u, u a unit translation along x: the belt's mass, kg."""
    M = element.mass()
    u = np.zeros(M.shape[1])
    u[::n_per_node * dim] = 1.0
    return float(np.einsum("i,eij,j->", u, M, u))


def _drive2d() -> BeltDrive:
    return BeltDrive(belt2d.spec(SCENES["belt2d"].resolve({})))


def _drive3d(model: int) -> Belt3DDrive:
    return Belt3DDrive(belt3d.spec(SCENES["belt3d"].resolve({"model": model})))


# ------------------------------------------------------------------ the records

def test_belt2d_record_is_table_3_1():
    """The belt2d scene's compiled record at its defaults: pulley centres and radii, the
    penalty and friction row, the driven pulley's inertia (no damping), the belt's mass
    rho A L0 = 1036 x 0.01^2 x 1.2727 kg in its mass matrix and the element data."""
    T, drive = TABLE_3_1, _drive2d()
    k = drive.kernel()
    assert k.centres.tolist() == [list(T["O1"]), list(T["O2"])]
    assert k.radii.tolist() == [T["R1"], T["R2"]]
    assert _friction(k.prm) == {"k_p": T["k_p"], "c_p": T["c_p"], "mu": T["mu"], "nu_s": T["nu_s"]}
    assert k.free.tolist() == [-1, 0] and k.inertia.tolist() == [T["I"]]
    assert k.damping.tolist() == [0.0]
    s = drive.spec
    assert (s.E, s.nu, s.rho, s.b, s.h, s.alpha1, s.alpha2) == (
        T["E"], T["nu"], T["rho"], T["side"], T["side"], T["alpha1"], T["alpha2"])
    assert s.belt_length == pytest.approx(T["belt_length"], rel=1e-12)
    assert s.path.span == pytest.approx(T["l_s"], abs=5e-7)
    mass = T["rho"] * T["side"] ** 2 * T["belt_length"]
    assert _belt_mass(drive.element, 3, 2) == pytest.approx(mass, rel=1e-12)


@pytest.mark.parametrize("model", [1, 2])
def test_belt3d_record_is_table_4_1(model):
    """The belt3d scene's compiled record per model: centres l_s = pi R apart, radii, the
    penalty and friction row, the driven pulley's inertia (no damping), the belt's mass
    rho h w L0 in its mass matrix (L0 = 4 pi R for Model 1, the belt as long as the path)
    and the plates' data."""
    T, drive = TABLE_4_1[model], _drive3d(model)
    k = drive.kernel()
    assert k.radii.tolist() == [T["R"], T["R"]]
    assert np.linalg.norm(k.centres[1] - k.centres[0]) == pytest.approx(math.pi * T["R"],
                                                                         rel=1e-14)
    assert _friction(k.prm) == {"k_p": T["k_p"], "c_p": T["c_p"], "mu": T["mu"], "nu_s": T["nu_s"]}
    assert k.free.tolist() == [-1, 0] and k.inertia.tolist() == [T["I"]]
    assert k.damping.tolist() == [0.0]
    assert k.axes.tolist() == [[0.0, 0.0, 1.0]] * 2
    s = drive.spec
    assert (s.E, s.nu, s.rho, s.width, s.h, s.n_elements, s.bending, s.t0, s.t1) == (
        T["E"], T["nu"], T["rho"], T["w"], T["h"], T["n_elements"], model == 1, T["t0"], T["t1"])
    if model == 1:
        assert s.belt_length == pytest.approx(4 * math.pi * T["R"], rel=1e-14)
    mass = T["rho"] * T["h"] * T["w"] * s.belt_length
    assert _belt_mass(drive.element, 3, 3) == pytest.approx(mass, rel=1e-12)


# ------------------------------------------------------------------ prescribed motions

def test_belt2d_driver_follows_eq_3_29_as_the_march_sees_it():
    """The laws the march evaluates (drive.laws): driver 12 (t - 0.05)/(0.6 - 0.05) rad/s,
    0 up to 0.05 s, 12 from 0.6 s; no opposing torque at the default Ta_max = 0."""
    t = np.array([0.0, 0.05, 0.2, 0.325, 0.5, 0.59, 0.6, 0.63, 1.0])
    want = 12.0 * np.clip((t - 0.05) / (0.6 - 0.05), 0.0, 1.0)
    laws = _drive2d().laws(t)
    assert laws[0] == pytest.approx(want, abs=1e-12)
    assert laws[1].tolist() == [0.0] * t.size


@pytest.mark.parametrize("model", [1, 2])
def test_belt3d_laws_are_eqs_3_29_4_46_and_4_47(model):
    """Driver ramp from t0 to Table 4.1's t1 up to omega0; Eq. 4.47's T_a = 1 - cos(pi t)
    (Model 2: T_max = 2 N m reached at 1.0 s; Model 1: none); Eq. 4.46's u = u0 t / t0,
    then u0 (Model 1: 2.5 mm)."""
    T = TABLE_4_1[model]
    t = np.array([0.0, 0.025, 0.05, 0.3, 0.6, 0.8, 1.0, 1.2])
    w, Ta, u, du = _drive3d(model).laws(t)
    assert w == pytest.approx(T["omega0"] * np.clip((t - T["t0"]) / (T["t1"] - T["t0"]), 0, 1),
                              abs=1e-12)
    want_Ta = np.where(t <= 0.05, 0.0, np.where(t <= 1.0, 1.0 - np.cos(np.pi * t), 2.0))
    assert Ta == pytest.approx(want_Ta if model == 2 else 0.0 * t, abs=1e-12)
    assert u == pytest.approx(T["u0"] * np.minimum(t / 0.05, 1.0), abs=1e-15)
    assert du == pytest.approx(np.where(t < 0.05, T["u0"] / 0.05, 0.0), abs=1e-15)


def test_model_1_driver_moves_away_from_the_driven_pulley():
    """Eq. 4.46 pre-tensions the belt: the driver moves along x away from the driven pulley,
    the centres end l_s + u0 apart, both in the drive's geometry and in the compiled
    record's centre plus u0 times its shift."""
    T, drive = TABLE_4_1[1], _drive3d(1)
    c = drive.pulley_centres(0.2)
    assert np.linalg.norm(c[1] - c[0]) == pytest.approx(math.pi * T["R"] + T["u0"], rel=1e-14)
    k = drive.kernel()
    moved = k.centres[0] + T["u0"] * k.shift
    assert np.linalg.norm(k.centres[1] - moved) == pytest.approx(math.pi * T["R"] + T["u0"],
                                                                 rel=1e-14)


def test_model_1_belt_is_tensioned_once_the_driver_has_moved():
    """A belt as long as the path, the path lengthened by 2 u0 = 5 mm: EA 2 u0 / (4 pi R) =
    31.8 N more in a quasi-static belt (less the penalty's give).  Two short Model 1 runs
    (8 plates, 25 contact points, to 0.1 s), with the driver moved by u0 and not at all:
    the mean of the span membrane forces rises by more than a quarter of that (today
    by 16.0 N, from 34.4 N: the laid belt's bending already presses it outwards); a
    driver moved the other way lowers it (by 12.5 N)."""
    T = TABLE_4_1[1]
    mean = []
    for u0 in (T["u0"], 0.0):
        out, _ = SCENES["belt3d"].execute({"model": 1, "n_elements": 8, "contact_points": 25,
                                           "t_end": 0.1, "u0": u0})
        assert out["converged"]
        mean.append(sum(out["results"]["tensions"]["membrane"].values()) / 2)
    quasi_static = T["E"] * T["h"] * T["w"] * 2 * T["u0"] / (4 * math.pi * T["R"])
    assert mean[0] - mean[1] > quasi_static / 4


# ------------------------------------------------------------------ the laid belt

def _stadium_arclength(r, x1, x2, R):
    """Arc length (m) of points r (n, 2) on the path round two pulleys of radius R centred
    at (x1, 0) and (x2, 0), counter-clockwise from (x1, -R), and their distances from it."""
    x, y = r[:, 0], r[:, 1]
    D = x2 - x1
    s, dist = np.empty(x.size), np.empty(x.size)
    left, right = x < x1, x > x2
    lower, upper = ~left & ~right & (y < 0), ~left & ~right & (y >= 0)
    s[lower], dist[lower] = x[lower] - x1, np.abs(y[lower] + R)
    s[upper], dist[upper] = D + math.pi * R + (x2 - x[upper]), np.abs(y[upper] - R)
    a = np.arctan2(y[right], x[right] - x2)
    s[right], dist[right] = D + R * (a + math.pi / 2), np.abs(np.hypot(y[right], x[right] - x2) - R)
    a = np.mod(np.arctan2(y[left], x[left] - x1), 2 * math.pi)
    s[left] = 2 * D + math.pi * R + R * (a - math.pi / 2)
    dist[left] = np.abs(np.hypot(y[left], x[left] - x1) - R)
    return s, dist


def _equal_spacing(s, P, n):
    """The consecutive arc-length steps of a closed sequence (mod P), m."""
    return np.mod(np.diff(np.append(s, s[0])), P)


def test_belt2d_laid_belt_lies_on_the_path_at_equal_arc_spacing():
    """The nodes of belt2d's laid belt lie on the path of Table 3.1 (circles of R about O1,
    O2 and the spans y = -+R, P = 2 pi R + 2 l_s = 1.27627 m) 1e-12 m close, P/n apart
    along it to 1e-12 m, running counter-clockwise; r_x is the tangent times P/L0."""
    T, drive = TABLE_3_1, _drive2d()
    n, R = drive.spec.n_elements, T["R1"]
    P = 2 * math.pi * R + 2 * T["l_s"]
    q = drive.q0.reshape(n, 3, 2)
    s, dist = _stadium_arclength(q[:, 0], T["O1"][0], T["O2"][0], R)
    assert dist.max() < 1e-12
    assert _equal_spacing(s, P, n) == pytest.approx(np.full(n, P / n), abs=1e-6 * P / n)
    assert np.linalg.norm(q[:, 1], axis=1) == pytest.approx(
        np.full(n, P / T["belt_length"]), rel=5e-6)


@pytest.mark.parametrize("model", [1, 2])
def test_belt3d_laid_belt_lies_on_the_path_at_equal_arc_spacing(model):
    """Both edges of belt3d's laid belt: the stadium of Table 4.1 (P = 4 pi R), P/n apart."""
    T, drive = TABLE_4_1[model], _drive3d(model)
    n, R = T["n_elements"], T["R"]
    q = drive.q0.reshape(n, 2, 3, 3)
    for edge, z in ((0, 0.0), (1, T["w"])):
        assert np.all(q[:, edge, 0, 2] == z)
        s, dist = _stadium_arclength(q[:, edge, 0, :2], 0.0, math.pi * R, R)
        assert dist.max() < 1e-12
        P = 4 * math.pi * R
        assert _equal_spacing(s, P, n) == pytest.approx(np.full(n, P / n), abs=1e-9)


# ------------------------------------------------------------------ the driven pulley

def test_model_2_driven_pulley_obeys_its_equation_of_motion_during_the_ramp():
    """Eq. 3.26 for the driven pulley: I (w(t2) - w(t1)) = int (M_f - T_a) dt, M_f the moment
    of the friction forces on it (post-processed from the run's states), T_a Eq. 4.47
    written out, I Table 4.1's 0.00025 kg m^2.  A short Model 2 run (10 plates, 25 contact
    points, every step sampled, to 0.08 s) over 0.05-0.08 s and 0.06-0.08 s: today
    3e-7 and 4.1e-6 apart (the trapezoidal rule over the 1e-4 s samples); tolerance 2e-5
    (5 x today's; an inertia 1.25 x off is 25 % off)."""
    out = SCENES["belt3d"].execute({"n_elements": 10, "contact_points": 25, "t_end": 0.08,
                                    "output_dt": 1e-4})[1]
    assert out.converged
    res, drive = out.extra["result"], out.extra["drive"]
    t, w = res.t, res.v[:, -1]
    Mf = np.array([pulley_moments(drive, x, v, ti)[1] for x, v, ti in zip(res.q, res.v, t)])
    Ta = np.where(t <= 0.05, 0.0, 1.0 - np.cos(np.pi * t))
    I = TABLE_4_1[2]["I"]
    for t1 in (0.05, 0.06):
        i, j = np.searchsorted(t, [t1 - 1e-9, 0.08 - 1e-9])
        impulse = np.trapezoid(Mf[i:j + 1] - Ta[i:j + 1], t[i:j + 1])
        assert I * (w[j] - w[i]) > 1e-3   # the pulley is spun up, not at rest
        assert impulse == pytest.approx(I * (w[j] - w[i]), rel=2e-5)
