"""The steady belt on N pulleys (analytic/belt_steady.py): for two pulleys it is Bechtel's
(analytic/bechtel.py); for a serpentine drive with a tensioner the same model assembled
here from its equations, on a path built here from tangency conditions, and solved by
fsolve from another start; the limits (no torque: uniform stretch; an idler that barely
touches a span: no change); bad layouts; the CLI."""
import json
import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import fsolve

from analytic import bechtel, belt_steady
from ancf.cli import main
from ancf.common.params import InputError
from ancf.study.schemas import schema, validate

BECHTEL = {p.name: p.default for p in bechtel.PARAMS}
#: the two are one model in two closed forms, each solved by Brent's method to 1e-12 N on
#: tensions of tens of N (we see up to 5e-14 relative; a slip arc ln(n_t / n_s) / mu amplifies it)
SAME = 1e-11
#: the independent assembly (fsolve, quadrature, tangency by fsolve, dP/dpsi by central
#: differences of 1e-5 rad): we see 1e-10 relative on tensions, 2e-11 rad on the arm, 1e-11
#: on the geometry
INDEPENDENT_REL, INDEPENDENT_ANGLE, GEOMETRY = 1e-9, 1e-9, 1e-10

#: a serpentine accessory drive (m, rad/s, N m, N m/rad): crankshaft (driver), tensioner on
#: the back of its slack span, air-conditioning compressor, alternator, back-side idler
SERPENTINE = [
    {"name": "crank", "centre": (0.0, 0.0), "radius": 0.08, "side": 1, "law": "prescribed",
     "omega": 100.0},
    {"name": "tensioner", "centre": (0.16, 0.0), "radius": 0.035, "side": -1, "law": "tensioner",
     "pivot": (0.24, -0.01), "stiffness": 20.0, "preload": 8.0},
    {"name": "ac", "centre": (0.28, 0.15), "radius": 0.06, "side": 1, "law": "driven",
     "torque": 5.0},
    {"name": "alternator", "centre": (0.05, 0.35), "radius": 0.03, "side": 1, "law": "driven",
     "torque": 2.0},
    {"name": "idler", "centre": (-0.05, 0.18), "radius": 0.035, "side": -1, "law": "idler"}]
BELT = {"EA": 1e5, "rhoA": 0.1, "mu": 0.5}
T_INSTALL = 300.0  # N: L0 = nominal path / (1 + T_INSTALL / EA)


def _L0(pulleys, EA=BELT["EA"]):
    return belt_steady.path_length(pulleys) / (1 + T_INSTALL / EA)


def _two_pulleys(p):
    """Bechtel's drive (Table 4.1: spans pi R, wraps pi) as a pulley list."""
    R = p["R"]
    return [{"name": "driver", "centre": (0.0, 0.0), "radius": R, "side": 1,
             "law": "prescribed", "omega": p["omega"]},
            {"name": "driven", "centre": (math.pi * R, 0.0), "radius": R, "side": 1,
             "law": "driven", "torque": p["T_a"]}]


def _as_bechtel(p):
    """Our solution in bechtel.summary's keys (span 0: driver -> driven, the slack one)."""
    r = belt_steady.solve(_two_pulleys(p), EA=p["k"], rhoA=p["rhoA"], mu=p["mu"],
                          L0=4 * math.pi * p["R"] / (1 + p["T_i"] / p["k"]))
    (slack, tight), (driver, driven) = r["spans"], r["pulleys"]
    assert driven["torque_Nm"] == pytest.approx(p["T_a"], rel=SAME, abs=1e-12)
    return {"T_tight_N": tight["tension_N"], "T_slack_N": slack["tension_N"],
            "v_tight": tight["speed"], "v_slack": slack["speed"],
            "slip_arc_driver_rad": driver["creep_arc_rad"],
            "slip_arc_driven_rad": driven["creep_arc_rad"],
            "omega_ratio": driven["omega"] / driver["omega"]}


@pytest.mark.parametrize("change", [{}, {"T_a": 0.0}, {"T_a": 0.5}, {"T_a": 3.0}, {"k": 25e3},
                                    {"rhoA": 0.0}, {"omega": 700.0}])
def test_two_pulleys_are_bechtels_belt(change):
    p = dict(BECHTEL, **change)
    ours, theirs = _as_bechtel(p), bechtel.summary(*bechtel.steady(p))
    for key, val in ours.items():
        assert val == pytest.approx(theirs[key], rel=SAME, abs=1e-12), key


