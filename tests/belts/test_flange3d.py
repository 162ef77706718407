"""Flanged pulleys of the plate belt (ancf.belts.flange3d, issue 36): the kernel's exact
derivatives against central differences, its force law, and the drive-file keys
``flanges``, ``face_width_m``, ``flange_height_m`` with their bad input."""
import numpy as np
import pytest

from ancf.belts import flange3d
from ancf.belts.drive_file import load, wrap_walk
from ancf.cli import main
from ancf.common.paths import REPO

THREE3D = REPO / "examples" / "three_pulleys_3d.toml"
THREE2D, SERPENTINE3D = REPO / "examples" / "three_pulleys.toml", REPO / "examples" / \
    "serpentine_3d.toml"
A, W, R, H = 0.02, 0.04, 0.05, 0.004  # element length, belt width, radius, flange height, m
KF, CF = 2.4e5, 6.0                    # N/m^2, N s/m^2 (k_p h, c_p h of three_pulleys_3d)


def _case(lift: float, seed: int = 1) -> tuple:
    """One plate across a flanged pulley (axis turned 2 deg from e_z, mid-face at z = W / 2),
    its mid surface ``lift`` m above the rim, 1 mm wider than the face (both edges
    pressed), perturbed at random: (E, V (1, 12, 3), S, w, table, o, odot, axes, radii)."""
    rng = np.random.default_rng(seed)
    E = np.zeros((1, 12, 3))
    for k, (x, y) in enumerate(((0, 0), (1, 0), (1, 1), (0, 1))):
        E[0, 3 * k] = (x * A - A / 2, R + lift, y * (W + 0.002) - 0.001)
        E[0, 3 * k + 1] = (1.0, 0.0, 0.0)
        E[0, 3 * k + 2] = (0.0, 0.0, 1.0)
    E[0, 0::3] += 1e-4 * rng.standard_normal((4, 3))
    E[0, 1::3] += 1e-2 * rng.standard_normal((4, 3))
    E[0, 2::3] += 1e-2 * rng.standard_normal((4, 3))
    V = 0.1 * rng.standard_normal((1, 12, 3))
    S, w = flange3d.edge_points(np.array([A]), W + 0.002, 5)
    table = np.array([[0, W / 2, W / 2, H, KF, CF]])
    a = np.radians(2.0)
    axes = np.array([[np.sin(a), 0.0, np.cos(a)]])
    return E, V, S, w, table, np.zeros((1, 3)), np.zeros((1, 3)), axes, np.array([R])


def _forces(E, V, S, w, table, o, odot, axes, radii, want_J=True) -> tuple:
    Q, K, C, Fa = np.zeros((1, 36)), np.zeros((1, 36, 36)), np.zeros((1, 36, 36)), np.zeros(1)
    pressed = flange3d.flange_forces3d(E, V, S, w, table, o, odot, axes, radii, want_J, Q, K,
                                       C, Fa)
    return Q[0], K[0], C[0], Fa[0], pressed


@pytest.mark.parametrize("lift", [0.0005, 0.0027])  # g = 1, and on the rim's taper
def test_jacobian_is_exact(lift):
    """dQ/de and dQ/dedot against central differences (step 1e-7, error O(step^2)) within
    1e-6 of their largest entry; every edge point pressed, some on the taper."""
    args = _case(lift)
    E, V = args[0], args[1]
    Q, K, C, _, pressed = _forces(*args)
    assert pressed == 10
    step = 1e-7
    for X, J in ((E, K), (V, C)):
        fd = np.zeros((36, 36))
        for j in range(36):
            for sgn in (1, -1):
                Xp = X.copy()
                Xp[0].ravel()[j] += sgn * step
                Ep, Vp = (Xp, V) if X is E else (E, Xp)
                fd[:, j] += sgn * _forces(Ep, Vp, *args[2:], want_J=False)[0] / (2 * step)
        assert np.abs(J - fd).max() <= 1e-6 * np.abs(J).max(), np.abs(J - fd).max()


