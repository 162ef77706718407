"""Steady state of a flat belt on a closed loop of N pulleys: Bechtel et al.'s extensible
string with the centrifugal term (:mod:`analytic.bechtel`, thesis 4.1) on any layout.

Input (plain data, so that a drive file's reader can call :func:`solve`): the belt's axial
stiffness ``EA`` (N), mass per unstretched length ``rhoA`` (kg/m), stress-free length
``L0`` (m), the Coulomb friction coefficient ``mu``, and the pulleys in belt order, each a
dict with ``name``, ``centre`` (x, y) m, ``radius`` m, ``side`` (+1: the belt's inner side
on it, -1: an idler on its back) and ``law`` with that law's fields (:data:`LAWS`):

* ``prescribed`` (exactly one, the driver): ``omega`` rad/s, its speed, positive
  counter-clockwise (its sign and side set the way the belt runs round the loop);
* ``driven``: ``torque`` N m, the load, positive opposing the motion; ``damping`` N m s
  (optional): a resisting torque ``damping * omega`` more;
* ``idler``: ``damping`` (optional), else it transmits no torque;
* ``tensioner`` (at most one): an idler on an arm turning about ``pivot`` (x, y) m; its
  ``centre`` is the arm's nominal position, where the torsion spring's moment turning the
  arm into the belt is ``preload`` N m; ``stiffness`` N m/rad; ``damping`` (optional).

Model (Bechtel's, as :mod:`analytic.bechtel` reads it; the pulley geometry from
:mod:`analytic.belt_layout`): stretch lambda = 1 + T / EA, mass flow G = rhoA v_o with
v = v_o lambda; n = T - G v = a lambda - EA, a = EA - rhoA v_o^2.  On each pulley the belt
sticks from its entry (n, T, v constant, v = omega R) and creeps over an arc phi at its
exit, where dn / dtheta = +-mu n, so phi = |ln(n_out / n_in)| / mu; phi must not exceed
the wrap.  The belt's moment on pulley i about its axis, along its rotation, is the
friction's R (n_out - n_in): the resisting torque (torque + damping omega) on a driven
pulley or an idler; the driver takes the rest.  The driver pulls its entry span in:
omega_d R_d = v_o lambda_entry.  The loop closes on the belt's mass: int ds / lambda over
the path = L0, written as int (1 - 1 / lambda) ds = P - L0 (well conditioned as EA grows;
L0 itself carries a round-off of 1e-16 P, a relative 1e-16 / strain on the tensions: 6e-9
at Bechtel's k = 1e9 N).
With n_t (N), the n of the driver's entry span, every span follows in closed form
(:func:`state`, walking against the belt from the driver); n_t is found by Brent's method
between the smallest n_t with positive n on every span and every creep arc within its wrap,
and a value where the belt is too short.  A tensioner's arm rotation psi (rad, into the
belt) is found by Brent's method on its moment balance, preload - stiffness psi = the
belt's moment on arm and pulley about the pivot, out of the belt (a slack belt's is 0).
For two equal pulleys, a wrap of pi each, this is :mod:`analytic.bechtel`
(tests/analytic/test_belt_steady.py).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ancf.common.params import InputError
from analytic.belt_layout import Layout, turn, wrap

#: absolute tolerance (N) and relative tolerance of Brent's method on n_t, as bechtel.py
XTOL_N, RTOL = 1e-12, 4e-15
#: tolerance of the arm rotation, rad; first step of the search for a bracket, rad
XTOL_PSI, PSI_STEP = 1e-14, 1e-3
#: |moment balance| / its terms at the arm's root: above it, the root is the jump where
#: friction starts to hold (no balance), not a balance
BALANCE_RTOL = 1e-6
#: law: (required fields, optional fields) besides name, centre, radius, side, law
LAWS = {"prescribed": (("omega",), ()), "driven": (("torque",), ("damping",)),
        "idler": ((), ("damping",)),
        "tensioner": (("pivot", "stiffness", "preload"), ("damping",))}


class Slack(InputError):
    """No steady state at this geometry: the belt is too long, or friction cannot carry
    the torques."""


@dataclass(frozen=True)
class State:
    """The belt at a given n_t: per span j (pulley j to j + 1) n, T (N), v (m/s); per
    pulley the creep arc (rad, any length: the caller checks it against the wrap);
    a = EA - rhoA v_o^2 (N)."""

    n: np.ndarray
    T: np.ndarray
    v: np.ndarray
    creep: np.ndarray
    a: float


def _driver(pulleys) -> int:
    return next(i for i, p in enumerate(pulleys) if p["law"] == "prescribed")


def state(n_t: float, pulleys, lay: Layout, EA: float, rhoA: float, mu: float) -> State:
    """Every span from n_t (N), the n of the driver's entry span.  Upstream of it, pulley
    i's entry n follows from its exit n and its resisting torque Q = torque + damping omega,
    omega = v_o (EA + n_in) / (a R): n_in = (n_out - torque / R - b EA) / (1 + b),
    b = damping v_o / (a R^2)."""
    N, dr = len(pulleys), _driver(pulleys)
    V = abs(pulleys[dr]["omega"]) * lay.radii[dr]
    v_o = 2.0 * V * EA / (EA + n_t + math.sqrt((EA + n_t) ** 2 + 4.0 * rhoA * V * V * EA))
    a = EA - rhoA * v_o * v_o
    n = np.zeros(N)
    n[dr - 1] = n_t
    for step in range(1, N):
        i = (dr - step) % N
        p, R = pulleys[i], lay.radii[i]
        b = p.get("damping", 0.0) * v_o / (a * R * R)
        n[i - 1] = (n[i] - p.get("torque", 0.0) / R - b * EA) / (1.0 + b)
    n_in = np.roll(n, 1)
    with np.errstate(divide="ignore", invalid="ignore"):
        creep = np.abs(np.log(n / n_in)) / mu
    return State(n, EA * (n + EA - a) / a, v_o * (EA + n) / a, creep, a)


def stretch(st: State, lay: Layout, EA: float, mu: float) -> float:
    """int (1 - 1 / lambda) ds over the path, m: (n + m) / (EA + n) on spans and stick
    arcs (m = rhoA v_o^2), in closed form over a creep arc, n = n_in e^(+-mu theta)."""
    n_in, m = np.roll(st.n, 1), EA - st.a
    R, phi = lay.radii, st.creep
    delta = st.n - n_in
    creep = R * phi * m / EA + np.sign(delta) * R * st.a / (EA * mu) * np.log1p(
        delta / (EA + n_in))
    stick = R * (lay.wrap - phi) * (n_in + m) / (EA + n_in)
    return float(lay.span @ ((st.n + m) / (EA + st.n)) + np.sum(stick + creep))


def _grow(f, x0: float) -> float:
    """An x >= x0 > 0 with f(x) > 0 for an increasing f (doubling)."""
    x = x0
    for _ in range(2000):
        if f(x) > 0:
            return x
        x *= 2.0
    raise Slack("no steady state found: the belt never becomes tight")


def _above(x: float) -> float:
    """A point past a root that Brent's method returned as x."""
    return x + 2.0 * (XTOL_N + RTOL * abs(x))


