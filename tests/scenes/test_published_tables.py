"""Acceptance: the published static tables (thesis 2.1-2.4, report 1-6) recomputed.

Tolerances follow today's agreement with a margin of 1.5 (our values are deterministic to
~1e-9 of the printed digits, so the margin only covers round-off and BLAS differences); the
acceptance of issue 2 (simply supported 0.01 %, cantilever 2e-4 m) is far looser.  Cells we
do not match are tested for the explanation the report gives (see reports/static_beams.md).
"""
import numpy as np
import pytest

from ancf.core.assembly import Assembly, ElementGroup
from ancf.core.constraints import Elimination
from ancf.elements.linear2d import LinearBeam2D
from ancf.core.mesh import BeamMesh
from ancf.core.quadrature import RectangularSection
from ancf.reports import published as pub
from ancf.scenes import SCENES
from ancf.solvers.static import NewtonOptions, solve_static

MARGIN = 1.5
# Simply supported, largest |ours - published| per document and column today, mm.  The
# thesis prints 6 decimals (half a unit: 5e-7 mm), the report 8 (5e-9 mm); both
# Omar-Shabana columns are off by more only at n = 64, nu = 0 (thesis 1.9e-6, report 1.5e-6).
SS_TODAY_MM = {("thesis", "omar-shabana"): 1.92e-6, ("thesis", "linear"): 4.8e-7,
               ("report", "omar-shabana"): 1.53e-6, ("report", "linear"): 4.8e-9}
# Cantilever: today <= 7.6e-6 m (report Table 4, linear, n = 16; the papers print 5
# decimals, half a unit 5e-6 m), tolerance 1.5 x 7.6e-6 m.
TIP_TOL = MARGIN * 7.6e-6


def _ss(element, n, nu):
    out, _ = SCENES["simply-supported"].execute(dict(element=element, n_elements=n, nu=nu))
    assert out["converged"], out["message"]
    return out["results"]["mid_deflection_m"] * 1e3  # mm, as published


def _tip(element, n, model, integration="thesis", clamp_x_slope="free"):
    out, _ = SCENES["cantilever"].execute(dict(element=element, n_elements=n,
                                               integration=integration,
                                               clamp_x_slope=clamp_x_slope, **model))
    return out


def _setting(table, element):
    """(integration, clamp_x_slope) that reproduces ``element``'s column of ``table``."""
    if element == "linear":
        return table["linear_integration"], "free"
    return table["os_integration"], table["os_clamp_x_slope"]


def _max_diff(out, p):
    r = out["results"]
    return max(abs(r["tip_x"] - p[0]), abs(r["tip_y"] - p[1]))


@pytest.mark.parametrize("doc,table", [("thesis", pub.THESIS_2_1), ("thesis", pub.THESIS_2_2),
                                       ("report", pub.REPORT_1), ("report", pub.REPORT_2)],
                         ids=["thesis2.1", "thesis2.2", "report1", "report2"])
@pytest.mark.parametrize("element", ["omar-shabana", "linear"])
def test_simply_supported_tables(doc, table, element):
    col, tol = table["columns"].index(element), MARGIN * SS_TODAY_MM[doc, element]
    for n, row in table["rows"].items():
        ours = _ss(element, n, table["nu"])
        assert abs(ours - row[col]) < tol, (n, ours, row[col])
        assert ours == pytest.approx(row[col], rel=1e-4)  # issue 2's acceptance


