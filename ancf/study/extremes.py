"""Stability at the extremes: where each element / quadrature / integrator works.

Every axis of issue 4 is declared in :data:`AXES`; an axis runs through
:func:`ancf.study.sweep.run_sweep` (a worker process per run, killed at the time limit) so
that every case ends in a converged result or a diagnosis (:func:`diagnosis`), never an
exception, a silent NaN or a hang.  Axes that need a scene the suite does not have yet
(contact, spinning beam, time integration) say so: ``applicable()`` returns the reason.

Static axes (cantilever): slenderness L/h 1..1e4 (locking per scheme, small-deflection
load against Timoshenko), Poisson's ratio 0..0.499, 2..1024 elements (Models 1 and 2
against Reissner), tip load up to 10x Model 1 (against Reissner), load steps and Newton
iterations per step at 10x load, and a watchdog case that exceeds its time limit.
Dynamic axes: time steps and tolerances on the soft and on the stiff pendulum (explicit,
implicit and generalised-alpha), spinning speed up to 10x omega_s.  Contact axes (belt
drive): penalty stiffness 1e4..1e10 N/m^2 and creep-rate factor nu_s 1e2..1e7 kg/(m s),
to the end of the driver's ramp, against the no-slip drive; a converged run with deep
penetration or large slip carries an accuracy warning (``Axis.warn``) as its diagnosis.

The reduced configuration of the reports (``--quick``) runs the axes that declare
``quick`` grids (the cells the acceptance checks read, and one case per outcome class)
and says "skipped" for the others.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Callable

import pandas as pd

from ancf.elements.catalogue import ELEMENTS
from ancf.study.references import cache_root
from ancf.scenes.belt2d import PENETRATION_WARN

E, L, B = 2.07e11, 2.0, 0.1
MODEL_1 = {"h": 0.1, "nu": 0.3}
MODEL_2 = {"h": 0.5, "nu": 0.0}
F1 = -5e8 * 0.1**3  # Model 1 tip load [N]
SCHEMES = tuple((name, s) for name, cls in ELEMENTS.items() for s in cls.schemes)
WORKS = 1e-2     # converged and error <= 1 %: works
ROUGH = 1e-1     # 1 % < error <= 10 %: usable; beyond: locked / wrong


def small_load(slenderness: float, nu: float = 0.3, deflection: float = 1e-3) -> dict:
    """h and F of a cantilever of length L = 2 m whose linear (Timoshenko) tip
    deflection is ``deflection`` x L."""
    from analytic import timoshenko
    h = L / slenderness
    unit = timoshenko.cantilever_tip_deflection(E, nu, L, h, B, -1.0)
    return {"h": h, "F": -deflection * L / abs(unit)}


@dataclass(frozen=True)
class Axis:
    name: str
    title: str
    scene: str
    grids: Callable[[], list]          # sub-grids (lists of values), built when run
    column: str                        # the parameter (or label column) along the axis
    rows: tuple                        # the columns that name a model (map rows)
    reference: str | None = None
    time_limit: float = 120.0
    requires: tuple = ()               # scenes that must exist
    na_reason: str = ""                # set: not applicable whatever exists
    doc: str = ""
    label: Callable[[pd.DataFrame], pd.Series] | None = None  # axis values for display
    extra: dict = field(default_factory=dict)
    quick: Callable[[], list] | None = None  # reduced grids of ``--quick`` (None: skipped)
    warn: Callable[[pd.Series], str | None] | None = None  # accuracy warning of an ok row

    def applicable(self) -> tuple[bool, str]:
        from ancf.scenes import SCENES
        if self.na_reason:
            return False, self.na_reason
        missing = [s for s in self.requires if s not in SCENES]
        if missing:
            return False, f"not applicable yet: no {' / '.join(missing)} scene in the suite"
        return True, ""


def _schemes(*pairs, **extra):
    pairs = pairs or SCHEMES
    return [{"element": [e], "integration": [i], **extra} for e, i in pairs]


def _slenderness_grids():
    out = []
    for s in (1, 10, 100, 1000, 10000):
        sl = small_load(s)
        for g in _schemes(n_elements=[4, 64]):
            out.append({**g, "h": [sl["h"]], "F": [sl["F"]], "nu": [0.3], "load_steps": [1]})
    return out


def _poisson_grids():
    sl = small_load(20)
    return [{**g, "h": [sl["h"]], "F": [sl["F"]], "nu": [0.0, 0.3, 0.45, 0.49, 0.499],
             "n_elements": [8, 64], "load_steps": [1]}
            for g in _schemes(("linear", "thesis"), ("omar-shabana", "thesis"),
                              ("omar-shabana", "exact"))]


def _slenderness_quick():
    """The pinned cells: L/h = 1e4, 64 elements, linear thesis and exact."""
    sl = small_load(10000)
    return [{**g, "h": [sl["h"]], "F": [sl["F"]], "nu": [0.3], "load_steps": [1]}
            for g in _schemes(("linear", "thesis"), ("linear", "exact"), n_elements=[64])]


_NS = [2, 4, 8, 16, 32, 64, 128, 256, 512, 1024]


def _elements_quick():
    return [{"element": ["linear"], "integration": ["thesis"], "n_elements": [_NS[0], _NS[-1]],
             **{k: [v] for k, v in MODEL_1.items()}}]


def _elements_grids():
    out = [{**g, "n_elements": _NS, **{k: [v] for k, v in MODEL_1.items()}}
           for g in _schemes(("linear", "thesis"), ("linear", "exact"),
                             ("linear", "report-selective"), ("omar-shabana", "thesis"))]
    out += [{**g, "n_elements": _NS, **{k: [v] for k, v in MODEL_2.items()}}
            for g in _schemes(("linear", "thesis"), ("linear", "report-selective"),
                              ("linear", "report-fix"))]
    return out


LOAD_FACTORS = (0.1, 1.0, 2.0, 5.0, 10.0)


def _load_grids():
    return [{**g, "F": [F1 * f for f in LOAD_FACTORS], "n_elements": [8, 32],
             **{k: [v] for k, v in MODEL_1.items()}}
            for g in _schemes(("linear", "thesis"), ("linear", "report-selective"),
                              ("omar-shabana", "thesis"))]


def _step_grids():
    return [{"element": ["linear"], "integration": ["thesis"], "n_elements": [16],
             "F": [10 * F1], "load_steps": [1, 10, 100, 1000], "max_iterations": [1, 3, 25],
             **{k: [v] for k, v in MODEL_1.items()}}]


def _watchdog_grids():
    return [{"element": ["omar-shabana"], "integration": ["thesis"], "n_elements": [4096],
             "stability_check": ["off"], **{k: [v] for k, v in MODEL_1.items()}}]


def _step_quick():
    return [{**_step_grids()[0], "load_steps": [1, 10], "max_iterations": [1, 25]}]


def _dyn_step_grids():
    return [{"integrator": ["generalized-alpha"], "dt": [1e-4, 1e-3, 1e-2, 5e-2, 2e-1],
             "n_elements": [4], "t_end": [1.0]},
            {"integrator": ["rk45", "dop853"], "rtol": [1e-10, 1e-6, 1e-2], "n_elements": [4],
             "max_steps": [2000], "t_end": [1.0]},
            {"integrator": ["radau", "bdf"], "rtol": [1e-10, 1e-6, 1e-2], "n_elements": [4],
             "t_end": [1.0]}]


def _stiff_step_grids():
    """Stiff pendulum (E = 2.07e11 Pa): the explicit stable step is about 1e-5 s."""
    stiff = {"E": [2.07e11], "n_elements": [4], "t_end": [1.0]}
    return [{"integrator": ["generalized-alpha"], "dt": [1e-4, 1e-3, 1e-2, 5e-2], **stiff},
            {"integrator": ["rk45", "dop853"], "rtol": [1e-6, 1e-2], "max_steps": [2000], **stiff},
            {"integrator": ["radau"], "rtol": [1e-4], **stiff},
            {"integrator": ["bdf"], "rtol": [1e-6, 1e-2], **stiff}]


def _stiff_step_quick():
    return [{"integrator": ["generalized-alpha"], "dt": [1e-2], "E": [2.07e11],
             "n_elements": [4], "t_end": [1.0]}]


def _spin_grids():
    return [{"omega_s": [4.0, 8.0, 20.0, 40.0], "integrator": ["generalized-alpha"],
             "n_elements": [3, 8], "dt": [5e-3]},
            {"omega_s": [40.0], "integrator": ["generalized-alpha"], "n_elements": [8],
             "dt": [2.5e-3]}]


BELT_T_END = 0.6       # s: the driver's ramp ends (Eq. 3.29)
BELT_SLIP = 1e-2       # slip beyond which a converged belt run is flagged


def _belt_grid(key, values):
    return [{key: list(values), "n_elements": [20], "dt": [2.5e-4], "t_end": [BELT_T_END]}]


def _penalty_grids():
    return _belt_grid("k_p", (1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10))


def _penalty_quick():
    return _belt_grid("k_p", (1e4, 1e7))


def _nu_s_grids():
    return _belt_grid("nu_s", (1e2, 1e3, 1e4, 1e5, 1e6, 1e7))


def _nu_s_quick():
    return _belt_grid("nu_s", (1e2, 1e7))


def _belt_label(key, unit):
    return lambda df: df[key].map(lambda v: f"{key} = {v:g} {unit}")


def belt_prestretch(row) -> float:
    """The pre-stretch per wrap (:func:`ancf.scenes.belt2d.prestretch`) of a belt2d row, m."""
    from ancf.scenes import SCENES
    from ancf.scenes import belt2d
    p = SCENES["belt2d"].resolve({k: row[k] for k in ("R1", "R2", "belt_length") if k in row
                                  and row[k] is not None and row[k] == row[k]})
    return belt2d.prestretch(belt2d.spec(p))


def belt_warning(row) -> str | None:
    """Accuracy warning of a converged belt2d row: deep penetration, else large slip."""
    pen, ratio = row.get("res_penetration_max_m"), row.get("res_omega_ratio_steady")
    if pen is not None and pen == pen and pen > PENETRATION_WARN * belt_prestretch(row):
        return (f"penetration {pen * 1e3:.2g} mm = {pen / row['h']:.2g} h = "
                f"{pen / belt_prestretch(row):.2g} × pre-stretch")
    err = row.get("error")
    if ratio is not None and err is not None and err == err and err > BELT_SLIP:
        return f"slip {100 * err:.2g} %"
    return None


def _step_label(df):
    return df.apply(lambda r: f"dt = {r['dt']:g}" if r["integrator"] == "generalized-alpha"
                    else f"rtol = {r['rtol']:g}", axis=1)


def _load_label(df):
    return (df["F"] / F1).round(3).map(lambda f: f"{f:g}× Model 1")


def _slender_label(df):
    return (L / df["h"]).round(0).map(lambda s: f"L/h = {s:g}")


AXES = (
    Axis("slenderness", "Slenderness L/h from 1 to 10⁴ (locking per integration scheme)",
         "cantilever", _slenderness_grids, "L/h", ("element", "integration", "n_elements"),
         reference="timoshenko", label=_slender_label, quick=_slenderness_quick,
         doc="Small-deflection cantilever (linear tip deflection 1e-3 L, ν = 0.3), error against "
             "the Timoshenko cantilever. At L/h = 1 the beam is a block and beam theory itself "
             "is approximate, so errors there measure the model more than the element. The "
             "Omar–Shabana rows are off by Poisson locking at ν = 0.3 (see the ν axis), at "
             "every slenderness: that is not shear locking."),
    Axis("poisson", "Poisson's ratio ν from 0 to 0.499", "cantilever", _poisson_grids, "nu",
         ("element", "integration", "n_elements"), reference="timoshenko",
         doc="Small-deflection cantilever, L/h = 20, error against Timoshenko (G = E/(2(1+ν)))."),
    Axis("elements", "2 to 1024 elements", "cantilever", _elements_grids, "n_elements",
         ("h", "element", "integration"), reference="reissner", quick=_elements_quick,
         doc="Model 1 (h = 0.1) and Model 2 (h = 0.5) at the papers' load, error against the "
             "Reissner rod (includes the constitutive floor of static_beams.md)."),
    Axis("load", "Tip load up to 10× Model 1", "cantilever", _load_grids, "F",
         ("element", "integration", "n_elements"), reference="reissner", label=_load_label,
         doc="Model 1 geometry, F = factor × (−5e5 N), error against the Reissner rod at the "
             "same load (10 load steps, adaptive)."),
    Axis("load-steps", "Load steps (static) from 1 to 1000, 1 to 25 Newton iterations per step",
         "cantilever", _step_grids, "load_steps", ("max_iterations",), reference="reissner",
         quick=_step_quick,
         doc="Linear element, thesis scheme, n = 16, at 10× the Model 1 load: the static "
             "analogue of the step-size axis (adaptive load stepping halves a failing increment "
             "down to 1/4096)."),
    Axis("watchdog", "Per-run time limit", "cantilever", _watchdog_grids, "n_elements",
         ("element", "integration"), reference="reissner", time_limit=0.5,
         quick=_watchdog_grids,
         doc="A run that cannot finish within its (deliberately short, 0.5 s) time limit: 4096 "
             "Omar–Shabana elements. The worker process is killed and the row says so."),
    Axis("time-steps", "Time steps from tiny to far beyond the explicit stability limit",
         "pendulum", _dyn_step_grids, "dt", ("integrator",), reference=None,
         requires=("pendulum",), time_limit=300.0, label=_step_label,
         doc="Flexible pendulum: generalized-α with dt from 1e-4 to 0.2 s, explicit and "
             "implicit scipy integrators with rtol from 1e-10 to 1e-2 (explicit ones with a "
             "2000-step budget). Error against the 32-element self-reference, so the 4-element "
             "model's discretisation error (3.8e-2) is the floor: a cell shows whether the "
             "integrator keeps it or departs from it. The scipy schemes are adaptive, so a loose "
             "tolerance cannot push an explicit one past its stability limit; on this soft "
             "pendulum that limit is mild, see the stiff axis below."),
    Axis("stiff-steps", "Time steps far beyond the explicit stability limit (stiff pendulum)",
         "pendulum", _stiff_step_grids, "dt", ("integrator",), reference="rigid-pendulum",
         requires=("pendulum",), time_limit=300.0, label=_step_label, quick=_stiff_step_quick,
         doc="The pendulum with E = 2.07e11 Pa (4 elements): its highest frequency (~1.8e5 rad/s) "
             "limits explicit schemes to steps of about 1e-5 s, so a 2000-step budget cannot "
             "reach 1 s whatever the tolerance; generalised-α (ρ∞ = 0.9) runs at up to 5000× "
             "that step; BDF at a loose tolerance blows up (its higher orders are not A-stable "
             "near the imaginary axis). Error against the rigid compound pendulum (the stiff "
             "limit; the flexible model sits 9e-4 L from it)."),
    Axis("spinning", "Spinning speed up to 10× ω_s", "spinning-beam", _spin_grids, "omega_s",
         ("integrator", "n_elements", "dt"), requires=("spinning-beam",), time_limit=300.0,
         doc="Spinning beam spun up to ω = factor × ω_s (ω_s = 4 rad/s), generalized-α "
             "(ρ∞ = 0.8), error against the steady extension (thesis Eq. 2.36). The beam itself "
             "has no critical speed (3 elements at 10× ω_s: +0.47 %). The 8-element run at "
             "10× ω_s with dt = 5 ms fails by a numerical instability of the integrator, not of "
             "the beam: every step converges quadratically (round-off floor of the residual "
             "~600× below the tolerance, one root per step from four starting guesses), yet a "
             "step-to-step oscillation in the axial modes (1.0–1.7e4 rad/s, dt·ω ≈ 50–85; 97 % "
             "of it in those modes at t = 14.45 s) grows from 5e2 to 4e5 m/s² between 13.5 and "
             "14.5 s, the known nonlinear instability of Newmark-type schemes for stiff axial "
             "modes under large rotation (0.2 rad of hub rotation per step). It needs low "
             "damping, a fine mesh and high speed together: ρ∞ ≤ 0.7 or dt = 2.5 ms (last row) "
             "removes it, as do n ≤ 4; either constraint form fails alike. Use dt ≤ 2.5 ms for "
             "n ≥ 6 at this speed (stronger damping biases the extension: +1.1 % at ρ∞ = 0.5)."),
    Axis("penalty", "Penalty stiffness 1e4 to 1e10", "belt2d", _penalty_grids, "k_p",
         ("n_elements", "dt"), reference="no-slip", requires=("belt2d",), time_limit=120.0,
         label=_belt_label("k_p", "N/m²"), quick=_penalty_quick, warn=belt_warning,
         doc=f"Belt drive (Table 3.1, 20 elements, dt = 2.5e-4 s) to t_end = {BELT_T_END:g} s, "
             "the end of the driver's ramp, where the driven pulley needs the most torque; k_p "
             "from 1e4 to 1e10 N/m² (default 1e7). Error against the no-slip drive "
             "(ω_driven / ω_driver = R1/R2), i.e. the slip over the last 0.1 s. A converged run "
             f"is flagged when its penetration at t_end exceeds {PENETRATION_WARN:g} × the "
             "belt's pre-stretch per wrap, (path − belt_length)/(2π): sunk that deep into the "
             "pulleys the belt has lost most of its pre-tension, so the drive slips; when its "
             f"slip exceeds {100 * BELT_SLIP:g} % the cell shows the slip."),
    Axis("nu_s", "ν_s (contact / friction regularisation) 1e2 to 1e7", "belt2d", _nu_s_grids,
         "nu_s", ("n_elements", "dt"), reference="no-slip", requires=("belt2d",),
         time_limit=120.0, label=_belt_label("nu_s", "kg/(m s)"), quick=_nu_s_quick,
         warn=belt_warning,
         doc=f"The same belt drive to t_end = {BELT_T_END:g} s with the friction creep-rate "
             "factor ν_s from 1e2 to 1e7 kg/(m s) (default 1e5): the friction force per unit "
             "length is ν_s × the sliding velocity up to μ × the normal force, so a small ν_s "
             "needs a large sliding velocity to carry the torque (slip), a large one makes the "
             "friction law stiff. Error and flags as on the penalty axis."),
)


QUICK_SKIPPED = "skipped in the reduced configuration (--quick)"

_LOAD_RE = re.compile(r"load factor reached ([0-9.eE+-]+)")


def diagnosis(row) -> str:
    """Short classification of a row: 'ok' or why it stopped (the run's own failure first;
    an inverted element found afterwards only where the run itself finished)."""
    status, msg = str(row.get("status")), str(row.get("message") or "")
    low = msg.lower()
    if status == "ok":
        return "ok"
    if status == "timeout":
        return "time limit exceeded"
    if status == "invalid":
        return "invalid input"
    if status == "worker-died":
        return "worker crashed"
    if "negative tangent eigenvalue" in low:
        return "unstable equilibrium"
    if "singular" in low:
        return "singular tangent"
    if "non-finite" in low or "not finite" in low or "nan" in low.split():
        return "non-finite"
    if "energy" in low and ("blow" in low or "grow" in low):
        return "energy blow-up"
    if "step size" in low and ("collapse" in low or "small" in low):
        return "step size collapse"
    if "budget" in low or "max_steps" in low or "too many steps" in low:
        return "step budget exceeded"
    m = re.search(r"diverged at step (\d+)", low)
    if m:
        return f"diverged at step {m.group(1)}"
    m = re.search(r"newton failed at t = ([0-9.eE+-]+) s", low)
    if m:
        return f"Newton failed at t = {float(m.group(1)):.4g} s"
    m = _LOAD_RE.search(msg)
    if m:
        return f"Newton diverged at load factor {float(m.group(1)):.3g}"
    m = re.search(r"from t = ([0-9.eE+-]+) s on: element \d+ of \d+ is inverted", msg)
    if m:
        return f"element inverted at t = {m.group(1)} s"
    if "is inverted" in low:
        return "inverted element"
    if status == "failed":
        return "error: " + msg[:60]
    return "not converged: " + msg[:60]


def run_axis(axis: Axis, workers=None, fresh: bool = True, log=None,
             quick: bool = False) -> pd.DataFrame:
    """Run one axis (resumable file under reports/.cache/extremes/); ``quick``: its
    reduced grids."""
    from ancf.study.sweep import run_sweep
    out = cache_root() / "extremes" / f"{axis.name}.parquet"
    if fresh:
        for p in (out, out.with_name(out.name + ".journal.jsonl")):
            if p.exists():
                p.unlink()
    grids = axis.quick() if quick else axis.grids()
    df = run_sweep(axis.scene, grids, out=out, reference=axis.reference, workers=workers,
                   time_limit=axis.time_limit, progress=False, log=log)
    df = df.copy()
    df["diagnosis"] = [diagnosis(r) for _, r in df.iterrows()]
    if axis.warn:
        df["diagnosis"] = [(axis.warn(r) or d) if d == "ok" else d
                           for d, (_, r) in zip(df["diagnosis"], df.iterrows())]
    return df
