"""Project Chrono's ANCF elements (issue 35) as report rows: Chrono's textbook static
cases of its beams (3243, 3333), brick (3843) and shells (3443, 3833) at Chrono's own
tolerances, the Princeton beam on the beams against ANSYS (:mod:`ancf.checks.chrono_princeton`)
and the simply supported square plate of the shells against Navier; shared by the chapter
``chrono_elements`` and ``tests/reports/test_chrono_elements_chapter.py``.

The case setups live here once; the model tests ``tests/models/test_chrono_beam_static.py``,
``test_chrono_continuum_static.py`` and ``test_chrono_shell.py`` take them from here and
cite Chrono's source line by line.

Static cases (Chrono's ``utest_FEA_ANCF*_Formulation.cpp``, snapshot 7689fbc0): a strip
of 20 elements, L = 20 in, aluminium rho = 2810 kg/m^3, E = 71.7 GPa, nu = 0.33, clamped
at x = 0, loaded at the tip; textbook values (m, or rad for the twist):

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


def reference(element: str, case: str) -> float:
    """The textbook value (m, rad) of Chrono's case on the element: P = M = 10 on the
    beams and brick (section :data:`CASES`), 1 on the shell strip (WIDE along y, THIN
    along z in every case)."""
    if element in cs.ELEMENTS:
        return textbook(case, WIDE, THIN, 1.0, shell=True)
    return textbook(case, *CASES[case][0], 10.0)


def measured(case: str, point, angles) -> float:
    """What Chrono compares with the textbook: the tip's u_x, u_z (m) or roll (rad), from
    the tip point (m) and its Cardan angles (rad)."""
    return {"axial": point[0] - L, "tip": point[2], "gravity": point[2],
            "twist": angles[0]}[case]


def beam(element: str, case: str, E_: float = E) -> cb.Beam:
    """Chrono's 20-element beam of the case, Young's modulus E_ (Pa)."""
    (H, W), _ = CASES[case]
    return cb.Beam(element=element, n=N, L=L, H=H, W=W, rho=RHO, E=E_, nu=NU, k1=K_SHEAR,
                   k2=K_SHEAR)


def beam_load(b: cb.Beam, case: str) -> np.ndarray:
    """The case's generalised load on the beam: P = M = 10 (N, N m) at the tip, or g."""
    return {"axial": lambda: cb.tip_load(b, force=(10.0, 0, 0)),
            "tip": lambda: cb.tip_load(b, force=(0, 0, 10.0)),
            "gravity": lambda: cb.gravity(b, (0, 0, GRAV)),
            "twist": lambda: cb.tip_load(b, moment=(10.0, 0, 0))}[case]()


@lru_cache(maxsize=None)
def beam_solution(element: str, case: str, E_: float = E):
    """(tip point in m, Cardan angles in rad, Newton solution) of the case's beam."""
    b = beam(element, case, E_)
    sol = cb.solve_static(b, beam_load(b, case))
    point, R = cb.tip_frame(b, sol.e)
    return point, cb.cardan_xyz(R), sol


def brick(case: str, E_: float = E) -> BrickBar:
    """20 3843 bricks of the case's section (w along y, h along z), Young's modulus E_ (Pa)."""
    (w, h), _ = CASES[case]
    return BrickBar(n=N, L=L, w=w, h=h, E=E_, nu=NU, rho=RHO)


@lru_cache(maxsize=None)
def brick_solution(case: str, E_: float = E):
    """(tip point in m, Cardan angles in rad, Newton residual) of the case's bricks."""
    b = brick(case, E_)
    f = {"axial": lambda: b.tip_force([10.0, 0, 0]), "tip": lambda: b.tip_force([0, 0, 10.0]),
         "gravity": lambda: b.gravity([0, 0, GRAV]),
         "twist": lambda: b.tip_moment([10.0, 0, 0])}[case]()
    u, _, res = b.solve(f)
    return (*b.tip_frame(u), res)


def strip(element: str) -> cs.Plate:
    """Chrono's 20 x 1 shell strip, 0.5 in wide (y in [-w/2, w/2]), 0.125 in thick."""
    return cs.Plate(element, nx=N, ny=1, a=L, b=WIDE, H=THIN, E=E, nu=NU, rho=RHO,
                    y0=-WIDE / 2)


