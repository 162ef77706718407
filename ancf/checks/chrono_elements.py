"""Project Chrono's ANCF elements (issue 35) as report rows: Chrono's textbook static
cases of its beams (3243, 3333), brick (3843) and shells (3443, 3833) at Chrono's own
tolerances, the Princeton beam on the beams against ANSYS (:mod:`ancf.checks.chrono_princeton`)
and the simply supported square plate of the shells against Navier; shared by the chapter
``chrono_elements`` and ``tests/reports/test_chrono_elements_chapter.py``.

Static cases (Chrono's ``utest_FEA_ANCF*_Formulation.cpp``, snapshot 7689fbc0; the
parameters and line numbers are in ``tests/models/test_chrono_beam_static.py``,
``test_chrono_continuum_static.py``, ``test_chrono_shell.py``): a strip of 20 elements,
L = 20 in, aluminium rho = 2810 kg/m^3, E = 71.7 GPa, nu = 0.33, clamped at x = 0, loaded
at the tip; textbook values (m, or rad for the twist):

    axial  P L/(A E)    tip  P L^3/(3 E I)    gravity  rho A g L^4/(8 E I)
    twist  M L/(G J),  J = 2.25 (a/2)^4 (square beam, brick), 0.281 w h^3 (shell strip)

with P = M = 10 (beams, brick) or 1 (shells), I = w h^3/12 about the bending axis.  Error =
ours / textbook - 1; a case passes when |error| is within Chrono's percent tolerance and
the off-axis Cardan angles within Chrono's bound (deg).
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from analytic import navier_plate, plate_modes
from ancf.checks import chrono_princeton as cp
from ancf.models import chrono_beam as cb
from ancf.models import chrono_shell as cs
from ancf.models.chrono_continuum import BrickBar
from ancf.scenes import beam3d_published as pub
from ancf.scenes import plate_square
from ancf.scenes.base import STEEL_DENSITY

INCH = 0.0254                                # m
N, L = 20, 20 * INCH                         # elements, m
RHO, E, NU, GRAV = 2810.0, 71.7e9, 0.33, -9.80665   # kg/m^3, Pa, -, m/s^2
K_SHEAR = 10 * (1 + NU) / (12 + 11 * NU)     # the beams' Timoshenko k1 = k2
THIN, WIDE = 0.125 * INCH, 0.5 * INCH        # m
#: case -> (section along y, along z in m, off-axis Cardan angles checked: 0 x, 1 y, 2 z)
CASES = {"axial": ((THIN, WIDE), (0, 1, 2)), "tip": ((THIN, WIDE), (0, 2)),
         "gravity": ((WIDE, THIN), (0, 2)), "twist": ((WIDE, WIDE), (1, 2))}
#: (element, case) -> (Chrono's percent tolerance, off-axis angle bound in deg)
TOLERANCE = {**{(el, c): (2.0, 0.001) for el in ("3243", "3333") for c in CASES},
             ("3843", "axial"): (2.0, 0.01), ("3843", "tip"): (5.0, 0.01),
             ("3843", "gravity"): (5.0, 0.001), ("3843", "twist"): (2.0, 0.001),
             **{("3443", c): (2.0 if c == "axial" else 15.0, 0.001) for c in CASES},
             **{("3833", c): (15.0 if c == "twist" else 2.0, 0.001) for c in CASES}}
PRINCETON_TOL = {"uy": 0.01, "uz": 0.005}    # relative, as tests/checks/test_chrono_princeton
PRINCETON_FINE = 32                          # elements of the rows that re-check the misses
PRINCETON_FINE_BETA = 90.0                   # deg, the misses re-checked
PLATE_TOL = 0.01                             # relative, Navier's w and frequencies
PLATE_N = 16                                 # elements per side


def textbook(case: str, H: float, W: float, load: float, shell: bool = False) -> float:
    """Chrono's textbook value (m, rad) for the section H (y) x W (z) in m and the tip
    load P = M (N, N m)."""
    A, I, G = H * W, H * W**3 / 12.0, E / (2.0 * (1.0 + NU))
    J = 0.281 * H * W**3 if shell else 2.25 * (0.5 * W) ** 4
    return {"axial": load * L / (A * E), "tip": load * L**3 / (3.0 * E * I),
            "gravity": RHO * A * GRAV * L**4 / (8.0 * E * I), "twist": load * L / (G * J)}[case]


def _beam(element: str, case: str):
    """(value, Cardan angles in rad) of a 20-element Chrono beam (P = M = 10)."""
    (H, W), _ = CASES[case]
    b = cb.Beam(element=element, n=N, L=L, H=H, W=W, rho=RHO, E=E, nu=NU, k1=K_SHEAR,
                k2=K_SHEAR)
    f = {"axial": lambda: cb.tip_load(b, force=(10.0, 0, 0)),
         "tip": lambda: cb.tip_load(b, force=(0, 0, 10.0)),
         "gravity": lambda: cb.gravity(b, (0, 0, GRAV)),
         "twist": lambda: cb.tip_load(b, moment=(10.0, 0, 0))}[case]()
    point, R = cb.tip_frame(b, cb.solve_static(b, f).e)
    return point, cb.cardan_xyz(R)


def _brick(case: str):
    """(tip point, Cardan angles in rad) of 20 3843 bricks (w along y, h along z)."""
    (w, h), _ = CASES[case]
    b = BrickBar(n=N, L=L, w=w, h=h, E=E, nu=NU, rho=RHO)
    f = {"axial": lambda: b.tip_force([10.0, 0, 0]), "tip": lambda: b.tip_force([0, 0, 10.0]),
         "gravity": lambda: b.gravity([0, 0, GRAV]),
         "twist": lambda: b.tip_moment([10.0, 0, 0])}[case]()
    return b.tip_frame(b.solve(f)[0])


def _shell(element: str, case: str):
    """(tip point, Cardan angles in rad) of Chrono's 20 x 1 shell strip, 0.5 in wide,
    0.125 in thick, P = M = 1 at (xi, eta) = (1, 0) of the last element."""
    plate = cs.Plate(element, nx=N, ny=1, a=L, b=WIDE, H=THIN, E=E, nu=NU, rho=RHO,
                     y0=-WIDE / 2)
    tip = dict(k=N - 1, xi=1.0, eta=0.0)
    f = {"axial": lambda: cs.point_load(plate, **tip, force=(1.0, 0, 0)),
         "tip": lambda: cs.point_load(plate, **tip, force=(0, 0, 1.0)),
         "gravity": lambda: cs.gravity(plate, (0, 0, GRAV)),
         "twist": lambda: cs.point_load(plate, **tip, moment=(1.0, 0, 0))}[case]()
    sol = cs.solve_static(plate, f, [plate.clamped("x0")])
    point, R = cs.section_frame(plate, sol.e, N - 1, 1.0, 0.0)
    return point, cs.cardan_xyz(R)


def static_row(element: str, case: str) -> dict:
    """One of Chrono's static cases: ours, textbook, error, tolerances, pass."""
    shell = element in cs.ELEMENTS
    point, angles = (_shell(element, case) if shell else _brick(case) if element == "3843"
                     else _beam(element, case))
    (H, W), off = CASES[case]
    if shell:   # the strip is 0.5 in wide (y) and 0.125 in thick (z) in every case
        H, W = WIDE, THIN
    ours = {"axial": point[0] - L, "tip": point[2], "gravity": point[2],
            "twist": angles[0]}[case]
    ref = textbook(case, H, W, 1.0 if shell else 10.0, shell)
    percent, bound = TOLERANCE[element, case]
    off_deg = float(np.degrees(np.abs(angles[list(off)])).max())
    err = ours / ref - 1.0
    return {"element": element, "case": case, "ours": float(ours), "textbook": ref,
            "error": err, "tolerance": percent / 100.0, "off-axis [deg]": off_deg,
            "angle bound [deg]": bound,
            "passed": bool(abs(err) < percent / 100.0 and off_deg < bound)}


