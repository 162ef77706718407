"""Issue 35: the Princeton beam (every load and angle) with Chrono's ANCF 3243 and 3333 at
16 elements against the ANSYS beam elements (``ancf.checks.chrono_princeton``): |u_y|
within 1 %, |u_z| within 0.5 % (ours / ANSYS - 1; components that ANSYS has at 0 by
symmetry are not compared, as in ``ancf.checks.beam3d_benchmarks``).

Strict xfail: u_z of the cases below is 0.53-1.40 % (3243) and 0.55-0.94 % (3333) low at
16 elements.  Cause: a discretisation locking of the continuum elements under large element
rotation, not the material: the error grows with the load (3243, 90 deg: F2 -0.86 %, F3
-1.40 %) and falls steeply with the mesh (F3, 90 deg: 3243 -13.8 / -1.40 / -0.09 % at 8 /
16 / 32 elements, 3333 -10.3 / -0.94 / -0.05 %); the small-load tip deflection is within
0.1 % of Timoshenko's; k_s = 5/6 instead of J/(I_y + I_z) moves it by 0.02 %; the Poisson
split is on (without it u_z is 23 % low).
"""
from __future__ import annotations

from functools import lru_cache

import pytest

from ancf.checks import chrono_princeton as cp
from ancf.scenes import beam3d_published as pub

TOL = {"uy": 0.01, "uz": 0.005}
LOCKING = ("u_z too stiff at 16 elements: large-rotation locking of the element's "
           "interpolated section (F3, 90 deg: within 0.1 % at 32 elements)")
#: (element, load, beta in deg) whose u_z is outside 0.5 % at 16 elements
UZ_LOCKED = {("3243", "F2", b) for b in (45.0, 60.0, 75.0, 90.0)} \
    | {("3243", "F3", b) for b in (30.0, 45.0, 60.0, 75.0, 90.0)} \
    | {("3333", "F2", b) for b in (75.0, 90.0)} \
    | {("3333", "F3", b) for b in (45.0, 60.0, 75.0, 90.0)}


@lru_cache(maxsize=None)
def row(element: str, load: str, beta: float) -> dict:
    return cp.row(element, load, beta)


def cases():
    for element in ("3243", "3333"):
        for load in pub.PRINCETON_LOADS:
            for beta in pub.PRINCETON_ANGLES:
                for c, published in zip(("uy", "uz"), cp.ansys(load, beta)):
                    if published == 0.0:
                        continue
                    marks = [pytest.mark.xfail(strict=True, reason=LOCKING)] \
                        if c == "uz" and (element, load, beta) in UZ_LOCKED else []
                    yield pytest.param(element, load, beta, c, marks=marks,
                                       id=f"{element}-{load}-{beta:g}-{c}")


@pytest.mark.slow
@pytest.mark.parametrize("element, load, beta, component", list(cases()))
def test_princeton_against_ansys(element, load, beta, component):
    r = row(element, load, beta)
    assert r["converged"], r
    assert abs(r[component + " error"]) <= TOL[component], cp.table([r])


def main():
    """Print the table of every case (``python tests/checks/test_chrono_princeton.py``)."""
    print(cp.table([row(e, ld, b) for e in ("3243", "3333") for ld in pub.PRINCETON_LOADS
                    for b in pub.PRINCETON_ANGLES]))


if __name__ == "__main__":
    main()