def _lowest(pulleys, lay, EA, rhoA, mu) -> tuple[float, int | None]:
    """(smallest n_t (N) with n > 0 on every span and every creep arc within its wrap, i.e.
    |n_out - n_in| <= min(n_in, n_out) (e^(mu theta) - 1); the pulley where that binds,
    None where only the positivity does)."""
    at = lambda x: state(x, pulleys, lay, EA, rhoA, mu).n  # noqa: E731
    low = lambda x: float(at(x).min())  # noqa: E731
    x = _above(0.0 if low(0.0) >= 0 else brentq(low, 0.0, _grow(low, -low(0.0)), xtol=XTOL_N,
                                                rtol=RTOL))

    def excess(y):  # N, per pulley
        n = at(y)
        n_in = np.roll(n, 1)
        return np.abs(n - n_in) - np.minimum(n, n_in) * np.expm1(mu * lay.wrap)

    over = lambda y: float(excess(y).max())  # noqa: E731
    if over(x) <= 0:
        return x, None
    x = brentq(over, x, _grow(lambda y: -over(y), 2.0 * x), xtol=XTOL_N, rtol=RTOL)
    return _above(x), int(np.argmax(excess(x)))


def at_geometry(pulleys, lay: Layout, EA, rhoA, L0, mu) -> State:
    """The steady belt on a fixed layout; Slack when there is none."""
    def f(x):  # m
        return stretch(state(x, pulleys, lay, EA, rhoA, mu), lay, EA, mu) - (lay.length - L0)

    lo, binding = _lowest(pulleys, lay, EA, rhoA, mu)
    if f(lo) > 0:
        if binding is None:
            raise Slack(f"L0 = {L0!r} m is out of range: the belt is too long for its path "
                        f"({lay.length:.9g} m), no positive tension; allowed: L0 < "
                        f"{L0 - f(lo):.9g} m")
        p = pulleys[binding]
        raise Slack(f"pulley {p['name']!r}: the torques need a creep arc longer than its wrap "
                    f"({lay.wrap[binding]:.6g} rad): friction (mu = {mu!r}) cannot transmit "
                    "them at this belt length; allowed: lower torques or a shorter belt (L0)")
    x = brentq(f, lo, _grow(f, max(2.0 * lo, 1.0)), xtol=XTOL_N, rtol=RTOL)
    return state(x, pulleys, lay, EA, rhoA, mu)


