"""Physical-sense checks of a finished run (issue 22 item 1): the run did what was asked,
these say when its answer is not what the scene stands for (a ``warnings`` line each).

Each check is a function of plain numbers returning a list of one-line warnings (empty:
the check passes), so that the scenes' ``warn`` functions only gather the numbers.  The
thresholds are named here and listed in the table "Physical-sense checks" of docs/guide/scenes.md.

Belt drives (``belt2d``, ``belt3d``, ``belt-drive``, 2D and plate belts alike) run one set,
:func:`drive`, on the numbers of a :class:`Drive` (its pulleys, spans and tensioner arms);
from the input: :func:`pretension`, :func:`capstan` per loaded pulley and the driver,
:func:`arm_preload` and :func:`steady_window`; from the means over the steady window of a
finished run: :func:`reversed_driven` per free pulley, :func:`gross_slip` per free pulley,
:func:`compression` and :func:`undefined_spans`, :func:`off_pulley` per pulley (at t_end),
:func:`arm_travel` and :func:`drift`.  The checks of two numbers each:

* :func:`reversed_driven`: a free pulley's rim runs against its belt (below
  -:data:`REVERSE_REL` x the driver's);
* :func:`gross_slip`: a free pulley's rim lags (or leads) the driver's by more than the
  belt's creep ``(T_t - T_s) / (k + T_t)`` (steady mass flow through the spans, ``k`` =
  E A; T_t, T_s the largest and smallest span tensions) plus :data:`SLIP_EXCESS`;
* :func:`off_pulley`: no belt point inside a pulley at t_end (the belt is off it);
* :func:`arm_travel`: a tensioner arm turned more than :data:`ARM_TRAVEL` from its start;
  :func:`arm_preload`: its spring turns it away from the belt;
* :func:`compression`: a span mean tension below zero (a belt cannot push);
* :func:`pretension`: a pre-tension ``T_0`` not above the centrifugal tension
  ``rho A v^2`` of the driver's rim speed (the belt lifts off; ``T_0 <= 0``: a belt as
  long as the path, which the penetration check cannot judge);
* :func:`capstan`: the load torque above the capstan bound ``2 T_0 r tanh(mu theta / 2)``
  (``T_t / T_s = exp(mu theta)`` with ``T_t + T_s = 2 T_0``, theta the smaller wrap);
* :func:`steady_window`: a steady window that starts before the prescribed ramps end;
* :func:`undefined_spans`: a span mean tension that is undefined (no belt point in its
  middle third at some sample: null in the JSON);
* :func:`drift`: the driven speed's trend over the window (least-squares slope times
  the window) above :data:`DRIFT_REL` of its mean.

Plates: :func:`thin_plate` (deflection against the thickness) and
:func:`near_singular` (the bending stiffness lost in round-off: exit 3).  Beams in 3D:
:func:`stretch` (an element's chord stretched or shortened by more than the 2D area
check's factor).  Statics: :func:`circle` (the free belt's shape against its circle).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ancf.core.validity import AREA_FACTOR

#: slip beyond the creep the span tensions explain: 0.05 (the belt2d default slips 0.0008,
#: Model 2 of belt3d 0.10 against a creep of 0.15; nu_s = 1e3 in the extremes study: 0.29)
SLIP_EXCESS = 0.05
#: the driven pulley counts as reversed below -REVERSE_REL x the driver's rim speed
REVERSE_REL = 0.01
#: trend of the driven speed over the steady window / its mean: 0.05 (ten times the
#: belt2d default's 0.005, the spans' vibration; Model 2 of belt3d: below 2e-4)
DRIFT_REL = 0.05
#: below this speed (rad/s) a pulley is at rest for the drift and reversal checks
SPEED_FLOOR = 1e-9
#: a tensioner arm's largest turn from its start, rad: 30 degrees (the serpentine
#: example's arm turns 0.3 degrees; a spring pulling away from the belt: 143 degrees)
ARM_TRAVEL = math.radians(30.0)
#: thin-plate (Kirchhoff, linear) range: centre deflection below this times h (membrane
#: action adds about (w/h)^2 / 2 to the stiffness: 0.3 h changes w by about 5 %)
THIN_PLATE_W_OVER_H = 0.3
#: the first-order share of shear deformation and rotary inertia that Euler-Bernoulli and
#: Kirchhoff neglect (their frequencies or deflection off Timoshenko's or Mindlin's by it):
#: 5 %, the accuracy the suite reads a thin or slender reference to (Navier at h / a = 0.1:
#: Mindlin 5.2 % softer, Reddy)
SHEAR_SHARE = 0.05
#: the shear correction factor of a plate section in Mindlin's correction (Reissner's 5/6;
#: Mindlin's pi^2 / 12 differs by 1 %)
PLATE_KAPPA = 5.0 / 6.0
#: plate36 stiffness: relative round-off of the bending terms, eps x 12 (l / h)^2 (the
#: membrane's E h against the bending's E h^3 / 12 over an element side l), above which the
#: linear solve holds no answer (h/l = 8e-7: 0.4 % off Navier's h^-3 scaling; 8e-8: 190 %)
BENDING_ROUNDOFF = 0.01
#: free belt: a shape off its circle by more than this share of the radius
CIRCLE_REL = 0.05


def membrane_force(k: float, stretch: float) -> float:
    """Axial force k lambda (lambda^2 - 1) / 2 (N) of a uniaxially stretched belt of
    axial stiffness k = E A (N) at stretch lambda (Green strain, S = E E)."""
    return 0.5 * k * stretch * (stretch * stretch - 1.0)


def capstan_torque(T0: float, mu: float, wrap: float, r: float) -> float:
    """Largest torque (N m) on a pulley of radius r (m) at pre-tension T0 (N): 2 T0 r
    tanh(mu wrap / 2), from T_t / T_s = exp(mu wrap) and T_t + T_s = 2 T0."""
    return 2.0 * max(T0, 0.0) * r * math.tanh(0.5 * mu * wrap)


def reversed_driven(rim_driver: float, rim_driven: float,
                    name: str = "the driven pulley") -> list[str]:
    """Mean rim speeds (m/s, along the belt's running direction: the driver's positive)
    of the driver and of a free pulley called ``name``."""
    if rim_driven >= -REVERSE_REL * abs(rim_driver) - SPEED_FLOOR:
        return []
    return [f"{name} turns against its belt (rim speed {rim_driven:.4g} m/s against the "
            f"driver's {rim_driver:.4g} m/s over the steady window): the belt does not drive "
            "it"]


def gross_slip(slip: float, T_t: float, T_s: float, k: float) -> list[str]:
    """``slip`` = 1 - a pulley's rim speed / the driver's (window means, signed), span
    tensions T_t, T_s (N: the largest and smallest) and the belt's axial stiffness k = E A
    (N): its rim lags (or runs ahead of) the driver's by more than the creep explains."""
    creep = (T_t - T_s) / (k + T_t) if k + T_t > 0 else 0.0
    if not (math.isfinite(slip) and abs(slip) > max(creep, 0.0) + SLIP_EXCESS):
        return []
    return [f"gross slip: its rim {'lags' if slip > 0 else 'runs ahead of'} the driver's by "
            f"{abs(slip):.3g} against a creep (T_t - T_s)/(k + T_t) = {creep:.3g} of the span "
            f"tensions (bound: creep + {SLIP_EXCESS:g}): the belt slides over the whole wrap"]


