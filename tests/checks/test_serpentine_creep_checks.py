"""The serpentine's running modes against the discrete model with creeping wraps
(ancf/checks/serpentine_creep.py): within the issue's 1 %, damping ratios alike, the
saturated zones read off the steady state, and each ingredient of the model needed."""
import numpy as np
import pytest

from ancf.checks import running_drives as rd
from ancf.checks import serpentine_creep as scc
from ancf.checks import serpentine_modes as sm

#: the damping ratios are not an acceptance row; we see 0.0001-0.0037 apart
ZETA = 0.006


@pytest.fixture(scope="module")
def rows():
    return scc.rows()


def test_within_one_percent_of_the_creep_model(rows):
    """Arm, alternator, pump within 1 % (seen -0.20, -0.76, +0.13 %), 5-7 % below the
    sticking model; the damping ratios within 0.006 (seen 0.116 against 0.116)."""
    check = scc.check(rows)
    assert check.passed, rows
    for r in rows:
        assert r["ours"] < 0.95 * r["sticking model"]
        assert abs(r["zeta"] - r["creep model zeta"]) <= ZETA, r
    moved = [{**r, "error_pct": 100 * (r["ours"] / (0.98 * r["creep model"]) - 1)}
             for r in rows]
    assert not scc.check(moved).passed


def _model(**change):
    """The creep model on the comparison's settings with one ingredient changed."""
    desc = rd.modes(rd.SERPENTINE, scc.SETTINGS, 16)[1].extra["description"]
    steady = rd.steady(rd.SERPENTINE, scc.SETTINGS, max_loads=False)[0]["results"]
    return scc.model(desc, steady, **change)


def test_the_creep_layer_and_its_zones_matter(rows):
    """Without the saturated zones the alternator's mode rises 0.5 % (seen 79.35 against
    78.90 Hz); a creep factor ten times the file's moves every mode by more than 1 %."""
    base = {r["mode"]: r["creep model"] for r in rows}
    label = scc.MODES["pulley alternator"]
    no_zones = _model(saturated=False)
    f = no_zones["frequencies_hz"][no_zones["labels"].index(label)]
    assert f > 1.004 * base["pulley alternator"]
    stiff = _model(creep=1e6)
    for ours, theirs in scc.MODES.items():
        f = stiff["frequencies_hz"][stiff["labels"].index(theirs)]
        assert f > 1.01 * base[ours], (ours, f)


def test_zones_read_off_the_steady_state():
    """The crank drives: its wrap saturates near its exit, the tension falling there (sigma
    -1); the tensioner's, alternator's and idler's do not saturate on the comparison's mesh."""
    out, res = rd.modes(rd.SERPENTINE, scc.SETTINGS, 16)
    desc = res.extra["description"]
    inp = sm.inputs(desc)
    from analytic import serpentine_rotational as sr
    lay = sr.matrices(inp["pulleys"], EA=inp["EA"], J=inp["J"], T=inp["T"],
                      J_arm=inp["J_arm"], arm_angle=inp["arm_angle"])["layout"]
    steady = rd.steady(rd.SERPENTINE, scc.SETTINGS, max_loads=False)[0]["results"]
    zones = scc.zones(steady, lay, desc.friction["mu"])
    L = lay.radii * lay.wrap
    assert zones[0] and all(0.9 * L[0] < lo < hi <= L[0] and s == -1 for lo, hi, s in zones[0])
    assert zones[1] == zones[2] == zones[3] == []
