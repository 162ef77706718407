"""Frequency studies (issue 24 items 3 and 4) as plain data, shared by
``tests/checks/test_frequencies.py`` and the report chapter ``frequencies``.

Every frequency comes from ``ancf modes`` (:func:`ancf.api.modes`) or from a ``belt2d`` run;
the references are computed: Timoshenko's beam (:mod:`analytic.beam_modes`), Navier's plate
and the Ritz series of the free plate (:mod:`analytic.plate_modes`), Euler's load and the
axially moving string (:mod:`analytic.moving_string`).  The only typed-in numbers are
Exudyn's published free-free ratios (:data:`EXUDYN_FREE_RATIOS`).
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from scipy.optimize import brentq

from analytic import beam_modes, moving_string, plate_modes
from ancf.belts.post2d import sample, span_speed, span_tension, spans
from ancf.checks import belt2d as b2
from ancf.checks.belt2d import Check
from ancf.scenes.modes import execute

#: the steel beam of the acceptance (L/h = 20 at h = b = 0.1 m); rho: ancf modes' default
BEAM = dict(E=2.07e11, nu=0.3, ks=5.0 / 6.0, L=2.0)
SLENDERNESS = (5, 20, 100)
MESHES = (2, 4, 8, 16, 32, 64)
ORDER_MESHES = (8, 16, 32, 64)  # the meshes the convergence order is fitted over
SUPPORTS = ("simply-supported", "cantilever")
#: element and integration scheme -> scene overrides
SCHEMES = {
    "linear, thesis": {"element": "linear", "integration": "thesis"},
    "linear, exact": {"element": "linear", "integration": "exact"},
    "linear, report-selective": {"element": "linear", "integration": "report-selective"},
    "linear, report-fix": {"element": "linear", "integration": "report-fix"},
    "omar-shabana": {"element": "omar-shabana"},
}
#: the coarsest meshes of the default element meeting 0.5 % at L/h = 20 (docs/guide/modes.md, test_modes)
ACCEPT_MESH = {"simply-supported": 48, "cantilever": 38}
BEAM_TOL = 5e-3
ORDER_TOL = 0.1
PLATE_MESHES = (4, 6, 8, 10, 12, 14, 16)
PLATE_COUNT = 6
PLATE_TOL = 1e-2
#: Exudyn's free-free plate (TestModels/ANCFThinPlateTests.py: Lx = Ly = 1, Em = 2e11 * 0.1,
#: rho = 7800, tPlate = 0.02, nu = 0.3)
EXUDYN_PLATE = dict(a=1.0, h=0.02, E=2e10, nu=0.3, rho=7800.0)
#: the free-free ratios omega / (pi^2 / a^2 sqrt(D / (rho h))) printed in Exudyn's
#: main/pythonDev/TestModels/ANCFThinPlateTests.py (commit e44aca1b4fe3, "FreeFree:
#: omega0=1.364614 * fact ..."), 7 significant digits
EXUDYN_FREE_RATIOS = (1.364614, 1.985504, 2.459086)
EXUDYN_DIGIT = 1e-6  # one unit of the last printed digit
FREE_MESHES = (4, 8, 16)
FREE_TOL = 2e-3  # 8 x 8 elements: the first three ratios within 0.2 % of the Ritz values
RITZ_DEGREE = 20
AXIAL_MESHES = (16, 64)
AXIAL_FRACTIONS = (0.0, 0.2, 0.4, 0.6, 0.8, 0.9, 0.95, 1.05)
EULER_TOL = 1e-2
SPAN_TOL = 5e-2
SPAN_START = 0.6  # s: the driver's ramp and the load torque reach their final values
ZERO_PAD = 16  # the FFT's length over the window's samples (peak interpolation)
SPAN_LOW = 20.0  # Hz: the spectrum's peak is sought above this (the slow drift below)
#: ... and below this fraction of the element passing frequency (whose second harmonic is
#: as high as the tight span's own peak)
SPAN_HIGH = 0.9


# ------------------------------------------------------------------ beams vs Timoshenko
def section(L: float, h: float) -> dict:
    """The square steel beam of slenderness L / h (b = h)."""
    return dict(BEAM, L=L, h=h, b=h)


@lru_cache(maxsize=None)
def _modes(scene: str, items: tuple, count: int, about: str = "reference") -> dict:
    return execute(scene, dict(items), count, about)[0]


def modes(scene: str, count: int, about: str = "reference", **sets) -> dict:
    """The JSON of ``ancf modes`` (cached within a process)."""
    return _modes(scene, tuple(sorted(sets.items())), count, about)


def bending(support: str, scheme: str, n: int, slenderness: float = 20) -> dict:
    """The lowest three bending frequencies (mostly along y; NaN where the mesh has fewer),
    the Timoshenko ones and the CPU seconds of the solve."""
    sets = dict(section(BEAM["L"], BEAM["L"] / slenderness), **SCHEMES[scheme], n_elements=n)
    size = modes(support, 1, **sets)["results"]["reduced_size"]
    res = modes(support, min(8, size - 1), **sets)
    r = res["results"]
    f = [f for f, s in zip(r["frequencies_hz"], r["mode_direction_shares"]) if s[1] > 0.5][:3]
    return {"f": np.array(f + [math.nan] * (3 - len(f))), "ref": timoshenko(support, res["params"]),
            "cpu": res["cpu_time_s"]}


def timoshenko(support: str, p: dict) -> np.ndarray:
    """The first three Timoshenko frequencies (Hz) of the scene parameters ``p``."""
    return np.array(beam_modes.timoshenko(
        support, count=3, L=p["L"], E=p["E"], G=p["E"] / (2.0 * (1.0 + p["nu"])),
        I=p["b"] * p["h"] ** 3 / 12.0, A=p["b"] * p["h"], rho=p["rho"], ks=p["ks"]))


def beam_rows(slenderness=(20,), meshes=MESHES) -> list[dict]:
    """One row per support, scheme, slenderness, mesh: frequencies and relative errors."""
    rows = []
    for support in SUPPORTS:
        for scheme in SCHEMES:
            for s in slenderness:
                for n in meshes:
                    b = bending(support, scheme, n, s)
                    err = b["f"] / b["ref"] - 1.0
                    rows.append({"support": support, "scheme": scheme, "L/h": s, "n": n,
                                 **{f"f{k + 1} Hz": b["f"][k] for k in range(3)},
                                 **{f"error f{k + 1}": err[k] for k in range(3)},
                                 "timing: CPU s": b["cpu"]})
    return rows


def orders(rows: list[dict]) -> list[dict]:
    """The fitted slope of log|error| over log n (ORDER_MESHES) per support, scheme and
    mode: -2 is second order; a locking scheme's pre-asymptotic range shows as a shallower
    or erratic slope."""
    out = []
    for support in SUPPORTS:
        for scheme in SCHEMES:
            sel = [r for r in rows if r["support"] == support and r["scheme"] == scheme
                   and r["n"] in ORDER_MESHES]
            n = np.array([r["n"] for r in sel], float)
            row = {"support": support, "scheme": scheme}
            for k in range(1, 4):
                e = np.abs([r[f"error f{k}"] for r in sel])
                row[f"order f{k}"] = float(np.polyfit(np.log(n), np.log(e), 1)[0])
            out.append(row)
    return out


# ------------------------------------------------------------------ plates
def navier(p: dict, count: int = PLATE_COUNT) -> np.ndarray:
    return plate_modes.navier_frequencies(p["a"], p["a"], p["h"], p["E"], p["nu"], p["rho"],
                                          count)[0]


def plate_rows() -> list[dict]:
    """The simply supported square (plate-square defaults) against Navier, per mesh."""
    rows = []
    for n in PLATE_MESHES:
        res = modes("plate-square", PLATE_COUNT, n_elements=n)
        err = np.array(res["results"]["frequencies_hz"]) / navier(res["params"]) - 1.0
        rows.append({"n per side": n, **{f"error f{k + 1}": err[k] for k in range(PLATE_COUNT)},
                     "timing: CPU s": res["cpu_time_s"]})
    return rows


def free_ratios(n: int) -> dict:
    """The free-free plate's first three elastic frequencies as Exudyn's ratios, the zero
    modes counted, the CPU seconds."""
    p = EXUDYN_PLATE
    res = modes("plate-square", 9, n_elements=n, supports="free", **p)
    D = p["E"] * p["h"] ** 3 / (12.0 * (1.0 - p["nu"] ** 2))
    scale = math.pi**2 / p["a"] ** 2 * math.sqrt(D / (p["rho"] * p["h"]))
    r = res["results"]
    rigid = r["rigid_body_modes"]
    w = 2.0 * math.pi * np.array(r["frequencies_hz"][rigid:rigid + 3])
    return {"ratios": w / scale, "rigid": rigid, "cpu": res["cpu_time_s"]}


#: the 8 x 8 decision (issue 24): quadratures compared, and the meshes of the fitted order
EVIDENCE_MESH = 8
EVIDENCE_NG = (4, 6)
PLATE_ORDER_MESHES = (8, 10, 12, 14, 16)
#: ours against Exudyn's ANCFThinPlate on the same mesh and constraints: the relative
#: difference of the first six frequencies (round-off of two eigen solvers; seen 9e-13)
EXUDYN_SAME_TOL = 1e-9
#: the plate's convergence order (fit over PLATE_ORDER_MESHES, modes 1-4): -2 within this
PLATE_ORDER_TOL = 0.15


def exudyn_plate(n: int, supports: str = "ours", count: int = PLATE_COUNT) -> dict | None:
    """The first ``count`` frequencies (Hz) and the CPU seconds of Exudyn's thin ANCF plate
    (``ObjectANCFThinPlate``, 4 nodes with r, r_x, r_y: 36 coordinates, the element of
    thesis 4.3 and ours) on the n x n mesh of plate-square's defaults, built by its
    ``ShellMesh`` as its ``TestModels/ANCFThinPlateTests.py`` does; None without exudyn.
    ``supports``: ``ours`` fixes what plate-square fixes (every in-plane component, w and
    the slope along the edge on the boundary); ``exudyn`` what its test's spherical joints
    fix (the boundary nodes' positions; no slope), with the in-plane components of the
    interior fixed as well (at the flat reference they decouple from the bending)."""
    try:
        import exudyn as exu
        from exudyn.shells import ShellMesh
    except ImportError:
        return None
    p = modes("plate-square", 1, n_elements=n)["params"]
    a = p["a"]
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    mesh = ShellMesh(vertices=[np.array(v, float) for v in ((0, 0, 0), (a, 0, 0), (a, a, 0),
                                                             (0, a, 0))],
                     numberOfElementsX=n, numberOfElementsY=n, youngsModulus=p["E"],
                     poissonsRatio=p["nu"], density=p["rho"], thickness=p["h"])
    mesh.CreateANCFThinPlateElements(mbs)
    mbs.Assemble()
    fixed = set()
    for node in mesh.nodeNumbers:
        c = mbs.GetNodeODE2Index(node)  # r, r_x, r_y: 3 components each
        x, y, _ = mbs.GetNodeOutput(node, exu.OutputVariableType.Position,
                                    exu.ConfigurationType.Reference)
        on_x, on_y = min(x, a - x) < 1e-12 * a, min(y, a - y) < 1e-12 * a
        fixed |= {c + 3 * s + i for s in range(3) for i in (0, 1)}
        fixed |= {c + 2} if on_x or on_y else set()
        if supports == "ours":
            fixed |= ({c + 8} if on_x else set()) | ({c + 5} if on_y else set())
    import time
    t0 = time.process_time()
    lam, _ = mbs.ComputeODE2Eigenvalues(constrainedCoordinates=sorted(fixed),
                                        numberOfEigenvalues=count, useSparseSolver=False)
    cpu = time.process_time() - t0
    return {"f": np.sqrt(np.abs(np.asarray(lam[:count]))) / (2.0 * math.pi), "cpu": cpu}


@lru_cache(maxsize=None)
def plate_evidence() -> dict:
    """The 8 x 8 simply supported plate, side by side: ours at two quadratures, Exudyn's
    thin plate with our constraints and with its test's, Navier; the fitted order of
    convergence of each mode over PLATE_ORDER_MESHES (errors from plate_rows)."""
    n = EVIDENCE_MESH
    ours = {ng: modes("plate-square", PLATE_COUNT, n_elements=n, ng=ng) for ng in EVIDENCE_NG}
    ref = navier(ours[EVIDENCE_NG[0]]["params"])
    rows = [{"source": f"ours, plate36, {ng} × {ng} Gauss points",
             "f": np.array(r["results"]["frequencies_hz"]), "cpu": r["cpu_time_s"]}
            for ng, r in ours.items()]
    for sup, what in (("ours", "our constraints (w, slope along the edge)"),
                      ("exudyn", "its test's constraints (boundary positions only)")):
        e = exudyn_plate(n, sup)
        if e is not None:
            rows.append({"source": f"Exudyn ObjectANCFThinPlate, {what}", **e})
    sel = [r for r in plate_rows() if r["n per side"] in PLATE_ORDER_MESHES]
    x = np.log([r["n per side"] for r in sel])
    order = [float(np.polyfit(x, np.log(np.abs([r[f"error f{k}"] for r in sel])), 1)[0])
             for k in range(1, PLATE_COUNT + 1)]
    below = all(r[f"error f{k}"] < 0 for r in plate_rows() for k in range(1, PLATE_COUNT + 1))
    return {"rows": rows, "navier": ref, "order": order, "from_below": below}


def exudyn_difference() -> float | None:
    """Largest relative difference of our 8 x 8 frequencies from Exudyn's thin plate on the
    same mesh and constraints (None without exudyn)."""
    ev = plate_evidence()
    ours = ev["rows"][0]["f"]
    same = [r["f"] for r in ev["rows"] if "our constraints" in r["source"]]
    return float(np.abs(same[0] / ours - 1.0).max()) if same else None


@lru_cache(maxsize=None)
def ritz() -> np.ndarray:
    """The free square plate's first three ratios by the Ritz series (nu of Exudyn's)."""
    return plate_modes.free_ratios(EXUDYN_PLATE["nu"], 3, RITZ_DEGREE)


# ------------------------------------------------------------------ axial bar
def euler_load(p: dict) -> float:
    """pi^2 E I / L^2 (N) of the pinned-pinned bar."""
    return math.pi**2 * p["E"] * p["b"] * p["h"] ** 3 / 12.0 / p["L"] ** 2


def engesser_load(p: dict) -> float:
    """Euler's load with Engesser's shear correction, P_E / (1 + P_E / (ks G A)) (N)."""
    P, G = euler_load(p), p["E"] / (2.0 * (1.0 + p["nu"]))
    return P / (1.0 + P / (p["ks"] * G * p["b"] * p["h"]))


def axial_lambda(fraction: float, n: int) -> float:
    """omega_1^2 (rad^2/s^2) of the axial bar about its equilibrium under ``fraction`` of
    Euler's load in compression (0: about the unloaded reference)."""
    p = modes("axial-bar", 1, n_elements=n)["params"]
    res = modes("axial-bar", 1, "equilibrium", n_elements=n, F=-fraction * euler_load(p))
    return res["results"]["eigenvalues_rad2_s2"][0]