def test_bechtels_largest_torque_is_ours():
    top = bechtel.results(BECHTEL)["max_torque_Nm"]
    _as_bechtel(dict(BECHTEL, T_a=(1 - 1e-6) * top))
    with pytest.raises(InputError, match=r"^pulley '(driver|driven)': the torques need a creep "
                                         r"arc longer than its wrap \(3.14159 rad\)"):
        _as_bechtel(dict(BECHTEL, T_a=(1 + 1e-6) * top))


# ------------------------------------------------------------ the independent assembly
def _contact_angles(c1, r1, s1, c2, r2, s2):
    """Angles (rad) of the points where the span from circle 1 (turning with sense s1) to
    circle 2 touches them: the belt's direction s (-sin a, cos a) is the same at both and
    lies along the span."""
    base = math.atan2(c2[1] - c1[1], c2[0] - c1[0])

    def ends(a):
        p = [np.add(c, r * np.array([math.cos(x), math.sin(x)])) for c, r, x in
             ((c1, r1, a[0]), (c2, r2, a[1]))]
        t = [s * np.array([-math.sin(x), math.cos(x)]) for s, x in ((s1, a[0]), (s2, a[1]))]
        return p, t

    def res(a):
        (p1, p2), (t1, t2) = ends(a)
        return [t1[0] * t2[1] - t1[1] * t2[0], (p2 - p1)[0] * t1[1] - (p2 - p1)[1] * t1[0]]

    a, info, _, msg = fsolve(res, [base - s1 * math.pi / 2, base - s2 * math.pi / 2],
                             full_output=True, xtol=1e-15)
    (p1, p2), (t1, t2) = ends(a)
    assert np.max(np.abs(info["fvec"])) < 1e-15 and t1 @ t2 > 0 and (p2 - p1) @ t1 > 0, msg
    return a, float(np.hypot(*(p2 - p1)))


def _path(centres, pulleys, sense):
    """(span lengths m, wraps rad, path length m)."""
    N = len(pulleys)
    spans, a_out, a_in = np.zeros(N), np.zeros(N), np.zeros(N)
    for j in range(N):
        k = (j + 1) % N
        (a_out[j], a_in[k]), spans[j] = _contact_angles(
            centres[j], pulleys[j]["radius"], sense[j], centres[k], pulleys[k]["radius"], sense[k])
    wraps = np.mod(sense * (a_out - a_in), 2 * math.pi)
    R = np.array([p["radius"] for p in pulleys])
    return spans, wraps, float(spans.sum() + R @ wraps)


def _independent(pulleys, EA, rhoA, L0, mu, sense, x0):
    """Unknowns: span tensions T (N), v_o (m/s), the tensioner's arm angle beta (rad).
    Equations: v = v_o (1 + T / EA); the driver's entry speed omega R; on every other pulley
    R (n_out - n_in) = torque + damping omega, n = T - rhoA v_o v; int ds / lambda = L0
    (creep arcs by quadrature); the arm: preload - stiffness psi = n dP/dpsi (central
    differences of this path)."""
    N = len(pulleys)
    dr = next(i for i, p in enumerate(pulleys) if p["law"] == "prescribed")
    t = next(i for i, p in enumerate(pulleys) if p["law"] == "tensioner")
    ten = pulleys[t]
    r0 = np.subtract(ten["centre"], ten["pivot"])
    arm, beta0 = float(np.hypot(*r0)), math.atan2(r0[1], r0[0])

    def path(beta):
        centres = [p["centre"] for p in pulleys]
        centres[t] = np.add(ten["pivot"], arm * np.array([math.cos(beta), math.sin(beta)]))
        return _path(centres, pulleys, sense)

    h = 1e-5
    into = math.copysign(1.0, path(beta0 + h)[2] - path(beta0 - h)[2])
    R = np.array([p["radius"] for p in pulleys])

    def residual(x):
        T, v_o, beta = x[:N], x[N], x[N + 1]
        lam = 1 + T / EA
        v, n = v_o * lam, T - rhoA * v_o * v_o * lam
        spans, wraps, _ = path(beta)
        eqs = [EA * (v[dr - 1] / (pulleys[dr]["omega"] * R[dr]) - 1)]
        length = spans @ (1 / lam)
        for i, p in enumerate(pulleys):
            n_in, n_out = n[i - 1], n[i]
            if i != dr:
                load = p.get("torque", 0.0) + p.get("damping", 0.0) * v[i - 1] / R[i]
                eqs.append((R[i] * (n_out - n_in) - load) / R[i])
            phi = abs(math.log(n_out / n_in)) / mu
            kappa = math.copysign(mu, n_out - n_in)
            creep = quad(lambda th: (EA - rhoA * v_o ** 2) / (EA + n_in * math.exp(kappa * th)),
                         0.0, phi, epsabs=0, epsrel=1e-13)[0]
            length += R[i] * ((wraps[i] - phi) / lam[i - 1] + creep)
        eqs.append(EA * (length - L0) / L0)
        dP = (path(beta + h)[2] - path(beta - h)[2]) / (2 * h) * into
        psi = into * (beta - beta0)
        eqs.append(ten["preload"] - ten["stiffness"] * psi - n[t] * dP)
        return eqs

    x, info, ier, msg = fsolve(residual, x0, full_output=True, xtol=1e-13)
    assert np.max(np.abs(info["fvec"])) < 1e-9, msg  # N, N m
    return x, path(x[N + 1])