def test_force_pushes_the_edges_back_along_the_axis():
    """Each edge beyond its wall is pushed back along the axis: the force's sum (over the
    nodes' position coordinates, the shape functions a partition of unity) is the axial
    force reported along p; with the plate inside the face it vanishes."""
    args = _case(0.0005)
    Q, _, _, Fa, _ = _forces(*args)
    p = args[7][0]
    S, w = args[2], args[3]
    total = Q.reshape(12, 3)[0::3].sum(axis=0)  # sum over nodes' r of the force: sum w f
    assert total == pytest.approx(Fa * p, abs=1e-9 * np.abs(Q).max())
    inside = list(args)
    inside[4] = args[4].copy()
    inside[4][0, flange3d.HALF] = W  # a face 2 W wide: no edge beyond
    assert _forces(*inside)[4] == 0 and not np.any(_forces(*inside)[0])
    assert S[0][:, 0::3].sum(axis=1) == pytest.approx(np.ones(10), abs=1e-12)  # unity
    assert w.sum() == pytest.approx(2 * A, rel=1e-12)  # two edges of length A


def test_wrap_walk_is_the_helix_advance():
    """wrap_walk: R wrap tan(tilt) without roll, the roll shrinking the effective tilt."""
    assert wrap_walk(R, np.pi, 3.0, 0.0) == pytest.approx(R * np.pi * np.tan(np.radians(3.0)))
    s = np.cos(np.radians(4.0)) * np.sin(np.radians(3.0))
    assert wrap_walk(R, 2.0, 3.0, 4.0) == pytest.approx(R * 2.0 * np.tan(np.arcsin(s)))


@pytest.mark.parametrize("path, item, words", [
    (SERPENTINE3D, "pulleys.tensioner.flanges=true", "pulleys.1.flanges = true is out of "
     "range for law = 'tensioner'; allowed: false"),
    (THREE2D, "pulleys.0.flanges=true", "pulleys.0.flanges = true is out of range for "
     "belt.element = 'dufva2d'; allowed: false"),
])
def test_flanges_only_where_they_can_act(path, item, words, capsys):
    """Flanges on a tensioner (its pulley moves with its arm) or on the 2D belt: one
    ``error:`` line, exit 2."""
    assert main(["run", "belt-drive", "--file", str(path), "--set", item]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: ") and words in err[0], err


@pytest.mark.parametrize("item, words", [
    ("pulleys.driven.face_width_m=0.03", "pulleys.2.face_width_m = 0.03 is out of range: the "
     "flanges would be inside the belt (belt.b = 0.04 m); allowed: 0 (1.1 b) or a number in "
     "[0.04, 1] m"),
    ("pulleys.driven.flange_height_m=0", "pulleys.2.flange_height_m = 0.0 is out of range; "
     "allowed: a number in (0, 0.1]"),
    ("pulleys.driven.flanges=1", "pulleys.2.flanges = 1 is not valid; allowed: true or false"),
    ("belt.b=0.01; pulleys.driven.axis_tilt_deg=5", "pulleys.2.axis_tilt_deg = 5.0 is out of "
     "range: the belt cannot wrap the tilted pulley"),
])
def test_bad_flanges_and_tilts_are_one_error_line(item, words, capsys):
    """One ``error:`` line naming the key and its allowed range, exit 2."""
    args = ["run", "belt-drive", "--file", str(THREE3D)]
    for one in item.split("; "):
        args += ["--set", one]
    assert main(args) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: ") and words in err[0], err


def test_wrap_limit_is_the_message_range(capsys):
    """The tilt limit the message gives is where wrap_walk reaches the belt's width."""
    assert main(["run", "belt-drive", "--file", str(THREE3D), "--set", "belt.b=0.01",
                 "--set", "pulleys.driven.axis_tilt_deg=5"]) == 2
    err = capsys.readouterr().err
    limit = float(err.split("allowed: a number in [-")[1].split(",")[0])
    d = load(THREE3D, ["belt.b=0.01"])
    R2, wrap = d.pulleys[2].radius, d.path.wraps[2]
    assert wrap_walk(R2, wrap, limit, 0.0) == pytest.approx(0.01, rel=1e-3)
