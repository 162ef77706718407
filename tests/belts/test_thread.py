"""The THREAD benchmark's stored Exudyn results (tests/data/thread, ancf/checks/thread.py):
the reader gives the figures issue 21 quotes, and the comparison passes the stored run
against itself (as a belt-drive result on our coordinate: the other sense, another start,
the stress-free length's scale) and fails a perturbed copy."""
import gzip
import math
from pathlib import Path

import numpy as np
import pytest

from ancf.belts.drive_file import load
from ancf.checks import thread as th
from ancf.common.paths import REPO

EXAMPLE = REPO / "examples" / "thread_benchmark.toml"


def test_stored_scalars_are_the_issues():
    """665.2 / 186.6 N, 11.340 rad/s, 47.68 N m as the issue rounds them; the stored run's
    own torque balance within 0.4 % (0.36 % seen: (T_t - T_s) R = 47.86 vs 47.68 N m)."""
    st = th.read()
    assert st.s_force.size == 480 and st.s_speed.size == 240 and st.s_contact.size == 960
    assert st.s_force.max() < st.length and st.t[-1] == pytest.approx(2.45)
    sc = th.scalars(st)
    assert round(sc["tight_N"], 1) == 665.2 and round(sc["slack_N"], 1) == 186.6
    assert round(sc["omega_mean"], 3) == 11.340 and round(sc["driver_torque_Nm"], 2) == 47.68
    assert abs(sc["belt_moment_Nm"] / sc["resisting_Nm"] - 1) < 4e-3


def _drive(tmp_path: Path):
    """The THREAD drive file; its bristle law replaced by Coulomb's while the file's law is
    not in ancf.belts.friction (the comparison reads only the layout, the laws and the
    belt)."""
    text = EXAMPLE.read_text()
    try:
        return load(EXAMPLE)
    except ValueError:
        text = (text.replace('law = "bristle"', 'law = "coulomb"\nv_reg = 1e-3')
                .replace("stiffness = 4e8", "").replace("damping = 5758.0", ""))
        path = tmp_path / "thread.toml"
        path.write_text(text)
        return load(path)


def _nominal(T, EA, law="green"):
    """Our axial force N whose th.true_force is T (fixed point, N)."""
    N = np.asarray(T, dtype=float)
    if law == "engineering":
        return N
    for _ in range(60):
        N = T / np.sqrt(1.0 + 2.0 * N / EA)
    return N


def test_true_force_inverts():
    T = np.array([0.0, 186.6, 665.2])
    assert np.allclose(th.true_force(_nominal(T, 8000.0), 8000.0), T, rtol=1e-12, atol=0)
    assert th.true_force(667.3, 8000.0) == pytest.approx(720.8, abs=0.1)  # at 8 % stretch
    assert th.true_force(665.2, 7600.0, "engineering") == 665.2  # already the real force


def _as_ours(st: th.Stored, desc, shift: float = 0.3) -> dict:
    """The stored run as a belt-drive result: points numbered counter-clockwise (against
    THREAD's s), starting ``shift`` m of belt from THREAD's origin, on L0."""
    L0, P, d, R = desc.belt["length"], st.length, th.DISTANCE, th.RADIUS
    sig = st.s_force
    s = np.mod(shift - sig * L0 / P, L0)
    order = np.argsort(s)
    a = np.mod(sig, P)
    arc2, lower = (a - d) / R, a - d - math.pi * R
    arc1 = (a - 2 * d - math.pi * R) / R
    x = np.select([a < d, a < d + math.pi * R, a < 2 * d + math.pi * R],
                  [a, d + R * np.sin(arc2), d - lower], -R * np.sin(arc1))
    y = np.select([a < d, a < d + math.pi * R, a < 2 * d + math.pi * R],
                  [np.full_like(a, R), R * np.cos(arc2), np.full_like(a, -R)], -R * np.cos(arc1))
    at = lambda ss, yy: np.interp(sig, ss, yy, period=P)  # noqa: E731
    EA, law = th.stiffness(desc), desc.belt["axial_strain"]
    tight, slack = (float(_nominal(f, EA, law))
                    for f in th.span_forces(st.s_force, st.axial_force, P))
    w = np.where(st.t < 0.05, 0.0, np.minimum(12 * (st.t - 0.05) / 0.55, 12.0))
    pick = lambda v: np.asarray(v)[order].tolist()  # noqa: E731
    return {"times": st.t.tolist(),
            "pulleys": [{"name": "driver", "omega": w.tolist(),
                         "torque_Nm": (-st.driver_torque).tolist()},
                        {"name": "driven", "omega": st.omega_driven.tolist(),
                         "torque_Nm": st.driver_torque.tolist()}],
            "spans": [{"from": "driver", "to": "driven", "tension_mean_N": slack,
                       "tension_N": slack},
                      {"from": "driven", "to": "driver", "tension_mean_N": tight,
                       "tension_N": tight}],
            "belt_s_m": pick(s), "belt_x_m": pick(x), "belt_y_m": pick(y),
            "axial_force_N": pick(_nominal(st.axial_force, EA, law)),
            "speed_m_s": pick(at(st.s_speed, st.speed)),
            "normal_force_N_m": pick(at(st.s_contact, st.normal)),
            "friction_force_N_m": pick(-at(st.s_contact, st.tangential))}