@pytest.mark.parametrize("damping", [0.0, 0.01])
def test_serpentine_is_the_same_model_assembled_independently(damping):
    pulleys = [dict(p, damping=damping) if p["law"] == "driven" else p for p in SERPENTINE]
    L0 = _L0(pulleys)
    r = belt_steady.solve(pulleys, L0=L0, **BELT)
    sense = np.sign([p["omega"] for p in r["pulleys"]])
    assert sense.tolist() == [1, -1, 1, 1, -1]  # counter-clockwise, idlers on the back
    R0 = SERPENTINE[1]["radius"]
    start = [T_INSTALL] * len(pulleys) + [SERPENTINE[0]["omega"] * R0,
                                          math.atan2(0.01, -0.08)]  # the nominal arm
    x, (spans, wraps, P) = _independent(pulleys, L0=L0, sense=sense, x0=start, **BELT)
    T, beta = x[:-2], x[-1]
    assert [s["tension_N"] for s in r["spans"]] == pytest.approx(T, rel=INDEPENDENT_REL)
    assert [s["speed"] for s in r["spans"]] == pytest.approx(
        x[-2] * (1 + T / BELT["EA"]), rel=INDEPENDENT_REL)
    assert r["pulleys"][1]["arm_angle_rad"] == pytest.approx(beta, abs=INDEPENDENT_ANGLE)
    assert [s["length_m"] for s in r["spans"]] == pytest.approx(spans, rel=GEOMETRY)
    assert [p["wrap_rad"] for p in r["pulleys"]] == pytest.approx(wraps, rel=GEOMETRY)
    assert r["path_length_m"] == pytest.approx(P, rel=GEOMETRY)


def test_serpentine_torques_speeds_and_arcs():
    r = belt_steady.solve(SERPENTINE, L0=_L0(SERPENTINE), **BELT)
    pul = {p["name"]: p for p in r["pulleys"]}
    spans = r["spans"]
    for s in spans:  # every pulley turns with the belt where it sticks: omega R = entry speed
        p = next(q for q in SERPENTINE if q["name"] == s["to"])
        assert abs(pul[s["to"]]["omega"]) * p["radius"] == pytest.approx(s["speed"], rel=1e-14)
    assert pul["ac"]["torque_Nm"] == pytest.approx(5.0, rel=1e-12)
    assert pul["alternator"]["torque_Nm"] == pytest.approx(2.0, rel=1e-12)
    assert pul["idler"]["torque_Nm"] == pul["tensioner"]["torque_Nm"] == 0.0
    R = {p["name"]: p["radius"] for p in SERPENTINE}
    assert -pul["crank"]["torque_Nm"] == pytest.approx(
        R["crank"] * (5.0 / R["ac"] + 2.0 / R["alternator"]), rel=1e-12)
    for p in pul.values():
        assert p["stick_arc_rad"] + p["creep_arc_rad"] == pytest.approx(p["wrap_rad"], rel=1e-14)
        assert 0 <= p["creep_arc_rad"] <= p["wrap_rad"]
    # the driver pulls its entry span in: the tightest; each driven pulley slips further
    assert max(s["tension_N"] for s in spans) == spans[-1]["tension_N"]
    assert 0 < pul["alternator"]["slip"] < pul["ac"]["slip"]