def compression(tensions: dict) -> list[str]:
    """Span mean tensions {name: N}."""
    bad = {k: v for k, v in tensions.items() if v is not None and v < 0}
    return [f"the {k} span is in compression (mean tension {v:.3g} N): a belt cannot push; "
            "it has gone slack" for k, v in bad.items()]


def span_samples(tensions: dict) -> list[str]:
    """Span mean tensions {name: N} that are NaN: no belt point was found in a span's
    middle third (the cause of a 'non-finite result' exit 3)."""
    return [f"no belt point in the middle third of the {k} span at some sample: its mean "
            "tension is undefined (the belt is far off its wrapped path, or too few elements)"
            for k, v in tensions.items() if v is not None and math.isnan(v)]


def pretension(T0: float, centrifugal: float) -> list[str]:
    """Pre-tension T0 (N) against the centrifugal tension rho A v^2 (N)."""
    if T0 > centrifugal:
        return []
    if T0 <= 0:
        return [f"no pre-tension (T_0 = {T0:.3g} N: the belt is at least as long as its path): "
                "nothing presses it on the pulleys, the penetration check has nothing to judge"]
    return [f"pre-tension T_0 = {T0:.3g} N is not above the centrifugal tension rho A v^2 = "
            f"{centrifugal:.3g} N at the driver's final rim speed: the belt lifts off the pulleys"]


