"""Free-span vibration of the Lagrangian belt march against the axially moving beam
(issue 34, "modes"): the thesis two-pulley drive at 120 rad/s (``examples/
thesis_table_3_1.toml`` with belt2d's 120 rad/s case, :data:`ancf.checks.belt2d.CASE_120`)
run by the ``belt-drive`` scene, and :func:`analytic.moving_beam.span_frequencies`.

Excitation.  The start-up excites the first span mode; the second hardly (it has a node
at mid-span and the drive is nearly symmetric).  The driven pulley's centre is therefore
moved :data:`SHIFT` (m) normal to the spans, reached at the end of the ramps (``centre_shift``
by ``ramp``, Eq. 4.46, reached at ``pulleys.T1`` = 0.6 s): the velocity step of one span end
at 0.6 s excites every span mode.

Measure.  Over the window [T1, t_end] every output state's belt (``post2d.sample``) is cut
by the line normal to the span (tangent point to tangent point) at the fraction a of its
length; the transverse offset y_a(t) (m) of the crossing, mean removed, a Hann window,
zero padded :data:`PAD` times, gives the spectrum; a peak is the largest bin of its band
refined by a parabola through the log amplitudes of its bin and neighbours.  Mode 1 is read
at a = 1/2, mode 2 (node at 1/2) at a = 1/4, in the band ``BAND`` x (n f_1 of the string).

Reference.  With the Green strain the march's axial force N (``post2d``, Eq. 3.17) is a
second Piola-Kirchhoff force: a transverse wave sees the true tension T = N lambda on the
mass per current length rho A / lambda, lambda = sqrt(1 + 2 N / EA) the stretch, so

    c^2 = T / (rho A / lambda) = N lambda^2 / (rho A)                                 (1)

(N, v: means over the span's middle third and the window's samples); L the span's
tangent-to-tangent length; EI = E alpha2 b h^3 / 12 (Dufva's bending, ``alpha2``).

Integrator.  The generalised-alpha march (rho_inf, step h) turns a free oscillation at f
into one at f_h = arg(mu) / (2 pi h), mu the amplification matrix's oscillatory
eigenvalue (:func:`alpha_frequency`, Arnold & Bruels 2007, ``ancf.solvers.generalized_alpha``):
f_h / f - 1 = -0.95 % at the thesis's 2.5e-4 s and f = 177 Hz, -3.6 % at 342 Hz.  The run
keeps the thesis's step (:data:`DT`) and the reference carries f -> f_h; measured at
2.5e-4 s / 1.25e-4 s, the peaks moved 175.96 -> 177.47 Hz (tight span, mode 1) as f_h does.

Measured (2.5e-4 s, window 0.6-1 s, bin 2.5 Hz): peaks within 0.22 % of the pinned beam's
f_h, 0.27-0.54 % below the clamped one's; the bending layer sqrt(EI / T) = 0.7-0.8 mm is 2 %
of an element (41.5 mm): the mesh resolves neither end condition, and bending moves f_1 by
0.003 % (pinned) only, so the string and the pinned beam agree to 3e-5.

THREAD (:func:`thread_run`, :func:`march_peaks`).  The same measure on THREAD's drive with
the creep-rate law, the driven centre moved 5 mm normal to the spans by 1.6 s, the window
1.6-3.6 s (THREAD's step 5e-5 s: the period error is below 1e-4 at 94 Hz); each mode's peak
sought within 5 % of the running mode it is compared with
(:func:`ancf.checks.running_drives.spectrum_rows`).  Seen: the four peaks within 0.1 % of
the running modes.
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from analytic import moving_beam, moving_string
from ancf.belts.post2d import sample
from ancf.belts.pulleys import T1
from ancf.checks.belt2d import CASE_120
from ancf.common.paths import REPO
from ancf.scenes import SCENES
from ancf.solvers.generalized_alpha import AlphaOptions

FILE = REPO / "examples" / "thesis_table_3_1.toml"
#: belt2d's parameters -> the drive file's keys
KEYS = {"E": "belt.E", "belt_length": "belt.length", "alpha2": "belt.alpha2",
        "Ta_max": "pulleys.driven.load_torque", "omega_final": "pulleys.driver.omega_final",
        "n_elements": "belt.n_elements", "output_dt": "run.output_dt"}
SHIFT = 3e-3        # m: the driven centre's shift normal to the spans (the perturbation)
DT = 2.5e-4         # s: the thesis's step (integrator period error, module doc)
PAD = 16            # the FFT's length over the window's samples
STATIONS = (0.5, 0.25)  # span fraction a where mode 1 and mode 2 are read
BAND = (0.95, 1.05)  # a mode n's peak is sought in BAND x n f_1 (string)
TOL = 4e-3          # relative: the measured 0.22 % (pinned, f_h) + 0.18 % margin
ENDS = ("pinned", "clamped")
#: THREAD (creep-rate law): its driven centre moved 5 mm normal to the spans, reached at
#: 1.6 s (after the load step), the march run on to 3.6 s: a 2 s window (bin 0.5 Hz at 24 Hz
#: after the zero padding's parabola; its span modes 24-94 Hz)
THREAD_FILE = REPO / "examples" / "thread_creep_rate.toml"
THREAD_SHIFT, THREAD_FROM, THREAD_END = 5e-3, 1.6, 3.6


def overrides(dt: float = DT) -> list[str]:
    """The drive file's overrides: belt2d's 120 rad/s case, the shift and the step."""
    return ([f"{KEYS[k]}={v!r}" for k, v in CASE_120.items()] +
            [f"pulleys.driven.centre_shift=[0.0, {SHIFT!r}]",
             f"pulleys.driven.centre_shift_time={T1!r}", f"run.dt={dt!r}"])


@lru_cache(maxsize=None)
def run(dt: float = DT):
    """(public JSON, SceneResult) of the belt-drive run, cached within a process."""
    out, res = SCENES["belt-drive"].execute({"file": str(FILE), "set": "; ".join(overrides(dt))})
    if not out["converged"]:
        raise RuntimeError(f"belt-drive 120 rad/s: {out['message']}")
    return out, res


def alpha_frequency(f, h: float, rho_inf: float) -> float:
    """f_h (Hz): the frequency the generalised-alpha march (step h s) gives a free
    oscillator of frequency f (Hz): arg of the oscillatory eigenvalue of the one-step map
    of (q, q', q'', a) for q'' = -omega^2 q, over 2 pi h."""
    am, af, g, b = AlphaOptions(rho_inf=rho_inf).coefficients()
    w2 = (2 * math.pi * f) ** 2
    lhs = np.array([[1, 0, 0, -h * h * b], [0, 1, 0, -h * g], [0, 0, af - 1, 1 - am],
                    [w2, 0, 1, 0]], dtype=float)
    rhs = np.array([[1, h, 0, h * h * (0.5 - b)], [0, 1, 0, h * (1 - g)], [0, 0, af, -am],
                    [0, 0, 0, 0]], dtype=float)
    mu = np.linalg.eigvals(np.linalg.solve(lhs, rhs))
    osc = mu[np.abs(mu.imag) > 1e-12 * np.abs(mu)]
    return float(np.abs(np.angle(osc[np.argmax(np.abs(osc))]))) / (2 * math.pi * h)


def offset(r: np.ndarray, span, a: float) -> float:
    """Offset (m) normal to ``span`` = (start, end) of the belt polyline r (closed) where it
    crosses the normal at the fraction a of the span; nan if it does not near the line."""
    A, B = span
    L = float(np.linalg.norm(B - A))
    u = (B - A) / L
    r = np.vstack([r, r[:1]])
    lam, off = (r - A) @ u / L, (r - A) @ np.array([-u[1], u[0]])
    hit = np.flatnonzero((np.abs(off[:-1]) < 0.1 * L) & ((lam[:-1] - a) * (lam[1:] - a) <= 0)
                         & (lam[:-1] != lam[1:]))
    if hit.size == 0:
        return math.nan
    i = hit[0]
    return float(off[i] + (a - lam[i]) / (lam[i + 1] - lam[i]) * (off[i + 1] - off[i]))


def spectrum(t: np.ndarray, y: np.ndarray) -> tuple:
    """(f Hz, |FFT|) of y - mean, Hann window, zero padded PAD times (uniform t, s)."""
    y = y - y.mean()
    size = PAD * y.size
    return np.fft.rfftfreq(size, t[1] - t[0]), np.abs(np.fft.rfft(y * np.hanning(y.size), size))


def peak(f: np.ndarray, amp: np.ndarray, lo: float, hi: float) -> float:
    """The largest bin of (lo, hi) Hz refined by a parabola through log |FFT| (Hz)."""
    i = np.flatnonzero((f > lo) & (f < hi))
    k = int(i[np.argmax(amp[i])])
    a, b, c = np.log(amp[k - 1:k + 2])
    return float(f[k] + 0.5 * (a - c) / (a - 2 * b + c) * (f[1] - f[0]))


def _window(res, t_from: float = T1) -> tuple:
    """(times, belt samples, spans' tangent points, description) from t_from (s) on."""
    r, drive, desc = res.extra["result"], res.extra["drive"], res.extra["description"]
    sel = np.flatnonzero(r.t >= t_from - 1e-12)
    smps = [sample(drive, r.q[i], r.v[i], float(r.t[i]), npts=16) for i in sel]
    ends = [desc.path(np.array([a, b]))[0] for _, a, b in desc.path.pieces()[1::2]]
    return r.t[sel], smps, ends, desc


def _means(smps, span) -> tuple:
    """(N, |v|): means over the middle third of span (within L/10 of it), N and m/s."""
    A, B = span
    L = float(np.linalg.norm(B - A))
    u = (B - A) / L
    N, v = [], []
    for s in smps:
        lam, off = (s.r - A) @ u / L, (s.r - A) @ np.array([-u[1], u[0]])
        m = (lam > 1 / 3) & (lam < 2 / 3) & (np.abs(off) < 0.1 * L)
        N.append(s.N[m])
        v.append(s.speed[m])
    return float(np.concatenate(N).mean()), float(np.concatenate(v).mean())


def thread_overrides() -> list[str]:
    """THREAD's drive file's overrides: the driven centre moved :data:`THREAD_SHIFT` normal
    to the spans by :data:`THREAD_FROM` s, the march run on to :data:`THREAD_END` s."""
    return [f"pulleys.driven.centre_shift=[0.0, {THREAD_SHIFT!r}]",
            f"pulleys.driven.centre_shift_time={THREAD_FROM!r}", f"run.t_end={THREAD_END!r}"]


@lru_cache(maxsize=None)
def thread_run():
    """(public JSON, SceneResult) of THREAD's march with :func:`thread_overrides`."""
    out, res = SCENES["belt-drive"].execute({"file": str(THREAD_FILE),
                                             "set": "; ".join(thread_overrides())})
    if not out["converged"]:
        raise RuntimeError(f"belt-drive THREAD: {out['message']}")
    return out, res


def march_peaks(res, t_from: float, bands: dict) -> dict:
    """Per span ("A -> B" of the drive's pulley names, belt order) in ``bands`` {span:
    [(lo, hi) Hz of mode 1, of mode 2]}: the spectral peaks (Hz) of the march ``res`` over
    [t_from, t_end], mode n read at the span fraction STATIONS[n - 1]."""
    t, smps, ends, desc = _window(res, t_from)
    names = [q.name for q in desc.pulleys]
    out = {}
    for k, span in enumerate(ends):
        key = f"{names[k]} -> {names[(k + 1) % len(names)]}"
        if key not in bands:
            continue
        got = []
        for (lo, hi), a in zip(bands[key], STATIONS):
            f, amp = spectrum(t, np.array([offset(s.r, span, a) for s in smps]))
            got.append(peak(f, amp, lo, hi))
        out[key] = np.array(got)
    return out


def references(T, rho_A, v, L, EI, h, rho_inf) -> dict:
    """First two frequencies (Hz): string, pinned and clamped beam, each as the march with
    step h sees it (:func:`alpha_frequency`, key + "_h")."""
    out = {"string": moving_string.span_frequencies(T, rho_A, v, L, 2)}
    out.update({e: moving_beam.span_frequencies(T, rho_A, v, L, EI, 2, e) for e in ENDS})
    out.update({f"{k}_h": np.array([alpha_frequency(x, h, rho_inf) for x in f])
                for k, f in list(out.items())})
    return out


@lru_cache(maxsize=None)
def spans(dt: float = DT) -> dict:
    """Per span (from -> to): tension, speed, length, the two measured peaks (Hz), the
    references and their relative differences, the FFT's bin width; and the CPU time."""
    out, res = run(dt)
    t, smps, ends, desc = _window(res)
    p, rows = desc.belt, {}
    EA, rho_A0 = p["E"] * p["b"] * p["h"], p["rho"] * p["b"] * p["h"]
    EI = p["E"] * p["alpha2"] * p["b"] * p["h"] ** 3 / 12
    names = [q.name for q in desc.pulleys]
    for k, span in enumerate(ends):
        N, v = _means(smps, span)
        lam, L = math.sqrt(1 + 2 * N / EA), float(np.linalg.norm(span[1] - span[0]))
        ref = references(N * lam, rho_A0 / lam, v, L, EI, dt, desc.run["rho_inf"])
        peaks = []
        for n, a in enumerate(STATIONS, 1):
            f, amp = spectrum(t, np.array([offset(s.r, span, a) for s in smps]))
            band = np.array(BAND) * ref["string"][n - 1]
            peaks.append(peak(f, amp, *band))
        peaks = np.array(peaks)
        rows[f"{names[k]} -> {names[(k + 1) % len(names)]}"] = {
            "N": N, "T": N * lam, "stretch": lam, "v": v, "L": L, "EI": EI, "rho_A0": rho_A0,
            "rho_inf": desc.run["rho_inf"],
            "layer": math.sqrt(EI / (N * lam)), "peaks": peaks, "ref": ref,
            "error": {key: peaks / f - 1 for key, f in ref.items()},
            "resolution": 1.0 / (t[-1] - t[0])}
    return {"spans": rows, "cpu_s": out["cpu_time_s"]}