def test_no_torque_stretches_the_belt_uniformly():
    """All torques zero: no creep, one tension everywhere, T = EA (P / L0 - 1) whatever the
    speed (mass conservation: the stretch is the path over the stress-free length)."""
    pulleys = [dict(p, torque=0.0) if p["law"] == "driven" else p for p in SERPENTINE
               if p["law"] != "tensioner"]
    L0 = _L0(pulleys)
    P = belt_steady.path_length(pulleys)
    r = belt_steady.solve(pulleys, L0=L0, **BELT)
    T = [s["tension_N"] for s in r["spans"]]
    assert T == pytest.approx([BELT["EA"] * (P / L0 - 1)] * len(T), rel=1e-10)
    assert all(p["creep_arc_rad"] == 0 and abs(p["slip"]) < 1e-15 for p in r["pulleys"])


def _with_idler(gap):
    """Bechtel's drive with a back-side idler under the middle of its slack span, its rim
    ``gap`` m below the span (negative: pressing into it)."""
    p = _two_pulleys(BECHTEL)
    R, r = BECHTEL["R"], 0.3 * BECHTEL["R"]
    idler = {"name": "idler", "centre": (math.pi * R / 2, -R - r - gap), "radius": r,
             "side": -1, "law": "idler"}
    return [p[0], idler, p[1]]


def test_an_idler_barely_touching_a_span_changes_nothing():
    p = BECHTEL
    kw = {"EA": p["k"], "rhoA": p["rhoA"], "mu": p["mu"],
          "L0": 4 * math.pi * p["R"] / (1 + p["T_i"] / p["k"])}
    bare = belt_steady.solve(_two_pulleys(p), **kw)
    touched = belt_steady.solve(_with_idler(-1e-9), **kw)
    wrap = touched["pulleys"][1]["wrap_rad"]  # the change is of first order in it, times strains
    assert 0 < wrap < 1e-7 and touched["pulleys"][1]["torque_Nm"] == 0.0
    assert touched["spans"][0]["tension_N"] == touched["spans"][1]["tension_N"]
    for ours, theirs in ((0, 0), (2, 1)):  # slack span (split by the idler), tight span
        assert touched["spans"][ours]["tension_N"] == pytest.approx(
            bare["spans"][theirs]["tension_N"], rel=wrap)
    with pytest.raises(InputError, match=r"^pulley 'idler' cannot be wrapped: the belt would "
                                         r"turn the other way round it \(wrap -"):
        belt_steady.solve(_with_idler(1e-6), **kw)


# ------------------------------------------------------------------------ bad input
def _moved(which, **fields):
    return [dict(p, **fields) if p["name"] == which else p for p in SERPENTINE]


@pytest.mark.parametrize("pulleys,L0,says", [
    (_moved("ac", centre=(0.1, 0.05)), None, "pulleys 'crank' and 'ac' overlap: centre distance"),
    (_moved("idler", centre=(-0.12, 0.18)), None, "pulley 'idler' cannot be wrapped: the belt "
                                                   "would turn the other way round it (wrap -"),
    (_moved("tensioner", preload=-8.0), None, "tensioner 'tensioner': no equilibrium of its arm "
                                              "before, at a rotation of -0.512 rad, pulley "
                                              "'tensioner' cannot be wrapped"),
    (_moved("alternator", torque=20.0), None, "tensioner 'tensioner': its spring (preload 8.0 "
                                              "N m, stiffness 20.0 N m/rad) cannot tension the "
                                              "belt where it balances the arm: pulley "
                                              "'alternator': the torques need a creep arc longer "
                                              "than its wrap (1.99207 rad)"),
    (_moved("ac", radius=-0.06), None, "pulleys.2.radius = -0.06 is out of range; allowed: a "
                                       "number in (0, inf)"),
    (_moved("ac", side=0), None, "pulleys.2.side = 0 is not valid"),
    (_moved("ac", law="fixed"), None, "pulleys.2.law = 'fixed' is not valid; allowed: one of "
                                      "prescribed, driven, idler, tensioner"),
    (_moved("ac", inertia=0.1), None, "pulleys.2.inertia: unknown field of law 'driven'"),
    ([dict(p, law="prescribed", omega=1.0) if p["name"] == "ac" else p for p in SERPENTINE],
     None, "pulleys.2.torque: unknown field of law 'prescribed'"),
    (_moved("idler", name="ac"), None, "pulleys: the name 'ac' is used twice"),
    (_moved("idler", law="prescribed", omega=1.0), None, "pulleys: 2 pulley(s) of law "
                                                         "'prescribed'; allowed: exactly one"),
    ([SERPENTINE[0]], None, "pulleys = [{'name': 'crank'"),
    (_moved("idler", centre=(0.15, 0.3)), None, "pulley 'idler' cuts the span from 'ac' to "
                                                   "'alternator'"),
])
def test_bad_layouts_name_the_pulley_and_the_limit(pulleys, L0, says):
    with pytest.raises(InputError) as exc:
        belt_steady.solve(pulleys, L0=L0 or _L0(SERPENTINE), **BELT)
    assert str(exc.value).startswith(says), str(exc.value)


