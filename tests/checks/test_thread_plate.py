"""THREAD's drive as a plate belt against the planar belt (ancf/checks/thread_plate.py):
the chapter's full runs (reports/data/belt3d_thread_plate.csv) within the issue's 2 %, and
a short run of both computed here: the laid, settled belts carry the same span forces."""
import csv

import pytest

from ancf.checks import thread_plate as tp
from ancf.common.paths import REPO

DATA = REPO / "reports" / "data" / "belt3d_thread_plate.csv"
#: 20 ms of both belts from the settled state (the driver barely started)
SHORT = ("run.t_end=0.02", "run.steady_window=0.01")


def _stored() -> list[dict]:
    with open(DATA, encoding="utf-8") as f:
        return [{**r, "difference_pct": float(r["difference_pct"])} for r in csv.DictReader(f)]


def test_plate_within_two_percent_of_the_planar_belt():
    """The full runs (2.45 s, bristle law): span forces within 2 % (seen 0.05 %), the driven
    speed within 0.1 %; the same rows 3 % apart fail."""
    got = _stored()
    assert tp.check(got).passed, got
    speed = next(r for r in got if r["quantity"].startswith("driven"))
    assert abs(speed["difference_pct"]) < 0.1
    moved = [{**r, "difference_pct": r["difference_pct"] + 3.0} for r in got]
    assert not tp.check(moved).passed


@pytest.fixture(scope="module")
def short():
    return tp.rows(*tp.runs(SHORT))


def test_settled_belts_carry_the_same_span_forces(short):
    """Laid and settled, the plate's membrane and the planar belt in Green strain carry
    the same span forces within 0.5 % (seen -0.04 %, 454 N); the planar Green force N
    itself, not times its stretch, is 5 % below (the comparison needs the true force)."""
    for r in short:
        if r["quantity"].startswith("span"):
            assert abs(r["difference_pct"]) < 0.5, r
            assert abs(r["plate"] / r["planar Green force N"] - 1) > 0.01, r
