"""What several analytic references share: a beam's section parameters, the number of
frequencies, the Navier plate's parameters, the check of a derived quantity's range, and
the range of validity every reference declares (:class:`Validity`, its thresholds)."""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Callable

from ancf.common.params import InputError, Param
from ancf.scenes.base import SceneResult
# the plate and shear thresholds the run scenes share (plate-square's thick-plate check)
from ancf.scenes.sense import PLATE_KAPPA, SHEAR_SHARE, kirchhoff_shear_share  # noqa: F401

#: a rectangular beam section and its material
SECTION = (
    Param("E", 2.07e11, float, "Pa", "Young's modulus", lo=0, lo_open=True),
    Param("nu", 0.0, float, "-", "Poisson's ratio", lo=0, hi=0.5, hi_open=True),
    Param("L", 2.0, float, "m", "beam length", lo=0, lo_open=True),
    Param("h", 0.1, float, "m", "section height", lo=0, lo_open=True),
    Param("b", 0.1, float, "m", "section width", lo=0, lo_open=True),
    Param("ks", 5.0 / 6.0, float, "-", "shear correction factor", lo=0, lo_open=True, hi=2),
)


def with_defaults(params, **defaults):
    """``params`` with other defaults (by name)."""
    return tuple(replace(p, default=defaults.get(p.name, p.default)) for p in params)


def count_param(default):
    """The number of frequencies computed, ``default`` unless given."""
    return Param("count", default, int, "-", "number of frequencies (the lowest, ascending)",
                 lo=1, hi=100)


#: the simply supported rectangular plate under uniform pressure (Navier)
NAVIER = (
    Param("a", 1.0, float, "m", "plate side along x", lo=0, lo_open=True, hi=1e3),
    Param("b", 1.0, float, "m", "plate side along y", lo=0, lo_open=True, hi=1e3),
    Param("h", 0.01, float, "m", "thickness", lo=0, lo_open=True, hi=1e2),
    Param("E", 2.1e11, float, "Pa", "Young's modulus", lo=0, lo_open=True),
    Param("nu", 0.3, float, "-", "Poisson's ratio", lo=0, hi=0.5, hi_open=True),
    Param("p", 1e3, float, "Pa", "uniform pressure (deflection positive along it)", lo=-1e12, hi=1e12),
    Param("rtol", 1e-10, float, "-", "relative truncation tolerance of the series", lo=1e-14, hi=1e-2),
)


def magnitudes(check, *fields):
    """A scene check: ``check(*p[fields])`` with its ValueError (a derived quantity out of
    double precision, the field named) as InputError."""
    def run(p):
        try:
            check(*(p[f] for f in fields))
        except ValueError as exc:
            raise InputError(str(exc)) from None
    return run


# ------------------------------------------------------------------ range of validity
# (issue 33 item 3) Every reference declares ``VALIDITY``: the assumptions of its
# derivation, each a bound on a quantity its answer or its input measures; a converged
# answer outside one gets a ``warnings`` line naming the quantity (the answer is still the
# exact one of the reference's equations: the studies compare elements with it on the same
# equations, so it is flagged, not withheld).  The thresholds several references share:

#: strain of the linear (small-strain) theories: their strain u' differs from the Green
#: strain u' + u'^2 / 2 of the ANCF elements by half the strain, 0.5 % at 1 %
SMALL_STRAIN = 0.01
#: a beam's span (or a mode's half-wave) against its section height: below 2 the St-Venant
#: zones of about one height at each support, load or node fill it, where plane sections
#: (Euler-Bernoulli, Timoshenko, Reissner) do not hold
MIN_LENGTH_OVER_HEIGHT = 2.0
#: shear correction factors of a solid rectangle in the literature: 2/3 (Timoshenko 1921),
#: pi^2 / 12 (Mindlin), 5/6 (Reissner), Cowper's 10 (1 + nu) / (12 + 11 nu) up to 0.870,
#: 1 (no correction); a factor outside [0.5, 1] describes no rectangle b x h
KS_RANGE = (0.5, 1.0)
#: a moving string's or belt span's speed against its transverse wave speed: its frequencies
#: (and the belt's pressure on a pulley, n = T - rho A v^2 / lambda) fall as 1 - v^2 / c^2,
#: at 0.95 to a tenth, where what the reference neglects (bending stiffness, a guide's
#: compliance, the belt lifting off) decides them
SPEED_OVER_WAVE = 0.95
#: belt strain T / EA of Bechtel's law T = EA (lambda - 1): the thesis's compliant belt
#: (k = 0.2 kN) runs at 0.36; at 1 the belt has doubled its length, where no belt material
#: is linear and its section has thinned by a third or more
BELT_STRAIN = 1.0
#: a creep (slip) arc against its wrap: the stick arc at the entry sets the pulley's speed;
#: beyond 0.95 of the wrap about 10 % more torque (mu theta near 2) slips the whole wrap
#: (gross slip) and the steady state is on that edge
CREEP_SHARE = 0.95


@dataclass(frozen=True)
class Bound:
    """One assumption of a reference's derivation: ``measure(params, result)`` (a number
    of the converged answer or its input, in the unit ``quantity`` names) must stay within
    [lo, hi]; ``reason``: what the derivation assumes there, one clause."""

    quantity: str
    measure: Callable[[dict, SceneResult], float]
    reason: str
    lo: float = -math.inf
    hi: float = math.inf

    def warning(self, params: dict, result: SceneResult) -> str | None:
        """The one-line warning when the answer is outside (None: inside, or not a number)."""
        v = float(self.measure(params, result))
        if math.isnan(v) or self.lo <= v <= self.hi:
            return None
        side = f"> {self.hi:g}" if v > self.hi else f"< {self.lo:g}"
        return (f"outside the reference's range of validity: {self.quantity} = {v:.4g} {side} "
                f"({self.reason})")


@dataclass(frozen=True)
class Validity:
    """A reference's range of validity, its :class:`Bound`s; as a Scene's ``warn``: the
    warnings of a converged answer (a failed run has none to judge)."""

    bounds: tuple

    def __call__(self, params: dict, result: SceneResult) -> list[str]:
        if not result.converged:
            return []
        return [w for b in self.bounds if (w := b.warning(params, result)) is not None]


def speed_over_wave(v: float, T: float, k: float, rhoA: float) -> float:
    """|v| / c of a belt span at speed v (m/s) and tension T (N), of axial stiffness k (N) and
    mass rhoA (kg per unstretched m): c = sqrt(T lambda / rhoA), lambda = 1 + T / k, its
    transverse wave speed (0 without mass, inf without tension)."""
    if rhoA == 0:
        return 0.0
    return abs(v) * math.sqrt(rhoA / (T * (1.0 + T / k))) if T > 0 else math.inf


def shear_factor() -> Bound:
    """ks of a rectangular section (:data:`SECTION`) within :data:`KS_RANGE`."""
    return Bound("the shear correction factor ks", lambda p, r: p["ks"],
                 "the section is a solid rectangle b x h, whose published factors lie in "
                 "[2/3, 1]", *KS_RANGE)


def span_over_height() -> Bound:
    """L / h of a beam (:data:`SECTION`) at least :data:`MIN_LENGTH_OVER_HEIGHT`."""
    return Bound("the slenderness L / h", lambda p, r: p["L"] / p["h"],
                 "beam theory: plane sections, which St-Venant zones of about one height at "
                 "the supports and loads leave no room for", lo=MIN_LENGTH_OVER_HEIGHT)
