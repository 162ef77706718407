"""The steady running state in the axially moving description (ancf.belts.ale2d,
ancf.belts.steady2d, ``ancf steady belt-drive``): the transport map and the steady flow's
inertia exact, the Jacobian against finite differences, the serpentine's steady state
against the march's (reports/data/belt_drives_serpentine_spans.csv, written by the
belt_drives chapter from ``ancf run belt-drive``), hubloads against the span tensions,
bad input."""
from __future__ import annotations

import csv

import numpy as np
import pytest

from ancf.belts.ale2d import spin_matrix, transport_map
from ancf.common.paths import REPO
from ancf.elements.basis import cubic2d_S, cubic2d_x

SERPENTINE = str(REPO / "examples" / "serpentine.toml")


def test_transport_map_gives_the_field_slope_exactly():
    """S (P E) = S_x E at every point of the element (centreline and section), so the
    material velocity vb r_x is what the kernels see; a wrong r_xx row fails."""
    rng = np.random.default_rng(1)
    l = np.array([0.013, 0.05])
    P = transport_map(l)
    E = rng.standard_normal((2, 12))
    for e in range(2):
        x, y = np.meshgrid(np.linspace(0, l[e], 7), np.linspace(-0.004, 0.004, 3))
        S = cubic2d_S(x, y, np.full_like(x, l[e]))          # (..., 6)
        Sx = cubic2d_x(x, y, np.full_like(x, l[e]))
        field = lambda Sh, q: np.einsum("...k,kd->...d", Sh, q.reshape(6, 2))  # noqa: E731
        slope = field(Sx, E[e])
        assert np.abs(field(S, P[e] @ E[e]) - slope).max() <= 1e-12 * np.abs(slope).max()
    bad = P.copy()
    bad[:, 2, 0] *= 1.01
    assert np.abs(field(S, bad[1] @ E[1]) - slope).max() > 1e-6


def test_spin_matrix_is_the_integral_of_the_slopes():
    """M_x = P^T M P equals rho int S_x^T S_x dV by Gauss quadrature (4 x 2 points: the
    integrand is quartic in x, quadratic in y)."""
    from ancf.core.quadrature import RectangularSection
    from ancf.elements.dufva2d import DufvaBelt2D
    l, b, h, rho = 0.02, 0.03, 0.004, 1100.0
    e0 = np.array([0, 0, 1, 0, 0, 1, l, 0, 1, 0, 0, 1], dtype=float)[None]
    el = DufvaBelt2D(np.array([l]), e0, RectangularSection(b, h), E=1e8, nu=0.3, rho=rho)
    Mx = spin_matrix(el.mass(), transport_map([l]))[0]
    gx, wx = np.polynomial.legendre.leggauss(4)
    gy, wy = np.polynomial.legendre.leggauss(2)
    ref = np.zeros((12, 12))
    for xi, wi in zip(gx, wx):
        for yj, wj in zip(gy, wy):
            Sx = cubic2d_x(l * (xi + 1) / 2, h * yj / 2, l)
            B = np.kron(Sx, np.eye(2))                       # (2, 12)
            ref += rho * b * (l / 2) * (h / 2) * wi * wj * B.T @ B
    assert np.abs(Mx - ref).max() <= 1e-12 * np.abs(ref).max()


@pytest.fixture(scope="module")
def serpentine():
    """The serpentine drive's steady state (problem, state) and the scene's run."""
    from ancf.scenes.belt_steady import SCENE
    out, res = SCENE.execute({"file": SERPENTINE})
    return out, res


def test_jacobian_matches_finite_differences(serpentine):
    """The steady equations' Jacobian (belt, transport speed, pulley speeds, arm angle)
    against central differences at the serpentine's steady state, within 1e-6 relative per
    column (seen: 8e-8)."""
    _, res = serpentine
    pb, st = res.extra["problem"], res.extra["steady"]
    u = pb.split(st.x, st.w, st.vb)
    J = pb.residual(st.x, st.w, st.vb, 1.0)[1].toarray()
    cols = list(range(0, pb.n - 1, 37)) + list(range(pb.n - 1, u.size))
    h = 1e-7
    for c in cols:
        up, um = u.copy(), u.copy()
        up[c] += h
        um[c] -= h
        d = (pb.residual(*pb.join(up, st.x), 1.0, False)[0]
             - pb.residual(*pb.join(um, st.x), 1.0, False)[0]) / (2 * h)
        assert np.abs(d - J[:, c]).max() <= 1e-6 * np.abs(J[:, c]).max(), c
    assert J.shape == (pb.n + pb.k, pb.n + pb.k)  # square: the gauge's column is vb's