# ------------------------------------------------------------------------ the tensioner
@dataclass(frozen=True)
class Arm:
    """A tensioner's arm: pulley index, pivot (m), length (m), nominal angle beta0 (rad,
    counter-clockwise from x), ``into`` = +1 / -1: the turn of beta that lengthens the path."""

    index: int
    pivot: np.ndarray
    length: float
    beta0: float
    into: int

    def centre(self, psi: float) -> np.ndarray:
        """Pulley centre at the rotation psi into the belt (rad), m."""
        b = self.beta0 + self.into * psi
        return self.pivot + self.length * np.array([math.cos(b), math.sin(b)])


def _layout(pulleys, arm: Arm | None = None, psi: float = 0.0) -> Layout:
    driver = pulleys[_driver(pulleys)]
    centres = [arm.centre(psi) if arm and i == arm.index else p["centre"]
               for i, p in enumerate(pulleys)]
    return wrap(centres, [p["radius"] for p in pulleys], [p["side"] for p in pulleys],
                [p["name"] for p in pulleys], int(math.copysign(driver["side"], driver["omega"])))


def _arm(pulleys, t: int) -> Arm:
    """The arm at its nominal position; ``into`` from dP / dbeta = (d_in - d_out) . Ĩ(c - p)
    (moving a pulley by dc lengthens the path by (d_in - d_out) . dc)."""
    p = pulleys[t]
    pivot, c = np.asarray(p["pivot"], float), np.asarray(p["centre"], float)
    lay = _layout(pulleys)
    dP = float((lay.d[t - 1] - lay.d[t]) @ turn(c - pivot))
    if dP == 0:
        raise InputError(f"pulleys.{t}.pivot = {list(p['pivot'])!r}: turning the arm of "
                         f"tensioner {p['name']!r} about it does not change the belt's path; "
                         "allowed: a pivot off the line of the belt's force on the pulley")
    return Arm(t, pivot, float(np.hypot(*(c - pivot))), math.atan2(*(c - pivot)[::-1]),
               1 if dP > 0 else -1)


def _belt_moment(arm: Arm, psi: float, lay: Layout, st: State) -> float:
    """The belt's moment on arm and pulley about the pivot, turning it into the belt, N m:
    the force n_out d_out - n_in d_in at the centre and the friction's moment."""
    t = arm.index
    F = st.n[t] * lay.d[t] - st.n[t - 1] * lay.d[t - 1]
    r = arm.centre(psi) - arm.pivot
    friction = lay.sense[t] * lay.radii[t] * (st.n[t] - st.n[t - 1])
    return arm.into * (float(r[0] * F[1] - r[1] * F[0]) + friction)