def strip_load(plate: cs.Plate, case: str) -> np.ndarray:
    """The case's load on the strip: P = M = 1 (N, N m) at (xi, eta) = (1, 0) of the last
    element, or g."""
    tip = dict(k=N - 1, xi=1.0, eta=0.0)
    return {"axial": lambda: cs.point_load(plate, **tip, force=(1.0, 0, 0)),
            "tip": lambda: cs.point_load(plate, **tip, force=(0, 0, 1.0)),
            "gravity": lambda: cs.gravity(plate, (0, 0, GRAV)),
            "twist": lambda: cs.point_load(plate, **tip, moment=(1.0, 0, 0))}[case]()


@lru_cache(maxsize=None)
def strip_solution(element: str, case: str):
    """(tip point in m, Cardan angles in rad of ``EvaluateSectionFrame(1, 0)``, Newton
    solution) of the clamped strip."""
    plate = strip(element)
    sol = cs.solve_static(plate, strip_load(plate, case), [plate.clamped("x0")])
    point, R = cs.section_frame(plate, sol.e, N - 1, 1.0, 0.0)
    return point, cs.cardan_xyz(R), sol


def static_row(element: str, case: str) -> dict:
    """One of Chrono's static cases: ours, textbook, error, tolerances, pass."""
    point, angles, _ = (strip_solution(element, case) if element in cs.ELEMENTS
                        else brick_solution(case) if element == "3843"
                        else beam_solution(element, case))
    ours, ref = measured(case, point, angles), reference(element, case)
    percent, bound = TOLERANCE[element, case]
    off_deg = float(np.degrees(np.abs(angles[list(CASES[case][1])])).max())
    err = ours / ref - 1.0
    return {"element": element, "case": case, "ours": float(ours), "textbook": ref,
            "error": err, "tolerance": percent / 100.0, "off-axis [deg]": off_deg,
            "angle bound [deg]": bound,
            "passed": bool(abs(err) < percent / 100.0 and off_deg < bound)}


def static_rows() -> list[dict]:
    """Every static case: the beams, the brick, the shells."""
    return [static_row(el, c) for el in ("3243", "3333", "3843", "3443", "3833") for c in CASES]


@lru_cache(maxsize=None)
def princeton_row(element: str, load: str, beta: float, n: int = cp.N_ELEMENTS,
                  naxis: int | None = None) -> dict:
    """:func:`ancf.checks.chrono_princeton.row` (``naxis`` Gauss points along the axis,
    None: exact) with n and whether |u_y|, |u_z| are within 1 %, 0.5 % of ANSYS (None
    where ANSYS is 0 by symmetry)."""
    r = dict(cp.row(element, load, beta, n, naxis=naxis), n=n)
    for c, tol in PRINCETON_TOL.items():
        err = r[f"{c} error"]
        r[f"{c} within"] = None if err is None else bool(abs(err) <= tol)
    return r


def princeton_rows() -> list[dict]:
    """Every load and angle on both beams at 16 elements, then the u_z misses at
    :data:`PRINCETON_FINE_BETA` (the largest per load) again at :data:`PRINCETON_FINE`
    elements (about 2 s CPU each)."""
    rows = [princeton_row(el, ld, b) for el in cb.ELEMENTS for ld in pub.PRINCETON_LOADS
            for b in pub.PRINCETON_ANGLES]
    return rows + [princeton_row(r["element"], r["load"], r["beta"], PRINCETON_FINE)
                   for r in rows if r["uz within"] is False and r["beta"] == PRINCETON_FINE_BETA]


def plate_parameters() -> dict:
    """The ``plate-square`` scene's defaults (m, Pa, -, Pa) and steel's density (kg/m^3)."""
    return {p.name: p.default for p in plate_square.params()} | {"rho": STEEL_DENSITY.default}