def static_rows() -> list[dict]:
    """Every static case: the beams, the brick, the shells."""
    return [static_row(el, c) for el in ("3243", "3333", "3843", "3443", "3833") for c in CASES]


@lru_cache(maxsize=None)
def princeton_row(element: str, load: str, beta: float, n: int = cp.N_ELEMENTS) -> dict:
    """:func:`ancf.checks.chrono_princeton.row` with n and whether |u_y|, |u_z| are within
    1 %, 0.5 % of ANSYS (None where ANSYS is 0 by symmetry)."""
    r = dict(cp.row(element, load, beta, n), n=n)
    for c, tol in PRINCETON_TOL.items():
        err = r[f"{c} error"]
        r[f"{c} within"] = None if err is None else bool(abs(err) <= tol)
    return r


def princeton_rows() -> list[dict]:
    """Every load and angle on both beams at 16 elements, then the u_z misses at
    :data:`PRINCETON_FINE_BETA` (the largest per load) again at :data:`PRINCETON_FINE`
    elements (about 10 s CPU each)."""
    rows = [princeton_row(el, ld, b) for el in cb.ELEMENTS for ld in pub.PRINCETON_LOADS
            for b in pub.PRINCETON_ANGLES]
    return rows + [princeton_row(r["element"], r["load"], r["beta"], PRINCETON_FINE)
                   for r in rows if r["uz within"] is False and r["beta"] == PRINCETON_FINE_BETA]


def plate_parameters() -> dict:
    """The ``plate-square`` scene's defaults (m, Pa, -, Pa) and steel's density (kg/m^3)."""
    return {p.name: p.default for p in plate_square.params()} | {"rho": STEEL_DENSITY.default}


