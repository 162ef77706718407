"""``ancf analytic plate-modes``: the simply supported Kirchhoff plate's natural
frequencies (Navier)."""
from __future__ import annotations

import math

from analytic import plate_modes
from ancf.common.params import Param
from ancf.scenes.analytic.shared import (NAVIER, PLATE_KAPPA, SHEAR_SHARE, Bound, Validity,
                                         count_param, magnitudes)
from ancf.scenes.base import INT, NUM, Scene, SceneResult, field

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 70


def _kirchhoff_share(p, r) -> float:
    """Mindlin's first-order correction of the highest mode computed, (k h)^2 (1 + 2 /
    (kappa (1 - nu))) / 24 with k^2 = pi^2 (m^2 / a^2 + n^2 / b^2) (1/m^2): rotary inertia
    and shear lower the frequency by about this share."""
    kh2 = max(math.pi ** 2 * ((m / p["a"]) ** 2 + (n / p["b"]) ** 2)
              for m, n in zip(r.results["m"], r.results["n"])) * p["h"] ** 2
    return kh2 * (1.0 + 2.0 / (PLATE_KAPPA * (1.0 - p["nu"]))) / 24.0


#: the range of validity (issue 33): a thin plate against the modes' half-waves
VALIDITY = Validity((
    Bound("the Kirchhoff shear and rotary-inertia share (k h)^2 (1 + 2 / (kappa (1 - nu))) / 24",
          _kirchhoff_share, "Kirchhoff's thin plate neglects them: h small against the "
          "half-waves a / m, b / n", hi=SHEAR_SHARE),))


def _plate_modes(p):
    f, mn = plate_modes.navier_frequencies(p["a"], p["b"], p["h"], p["E"], p["nu"], p["rho"],
                                           count=p["count"])
    return SceneResult(True, "Navier: omega_mn = pi^2 (m^2/a^2 + n^2/b^2) sqrt(D / (rho h))",
                       {"frequencies_hz": f.tolist(), "m": [m for m, _ in mn],
                        "n": [n for _, n in mn]})


RESULTS = {
    "frequencies_hz": field("array", "natural frequencies, ascending, Hz", items=NUM),
    "m": field("array", "half-waves along a of each frequency", items=INT),
    "n": field("array", "half-waves along b of each frequency", items=INT)}


REFERENCE = Scene(
    "plate-modes", "Natural frequencies of the simply supported Kirchhoff plate (Navier), "
    "with their half-wave numbers m (along a) and n (along b).",
    tuple(p for p in NAVIER if p.name not in ("p", "rtol"))
    + (Param("rho", 7850.0, float, "kg/m^3", "density", lo=0, lo_open=True), count_param(4)),
    _plate_modes,
    magnitudes(plate_modes.check_magnitudes, "a", "b", "h", "E", "nu", "rho"), results=RESULTS,
    warn=VALIDITY)
