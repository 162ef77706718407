"""Crowned pulleys centre an off-centre plate belt (issue 36 item 4) against the tensioned-
span rule of :func:`ancf.checks.belt_tracking3d.crown_rule` (Eq. C5): the keys' defaults,
the rule's scaling, and the run of :data:`ancf.checks.belt_tracking3d.CROWN_SETS` (both
50 mm pulleys crowned 1 mm, every face 2 mm off the laid belt, at v = 1 m/s: 3 s here,
7 s in the chapter, whose stored rows the acceptance reads).  Seen: the rule's return to
10 % of the offset 2.40 s (tau 1.04 s), the run's 6.30 s and 6.43 s (tau 2.74 s and
2.71 s): the belt centres, exponentially as the rule says, about 2.7 times slower (a miss,
kept as a strict xfail)."""
import csv

import numpy as np
import pytest

from ancf.belts.drive_data import FLANGES
from ancf.belts.drive_file import load
from ancf.belts.tracking3d import crowns_of
from ancf.checks import belt_tracking3d as bt
from ancf.common.paths import REPO

THREE3D = REPO / "examples" / "three_pulleys_3d.toml"


def test_crown_keys_default_to_a_cylinder():
    """A pulley that names neither key is a cylinder with its face on the laid belt: crown_m
    and face_offset_m take their declared defaults (0 m) and no crown row is built."""
    desc = load(THREE3D)
    default = {k: FLANGES[k].default for k in ("crown_m", "face_offset_m")}
    assert default == {"crown_m": 0.0, "face_offset_m": 0.0}
    for q in desc.pulleys:
        assert {k: q.params[k] for k in default} == default
    assert crowns_of(desc) is None


def test_crown_rule_scales_as_eq_c5():
    """tau = P W^2 / (8 v sum c (L G + L H) / R): doubling the crowns halves tau, doubling
    the face widths (W 88 mm) quadruples it, doubling v halves it (to 1e-12); no crown:
    no return (inf).  span_reach's G -> 1/k - 1/(k^2 L) and H -> 1/(k^2 L) for k L >> 1."""
    desc = load(THREE3D, list(bt.CROWN_SETS))
    tau = bt.crown_rule(desc, 1.0)["tau_s"]
    twice = load(THREE3D, [*bt.CROWN_SETS, "pulleys.driver.crown_m=0.002",
                           "pulleys.driven.crown_m=0.002"])
    wide = load(THREE3D, [*bt.CROWN_SETS, "pulleys.driver.face_width_m=0.088",
                          "pulleys.driven.face_width_m=0.088"])
    assert bt.crown_rule(twice, 1.0)["tau_s"] == pytest.approx(tau / 2, rel=1e-12)
    assert bt.crown_rule(wide, 1.0)["tau_s"] == pytest.approx(4 * tau, rel=1e-12)
    assert bt.crown_rule(desc, 2.0)["tau_s"] == pytest.approx(tau / 2, rel=1e-12)
    assert bt.crown_rule(load(THREE3D), 1.0)["tau_s"] == np.inf
    k, L = 50.0, 2.0
    G, H = bt.span_reach(L, k)
    assert G == pytest.approx(1 / k - 1 / (k * k * L), rel=1e-12)
    assert H == pytest.approx(1 / (k * k * L), rel=1e-12)


#: the chapter's run (7 s, reports/data/belt3d_crown_span.csv, written by
#: ``python -m ancf.reports --chapter belt3d.md``) and the shorter run computed here, s
STORED = REPO / "reports" / "data" / "belt3d_crown_span.csv"
SHORT_T_END = 3.0


def _stored() -> list[dict]:
    with open(STORED, encoding="utf-8") as f:
        return [{k: (v if k == "pulley" else float(v)) for k, v in r.items()}
                for r in csv.DictReader(f)]