@lru_cache(maxsize=None)
def square_plate(element: str, n: int = PLATE_N, nu: float | None = None,
                 poisson: str = "3d"):
    """(plate, fixed coordinates): the ``plate-square`` scene on n x n shells, Poisson's
    ratio nu (the scene's if None), ``poisson`` the 3443's law (``Plate.poisson``); simply
    supported on all four edges (w = 0 along each, ``Plate.simply_supported``), in-plane
    rigid motions removed, all else free."""
    p = plate_parameters()
    plate = cs.Plate(element, nx=n, ny=n, a=p["a"], b=p["a"], H=p["h"], E=p["E"],
                     nu=p["nu"] if nu is None else nu, rho=p["rho"], poisson=poisson)
    fixed = [plate.simply_supported(s) for s in ("x0", "x1", "y0", "y1")]
    return plate, fixed + [plate.in_plane_rigid()]


def centre_deflection(plate: cs.Plate, e: np.ndarray) -> float:
    """w (m) at the centre node of the square plate, the corner A of element (n/2, n/2)."""
    n = plate.nx
    return cs.point(plate, e, (n // 2) * n + n // 2, -1.0, -1.0)[2]


def navier_w(nu: float | None = None) -> float:
    """Navier's centre deflection (m) of the scene's plate, Poisson's ratio nu (the
    scene's if None)."""
    p = plate_parameters()
    nu = p["nu"] if nu is None else nu
    return navier_plate.centre_deflection(p["a"], p["a"], p["h"], p["E"], nu, p["p"])[0]


def navier_f(k: int = 6) -> np.ndarray:
    """The analytic plate's first k natural frequencies (Hz)."""
    p = plate_parameters()
    return plate_modes.navier_frequencies(p["a"], p["a"], p["h"], p["E"], p["nu"], p["rho"],
                                          k)[0]


@lru_cache(maxsize=None)
def plate_row(element: str, n: int = PLATE_N, poisson: str = "3d") -> dict:
    """The simply supported square plate of n x n shells (the 3443 with the Poisson law
    ``poisson``): centre deflection w (m, Newton) against Navier, the first six frequencies
    (Hz) against the analytic plate, the largest errors."""
    plate, fixed = square_plate(element, n, poisson=poisson)
    sol = cs.solve_static(plate, cs.pressure(plate, plate_parameters()["p"]), fixed)
    w, w_ref = centre_deflection(plate, sol.e), navier_w()
    f, f_ref = cs.modes(plate, fixed, 6), navier_f()
    return {"element": element, "poisson": poisson, "n": n, "w": w, "Navier w": w_ref,
            "w error": w / w_ref - 1, "f": tuple(f), "f ref": tuple(f_ref),
            "f error": float(np.abs(f / f_ref - 1).max()),
            "locking": locking_factor(plate_parameters()["nu"])}


def locking_factor(nu: float) -> float:
    """(1 - nu)^2/(1 - 2 nu): the 3443's bending stiffness over Kirchhoff's D when its
    constant fibre r_z leaves no free thickness contraction (Poisson locking)."""
    return (1 - nu) ** 2 / (1 - 2 * nu)


#: (element, Poisson law) of the chapter's plate rows: the 3443 locked and with the remedy,
#: the ANS/EAS 3423 and the 3833 (both with the 3D law)
PLATE_CASES = (("3443", "3d"), ("3443", "plane_stress"), ("3423", "3d"), ("3833", "3d"))


def plate_rows() -> list[dict]:
    return [plate_row(el, poisson=law) for el, law in PLATE_CASES]


def plate_label(row: dict) -> str:
    """The element of a plate row, with the 3443's Poisson law where not Chrono's "3d"."""
    law = row["poisson"].replace("_", " ")
    return row["element"] if row["poisson"] == "3d" else f"{row['element']} ({law})"


def locked(row: dict) -> bool:
    """Whether a plate row is the 3443 with Chrono's 3D law (Poisson locking)."""
    return row["element"] == "3443" and row["poisson"] == "3d"


def plate_w_name(row: dict) -> str:
    """The name of a plate row's check on w (its element, law and n)."""
    what = "w × (1 − ν)²/(1 − 2ν)" if locked(row) else "w"
    return f"Square plate {row['n']} × {row['n']}, {plate_label(row)}: {what} within 1 % of Navier"


PLATE_F_NAME = "Square plate, 3833: first six frequencies within 1 % of the analytic plate"


def plate_checks(plates: list) -> list:
    """The square plate's checks: every row's w (the locked 3443's times the locking
    factor) within 1 % of Navier, the 3833's six frequencies within 1 %."""
    from ancf.checks.belt2d import Check
    out = []
    for r in plates:
        scale = r["locking"] if locked(r) else 1.0
        w = abs(r["w"] * scale / r["Navier w"] - 1)
        out.append(Check(plate_w_name(r), r["w"] * scale, r["Navier w"], w, PLATE_TOL, "m",
                         "relative"))
    return out + [Check(PLATE_F_NAME, r["f error"], 0.0, r["f error"], PLATE_TOL, "-",
                        "largest relative") for r in plates if r["element"] == "3833"]


#: the element groups of the static cases' checks
STATIC_GROUPS = (("3243", "3333"), ("3843",), ("3443", "3833"))
PRINCETON_UY_NAME = (f"Princeton beam, {cp.N_ELEMENTS} elements: every u_y within "
                     f"{100 * PRINCETON_TOL['uy']:g} % of ANSYS")
PRINCETON_FINE_NAME = (f"Princeton beam: the {cp.N_ELEMENTS}-element u_z misses at "
                       f"{PRINCETON_FINE_BETA:g}° within {100 * PRINCETON_TOL['uz']:g} % at "
                       f"{PRINCETON_FINE} elements")


def static_name(elements: tuple) -> str:
    return f"Chrono's static cases, {' and '.join(elements)}: within Chrono's tolerances"


def solved_names() -> list[str]:
    """The names of the checks on solved rows (static cases, Princeton beam, square plate),
    in the order of :func:`checks`: what the reduced configuration skips."""
    plates = [{"element": el, "poisson": law, "n": PLATE_N} for el, law in PLATE_CASES]
    return ([static_name(els) for els in STATIC_GROUPS]
            + [PRINCETON_UY_NAME, PRINCETON_FINE_NAME]
            + [plate_w_name(r) for r in plates]
            + [PLATE_F_NAME for r in plates if r["element"] == "3833"])


def matrix_checks() -> list:
    """The stored matrices' checks: per kind the largest difference within its bound."""
    from ancf.checks import chrono_matrices as cm
    from ancf.checks.belt2d import Check
    matrices = cm.table()
    return [Check(f"Chrono's stored {k} files: every element within {b:g}", worst, 0.0, worst,
                  b, "-", "largest max abs(ours − Chrono) / max abs(Chrono)")
            for k, b in (("mass", cm.RTOL_MASS), ("gravity", cm.RTOL_MASS),
                         ("force", cm.RTOL_FORCE), ("Jacobian", cm.RTOL_JAC))
            for worst in [max(r["difference"] for r in matrices if r["kind"] == k)]]


def checks(static=None, princeton=None, plates=None) -> tuple:
    """The acceptance checks (rows computed here unless given)."""
    from ancf.checks.belt2d import Check
    static = static_rows() if static is None else static
    princeton = princeton_rows() if princeton is None else princeton
    plates = plate_rows() if plates is None else plates
    out = matrix_checks()
    for els in STATIC_GROUPS:
        rows = [r for r in static if r["element"] in els]
        worst = max(abs(r["error"]) / r["tolerance"] for r in rows)
        angles = all(r["off-axis [deg]"] < r["angle bound [deg]"] for r in rows)
        out.append(Check(static_name(els), worst, 0.0, worst if angles else math.inf, 1.0, "-",
                         "largest abs(error) / Chrono's tolerance (angles: all within)"
                         if angles else "off-axis angles outside Chrono's bounds"))
    coarse = [r for r in princeton if r["n"] == cp.N_ELEMENTS]
    uy = max(abs(r["uy error"]) for r in coarse if r["uy error"] is not None)
    out.append(Check(PRINCETON_UY_NAME, uy, 0.0, uy, PRINCETON_TOL["uy"], "-",
                     "largest relative"))
    fine = [r for r in princeton if r["n"] == PRINCETON_FINE]
    uz = max((abs(r["uz error"]) for r in fine), default=0.0)
    out.append(Check(PRINCETON_FINE_NAME, uz, 0.0, uz, PRINCETON_TOL["uz"], "-",
                     "largest relative"))
    out += plate_checks(plates)
    return tuple(out)