def _march_spans() -> dict:
    path = REPO / "reports" / "data" / "belt_drives_serpentine_spans.csv"
    with open(path, encoding="utf-8") as f:
        return {row["span"]: float(row["ours N"]) for row in csv.DictReader(f)}


def test_serpentine_spans_match_the_march(serpentine):
    """Span tensions within 0.5 % of the march's steady window (the belt_drives chapter's
    run of the same file); seen: 0.07-0.26 %."""
    out, _ = serpentine
    assert out["converged"] and not out["warnings"]
    march = _march_spans()
    for s in out["results"]["spans"]:
        T = march[f"{s['from']} → {s['to']}"]
        assert abs(s["tension_mean_N"] / T - 1) <= 0.005, s


def test_hubloads_are_the_span_tensions_summed(serpentine):
    """Each pulley's hubload equals the vector sum of its two spans' tensions less the
    belt's centrifugal rho A v^2 (the wrap's own inertia), within 1 % of its magnitude:
    the true force N |r_x| of the Green law's N (ancf.checks.thread.true_force), the span
    directions from the belt's points on each span."""
    out, res = serpentine
    r, desc = out["results"], res.extra["description"]
    xy = np.column_stack([r["belt_x_m"], r["belt_y_m"]])
    b = desc.belt
    rhoA = b["rho"] * b["b"] * b["h"]
    spans, N = r["spans"], len(r["pulleys"])
    ends = [desc.path(np.array([a, c]))[0] for _, a, c in desc.path.pieces()[1::2]]
    for k, p in enumerate(r["pulleys"]):
        total = np.zeros(2)
        for j, sign in ((k, 1.0), ((k - 1) % N, -1.0)):
            a, c = ends[j]  # the laid span; the belt's own points near its thirds
            near = [xy[np.argmin(np.linalg.norm(xy - (a + f * (c - a)), axis=1))]
                    for f in (1 / 3, 2 / 3)]
            e = (near[1] - near[0]) / np.linalg.norm(near[1] - near[0])
            v = spans[j]["speed_m_s"]
            stretch = v / r["transport_speed_m_s"]  # |r_x|: the Green law's N is per |r_x|
            total += sign * e * (spans[j]["tension_mean_N"] * stretch - rhoA * v * v)
        hub = np.array(p["hubload_N"])
        assert np.linalg.norm(hub - total) <= 0.01 * np.linalg.norm(hub), (p["name"], hub, total)
    assert xy.shape[0] == len(r["axial_force_N"])


@pytest.mark.slow
def test_load_changes_the_state(serpentine, cli):
    """The alternator's load torque reaches its speed and its moment (a key that matters),
    and the largest load exceeds the file's."""
    out, _ = serpentine
    rc, text, _ = cli("steady", "belt-drive", "--file", SERPENTINE, "--json",
                      "--set", "pulleys.alternator.load_torque=4.0")
    import json
    alt = [p for p in json.loads(text)["results"]["pulleys"] if p["name"] == "alternator"][0]
    base = [p for p in out["results"]["pulleys"] if p["name"] == "alternator"][0]
    assert rc == 0
    assert alt["torque_Nm"] == pytest.approx(4.0 + 1e-3 * alt["omega"], rel=1e-3)
    assert alt["omega"] < base["omega"]
    assert base["max_load_Nm"] > 2.0


@pytest.mark.parametrize("name, field", [("three_pulleys_3d.toml", "belt.element"),
                                         ("thread_benchmark.toml", "friction.law")])
def test_bad_input_is_one_line(cli, name, field):
    """The plate belt and the bristle law (a state per contact point) have no steady form:
    exit 2, one line naming the key and the allowed values."""
    rc, _, err = cli("steady", "belt-drive", "--file", str(REPO / "examples" / name))
    assert rc == 2 and err.startswith(f"error: {field}") and err.count("\n") == 1, err
    assert "allowed:" in err


