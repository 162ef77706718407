"""Issue 35: why Chrono's beams miss u_z of the Princeton beam at 16 elements and the 3443
misses f4-f6 of the square plate at 16 x 16 (``ancf.checks.chrono_locking``).

Beams: locking of the interpolation, freed by an inexact rule along the axis.  Chrono's
own 3 points give the exact rule's u_z (1e-4 relative); 2 points bring every u_z within
0.5 % of ANSYS, but give the 3243 mechanisms and the 3333 u_y beyond 1 %.  Reducing one
part of D0 alone: the axial part is the 3333's locking (membrane locking: within 0.5 %
with that part alone); the thickness part removes more than half the 3243's miss.

Plate: with G_13, G_23 x 100 the 3443's frequencies rise more than 10 % above Navier's
(Kirchhoff's limit of a plate stiff in shear: a locking-free element stays within its
discretisation error of it), at the material's moduli f4-f6 miss by 1-2 % at 16 x 16 and
every frequency is within 1 % at 24 x 24.
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np
import pytest

from ancf.checks import chrono_elements as ce
from ancf.checks import chrono_locking as cl
from ancf.checks import chrono_princeton as cp
from ancf.elements import ancf3243, ancf3333
from ancf.models import chrono_beam as cb
from ancf.models import chrono_shell as cs

UZ, UY = ce.PRINCETON_TOL["uz"], ce.PRINCETON_TOL["uy"]
SAME_RULE = 1e-4      # relative: u_z of Chrono's 3-point rule against the exact rule's
SAME_SHELL_RULE = 1e-5  # relative: the 3443's f with Chrono's 3 x 3 x 2 rule against exact
RIGID = 6             # rigid motions of a free element: its zero-energy modes without mechanisms


@lru_cache(maxsize=None)
def reduced_rows() -> tuple:
    return tuple(cl.princeton_rule_rows())


@lru_cache(maxsize=None)
def plate_rows() -> tuple:
    return tuple(cl.plate_rows())


@pytest.mark.slow   # about 10 s (28 Newton solves)
def test_two_point_axial_rule_brings_every_uz_within_tolerance():
    rows = reduced_rows()
    assert all(r["converged"] for r in rows)
    assert all(abs(r["uz error"]) <= UZ for r in rows if r["uz error"] is not None)
    assert cl.checks(list(rows), list(plate_rows()))[0].passed


@pytest.mark.slow
def test_two_point_axial_rule_is_no_fix():
    """The 3243 gets mechanisms (the exact rule has none), the 3333's u_y leaves 1 %."""
    assert cl.zero_energy_modes("3243") == cl.zero_energy_modes("3333") == RIGID
    assert cl.zero_energy_modes("3243", cl.REDUCED_AXIS) > RIGID
    assert cl.zero_energy_modes("3333", cl.REDUCED_AXIS) == RIGID
    uy = [abs(r["uy error"]) for r in reduced_rows()
          if r["element"] == "3333" and r["uy error"] is not None]
    assert max(uy) > UY


@pytest.mark.slow
@pytest.mark.parametrize("element", ["3243", "3333"])
def test_chronos_three_point_rule_gives_the_exact_rules_uz(element):
    exact = cp.solve(element, "F3", 90.0)
    chrono = cp.solve(element, "F3", 90.0, naxis=3)
    assert abs(chrono.uz / exact.uz - 1) < SAME_RULE


def _reduce_only(monkeypatch, entries):
    """The beams' D0 entries ``entries`` (Voigt indices) by 2 points along the axis, the
    rest of D0 and the Poisson part Dv by the exact rules."""
    for module in (ancf3243, ancf3333):
        exact = module.continuum

        def continuum(*args, _exact=exact, **kw):
            basis = _exact(*args)[0]
            D0, Dv = ancf3243.elasticity(*args[3:7])
            part = np.zeros_like(D0)
            part[entries, entries] = D0[entries, entries]
            return basis, [(D0 - part, *ancf3243.rule(ancf3243.NAXIS, ancf3243.NSECTION)),
                           (part, *ancf3243.rule(cl.REDUCED_AXIS, ancf3243.NSECTION)),
                           (Dv, *ancf3243.rule(ancf3243.NAXIS, 1))]
        monkeypatch.setattr(module, "continuum", continuum)
    cb._kernel.cache_clear()


@pytest.fixture
def fresh_kernels():
    cb._kernel.cache_clear()
    yield
    cb._kernel.cache_clear()


@pytest.mark.slow
def test_the_3333_locks_in_its_axial_strain(monkeypatch, fresh_kernels):
    _reduce_only(monkeypatch, [0])
    r = cp.row("3333", "F3", 90.0)
    assert r["converged"] and abs(r["uz error"]) <= UZ, r


@pytest.mark.slow
def test_the_3243_locks_in_its_thickness_strains(monkeypatch, fresh_kernels):
    exact = cp.row("3243", "F3", 90.0)
    _reduce_only(monkeypatch, [1, 2])
    r = cp.row("3243", "F3", 90.0)
    assert r["converged"] and abs(r["uz error"]) < 0.5 * abs(exact["uz error"]), (r, exact)


@pytest.mark.slow   # about 5 s (three sparse eigenproblems)
def test_3443_frequencies_rise_above_kirchhoff_with_stiffer_shear():
    base, stiff, fine = plate_rows()
    assert (base["n"], base["shear"]) == (ce.PLATE_N, 1.0)
    high = np.abs(base["errors"][3:])
    assert np.all(high > ce.PLATE_TOL) and np.all(high < 2 * ce.PLATE_TOL)
    assert min(stiff["errors"]) > cl.LOCKED_ABOVE
    assert fine["n"] == cl.PLATE_FINE and max(np.abs(fine["errors"])) < ce.PLATE_TOL
    check = cl.checks(list(reduced_rows()), list(plate_rows()))[1]
    assert check.passed and check.value == min(stiff["errors"])


def test_shear_scaled_law_scales_only_the_transverse_shear():
    p = ce.plate_parameters()
    args = dict(nx=1, ny=1, a=p["a"], b=p["a"], H=p["h"], E=p["E"], nu=p["nu"])
    D = cl.ShearScaled("3443", **args).material()[0]
    D2 = cl.ShearScaled("3443", **args, shear=cl.SHEAR_SCALE).material()[0]
    scale = np.ones((6, 6))
    scale[3, 3] = scale[4, 4] = cl.SHEAR_SCALE
    np.testing.assert_array_equal(D2, D * scale)


def test_chronos_three_point_shell_rule_gives_the_same_frequencies():
    """Chrono's header names NP = 3, NT = 2 a less stiff 3443: about the flat plate its
    frequencies are the exact rule's within 1e-5 relative (8 x 8: 7e-6 lower), no remedy
    for a 1 % miss."""
    from dataclasses import dataclass

    @dataclass(frozen=True)
    class ChronoRule(cl.ShearScaled):
        def options(self):
            return {**super().options(), "n_plane": 3, "n_thick": 2}

    p = ce.plate_parameters()
    f = []
    for cls in (cl.ShearScaled, ChronoRule):
        plate = cls("3443", nx=8, ny=8, a=p["a"], b=p["a"], H=p["h"], E=p["E"], nu=p["nu"],
                    rho=p["rho"], poisson="plane_stress")
        fixed = [plate.simply_supported(s) for s in ("x0", "x1", "y0", "y1")]
        f.append(cs.modes(plate, fixed + [plate.in_plane_rigid()], 6))
    np.testing.assert_allclose(f[1], f[0], rtol=SAME_SHELL_RULE)
    assert np.all(f[1] <= f[0])