@pytest.mark.slow
def test_crowned_pulleys_centre_the_belt():
    """A 3 s run of the chapter's drive (about 55 CPU s warm against the chapter's 7 s, 150 s):
    both crowned pulleys' lateral_position_m fall below 40 % of the 2 mm offset (seen
    33 % and 35 %; uncrowned, the belt stays off-centre), the whole belt moving as one
    (their time constants within 5 %), each 4-sample mean at most 1 % of y0 above the one
    0.5 s before (a monotone return past 0.5 s); each time constant within 3 % of the
    chapter's 7 s run (seen 0.5 %: the return is exponential, and the stored rows are
    this code's), and the rule (Eq. C5) the faster."""
    out, v, desc = bt.crown_run(t_end=SHORT_T_END)
    rule = bt.crown_rule(desc, v)
    times = np.array(out["results"]["times"])
    t = bt.mean4(times)
    stored = _stored()
    assert [r["pulley"] for r in stored] == ["driver", "driven"]
    taus = []
    for k, row in zip((0, 2), stored):
        y0 = desc.pulleys[k].params["face_offset_m"]
        lateral = np.array(out["results"]["pulleys"][k]["lateral_position_m"], float)
        e = np.abs(bt.mean4(lateral))[t >= 0.5]
        assert e[-1] <= 0.4 * y0, (k, e[-1] / y0)
        assert np.all(e[50:] <= e[:-50] + 0.01 * y0)
        tau = bt.return_time(times, lateral, y0)["tau_s"]
        assert tau == pytest.approx(row["run_tau_s"], rel=0.03)
        assert rule["tau_s"] < tau
        taus.append(tau)
    assert taus[0] == pytest.approx(taus[1], rel=0.05)


@pytest.mark.xfail(strict=True, reason="the run returns about 2.7 times slower than the "
                   "tensioned-span rule (Eq. C5): 6.3 s against 2.4 s")
def test_return_time_within_10_percent_of_the_rule():
    """The acceptance on the chapter's 7 s run (its stored rows, tied to this code by the
    test above): the simulated return to 10 % of the offset within 10 % of the rule's time
    (:data:`ancf.checks.belt_tracking3d.CROWN`); a run that never got there (NaN) fails too."""
    rows = _stored()
    assert all(np.isfinite(r["run_t10_s"]) for r in rows), rows
    check = bt.crown_check(rows)
    assert check.passed, (check.value, check.tolerance)


def test_creep_limit_is_the_fit_s_intercept():
    """:func:`ancf.checks.belt_tracking3d.creep_limit` recovers tau_inf of
    tau = tau_inf + A / nu_s exactly from three factors, whatever tau_inf and A are, and
    the chapter's variants list the creep factors it fits (nu_s without other overrides)."""
    nus = np.array([1e6, 2e6, 3e6])
    for tau_inf, a in ((2.6, 4.4e5), (1.0, 0.0), (0.3, 2e6)):
        assert bt.creep_limit(nus, tau_inf + a / nus) == pytest.approx(tau_inf, rel=1e-12)
    creep = [nu for nu, extra in bt.CROWN_VARIANTS.values() if not extra]
    assert sorted(bt.CROWN_NU if nu is None else nu for nu in creep) == [1e6, 2e6, 3e6]


def test_the_chapter_s_crown_variants_support_its_reading():
    """The chapter's reading of its variants (``reports/data/belt3d_crown_variants.csv``,
    :func:`ancf.checks.belt_tracking3d.crown_sensitivity`): every variant is listed in
    order; 30 plates and 49 contact points within 3 % of the run (seen 0.7 % and 2.0 %);
    half the crowns within 5 % of the rule's doubling (seen 1.93 against 2.00); a belt that
    cannot creep still more than twice the rule's time (seen 2.55 s against 1.04 s)."""
    path = REPO / "reports" / "data" / "belt3d_crown_variants.csv"
    with open(path, encoding="utf-8") as f:
        rows = {r["variant"]: {k: float(v) for k, v in r.items() if k != "variant"}
                for r in csv.DictReader(f)}
    assert list(rows) == list(bt.CROWN_VARIANTS)
    base = rows["as run (20 plates, 25 points, nu_s 2e6)"]
    for k in ("30 plates", "49 contact points"):
        assert rows[k]["run_tau_s"] == pytest.approx(base["run_tau_s"], rel=0.03), k
    half = rows["crowns 0.5 mm"]
    assert (half["run_tau_s"] / base["run_tau_s"]
            == pytest.approx(half["rule_tau_s"] / base["rule_tau_s"], rel=0.05))
    creep = [(bt.CROWN_NU if nu is None else nu, rows[k]["run_tau_s"])
             for k, (nu, extra) in bt.CROWN_VARIANTS.items() if not extra]
    assert bt.creep_limit(*zip(*creep)) > 2 * base["rule_tau_s"]