def _checks(results, desc, st):
    return {c.name: c for c in th.compare(results, desc, st)}


def test_stored_run_against_itself_passes(tmp_path):
    st, desc = th.read(), _drive(tmp_path)
    got = _checks(_as_ours(st, desc), desc, st)
    for name in ("THREAD tight span force", "THREAD slack span force",
                 "THREAD driven ω mean", "THREAD driver torque"):
        assert got[name].difference < 1e-9, name
    assert got["THREAD axial force along the belt, RMS"].difference < 1e-4  # % (5e-6 seen)
    assert got["THREAD torque balance (T_t − T_s) R = load + damping"].passed
    cur = th.curves(_as_ours(st, desc, shift=0.9), desc, st)
    back = np.interp(st.s_force, cur.sigma, cur.axial_force, period=st.length)
    assert np.abs(back - st.axial_force).max() < 1e-6 * st.axial_force.max()
    wrap = (cur.sigma > th.DISTANCE) & (cur.sigma < th.DISTANCE + math.pi * th.RADIUS)
    stored = (st.s_contact > th.DISTANCE) & (st.s_contact < th.DISTANCE + math.pi * th.RADIUS)
    assert np.mean(cur.tangential[wrap]) == pytest.approx(np.mean(st.tangential[stored]),
                                                          rel=0.05)  # the friction's sense


@pytest.mark.parametrize("key,scale,failing", [
    ("axial_force_N", 1.05, "THREAD axial force along the belt, RMS"),
    ("omega", 1.005, "THREAD driven ω mean"),
    ("tension_mean_N", 1.03, "THREAD tight span force")])
def test_perturbed_copy_fails(tmp_path, key, scale, failing):
    st, desc = th.read(), _drive(tmp_path)
    res = _as_ours(st, desc)
    if key == "omega":
        res["pulleys"][1]["omega"] = (np.array(res["pulleys"][1]["omega"]) * scale).tolist()
    elif key == "tension_mean_N":
        res["spans"][1]["tension_mean_N"] *= scale
    else:
        res[key] = (np.array(res[key]) * scale).tolist()
    got = _checks(res, desc, st)
    assert not got[failing].passed