def capstan(Ta: float, bound: float, T0: float, mu: float, wrap: float) -> list[str]:
    """Load torque Ta (N m) against :func:`capstan_torque`'s ``bound``."""
    if Ta <= bound:
        return []
    return [f"load torque {Ta:g} N m is above what friction can transmit, 2 T_0 r tanh(mu "
            f"theta / 2) = {bound:.4g} N m (capstan bound at T_0 = {T0:.4g} N, mu = {mu:g}, "
            f"theta = {wrap:.4g} rad): the belt cannot carry it"]


def steady_window(t_end: float, window: float, ramps: dict) -> list[str]:
    """A window (s) before t_end (s) against the end times (s) of the ramps {name: t1}."""
    start = t_end - window
    late = {k: v for k, v in ramps.items() if start < v}
    if not late:
        return []
    name, t1 = max(late.items(), key=lambda kv: kv[1])
    return [f"the steady window [{max(start, 0.0):g}, {t_end:g}] s starts before the {name} "
            f"ends at {t1:g} s: the steady results are transient values"]


def drift(t, omega, window: float) -> list[str]:
    """Driven speeds ``omega`` (rad/s) at times ``t`` (s) of the steady window."""
    t, omega = np.asarray(t, dtype=float), np.asarray(omega, dtype=float)
    if t.size < 3 or not np.all(np.isfinite(omega)):
        return []
    trend = abs(float(np.polyfit(t - t[0], omega, 1)[0])) * window
    mean = abs(float(omega.mean()))
    if trend <= DRIFT_REL * mean or trend <= SPEED_FLOOR:
        return []
    return [f"not steady: the speed changes by {trend:.3g} rad/s over the {window:g} s "
            f"window (trend), {trend / max(mean, SPEED_FLOOR):.3g} of its mean {mean:.3g} "
            f"rad/s (bound {DRIFT_REL:g}): run longer"]


def undefined_spans(tensions: dict) -> list[str]:
    """Span mean tensions {name: N} that are None (null in the JSON) or NaN."""
    return span_samples({k: float("nan") if v is None else v for k, v in tensions.items()})


def off_pulley(name: str, penetration: float) -> list[str]:
    """The largest penetration (m) of the belt into a pulley at t_end: none (<= 0) means
    no contact over its whole wrap."""
    if penetration > 0:
        return []
    return [f"the belt is off pulley {name} at t_end (no contact over its wrap: largest "
            f"penetration {1e3 * penetration:.3g} mm): it neither carries nor guides the belt"]


def arm_travel(name: str, turn: float) -> list[str]:
    """A tensioner arm's largest turn (rad) from its start over the run."""
    if not abs(turn) > ARM_TRAVEL:
        return []
    return [f"tensioner {name}: its arm turned {math.degrees(abs(turn)):.3g} deg from its "
            f"start (bound {math.degrees(ARM_TRAVEL):g} deg): the arm is beyond its travel, "
            "the layout is not the file's"]


def arm_preload(name: str, preload: float, into: float) -> list[str]:
    """A tensioner's spring preload (N m, counter-clockwise positive) against ``into``
    (+1 if turning its arm counter-clockwise presses the pulley into the belt, -1 if
    clockwise does)."""
    if not preload * into < 0:
        return []
    return [f"tensioner {name}: its spring preload {preload:g} N m turns the arm away from "
            "the belt (change its sign): the spring slackens the belt instead of tensioning it"]


@dataclass(frozen=True)
class Pulley:
    """A pulley as the drive checks see it: ``name``; ``role`` its law (``prescribed``,
    ``driven``, ``idler``, ``tensioner``, ``fixed``); contact ``radius`` (m); ``side`` (+1
    the belt's inner side on it, -1 its back); ``wrap`` the belt's wrap on it (rad);
    ``load`` its final load torque T_a (N m, resisting its running direction; 0: none);
    ``omega`` its final law's angular velocity (a prescribed pulley's, rad/s); from a run:
    ``omega_mean`` over the steady window (rad/s), ``trace`` its angular velocity at the
    window's samples (rad/s), ``penetration`` the belt's largest into it at t_end (m)."""

    name: str
    role: str
    radius: float
    side: int = 1
    wrap: float = math.pi
    load: float = 0.0
    omega: float = 0.0
    omega_mean: float | None = None
    trace: tuple = ()
    penetration: float | None = None

    @property
    def free(self) -> bool:
        return self.role in FREE_ROLES

    def rim(self, omega: float) -> float:
        """Its rim speed (m/s) at angular velocity omega (rad/s) along the belt's
        counter-clockwise running direction: side omega radius."""
        return self.side * omega * self.radius