def _tensioned(pulleys, arm: Arm, EA, rhoA, L0, mu):
    """(psi rad, layout, state) where the spring balances the belt on the arm."""
    p = pulleys[arm.index]
    name = p["name"]

    def balance(psi):  # N m, the layout, and the state or why there is none
        lay = _layout(pulleys, arm, psi)
        try:
            st = at_geometry(pulleys, lay, EA, rhoA, L0, mu)
        except Slack as exc:
            return p["preload"] - p["stiffness"] * psi, lay, exc
        return p["preload"] - p["stiffness"] * psi + _belt_moment(arm, psi, lay, st), lay, st

    g0 = balance(0.0)[0]
    way, prev, psi = (1.0 if g0 > 0 else -1.0), 0.0, PSI_STEP
    while g0 != 0:
        try:
            g = balance(way * psi)[0]
        except InputError as exc:
            raise InputError(f"tensioner {name!r}: no equilibrium of its arm before, at a "
                             f"rotation of {way * psi:.6g} rad, {exc}") from None
        if g * g0 <= 0:
            break
        prev, psi = way * psi, 2.0 * psi
        if psi > math.pi:
            raise InputError(f"tensioner {name!r}: no equilibrium of its arm within half a "
                             "turn; allowed: a spring (preload, stiffness) that can hold it")
    root = 0.0 if g0 == 0 else brentq(lambda x: balance(x)[0], prev, way * psi, xtol=XTOL_PSI,
                                      rtol=RTOL)
    g, lay, st = balance(root)
    if isinstance(st, Slack) or abs(g) > BALANCE_RTOL * (
            abs(p["preload"]) + p["stiffness"] * abs(root) + abs(_belt_moment(arm, root, lay, st))):
        back = balance(root - way * 8.0 * (XTOL_PSI + RTOL * abs(root)))[2]  # the slack side
        why = st if isinstance(st, Slack) else back if isinstance(back, Slack) else (
            "friction cannot transmit the torques")
        raise InputError(f"tensioner {name!r}: its spring (preload {p['preload']!r} N m, "
                         f"stiffness {p['stiffness']!r} N m/rad) cannot tension the belt where "
                         f"it balances the arm: {why}")
    return root, lay, st


# ------------------------------------------------------------------------ input, output
def _number(key: str, value, lo=None, lo_open=False) -> float:
    """A finite float, else InputError naming ``key`` and the range."""
    ok = isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool)
    v = float(value) if ok else math.nan
    if not math.isfinite(v) or (lo is not None and (v <= lo if lo_open else v < lo)):
        where = "-inf" if lo is None else f"{lo:g}"
        raise InputError(f"{key} = {value!r} is out of range; allowed: a number in "
                         f"{'(' if lo_open or lo is None else '['}{where}, inf)")
    return v


def _point(key: str, value) -> np.ndarray:
    if not (isinstance(value, (list, tuple, np.ndarray)) and len(value) == 2):
        raise InputError(f"{key} = {value!r} is not valid; allowed: a point [x, y] in m")
    return np.array([_number(f"{key}.{k}", v) for k, v in enumerate(value)])


_POSITIVE = {"radius"}
_NONNEGATIVE = {"damping", "stiffness"}


def _pulley(i: int, p) -> dict:
    """One pulley's fields checked (InputError naming ``pulleys.i.field``), defaults filled."""
    key = f"pulleys.{i}"
    if not isinstance(p, dict):
        raise InputError(f"{key}: a pulley is a table of fields; got {p!r}")
    law = p.get("law")
    if law not in LAWS:
        raise InputError(f"{key}.law = {law!r} is not valid; allowed: one of {', '.join(LAWS)}")
    required, optional = LAWS[law]
    required = ("name", "centre", "radius", "side", "law") + required
    for k in required:
        if k not in p:
            raise InputError(f"{key}.{k}: missing (law {law!r} needs {', '.join(required)})")
    for k in p:
        if k not in required + optional:
            raise InputError(f"{key}.{k}: unknown field of law {law!r}; allowed: "
                             f"{', '.join(required + optional)}")
    if not isinstance(p["name"], str) or not p["name"]:
        raise InputError(f"{key}.name = {p['name']!r} is not valid; allowed: a non-empty name")
    if p["side"] not in (1, -1) or isinstance(p["side"], bool):
        raise InputError(f"{key}.side = {p['side']!r} is not valid; allowed: 1 (the belt's "
                         "inner side on it) or -1 (an idler on the belt's back)")
    out = {"name": p["name"], "law": law, "side": int(p["side"]), "damping": 0.0}
    for k in ("centre", "pivot"):
        if k in p:
            out[k] = _point(f"{key}.{k}", p[k])
    for k in ("radius", "omega", "torque", "damping", "stiffness", "preload"):
        if k in p:
            out[k] = _number(f"{key}.{k}", p[k], 0 if k in _POSITIVE | _NONNEGATIVE else None,
                             lo_open=k in _POSITIVE)
    if out.get("omega") == 0:
        raise InputError(f"{key}.omega = {p['omega']!r} is out of range; allowed: a number "
                         "other than 0 (positive counter-clockwise)")
    return out


