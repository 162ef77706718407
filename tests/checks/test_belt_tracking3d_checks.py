"""The tracking rows of the 3D chapter (:mod:`ancf.checks.belt_tracking3d`): a table whose
walk stays within 10 % of the held-span reference passes, one that leaves the band fails,
and the aligned drift row follows the 1e-6 m per revolution bound (the runs themselves:
tests/belts/test_belt3d_tracking.py)."""
from __future__ import annotations

import pytest

from ancf.checks import belt_tracking3d as bt


def _table(lo: float, hi: float) -> list[dict]:
    return [{"tilt_deg": t, "reference": ref, "ratio_min": lo, "ratio_max": hi,
             "travel_end_spans": 2.1}
            for t in bt.TILTS for ref in ("held span, L (Eq. 3)", "free span, x tan(tilt) (Eq. 1)")]


@pytest.mark.parametrize("lo, hi, drift, passed", [
    (0.92, 1.00, 1e-8, (True, True, True)),
    (0.92, 1.12, 1e-8, (True, False, False)),
    (0.85, 1.00, 2e-6, (False, False, False))])
def test_rows_follow_their_bounds(monkeypatch, lo, hi, drift, passed):
    monkeypatch.setattr(bt, "aligned_drift", lambda: drift)
    got = bt.checks(_table(lo, hi))
    assert [c.name for c in got] == list(bt.NAMES)
    assert tuple(c.passed for c in got) == passed
    assert got[1].difference == pytest.approx(max(1 - lo, hi - 1))
