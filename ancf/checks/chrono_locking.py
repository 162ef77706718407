"""Why Chrono's elements miss two acceptance bounds at the acceptance mesh (issue 35): the
Princeton beam's u_z on the 3243 and 3333 at 16 elements, and the 3443 shell's
frequencies f4-f6 on the 16 x 16 square plate.  Rows for the chapter ``chrono_elements``
and ``tests/checks/test_chrono_locking.py``.

Princeton beam (:mod:`ancf.checks.chrono_princeton`): the same 16-element runs with the
Gauss rule along the axis cut from the exact 5 points (Chrono's ``NP`` = 3 gives the
same u_z to 1e-4 relative) to 2, Chrono's smallest (``ChElementBeamANCF_3243.h``: fewer
"will likely result in numerical issues").  A rule that integrates the axial and
thickness strain energy inexactly frees what an element's interpolation cannot
represent under large rotation: the axis's stretch (membrane locking; the 3333's
quadratic axis cannot bend without stretching) and the section's thickness strain (the
3243's section gradients are interpolated linearly along the axis: a chord of a rotating
unit vector is short).  Zero-energy modes: the eigenvalues of one element's K(e0) below
1e-9 of its largest (6 rigid motions; more are spurious mechanisms).

Square plate (:mod:`ancf.checks.chrono_elements`): the 3443 with its plane-stress law
and the transverse shear moduli G_13, G_23 of its law scaled by ``SHEAR_SCALE``.  The
Kirchhoff plate (Navier's frequencies) is the limit of a plate whose transverse shear
stiffness grows without bound: frequencies of a locking-free element approach it from
below as G_13, G_23 grow (up to its discretisation error).  An element whose frequencies
rise far above it carries shear strain that the plate does not have: its bilinear fibre
r_z cannot follow the cubic slopes r_x, r_y of its mid-surface (transverse shear
locking).  The 3423 (``ancf3423``: assumed natural transverse shear and thickness strains,
enhanced assumed strains) under the same test: G_13, G_23 times ``SHEAR_SCALE`` moves its
frequencies by less than ``PLATE_TOL`` (no shear locking), and what it misses at 16 x 16 is
its bilinear interpolation's discretisation error, of order 2 in the element size: on
:data:`ANS_FINE` x :data:`ANS_FINE` elements the six are within ``PLATE_TOL``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ancf.checks import chrono_elements as ce
from ancf.checks import chrono_princeton as cp
from ancf.elements.ancf3423 import Shell3423
from ancf.elements.material import isotropic_3d
from ancf.models import chrono_beam as cb
from ancf.models import chrono_shell as cs
from ancf.scenes import beam3d_published as pub

REDUCED_AXIS = 2          # Gauss points along the axis of the reduced rule (Chrono's least)
SHEAR_SCALE = 100.0       # factor on the 3443's G_13, G_23 in the shear-locking rows
PLATE_FINE = 24           # elements per side of the plate row that shows the mesh converge
ZERO = 1e-9               # eigenvalue below ZERO * largest: a zero-energy mode
LOCKED_ABOVE = 0.10       # relative rise above Navier's f that only locking explains
ANS_MESHES = (8, 16, 32)  # elements per side of the 3423's plate rows (G as the law's)
ANS_FINE = 32             # the 3423's mesh held to PLATE_TOL on all six frequencies


def zero_energy_modes(element: str, naxis: int | None = None) -> int:
    """The eigenvalues of one Princeton element's K(e0) (N/m) below :data:`ZERO` times its
    largest: 6 are the rigid motions, more are mechanisms of the rule ``naxis``."""
    b = cp.beam(element, 1, naxis)
    K = cb.assemble(b, b.reference())[1]
    w = np.abs(np.linalg.eigvalsh(0.5 * (K + K.T)))
    return int(np.sum(w < ZERO * w.max()))


def princeton_rule_rows(naxis: int | None = REDUCED_AXIS) -> list[dict]:
    """Every load and angle on both beams at 16 elements with ``naxis`` Gauss points
    along the axis (``chrono_elements.princeton_row``'s keys plus ``naxis``)."""
    return [{**ce.princeton_row(el, ld, b, naxis=naxis), "naxis": naxis}
            for el in cb.ELEMENTS for ld in pub.PRINCETON_LOADS for b in pub.PRINCETON_ANGLES]


def princeton_summary(rows: list[dict]) -> list[dict]:
    """Per element and axial rule of ``rows``: the largest |error| of u_y and u_z
    (relative), how many of the compared pass, and the element's zero-energy modes."""
    out = []
    keys = dict.fromkeys((r["element"], r.get("naxis")) for r in rows)
    for el, naxis in keys:
        mine = [r for r in rows if r["element"] == el and r.get("naxis") == naxis]
        row = {"element": el, "naxis": naxis,
               "zero-energy modes": zero_energy_modes(el, naxis)}
        for c in ("uy", "uz"):
            compared = [r for r in mine if r[f"{c} error"] is not None]
            row[f"{c} worst"] = max((r[f"{c} error"] for r in compared), key=abs)
            row[f"{c} passed"] = sum(bool(r[f"{c} within"]) for r in compared)
            row[f"{c} compared"] = len(compared)
        out.append(row)
    return out


@dataclass(frozen=True)
class ShearScaled(cs.Plate):
    """A :class:`~ancf.models.chrono_shell.Plate` of 3443s whose law has G_13, G_23 (the
    Voigt entries 23, 13, Pa) times ``shear`` (-): the diagnosis above, for ``cs.modes``."""

    shear: float = 1.0

    def material(self):
        (D,) = super().material()
        D = np.array(D, dtype=float)
        D[3, 3] *= self.shear
        D[4, 4] *= self.shear
        return (D,)


@dataclass(frozen=True)
class ShearScaled3423(cs.Plate):
    """A :class:`~ancf.models.chrono_shell.Plate` of 3423s whose isotropic law has G_13,
    G_23 (Voigt entries 23, 13, Pa) times ``shear`` (-), for ``cs.modes``."""

    shear: float = 1.0

    def shell3423(self, nel: int):
        D = isotropic_3d(self.E, self.nu)
        D[3, 3] *= self.shear
        D[4, 4] *= self.shear
        return Shell3423(np.full(nel, self.dims[0]), np.full(nel, self.dims[1]), self.H,
                         self.E, self.nu, D=D)


def plate_frequency_row(n: int = ce.PLATE_N, shear: float = 1.0,
                        element: str = "3443") -> dict:
    """The 3443 (plane-stress law) or the 3423 (its 3D law) on the n x n square plate,
    G_13, G_23 times ``shear``: its first six frequencies (Hz), Navier's, and each one's
    relative error."""
    p = ce.plate_parameters()
    args = dict(nx=n, ny=n, a=p["a"], b=p["a"], H=p["h"], E=p["E"], nu=p["nu"], rho=p["rho"],
                shear=shear)
    plate = (ShearScaled3423("3423", **args) if element == "3423"
             else ShearScaled("3443", poisson="plane_stress", **args))
    fixed = [plate.simply_supported(s) for s in cs.EDGES] + [plate.in_plane_rigid()]
    f, f_ref = cs.modes(plate, fixed, 6), ce.navier_f()
    return {"element": element, "n": n, "shear": shear, "f": tuple(f), "f ref": tuple(f_ref),
            "errors": tuple(f / f_ref - 1)}


def plate_rows() -> list[dict]:
    """The 16 x 16 plate with the material's shear moduli and :data:`SHEAR_SCALE` times
    them, and the material's at :data:`PLATE_FINE` x :data:`PLATE_FINE`."""
    return [plate_frequency_row(), plate_frequency_row(shear=SHEAR_SCALE),
            plate_frequency_row(PLATE_FINE)]


def ans_rows() -> list[dict]:
    """The 3423 on :data:`ANS_MESHES` with its law's shear moduli, and at 16 x 16 with
    :data:`SHEAR_SCALE` times them (about 2 s CPU in all)."""
    rows = [plate_frequency_row(n, element="3423") for n in ANS_MESHES]
    return rows + [plate_frequency_row(shear=SHEAR_SCALE, element="3423")]


def ans_order(rows: list[dict]) -> np.ndarray:
    """The observed order of the 3423's frequency errors from 8 to 16 elements per side,
    log2(e_8 / e_16) per frequency (-); finer meshes reach the shear-deformable plate's
    own offset from Kirchhoff's (-0.04 % on f1 at 32 x 32), which blurs the ratio."""
    e = {r["n"]: np.abs(r["errors"]) for r in rows if r["shear"] == 1.0}
    return np.log2(e[ce.PLATE_N // 2] / e[ce.PLATE_N])


#: the names of :func:`ans_checks`
ANS_NAMES = (f"Square plate {ce.PLATE_N} × {ce.PLATE_N}, 3423, G₁₃, G₂₃ × {SHEAR_SCALE:g}: "
             f"every f within {100 * ce.PLATE_TOL:g} % of its own at G × 1 (no shear locking)",
             f"Square plate {ANS_FINE} × {ANS_FINE}, 3423: first six frequencies within "
             f"{100 * ce.PLATE_TOL:g} % of the analytic plate")


def ans_checks(rows: list | None = None) -> tuple:
    """The 3423's checks (rows computed here unless given): G_13, G_23 x
    :data:`SHEAR_SCALE` moves every frequency at 16 x 16 by less than ``PLATE_TOL``
    (relative to its own at the law's G; the 3443's rise by over :data:`LOCKED_ABOVE`),
    and the :data:`ANS_FINE` mesh's six are within ``PLATE_TOL`` of Navier's."""
    from ancf.checks.belt2d import Check
    rows = ans_rows() if rows is None else rows
    base = next(r for r in rows if r["n"] == ce.PLATE_N and r["shear"] == 1.0)
    stiff = next(r for r in rows if r["shear"] == SHEAR_SCALE)
    fine = next(r for r in rows if r["n"] == ANS_FINE and r["shear"] == 1.0)
    move = float(np.max(np.abs(np.array(stiff["f"]) / base["f"] - 1)))
    worst = float(np.max(np.abs(fine["errors"])))
    return (Check(ANS_NAMES[0], move, 0.0, move, ce.PLATE_TOL, "-", "largest relative change"),
            Check(ANS_NAMES[1], worst, 0.0, worst, ce.PLATE_TOL, "-", "largest relative"))


#: the names of :func:`checks`
NAMES = (f"Princeton beam, {REDUCED_AXIS} Gauss points along the axis: every u_z within "
         f"{100 * ce.PRINCETON_TOL['uz']:g} % of ANSYS at {cp.N_ELEMENTS} elements (the "
         "misses are locking)",
         f"Square plate {ce.PLATE_N} × {ce.PLATE_N}, 3443 (plane stress), G₁₃, G₂₃ × "
         f"{SHEAR_SCALE:g}: every f above Navier by more than {100 * LOCKED_ABOVE:g} % "
         "(shear locking)")


def checks(reduced: list | None = None, plates: list | None = None) -> tuple:
    """The chapter's locking checks (rows computed here unless given): the 2-point axial
    rule brings every u_z of both beams within 0.5 % of ANSYS at 16 elements; the 3443's
    frequencies at G_13, G_23 x :data:`SHEAR_SCALE` lie above Navier's by more than
    :data:`LOCKED_ABOVE` (a locking-free element approaches them from below, up to its
    discretisation error: the 3833's is 0.8 % at 16 x 16)."""
    from ancf.checks.belt2d import Check
    reduced = princeton_rule_rows() if reduced is None else reduced
    plates = plate_rows() if plates is None else plates
    uz = max(abs(r["uz error"]) for r in reduced if r["uz error"] is not None)
    stiff = next(r for r in plates if r["shear"] == SHEAR_SCALE)
    rise = min(stiff["errors"])
    return (
        Check(NAMES[0], uz, 0.0, uz,
              ce.PRINCETON_TOL["uz"], "-", "largest relative"),
        Check(NAMES[1], rise, LOCKED_ABOVE, max(LOCKED_ABOVE - rise, 0.0), 0.0, "-",
              "smallest relative rise; difference = bound − rise where positive"))