def test_outputs_follow_their_schemas(serpentine, cli):
    """``ancf steady belt-drive`` and ``ancf modes belt-drive --about steady`` print JSON
    that validates against their schemas (reports/schemas.md)."""
    import json
    from ancf.study.schemas import validate
    out, _ = serpentine
    assert validate(json.loads(json.dumps(out)), "steady belt-drive") == []
    rc, text, _ = cli("modes", "belt-drive", "--file", SERPENTINE, "--count", "3", "--json")
    modes = json.loads(text)
    assert rc == 0 and len(modes["results"]["frequencies_hz"]) == 3
    assert validate(modes, "modes belt-drive") == []
    assert modes["results"]["labels"][0] == "arm tensioner"


@pytest.mark.parametrize("sets, words", [
    (("pulleys.crank.omega_final=600",), ("crank", "sqrt(T0 / rho A)")),
    (("pulleys.alternator.load_torque=30",), ("alternator", "gross slip"))])
def test_no_steady_state_is_exit_3_with_the_reason(cli, sets, words):
    """Beyond the critical speed (the wraps unload) or a load past the alternator's largest
    (11.9 N m): exit 3, the message naming the slipping pulley and the cause."""
    args = [a for s in sets for a in ("--set", s)]
    rc, out, _ = cli("steady", "belt-drive", "--file", SERPENTINE, *args)
    assert rc == 3 and all(w in out for w in words), out


@pytest.mark.parametrize("args, field", [(("--about", "reference"), "--about"),
                                         (("--count", "0"), "--count")])
def test_running_modes_bad_input(cli, args, field):
    rc, _, err = cli("modes", "belt-drive", "--file", SERPENTINE, *args)
    assert rc == 2 and err.startswith(f"error: {field}") and err.count("\n") == 1, err


@pytest.mark.slow
def test_friction_keys_change_the_answer(serpentine, cli):
    """mu sets the largest load (a wrap's capacity), nu_s the creep (the slip)."""
    import json
    base = {p["name"]: p for p in serpentine[0]["results"]["pulleys"]}
    for key, value, what in (("friction.mu", "0.4", "max_load_Nm"), ("friction.nu_s", "2e4",
                                                                     "slip")):
        rc, text, _ = cli("steady", "belt-drive", "--file", SERPENTINE, "--json",
                          "--set", f"{key}={value}")
        got = {p["name"]: p for p in json.loads(text)["results"]["pulleys"]}
        assert rc == 0
        assert abs(got["alternator"][what] / base["alternator"][what] - 1) > 0.05, key


def test_steady_route_of_recommend():
    """``ancf recommend belt-drive`` offers ``ancf steady`` where the file takes it, and
    names the key where it does not (the bristle law)."""
    from ancf.scenes.belt_steady import steady_route
    ok = steady_route({"file": SERPENTINE, "set": "friction.mu=0.7"})
    assert ok["applies"] and ok["command"].endswith("--set friction.mu=0.7")
    no = steady_route({"file": str(REPO / "examples" / "thread_benchmark.toml"), "set": ""})
    assert not no["applies"] and no["why"].startswith("friction.law")


@pytest.mark.slow
def test_a_centre_motion_is_done_before_the_belt_is_laid(serpentine, cli):
    """A pulley moved by ``centre_shift`` has its steady state on the moved drive: the belt
    is laid and pre-tensioned there (a shift laid on the unmoved path sank the belt into
    THREAD's stiff rims: no steady state).  The same state as the centre moved in the file
    (within 1e-6), and the shift matters (the spans' tensions move by over 0.3 %, seen 0.7 %:
    the tensioner takes up most of it)."""
    import json
    from ancf.belts.drive_file import load
    pump = next(q for q in load(SERPENTINE, []).pulleys if q.name == "pump")
    moved = [pump.centre[0] + 0.004, pump.centre[1] - 0.003]
    runs = [("pulleys.pump.centre_shift=[0.004, -0.003]",),
            (f"pulleys.pump.centre={moved!r}",)]
    got = []
    for sets in runs:
        rc, text, _ = cli("steady", "belt-drive", "--file", SERPENTINE, "--json",
                          *[a for s in sets for a in ("--set", s)])
        assert rc == 0
        got.append(np.array([s["tension_mean_N"] for s in json.loads(text)["results"]["spans"]]))
    base = np.array([s["tension_mean_N"] for s in serpentine[0]["results"]["spans"]])
    assert np.allclose(got[0], got[1], rtol=1e-6)
    assert np.abs(got[0] / base - 1).max() > 0.003