@lru_cache(maxsize=None)
def euler_crossing(n: int) -> float:
    """The compression (fraction of Euler's load) where omega_1^2 crosses zero."""
    return brentq(lambda f: axial_lambda(f, n), 0.9, 1.1, xtol=1e-6)


def axial_rows() -> list[dict]:
    return [{"n": n, "P / P_E": f, "omega² / omega0²": axial_lambda(f, n) / axial_lambda(0, n)}
            for n in AXIAL_MESHES for f in AXIAL_FRACTIONS]


# ------------------------------------------------------------------ belt span
def spectrum(t: np.ndarray, y: np.ndarray, high: float = np.inf) -> tuple:
    """(frequencies Hz, |FFT| of y - mean with a Hann window, zero-padded ZERO_PAD times,
    the peak's frequency between SPAN_LOW and ``high``) of the uniformly sampled y(t)."""
    y = y - y.mean()
    size = ZERO_PAD * y.size
    amp = np.abs(np.fft.rfft(y * np.hanning(y.size), size))
    f = np.fft.rfftfreq(size, t[1] - t[0])
    above = (f > SPAN_LOW) & (f < high)
    return f, amp, float(f[above][np.argmax(amp[above])])


@lru_cache(maxsize=None)
def belt_spans() -> dict:
    """The 120 rad/s case of belt2d (thesis Figs 3.10-3.20): per span, the mid-span
    spectrum over [SPAN_START, t_end] against the moving string at the span's tension and
    speed averaged over the same window's states."""
    out, res = b2.run(**b2.CASE_120)
    r, drive = res.extra["result"], res.extra["drive"]
    t = np.asarray(out["results"]["times"])
    sel = t >= SPAN_START - 1e-12
    sp, path = spans(drive.spec.path), drive.spec.path
    R = min(path.R1, path.R2)
    smps = [sample(drive, r.q[i], r.v[i], float(r.t[i])) for i in np.flatnonzero(sel)]
    p, rows = out["params"], {}
    rho_A, EA = p["rho"] * p["b"] * p["h"], p["E"] * p["b"] * p["h"]
    T_tight = float(np.mean([span_tension(s, sp["tight"], R) for s in smps]))
    rows["passing Hz"] = p["omega_final"] * p["R1"] / ((1.0 + T_tight / EA) * drive.mesh.lengths[0])
    for name in ("tight", "slack"):
        y = np.asarray(out["results"][f"mid_{name}_y_m"])[sel]
        f, amp, peak = spectrum(t[sel], y, SPAN_HIGH * rows["passing Hz"])
        T = float(np.mean([span_tension(s, sp[name], R) for s in smps]))
        v = float(np.mean([span_speed(s, sp[name], R) for s in smps]))
        L = float(np.linalg.norm(sp[name][1] - sp[name][0]))
        string = moving_string.span_frequencies(T, rho_A, v, L, 3)
        rows[name] = {"tension N": T, "speed m/s": v, "length m": L, "peak Hz": peak,
                      "string Hz": string, "error": peak / string[0] - 1.0, "f": f, "amp": amp,
                      "resolution Hz": 1.0 / (t[sel][-1] - t[sel][0])}
    rows["params"], rows["timing: CPU s"] = p, out["cpu_time_s"]
    return rows