def test_linear_element_default_ks_reproduces_report_table_1():
    """LinearBeam2D's own ks default (the scenes always pass theirs) is the papers' 5/6: the
    simply supported beam of the scene's data, built from the element with no ks, gives the
    report's Table 1 cell (a 1 % change of ks moves it by 5.7e-6 mm)."""
    p = SCENES["simply-supported"].resolve({"element": "linear"})
    n = p["n_elements"]
    mesh = BeamMesh(p["L"], n, LinearBeam2D.slots)
    q0 = mesh.reference()
    el = LinearBeam2D(mesh.lengths, q0[mesh.dofmap], RectangularSection(p["b"], p["h"]), p["E"],
                      p["nu"])
    elim = Elimination(mesh.n_dofs)
    for d in (mesh.dof(0, "r", 0), mesh.dof(0, "r", 1), mesh.dof(n, "r", 1)):
        elim.fix(d, q0[d])
    load, mid = np.zeros(mesh.n_dofs), mesh.dof(n // 2, "r", 1)
    load[mid] = p["F"]
    res = solve_static(Assembly(mesh.n_dofs, [ElementGroup(el, mesh.dofmap)]), elim, load, q0,
                       NewtonOptions())
    assert res.converged
    published = pub.REPORT_1["rows"][n][pub.REPORT_1["columns"].index("linear")]
    assert abs((res.q[mid] - q0[mid]) * 1e3 - published) < MARGIN * SS_TODAY_MM["report", "linear"]


@pytest.mark.parametrize("key,table,elements", [
    ("thesis2.3", pub.THESIS_2_3, ("omar-shabana", "linear")),
    ("thesis2.4", pub.THESIS_2_4, ("omar-shabana", "linear")),
    ("report3", pub.REPORT_3, ("linear",)),
    ("report4", pub.REPORT_4, ("omar-shabana",)),
    ("report5", pub.REPORT_5, ("omar-shabana", "linear")),
])
def test_cantilever_tables(key, table, elements):
    for n, row in table["rows"].items():
        for el in elements:
            out = _tip(el, n, table["model"], *_setting(table, el))
            assert out["converged"], (key, el, n, out["message"])
            p = row[pub.CANTILEVER_COLUMNS.index(el)]
            assert _max_diff(out, p) < TIP_TOL, (key, el, n, out["results"], p)


def test_report_table_4_linear_and_no_convergence():
    """Report Table 4: the 1-point-shear scheme matches up to 16 elements and, at 32 and 64,
    Newton ends on an unstable equilibrium, which is reported as no convergence."""
    for n, row in pub.REPORT_4["rows"].items():
        out = _tip("linear", n, pub.MODEL_2, "report-selective")
        if row[1] is None:
            assert not out["converged"] and "No convergence" in out["message"]
            assert out["results"]["negative_tangent_eigenvalues"] >= 1
        else:
            r = out["results"]
            assert out["converged"]
            assert abs(r["tip_x"] - row[1][0]) < TIP_TOL and abs(r["tip_y"] - row[1][1]) < TIP_TOL


# Report Table 3, Omar-Shabana: no setting reproduces it to the printed digits; today
# <= 2.62e-5 m away apart from the n = 4 cell (reports/static_beams.md); tolerance 1.5 x.
REPORT_3_OS_TOL = MARGIN * 2.62e-5


def test_report_table_3_omar_shabana_single_outlier():
    """Report Table 3, Omar-Shabana, n = 4: only x is off (2.7e-3 m); y and every other row
    match, and the thesis's Table 2.3 prints our x for the same cell, so the report's cell
    is a transcription error (see reports/static_beams.md)."""
    for n, row in pub.REPORT_3["rows"].items():
        r = _tip("omar-shabana", n, pub.MODEL_1, *_setting(pub.REPORT_3, "omar-shabana"))["results"]
        assert abs(r["tip_y"] - row[0][1]) < REPORT_3_OS_TOL
        if n == 4:
            assert abs(r["tip_x"] - row[0][0]) > 10 * REPORT_3_OS_TOL
            assert abs(r["tip_x"] - pub.THESIS_2_3["rows"][4][0][0]) < REPORT_3_OS_TOL
        else:
            assert abs(r["tip_x"] - row[0][0]) < REPORT_3_OS_TOL


# Omar-Shabana with each document's setting: today <= 5.0e-6 m (report Table 4, n = 8),
# half a unit of the printed 5th decimal; tolerance 1.5 x.
PRINTED = MARGIN * 5.0e-6


@pytest.mark.parametrize("table,other", [(pub.THESIS_2_4, pub.REPORT_4),
                                         (pub.REPORT_4, pub.THESIS_2_4)],
                         ids=["thesis2.4", "report4"])
def test_omar_shabana_model_2_setting_per_document(table, other):
    """The evidence quoted in the report: the two documents' Model 2 columns differ from
    each other by more than the tolerance; each is reproduced to the printed digits by its
    own setting (dr/dx clamped too; thesis closed form, report 2 Gauss points across y),
    and neither by the other document's setting or by the clamp the papers state."""
    gap = max(abs(a - b) for n in pub.N
              for a, b in zip(table["rows"][n][0], other["rows"][n][0]))
    assert gap > 2 * TIP_TOL
    own, theirs = _setting(table, "omar-shabana"), _setting(other, "omar-shabana")
    for n in (2, 4, 64):
        p = table["rows"][n][0]
        assert _max_diff(_tip("omar-shabana", n, pub.MODEL_2, *own), p) < PRINTED, n
    p = table["rows"][4][0]
    assert _max_diff(_tip("omar-shabana", 4, pub.MODEL_2, *theirs), p) > TIP_TOL
    assert _max_diff(_tip("omar-shabana", 4, pub.MODEL_2, own[0], "free"), p) > TIP_TOL


def test_thesis_table_2_3_omar_shabana_to_the_printed_digits():
    table = pub.THESIS_2_3
    for n, row in table["rows"].items():
        out = _tip("omar-shabana", n, table["model"], *_setting(table, "omar-shabana"))
        assert _max_diff(out, row[0]) < PRINTED, n


def test_model_1_is_the_cantilever_defaults():
    """README: Model 1 is `ancf run cantilever` with its defaults (E, nu, L, h, b, ks, F and
    n_elements), so a change of any default moves the tip off thesis Table 2.3."""
    for el in ("omar-shabana", "linear"):
        integration, clamp = _setting(pub.THESIS_2_3, el)
        out, _ = SCENES["cantilever"].execute(dict(element=el, integration=integration,
                                                   clamp_x_slope=clamp))
        row = pub.THESIS_2_3["rows"][out["params"]["n_elements"]]
        assert _max_diff(out, row[pub.CANTILEVER_COLUMNS.index(el)]) < TIP_TOL, el


def test_clamp_x_slope_changes_only_the_omar_shabana_model():
    """The linear element has no dr/dx coordinate: both clamps give the same model."""
    free = _tip("linear", 4, pub.MODEL_2, clamp_x_slope="free")["results"]
    fixed = _tip("linear", 4, pub.MODEL_2, clamp_x_slope="fixed")["results"]
    assert (free["tip_x"], free["tip_y"]) == (fixed["tip_x"], fixed["tip_y"])


@pytest.mark.parametrize("element", ["omar-shabana", "linear"])
@pytest.mark.parametrize("nu", [0.0, 0.3])
def test_report_table_6_elongation(element, nu):
    out, _ = SCENES["axial-bar"].execute(dict(element=element, nu=nu))
    ours_mm = out["results"]["elongation_m"] * 1e3
    # today <= 8.9e-6 relative (the report prints 6 decimals: 1e-5 relative); 1.5 x
    assert ours_mm == pytest.approx(pub.REPORT_6[(element, nu)], rel=MARGIN * 8.9e-6)
    assert abs(out["results"]["tip_reaction_y_N"]) < 1e-6  # the roller carries no load


@pytest.mark.parametrize("slenderness", [20, 200, 2000])
def test_shear_locking_exact_vs_thesis(slenderness):
    """Small-deflection cantilever vs the Timoshenko cantilever: exact integration locks
    (more so when slender), the thesis scheme does not: today its 64 elements are 6.1e-5 below
    Timoshenko at every slenderness (discretisation error), tolerance 1.5 x; exact integration
    is 3.04 %, 75.8 % and 99.68 % below (locking), required at least that / 1.5."""
    from analytic.timoshenko import cantilever_tip_deflection
    h = 2.0 / slenderness
    F = -1e-5 * 2.0 / abs(cantilever_tip_deflection(2.07e11, 0.3, 2.0, h, 0.1, -1.0))
    ref = cantilever_tip_deflection(2.07e11, 0.3, 2.0, h, 0.1, F)
    ratio = {}
    for integ in ("exact", "thesis"):
        out, _ = SCENES["cantilever"].execute(dict(integration=integ, n_elements=64, h=h, F=F,
                                                   load_steps=1))
        assert out["converged"], out["message"]
        ratio[integ] = out["results"]["tip_y"] / ref
    assert ratio["thesis"] == pytest.approx(1.0, abs=MARGIN * 6.11e-5)
    assert 1 - ratio["exact"] > {20: 0.0304, 200: 0.758, 2000: 0.9968}[slenderness] / MARGIN