def _fixed(torques):
    """The serpentine with its tensioner held at its nominal place (an idler) and these
    load torques (N m) on the driven pulleys."""
    return [{k: p[k] for k in ("name", "centre", "radius", "side")} | {"law": "idler"}
            if p["law"] == "tensioner" else dict(p, torque=torques[p["name"]])
            if p["law"] == "driven" else p for p in SERPENTINE]


def test_a_belt_too_long_states_the_longest():
    """No torque: at zero n only the centrifugal tension stretches the belt, uniformly:
    lambda = EA / a, so the longest belt is P (1 - rhoA v_o^2 / EA), v_o = omega R a / EA."""
    pulleys = _fixed({"ac": 0.0, "alternator": 0.0})
    P = belt_steady.path_length(pulleys)
    with pytest.raises(InputError) as exc:
        belt_steady.solve(pulleys, L0=P, **BELT)
    text = str(exc.value)
    assert text.startswith(f"L0 = {P!r} m is out of range: the belt is too long for its path "
                           f"({P:.9g} m), no positive tension; allowed: L0 < ")
    V, EA, rhoA = SERPENTINE[0]["omega"] * SERPENTINE[0]["radius"], BELT["EA"], BELT["rhoA"]
    a = EA / 2 + math.sqrt(EA * EA / 4 - rhoA * V * V * EA)  # a = EA - rhoA (V a / EA)^2
    longest = float(text.rpartition("< ")[2].split()[0])
    assert longest == pytest.approx(P * (1 - rhoA * (V * a / EA) ** 2 / EA), rel=1e-8)
    assert P - longest > 1e3 * P * 1e-8  # the test sees the centrifugal term


def test_too_much_torque_names_the_pulley_and_its_wrap():
    pulleys = _fixed({"ac": 5.0, "alternator": 10.0})
    gripped = belt_steady.solve(pulleys, L0=_L0(pulleys), **dict(BELT, mu=10.0))
    wrap = gripped["pulleys"][0]["wrap_rad"]
    with pytest.raises(InputError, match=rf"^pulley 'crank': the torques need a creep arc longer "
                                         rf"than its wrap \({wrap:.6g} rad\): friction \(mu = "
                                         r"0.5\) cannot transmit them at this belt length"):
        belt_steady.solve(pulleys, L0=_L0(pulleys), **BELT)


def test_the_driver_sets_the_sense():
    """Two pulleys turned clockwise: the mirror image, the same tensions."""
    p = _two_pulleys(BECHTEL)
    kw = dict(BELT, L0=0.99 * belt_steady.path_length(p))
    ccw = belt_steady.solve(p, **kw)
    cw = belt_steady.solve([dict(p[0], omega=-p[0]["omega"]), p[1]], **kw)
    assert [s["tension_N"] for s in cw["spans"]] == [s["tension_N"] for s in ccw["spans"]]
    assert [q["omega"] for q in cw["pulleys"]] == [-q["omega"] for q in ccw["pulleys"]]


# ------------------------------------------------------------------------------ CLI
def test_cli_three_pulleys(capsys):
    assert main(["analytic", "belt-steady", "--set", "law3=idler", "--json"]) == 0
    out = json.loads(capsys.readouterr()[0])
    assert validate(out, schema("analytic belt-steady")) == []
    idler = out["results"]["pulleys"][1]
    assert idler["torque_Nm"] == 0.0 and idler["arm_angle_rad"] is None
    del out["results"]["spans"][0]["tension_N"]
    assert validate(out, schema("belt-steady")) == ["$.results.spans[0]: missing key 'tension_N'"]


def test_cli_bad_layout_is_one_error_line(capsys):
    assert main(["analytic", "belt-steady", "--set", "x2=0.1", "--set", "y2=0", "--json"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1
    assert err.startswith("error: pulleys 'driver' and 'driven' overlap")