# ------------------------------------------------------------------ the checks
def _worst(support: str) -> float:
    b = bending(support, "linear, thesis", ACCEPT_MESH[support])
    return float(np.abs(b["f"] / b["ref"] - 1.0).max())


def _evidence_checks() -> tuple:
    """The 8 x 8 decision's checks: the element's own convergence from below at second
    order, and Exudyn's thin plate giving the same numbers (when exudyn is installed)."""
    ev = plate_evidence()
    worst = max(abs(o + 2.0) for o in ev["order"][:4])
    out = [Check("Plate simply supported: first four frequencies converge from below at "
                 "order 2 (fit over n = 8…16)", ev["order"][0], -2.0,
                 worst if ev["from_below"] else math.inf, PLATE_ORDER_TOL, "-",
                 "largest |slope + 2| (inf if any error is positive)")]
    diff = exudyn_difference()
    if diff is not None:
        out.append(Check("Plate simply supported, 8 × 8: first six frequencies = Exudyn's "
                         "ANCFThinPlate on the same mesh and constraints",
                         float(ev["rows"][0]["f"][3]), float(ev["rows"][2]["f"][3]), diff,
                         EXUDYN_SAME_TOL, "Hz", "largest relative difference"))
    return tuple(out)


@lru_cache(maxsize=None)
def checks() -> tuple:
    """Every acceptance check of the chapter, in table order (cached)."""
    o = {r["support"]: r for r in orders(beam_rows()) if r["scheme"] == "linear, thesis"}
    plate8 = [r for r in plate_rows() if r["n per side"] == 8][0]["error f1"]
    free = free_ratios(8)["ratios"]
    free_err = float(np.abs(free / ritz() - 1.0).max())
    exu = float(np.abs(ritz() - np.array(EXUDYN_FREE_RATIOS)).max())
    belt = belt_spans()
    return (
        *(Check(f"Beam {s}, linear thesis, L/h = 20, {ACCEPT_MESH[s]} el.: first three "
                "frequencies within 0.5 % of Timoshenko", _worst(s), 0.0, _worst(s), BEAM_TOL,
                "-", "largest relative error") for s in SUPPORTS),
        *(Check(f"Beam {s}, linear thesis: convergence order 2 (fit over n = 8…64, modes 1-2)",
                o[s]["order f1"], -2.0, max(abs(o[s][f"order f{k}"] + 2.0) for k in (1, 2)),
                ORDER_TOL, "-", "largest |slope + 2| of log error over log n")
          for s in SUPPORTS),
        Check("Plate simply supported, 8 × 8: fundamental within 1 % of Navier", plate8, 0.0,
              abs(plate8), PLATE_TOL, "-", "relative error"),
        *_evidence_checks(),
        Check("Plate free-free, 8 × 8: first three ratios within 0.2 % of the Ritz series",
              float(free[0]), float(ritz()[0]), free_err, FREE_TOL, "-", "largest relative"),
        Check("Plate free-free: Ritz series = Exudyn's published ratios to their last digit",
              float(ritz()[2]), EXUDYN_FREE_RATIOS[2], exu, EXUDYN_DIGIT, "-",
              "largest absolute difference"),
        *(Check(f"Axial bar, {n} el.: ω₁ about the equilibrium vanishes within 1 % of Euler's "
                "load", euler_crossing(n), 1.0, abs(euler_crossing(n) - 1.0), EULER_TOL, "-",
                "crossing load / P_E, relative") for n in AXIAL_MESHES),
        *(Check(f"Belt 120 rad/s, {k} span: mid-span frequency within 5 % of the moving "
                "string", belt[k]["peak Hz"], float(belt[k]["string Hz"][0]),
                abs(belt[k]["error"]), SPAN_TOL, "Hz", "relative") for k in ("tight", "slack")),
    )