def test_misaligned_copy_fails(tmp_path):
    """The alignment matters: our points moved by a tenth of the belt along it."""
    st, desc = th.read(), _drive(tmp_path)
    res = _as_ours(st, desc)
    res["axial_force_N"] = np.roll(res["axial_force_N"], len(res["axial_force_N"]) // 10).tolist()
    assert not _checks(res, desc, st)["THREAD axial force along the belt, RMS"].passed


def _header(case: str) -> dict:
    """The ``key=value`` lines of a stored case's beamForce header, as floats."""
    path, opener = th.DATA / f"beamForce-{case}-.txt", open
    if not path.exists():
        path, opener = path.with_name(path.name + ".gz"), gzip.open
    out = {}
    with opener(path, "rt") as f:
        for line in f:
            key, eq, value = line.lstrip("#").strip().partition("=")
            if line.startswith("#") and eq:
                try:
                    out[key] = float(value)
                except ValueError:
                    pass
    return out


@pytest.mark.parametrize("case", th.VARIANTS)
def test_case_names_decode_as_their_headers(case):
    """Element count, segments, step, contact stiffness per unit length (the header's per
    segment over the segment's laid length) and mu as each file's header states them."""
    p, h = th.case_parameters(case), _header(case)
    assert p["elements"] == h["nANCFnodes"] and p["segments"] == h["nSegments"]
    assert p["step"] == pytest.approx(h["stepSize"], rel=1e-12)
    assert p["mu"] == pytest.approx(h["dryFriction"], rel=1e-12)
    seg = th.PATH / (p["elements"] * p["segments"])
    assert p["k_p"] == pytest.approx(h["contactStiffness"] / seg, rel=1e-9)


def test_coordinate_on_the_path():
    """THREAD's s at the tangent points and the middles of spans and wraps."""
    R, d, P = th.RADIUS, th.DISTANCE, th.PATH
    pts = [(d / 2, R, d / 2), (d, R, d), (d + R, 0.0, d + math.pi * R / 2),
           (d, -R, d + math.pi * R), (d / 2, -R, 1.5 * d + math.pi * R),
           (-R, 0.0, 2 * d + 1.5 * math.pi * R), (-R * math.sqrt(0.5), R * math.sqrt(0.5),
                                                   P - math.pi * R / 4)]
    for x, y, s in pts:
        assert float(th.coordinate(x, y)) == pytest.approx(s, abs=1e-12)


def test_stick_tension_is_the_flat_stretch():
    """A wrap with a 20 N entry drop, a flat stick arc at 600 N and an Euler slip arc: the
    flat stretch's value, whatever the slip arc's length."""
    a, b, mu = 2 * th.DISTANCE + math.pi * th.RADIUS, th.PATH, 0.5
    s = np.linspace(a + 1e-4, b - 1e-4, 400)
    u = b - s                       # m from the wrap's entry, along the running direction
    slip = u > 0.12
    N = np.where(u < 0.01, 620.0 - 2000.0 * u, 600.0)
    N = np.where(slip, 600.0 * np.exp(-mu * (u - 0.12) / th.RADIUS), N)
    assert th.stick_tension(s, N, (a, b), mu) == pytest.approx(600.0, rel=1e-12)


def test_variants_turn_at_their_stick_arcs():
    """Every stored THREAD case's driven omega is the rolling speed of its stick arcs
    within 0.01 % (0.0056 % seen), and lies above the creep speed of its span forces by
    more than 0.05 % (0.08-0.54 % seen): the pulleys turn with the belt where it sticks,
    after entry zones whose tension change the span forces do not show."""
    EA = th.stiffness(load(EXAMPLE))
    for case in th.VARIANTS:
        v = th.read_variant(case)
        creep, rolling = v.speeds(EA)
        assert abs(v.omega_mean / rolling - 1) < 1e-4, case
        assert v.omega_mean / creep - 1 > 5e-4, case


def test_reference_spread_is_the_limits_size():
    """THREAD's own omega over its discretisation and penalty variants (mu of the base
    case) spans more than the 0.3 % acceptance (0.448 % seen); the case its plot script
    calls the reference solution lies 0.1-0.2 % below the base case (0.141 % seen); the
    driver's entry drop (span force less stick-arc tension) falls from 60 to 120 to 240
    elements and halves again with half as long contact segments either way (480 x 4 or
    240 x 8)."""
    vs = {c: th.read_variant(c) for c in th.VARIANTS}
    base = vs[th.CASE]
    w = [v.omega_mean for v in vs.values() if v.params["mu"] == base.params["mu"]]
    assert 100 * (max(w) - min(w)) / base.omega_mean > th.TOLERANCES["omega"]
    assert 1e-3 < 1 - vs[th.FINEST].omega_mean / base.omega_mean < 2e-3
    drop = {(v.params["elements"], v.params["segments"], v.params["step"]): v.tight - v.stick_driver
            for c, v in vs.items() if "-cs10-fs10-" in c and c.endswith("df5")}
    b = drop[(240, 4, base.params["step"])]
    assert drop[(60, 4, base.params["step"])] > drop[(120, 4, base.params["step"])] > b
    assert drop[(480, 4, vs[th.FINEST].params["step"])] < 0.5 * b
    assert drop[(240, 8, base.params["step"])] < 0.5 * b


def test_base_case_omega_is_explained_only_by_the_finest_case():
    """The base-case ω row reads "DIFFERS (explained)" only while THREAD's own variants
    spread beyond its tolerance and ours is within the tolerance of the finest case."""
    from ancf.checks.belt2d import Check
    fine = th.read_variant(th.FINEST).omega_mean
    tol = th.TOLERANCES["omega"]

    def checks(omega):
        d = 100 * abs(omega / fine - 1)
        return [Check(th.FINEST_ROW, omega, fine, d, tol, "rad/s", "%")]

    assert th.omega_spread() > tol
    assert th.omega_explained(checks(fine * (1 - 0.9 * tol / 100)))
    assert not th.omega_explained(checks(fine * (1 - 1.1 * tol / 100)))


@pytest.mark.slow
def test_the_races_quadrature_changes_the_drive_little():
    """benchmarks/peers_thread.py races Exudyn with 3 elastic and 4 contact Gauss points per
    element (the file: 5 and 5) at Exudyn's 240 elements and step 1e-4 s: over the first
    0.3 s (the ramp, the driven pulley at 5.4 rad/s) the driven speed moves by 1e-5, the span
    forces by 1e-4 and the driver torque by 4e-4 of their values (seen); bounds 3x."""
    from ancf.scenes import SCENES
    from ancf.scenes.belt_drive import SEP
    from benchmarks.peers_thread import N_ELEMENTS, QUADRATURE, SOLVER, STEP

    base = [f"belt.n_elements={N_ELEMENTS}", f"run.dt={STEP:g}", *SOLVER, "run.t_end=0.3",
            "run.steady_window=0.05", "run.output_dt=0.01"]
    runs = [SCENES["belt-drive"].execute({"file": str(EXAMPLE), "set": SEP.join(sets)})[0]
            for sets in (base, [*base, *QUADRATURE])]
    (p0, s0), (p1, s1) = [(o["results"]["pulleys"], o["results"]["spans"]) for o in runs]
    assert p1[1]["omega"][-1] == pytest.approx(p0[1]["omega"][-1], rel=3e-5)
    assert p0[1]["omega"][-1] > 5.0  # the drive is running
    for a, b in zip(s0, s1):
        assert b["tension_N"] == pytest.approx(a["tension_N"], rel=3e-4)
    assert p1[0]["torque_Nm"][-1] == pytest.approx(p0[0]["torque_Nm"][-1], rel=1.2e-3)


def test_the_races_overrides_replace_its_own_keys():
    """benchmarks/peers_thread.py --set: a key the race sets itself is replaced, not given
    twice (the drive file takes a key once), so the file's own quadrature can race."""
    from benchmarks.peers_thread import OURS, QUADRATURE, our_sets

    extra = ["belt.elastic_points=5", "contact.gauss_points=5"]
    sets = our_sets(2.45, extra)
    keys = [s.split("=", 1)[0] for s in sets]
    assert len(keys) == len(set(keys))
    assert sets[-2:] == extra and not set(QUADRATURE) & set(sets)
    assert our_sets(0.3, [])[: len(OURS)] == list(OURS)
    load(EXAMPLE, sets)  # one value per key: accepted


def test_the_races_own_settings_are_the_files_defaults():
    """benchmarks/peers_thread.py --own: our run sets the element count, the step, the end
    time and window alone, so every key the race sets besides (its quadrature and Newton
    settings, any added later) keeps the drive file's value or default."""
    from benchmarks.peers_thread import OWN, our_sets

    sets = our_sets(2.45, [], OWN)
    assert {s.split("=", 1)[0] for s in sets} == {"belt.n_elements", "run.dt", "run.t_end",
                                                   "run.steady_window"}
    own, file = load(EXAMPLE, sets), load(EXAMPLE)
    raced = [s.split("=", 1)[0].split(".") for s in our_sets(2.45, [])]
    extra = [(t, k) for t, k in raced if (t, k) not in {("belt", "n_elements"), ("run", "dt"),
                                                        ("run", "t_end"),
                                                        ("run", "steady_window")}]
    assert len(extra) >= 7  # quadrature (2) and Newton settings (5)
    for table, key in extra:
        assert getattr(own, table)[key] == getattr(file, table)[key], (table, key)


def test_stored_friction_carries_its_tension_change():
    """Exudyn's stored friction (per laid length) integrated over each pulley's belt
    (``th.WRAPS``) is the change of its span forces within 0.5 % (0.35 % seen): the
    balance the wrap row holds ours to."""
    st = th.read()
    sc = th.scalars(st)
    ds = st.length / st.s_contact.size
    for name, (a, b) in th.WRAPS.items():
        sel = np.mod(st.s_contact - a, th.PATH) < b - a
        change = (sc["tight_N"] - sc["slack_N"]) * (1 if name == "driven" else -1)
        assert np.sum(st.tangential[sel]) * ds == pytest.approx(change, rel=0.005), name


@pytest.mark.parametrize("scale,passes", [(1.0, True), (0.35, False)])
def test_wrap_row_sees_friction_that_does_not_carry_the_tension(tmp_path, scale, passes):
    """The stored run as ours, its friction per stress-free length (x P / L0) passes the
    wrap row; scaled to 0.35 (the bristle damper's alone, what the post-processing
    reported before it took the march's state: 167 of 478 N) it fails."""
    st, desc = th.read(), _drive(tmp_path)
    res = _as_ours(st, desc)
    res["friction_force_N_m"] = (np.asarray(res["friction_force_N_m"]) * scale * st.length
                                 / desc.belt["length"]).tolist()
    assert _checks(res, desc, st)[th.WRAP_ROW].passed is passes