@dataclass(frozen=True)
class Arm:
    """A tensioner's arm: its pulley's ``name``, ``preload`` (N m, counter-clockwise),
    ``into`` (+1: turning the arm counter-clockwise presses the pulley into the belt, -1:
    clockwise does) and, from a run, ``turn`` its largest turn from its start (rad)."""

    name: str
    preload: float
    into: float
    turn: float | None = None


@dataclass(frozen=True, kw_only=True)
class Drive:
    """A belt drive's numbers for :func:`drive`: ``pulleys`` (:class:`Pulley`, the driver
    the first prescribed one), the belt's pre-tension ``T0`` (N, on the path at rest),
    axial stiffness ``k`` = E A (N), mass per length ``rhoA`` (kg/m), friction ``mu``,
    ``t_end``, ``window`` (s) and the laws' ``ramps`` {name: end time s}; ``arms``
    (:class:`Arm`); from a finished run (``finished``): ``spans`` {name: mean tension N or
    None} and the window's sample ``times`` (s)."""

    pulleys: tuple
    T0: float
    k: float
    rhoA: float
    mu: float
    t_end: float
    window: float
    ramps: dict = field(default_factory=dict)
    arms: tuple = ()
    finished: bool = False
    spans: dict = field(default_factory=dict)
    times: tuple = ()

    @property
    def driver(self) -> Pulley:
        return next(q for q in self.pulleys if q.role == "prescribed")


#: the roles whose pulleys turn freely (their speed is the belt's doing)
FREE_ROLES = ("driven", "idler", "tensioner")


def _direction(d: Drive) -> float:
    """The belt's running direction (+1 counter-clockwise): the driver's mean rim speed's
    sign, else its final law's, else +1."""
    dr = d.driver
    rim = dr.rim(dr.omega_mean) if dr.omega_mean else dr.rim(dr.omega)
    return -1.0 if rim < 0 else 1.0


def slips(d: Drive) -> list:
    """Per pulley, 1 - its mean rim speed / the driver's (:meth:`Pulley.rim`, signed: above
    1 it runs against the belt, below 0 ahead of the driver); NaN where the driver's is 0
    or a mean is missing."""
    dr = d.driver
    rim_d = dr.rim(dr.omega_mean) if dr.omega_mean is not None else 0.0
    return [1.0 - q.rim(q.omega_mean) / rim_d if rim_d and q.omega_mean is not None
            else float("nan") for q in d.pulleys]


def loads(d: Drive) -> list[str]:
    """The capstan bound (:func:`capstan`) of every loaded pulley on its own wrap, and of
    the driver for the sum of the loads brought to its radius (sum |T_a| r_d / r)."""
    out = []
    for q in d.pulleys:
        if q.load:
            out += [f"{q.name}: {w}" for w in capstan(
                abs(q.load), capstan_torque(d.T0, d.mu, q.wrap, q.radius), d.T0, d.mu, q.wrap)]
    dr = d.driver
    total = sum(abs(q.load) * dr.radius / q.radius for q in d.pulleys if q.load)
    if total and not out:
        out += [f"{dr.name} (driver, the loads at its radius): {w}" for w in capstan(
            total, capstan_torque(d.T0, d.mu, dr.wrap, dr.radius), d.T0, d.mu, dr.wrap)]
    return out


def _slip_lines(d: Drive) -> list[str]:
    """Turning against the belt, else gross slip (against the largest and smallest span
    tensions), per free pulley."""
    T = [v for v in d.spans.values() if v is not None and math.isfinite(v)] or [0.0]
    sign, dr = _direction(d), d.driver
    rim_d = sign * dr.rim(dr.omega_mean or 0.0)
    out = []
    for q, s in zip(d.pulleys, slips(d)):
        if not q.free or q.omega_mean is None:
            continue
        out += reversed_driven(rim_d, sign * q.rim(q.omega_mean), q.name) or [
            f"{q.name}: {w}" for w in gross_slip(s, max(T), min(T), d.k)]
    return out


def drive(d: Drive) -> list[str]:
    """Every belt drive's physical-sense checks (module docstring) on its numbers: the
    input's always, the run's when it finished and its window lies after the ramps."""
    dr = d.driver
    out = (pretension(d.T0, d.rhoA * dr.rim(dr.omega) ** 2) + loads(d)
           + [w for a in d.arms for w in arm_preload(a.name, a.preload, a.into)])
    ramp = steady_window(d.t_end, d.window, d.ramps)
    if ramp or not d.finished:
        return out + ramp
    out += undefined_spans(d.spans) + compression(d.spans) + _slip_lines(d)
    out += [w for q in d.pulleys if q.penetration is not None
            for w in off_pulley(q.name, q.penetration)]
    out += [w for a in d.arms if a.turn is not None for w in arm_travel(a.name, a.turn)]
    sel = np.asarray(d.times, dtype=float)
    for q in d.pulleys:
        if q.free and len(q.trace) == sel.size:
            out += [f"{q.name}: {w}" for w in drift(sel, q.trace, d.window)]
    return out