def _checked(pulleys) -> list[dict]:
    if not isinstance(pulleys, (list, tuple)) or len(pulleys) < 2:
        raise InputError(f"pulleys = {pulleys!r} is not valid; allowed: a list of at least 2 "
                         "pulleys in belt order")
    out = [_pulley(i, p) for i, p in enumerate(pulleys)]
    names = [p["name"] for p in out]
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise InputError(f"pulleys: the name {twice[0]!r} is used twice; allowed: unique names")
    for law, lo, hi in (("prescribed", 1, 1), ("tensioner", 0, 1)):
        count = sum(p["law"] == law for p in out)
        if not lo <= count <= hi:
            raise InputError(f"pulleys: {count} pulley(s) of law {law!r}; allowed: "
                             f"{'exactly one' if lo == hi else 'at most one'}")
    return out


def solve(pulleys, *, EA: float, rhoA: float, L0: float, mu: float) -> dict:
    """The steady belt on ``pulleys`` (see the module docstring for the fields); InputError
    (a ValueError) naming the field, the pulley and the limit when there is none.  Returns
    :func:`summary`'s dict."""
    EA, rhoA = _number("belt.EA", EA, 0, True), _number("belt.rhoA", rhoA, 0)
    L0, mu = _number("belt.L0", L0, 0, True), _number("friction.mu", mu, 0, True)
    pulleys = _checked(pulleys)
    t = next((i for i, p in enumerate(pulleys) if p["law"] == "tensioner"), None)
    if t is None:
        lay = _layout(pulleys)
        return summary(pulleys, lay, at_geometry(pulleys, lay, EA, rhoA, L0, mu), L0)
    arm = _arm(pulleys, t)
    psi, lay, st = _tensioned(pulleys, arm, EA, rhoA, L0, mu)
    return summary(pulleys, lay, st, L0, arm.beta0 + arm.into * psi)


def summary(pulleys, lay: Layout, st: State, L0: float, arm_angle: float | None = None) -> dict:
    """The JSON result keys: path and belt lengths (m), per span (from, to, length m,
    tension N, speed m/s), per pulley (wrap, stick and creep arcs rad, omega rad/s positive
    counter-clockwise, torque N m: the belt's moment along its rotation, slip: 1 - its rim
    speed / the driver's, arm angle rad of a tensioner, else null)."""
    N, dr = len(pulleys), _driver(pulleys)
    names = [p["name"] for p in pulleys]
    spans = [{"from": names[j], "to": names[(j + 1) % N], "length_m": float(lay.span[j]),
              "tension_N": float(st.T[j]), "speed": float(st.v[j])} for j in range(N)]
    out = []
    for i, p in enumerate(pulleys):
        R = lay.radii[i]
        out.append({"name": p["name"], "law": p["law"], "wrap_rad": float(lay.wrap[i]),
                    "stick_arc_rad": float(lay.wrap[i] - st.creep[i]),
                    "creep_arc_rad": float(st.creep[i]),
                    "omega": float(lay.sense[i] * st.v[i - 1] / R),
                    "torque_Nm": float(R * (st.n[i] - st.n[i - 1])),
                    "slip": float(1.0 - st.v[i - 1] / st.v[dr - 1]),
                    "arm_angle_rad": arm_angle if p["law"] == "tensioner" else None})
    return {"path_length_m": lay.length, "L0_m": L0, "spans": spans, "pulleys": out}


def path_length(pulleys) -> float:
    """Length of the wrapped path at the given centres (a tensioner's nominal one), m."""
    return _layout(_checked(pulleys)).length