@lru_cache(maxsize=None)
def plate_row(element: str, n: int = PLATE_N) -> dict:
    """The simply supported square plate of n x n shells: centre deflection w (m) against
    Navier, the first six frequencies (Hz) against the analytic plate, the largest errors."""
    p = plate_parameters()
    plate = cs.Plate(element, nx=n, ny=n, a=p["a"], b=p["a"], H=p["h"], E=p["E"],
                     nu=p["nu"], rho=p["rho"])
    fixed = [plate.simply_supported(s) for s in ("x0", "x1", "y0", "y1")]
    fixed.append(plate.in_plane_rigid())
    sol = cs.solve_static(plate, cs.pressure(plate, p["p"]), fixed)
    w = cs.point(plate, sol.e, (n // 2) * n + n // 2, -1.0, -1.0)[2]
    w_ref = navier_plate.centre_deflection(p["a"], p["a"], p["h"], p["E"], p["nu"], p["p"])[0]
    f = cs.modes(plate, fixed, 6)
    f_ref = plate_modes.navier_frequencies(p["a"], p["a"], p["h"], p["E"], p["nu"], p["rho"],
                                           6)[0]
    return {"element": element, "n": n, "w": w, "Navier w": w_ref, "w error": w / w_ref - 1,
            "f": tuple(f), "f ref": tuple(f_ref),
            "f error": float(np.abs(f / f_ref - 1).max()), "locking": locking_factor(p["nu"])}


def locking_factor(nu: float) -> float:
    """(1 - nu)^2/(1 - 2 nu): the 3443's bending stiffness over Kirchhoff's D when its
    constant fibre r_z leaves no free thickness contraction (Poisson locking)."""
    return (1 - nu) ** 2 / (1 - 2 * nu)


def plate_rows() -> list[dict]:
    return [plate_row(el) for el in cs.ELEMENTS]


def checks(static=None, princeton=None, plates=None) -> tuple:
    """The acceptance checks (rows computed here unless given)."""
    from ancf.checks import chrono_matrices as cm
    from ancf.checks.belt2d import Check
    static = static_rows() if static is None else static
    princeton = princeton_rows() if princeton is None else princeton
    plates = plate_rows() if plates is None else plates
    matrices = cm.table()
    out = [Check(f"Chrono's stored {k} files: every element within {b:g}", worst, 0.0, worst,
                 b, "-", "largest max abs(ours − Chrono) / max abs(Chrono)")
           for k, b in (("mass", cm.RTOL_MASS), ("gravity", cm.RTOL_MASS),
                        ("force", cm.RTOL_FORCE), ("Jacobian", cm.RTOL_JAC))
           for worst in [max(r["difference"] for r in matrices if r["kind"] == k)]]
    for els in (("3243", "3333"), ("3843",), ("3443", "3833")):
        rows = [r for r in static if r["element"] in els]
        worst = max(abs(r["error"]) / r["tolerance"] for r in rows)
        angles = all(r["off-axis [deg]"] < r["angle bound [deg]"] for r in rows)
        out.append(Check(f"Chrono's static cases, {' and '.join(els)}: within Chrono's "
                         "tolerances", worst, 0.0, worst if angles else math.inf, 1.0, "-",
                         "largest abs(error) / Chrono's tolerance (angles: all within)"
                         if angles else "off-axis angles outside Chrono's bounds"))
    coarse = [r for r in princeton if r["n"] == cp.N_ELEMENTS]
    uy = max(abs(r["uy error"]) for r in coarse if r["uy error"] is not None)
    out.append(Check("Princeton beam, 16 elements: every u_y within 1 % of ANSYS", uy, 0.0,
                     uy, PRINCETON_TOL["uy"], "-", "largest relative"))
    fine = [r for r in princeton if r["n"] == PRINCETON_FINE]
    uz = max((abs(r["uz error"]) for r in fine), default=0.0)
    out.append(Check(f"Princeton beam: the 16-element u_z misses at {PRINCETON_FINE_BETA:g}° "
                     f"within 0.5 % at {PRINCETON_FINE} elements", uz, 0.0, uz,
                     PRINCETON_TOL["uz"], "-",
                     "largest relative"))
    for r in plates:
        scale = 1.0 if r["element"] == "3833" else r["locking"]
        w = abs(r["w"] * scale / r["Navier w"] - 1)
        what = "w" if scale == 1.0 else "w × (1 − ν)²/(1 − 2ν)"
        out.append(Check(f"Square plate {r['n']} × {r['n']}, {r['element']}: {what} within "
                         "1 % of Navier", r["w"] * scale, r["Navier w"], w, PLATE_TOL, "m",
                         "relative"))
    r3833 = next(r for r in plates if r["element"] == "3833")
    out.append(Check("Square plate, 3833: first six frequencies within 1 % of the analytic "
                     "plate", r3833["f error"], 0.0, r3833["f error"], PLATE_TOL, "-",
                     "largest relative"))
    return tuple(out)