def thin_plate(w: float, h: float) -> list[str]:
    """Centre deflection w (m) of a linear thin plate of thickness h (m)."""
    if not (math.isfinite(w) and abs(w) > THIN_PLATE_W_OVER_H * h):
        return []
    return [f"centre deflection {abs(w):.3g} m = {abs(w) / h:.3g} h is beyond the linear "
            f"thin-plate range (|w| <= {THIN_PLATE_W_OVER_H:g} h): membrane stretching, "
            "ignored by the linear solve, would carry the load"]


def kirchhoff_shear_share(a: float, b: float, h: float, nu: float) -> float:
    """Mindlin's first-order correction of a simply supported plate's fundamental
    deflection term (sides a, b, thickness h in m): shear adds about (k h)^2 / (6 kappa
    (1 - nu)) of it, k^2 = pi^2 (1 / a^2 + 1 / b^2), kappa = PLATE_KAPPA (-)."""
    k2 = math.pi ** 2 * (1.0 / a ** 2 + 1.0 / b ** 2)
    return k2 * h ** 2 / (6.0 * PLATE_KAPPA * (1.0 - nu))


def thick_plate(share: float, h: float, side: float, bound: float) -> list[str]:
    """A plate (thickness h, side, m) whose Kirchhoff shear share (Mindlin's first-order
    correction, :func:`kirchhoff_shear_share`) exceeds
    ``bound``: Kirchhoff's element and Navier's series both neglect the shear."""
    if not share > bound:
        return []
    return [f"a thick plate (h/a = {h / side:.3g}): transverse shear would add about "
            f"{share:.3g} of the deflection (bound {bound:g}), which the Kirchhoff "
            "element and Navier's series both neglect: a model's answer, not the plate's"]


def bending_roundoff(h: float, side: float) -> float:
    """Relative round-off (-) of a plate element's bending stiffness: eps 12 (side / h)^2,
    the double-precision eps against the ratio (h / side)^2 / 12 of the bending terms
    E h^3 / 12 to the membrane terms E h they are summed with (h, side in m)."""
    return float(np.finfo(float).eps) * 12.0 * (side / h) ** 2


def near_singular(h: float, side: float) -> str | None:
    """The cause of a plate solve that holds no digits (None: it is well conditioned)."""
    err = bending_roundoff(h, side)
    if not err > BENDING_ROUNDOFF:
        return None
    return (f"No solution: the bending stiffness is lost in round-off (h = {h:g} m on elements "
            f"of side {side:g} m: relative error eps 12 (side/h)^2 = {err:.3g} > "
            f"{BENDING_ROUNDOFF:g}); a thicker plate or larger elements")


def stretch(chords, chords0, what: str = "element", body: str = "a beam") -> list[str]:
    """Chord lengths (m) deformed and in the reference (of ``what``: beam elements, plate
    element sides): a chord stretched or shortened by more than AREA_FACTOR (the 2D area
    check's factor)."""
    ratio = np.asarray(chords, dtype=float) / np.asarray(chords0, dtype=float)
    factor = np.maximum(ratio, 1.0 / np.maximum(ratio, 1e-300))
    k = int(np.argmax(factor))
    if not factor[k] > AREA_FACTOR:
        return []
    return [f"{what} {k + 1} of {ratio.size} changes its length by a factor {factor[k]:.3g}: "
            "strains far beyond the small-strain range of the St Venant-Kirchhoff material, "
            f"the result is a property of the model, not of {body}"]


def circle(radius_mean: float, max_dev: float, radius_ref: float) -> list[str]:
    """The free belt's mean radius and largest deviation from it against L/(2 pi), m."""
    off = max(abs(radius_mean - radius_ref), max_dev) / radius_ref
    if not off > CIRCLE_REL:
        return []
    return [f"the equilibrium found is no circle: {off:.3g} of the radius L/(2 pi) = "
            f"{radius_ref:.4g} m off (bound {CIRCLE_REL:g}); a zero-energy mode of the "
            "under-integrated elements (raise elastic_points)"]
