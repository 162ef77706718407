"""Running drives (issue 34): the steady solve (``ancf steady belt-drive``,
:mod:`ancf.belts.steady2d`) against the Lagrangian march's steady window on the same drive
file and law, hubloads against the span tensions, the running drive's modes (``ancf modes
belt-drive --about steady``, :mod:`ancf.belts.modes2d`) against the axially moving beam
(:mod:`analytic.moving_beam`), the serpentine's rotational modes against the march's
(:mod:`ancf.checks.serpentine_modes`) and the discrete models (sticking here, creeping
wraps in :mod:`ancf.checks.serpentine_creep`), and each route's CPU time.

Drives: THREAD's benchmark with the creep-rate law (``examples/thread_creep_rate.toml``:
the steady solve takes stateless laws), the serpentine (``examples/serpentine.toml``),
the thesis drive at 120 rad/s (:mod:`ancf.checks.span_spectrum`'s overrides).

Span modes.  A span's modes are those labelled with it; the reference is the pinned moving
beam on the laid path's tangent-to-tangent length at the true tension on rho A / lambda
(:mod:`ancf.checks.span_spectrum`, Eq. (1): T = N lambda of the element's Green force N over
the span's middle third, N itself under the engineering strain,
:func:`ancf.checks.thread.true_force`; lambda = |r_x| the span's material speed over the
transport speed) and the span's material speed.
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from ancf.checks.belt2d import Check
from ancf.common.paths import REPO

EXAMPLES = REPO / "examples"
THREAD = EXAMPLES / "thread_creep_rate.toml"
SERPENTINE = EXAMPLES / "serpentine.toml"
THESIS = EXAMPLES / "thesis_table_3_1.toml"
#: the serpentine's span modes on a mesh of twice the file's elements (3 per 10 cm of span)
SERPENTINE_FINE = ("belt.n_elements=120",)
#: the march in the axially moving description (``belt.formulation``, ancf.belts.ale_march2d)
ALE = ('belt.formulation="ale"',)
#: the issue's acceptance: %, %, degree, % (hubloads), % (span modes), ratio (CPU: the
#: timing page's, and benchmarks/running_drives.py's)
TOL = {"spans": 0.5, "speeds": 0.1, "pulleys": 0.5, "arm": 0.05, "hub": 1.0, "modes": 1.0,
       "rotational": 1.0, "cpu": 1 / 30}
#: the serpentine's rotational modes: our label -> the discrete model's
ROTATIONAL = {"arm tensioner": "psi", "pulley alternator": "theta_alternator",
              "pulley pump": "theta_pump"}
#: the belt's density factor of :func:`mass_effect` (a belt nearly without mass)
LIGHT = 1e-3
#: crank speeds of the serpentine's Campbell diagram, rad/s
CAMPBELL = (10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0)


def _sets(items) -> str:
    return "; ".join(items)


@lru_cache(maxsize=None)
def steady(path, items: tuple = (), max_loads: bool = True) -> tuple:
    """(JSON, SceneResult) of ``ancf steady belt-drive --file path --set items``
    (``max_loads`` False: without the driven pulleys' largest loads, the steady state
    alone)."""
    from dataclasses import replace
    from functools import partial

    from ancf.scenes.belt_steady import SCENE, run
    scene = SCENE if max_loads else replace(SCENE, run=partial(run, max_loads=False))
    out, res = scene.execute({"file": str(path), "set": _sets(items)})
    if not out["converged"]:
        raise RuntimeError(f"steady {path.name}: {out['message']}")
    return out, res


@lru_cache(maxsize=None)
def modes(path, items: tuple = (), count: int = 12) -> tuple:
    """(JSON, SceneResult) of ``ancf modes belt-drive --about steady --count count``."""
    from ancf.scenes.belt_modes import execute
    out, res = execute({"file": str(path), "set": _sets(items)}, count)
    if not out["converged"]:
        raise RuntimeError(f"modes {path.name}: {out['message']}")
    return out, res


@lru_cache(maxsize=None)
def march(path, items: tuple = ()) -> dict:
    """The JSON of ``ancf run belt-drive`` on the same file."""
    from ancf.scenes import SCENES
    out, _ = SCENES["belt-drive"].execute({"file": str(path), "set": _sets(items)})
    if not out["converged"]:
        raise RuntimeError(f"march {path.name}: {out['message']}")
    return out


def against_march(path, items: tuple = ()) -> dict:
    """Steady against march: per pulley speed (%), per span tension (%), per arm angle
    (degree), the CPU times (s) of the march, of the steady state alone and of the whole
    ``ancf steady`` (with the largest loads)."""
    s, m = steady(path, items)[0], march(path, items)
    alone = steady(path, items, False)[0]
    pct = lambda a, b: 100 * (a / b - 1) if b else 0.0  # noqa: E731
    pulleys = [{"name": a["name"], "steady": a["omega"], "march": b["omega_mean"],
                "error_pct": pct(a["omega"], b["omega_mean"]),
                "torque_steady": a["torque_Nm"], "torque_march": b["torque_mean_Nm"]}
               for a, b in zip(s["results"]["pulleys"], m["results"]["pulleys"])]
    spans = [{"span": f"{a['from']} → {a['to']}", "steady": a["tension_mean_N"],
              "march": b["tension_mean_N"], "error_pct": pct(a["tension_mean_N"],
                                                            b["tension_mean_N"])}
             for a, b in zip(s["results"]["spans"], m["results"]["spans"])]
    arms = [{"name": a["name"], "steady_deg": math.degrees(a["angle_rad"]),
             "march_deg": math.degrees(b["angle_mean_rad"]),
             "error_deg": math.degrees(a["angle_rad"] - b["angle_mean_rad"])}
            for a, b in zip(s["results"]["arms"], m["results"]["arms"])]
    return {"pulleys": pulleys, "spans": spans, "arms": arms, "cpu_steady_s": alone["cpu_time_s"],
            "cpu_command_s": s["cpu_time_s"], "cpu_march_s": m["cpu_time_s"]}


def march_checks(label: str, cmp: dict, driven: str | None = None) -> list[Check]:
    """The acceptance rows of one drive: span tensions (%), free pulleys' speeds (% or, for
    ``driven``, the driven pulley's against 0.1 %), arms (degree).  The CPU ratio is the
    timing page's (it varies per run)."""
    spans = max(abs(r["error_pct"]) for r in cmp["spans"])
    rows = [Check(f"{label}: steady span tensions within 0.5 % of the march", spans, 0.0,
                  spans, TOL["spans"], "%", "largest abs(steady / march − 1) over the spans")]
    if driven is not None:
        e = next(abs(r["error_pct"]) for r in cmp["pulleys"] if r["name"] == driven)
        rows.append(Check(f"{label}: steady driven ω within 0.1 % of the march", e, 0.0, e,
                          TOL["speeds"], "%", "abs(steady / march − 1)"))
    else:
        e = max(abs(r["error_pct"]) for r in cmp["pulleys"])
        rows.append(Check(f"{label}: steady pulley speeds within 0.5 % of the march", e, 0.0,
                          e, TOL["pulleys"], "%", "largest abs(steady / march − 1)"))
    for a in cmp["arms"]:
        d = abs(a["error_deg"])
        rows.append(Check(f"{label}: arm of {a['name']} within 0.05° of the march", d, 0.0, d,
                          TOL["arm"], "deg", "abs(steady − march mean)"))
    return rows


def hubloads(path, items: tuple = ()) -> list[dict]:
    """Per pulley the hubload against the two spans' tensions summed as vectors: the true
    force N |r_x| less rho A v^2 (the wrap's centrifugal part) along each span's direction
    (the belt's points at its thirds); % of the hubload's magnitude."""
    out, res = steady(path, items, False)
    r, desc = out["results"], res.extra["description"]
    xy = np.column_stack([r["belt_x_m"], r["belt_y_m"]])
    b = desc.belt
    rhoA, spans, N = b["rho"] * b["b"] * b["h"], r["spans"], len(r["pulleys"])
    ends = [desc.path(np.array([a, c]))[0] for _, a, c in desc.path.pieces()[1::2]]
    rows = []
    for k, p in enumerate(r["pulleys"]):
        total = np.zeros(2)
        for j, sign in ((k, 1.0), ((k - 1) % N, -1.0)):
            a, c = ends[j]
            near = [xy[np.argmin(np.linalg.norm(xy - (a + f * (c - a)), axis=1))]
                    for f in (1 / 3, 2 / 3)]
            e = (near[1] - near[0]) / np.linalg.norm(near[1] - near[0])
            v = spans[j]["speed_m_s"]
            total += sign * e * (_true(spans[j], desc, r) - rhoA * v * v)
        hub = np.array(p["hubload_N"])
        rows.append({"pulley": p["name"], "hubload_N": hub, "spans_N": total,
                     "error_pct": 100 * np.linalg.norm(hub - total) / np.linalg.norm(hub)})
    return rows


def _true(span: dict, desc, results: dict) -> float:
    """A span's true tension (N): :func:`ancf.checks.thread.true_force` of its N, the stretch
    |r_x| its speed over the transport speed."""
    lam = span["speed_m_s"] / results["transport_speed_m_s"]
    return float(span["tension_mean_N"] * (lam if desc.belt["axial_strain"] == "green" else 1.0))


def span_modes(path, items: tuple = (), count: int = 12) -> list[dict]:
    """Per free span whose two first modes are among the ``count`` lowest: their
    frequencies (Hz) against the pinned and the clamped moving beam (module docstring);
    ``moving_end`` whether an end is a tensioner's pulley (its centre moves with the arm)."""
    from analytic import moving_beam
    out, res = modes(path, items, count)
    r, desc = out["results"], res.extra["description"]
    b = desc.belt
    rhoA0 = b["rho"] * b["b"] * b["h"]
    EI = res.extra["problem"].drive.spec.E * b["alpha2"] * b["b"] * b["h"] ** 3 / 12
    ends = [desc.path(np.array([a, c]))[0] for _, a, c in desc.path.pieces()[1::2]]
    rows = []
    for span, (a, c) in zip(r["steady"]["spans"], ends):
        label = f"span {span['from']}-{span['to']}"
        ours = [f for f, l in zip(r["frequencies_hz"], r["labels"]) if l == label][:2]
        if len(ours) < 2:
            continue
        lam = span["speed_m_s"] / r["steady"]["transport_speed_m_s"]
        L = float(np.linalg.norm(c - a))
        args = (_true(span, desc, r["steady"]), rhoA0 / lam, span["speed_m_s"], L, EI, 2)
        pinned = moving_beam.span_frequencies(*args, "pinned")
        clamped = moving_beam.span_frequencies(*args, "clamped")
        arms = {p.name for p in desc.pulleys if p.law == "tensioner"}
        rows.append({"span": f"{span['from']} → {span['to']}", "ours": np.array(ours),
                     "moving_end": bool(arms & {span["from"], span["to"]}),
                     "pinned": pinned, "clamped": clamped,
                     "error_pct": 100 * (np.array(ours) / pinned - 1)})
    return rows


def rotational(march_too: bool = True) -> list[dict]:
    """The serpentine's rotational modes: ours against the discrete model and (``march_too``)
    the march's matrix pencil (:func:`ancf.checks.serpentine_modes.compare`)."""
    from ancf.checks import serpentine_modes as sm
    out, res = modes(SERPENTINE)
    r = out["results"]
    inp = sm.inputs(res.extra["description"])
    ref, heavy = sm.discrete(inp), sm.discrete(inp, belt_mass=True)
    measured = {m["label"]: m for m in sm.compare()["modes"]} if march_too else {}
    rows = []
    for ours, theirs in ROTATIONAL.items():
        k = r["labels"].index(ours)
        f_ref = float(ref["frequencies_hz"][ref["labels"].index(theirs)])
        row = {"mode": ours, "ours": r["frequencies_hz"][k], "zeta": r["damping_ratios"][k],
               "discrete": f_ref, "error_discrete_pct": 100 * (r["frequencies_hz"][k] / f_ref - 1)}
        f_heavy = float(heavy["frequencies_hz"][heavy["labels"].index(theirs)])
        row.update(discrete_belt_mass=f_heavy,
                   error_belt_mass_pct=100 * (r["frequencies_hz"][k] / f_heavy - 1))
        if theirs in measured:
            m = measured[theirs]
            row.update(march=m["f"], march_zeta=m["zeta"],
                       error_march_pct=100 * (r["frequencies_hz"][k] / m["f"] - 1))
        rows.append(row)
    return rows


def campbell(speeds=CAMPBELL, count: int = 8) -> list[dict]:
    """The serpentine's modes at each crank speed (rad/s): frequencies and labels."""
    rows = []
    for w in speeds:
        out, _ = modes(SERPENTINE, (f"pulleys.crank.omega_final={w!r}",), count)
        rows.append({"omega": w, "frequencies_hz": out["results"]["frequencies_hz"],
                     "labels": out["results"]["labels"]})
    return rows


def span_check(label: str, rows: list[dict]) -> Check:
    """The worst span mode of ``rows`` (those between fixed centres) against the pinned beam."""
    worst = max(float(np.abs(r["error_pct"]).max()) for r in rows if not r["moving_end"])
    return Check(f"{label}: span modes 1-2 within 1 % of the moving beam", worst, 0.0, worst,
                 TOL["modes"], "%", "largest abs(f / f_pinned − 1) over the spans between "
                 "fixed centres and their first two modes")


def hub_check(label: str, rows: list[dict]) -> Check:
    worst = max(r["error_pct"] for r in rows)
    return Check(f"{label}: hubloads within 1 % of the span tensions summed", worst, 0.0, worst,
                 TOL["hub"], "%", "largest abs(hub − Σ (T − ρAv²) e) / abs(hub) over the pulleys")


def rotational_check(rows: list[dict]) -> Check:
    worst = max(abs(r["error_march_pct"]) for r in rows)
    return Check("Serpentine: rotational modes within 1 % of the march's", worst, 0.0, worst,
                 TOL["rotational"], "%", "largest abs(f / f_march − 1): arm, alternator, pump "
                 "(the march's matrix pencil, ancf/checks/serpentine_modes.py)")


def mass_effect(rows: list[dict]) -> list[dict]:
    """The belt's inertia alone: per rotational mode, ours over ours with the belt
    :data:`LIGHT` times as dense, against the discrete model with its belt mass over the
    massless one (the same ratio if both carry the belt's inertia alike)."""
    desc = modes(SERPENTINE)[1].extra["description"]
    light = modes(SERPENTINE, (f"belt.rho={desc.belt['rho'] * LIGHT!r}",))[0]["results"]
    out = []
    for r in rows:
        f = light["frequencies_hz"][light["labels"].index(r["mode"])]
        ours, theirs = r["ours"] / f, r["discrete_belt_mass"] / r["discrete"]
        out.append({"mode": r["mode"], "ours / light belt": ours,
                    "discrete with / without belt mass": theirs,
                    "difference %": 100 * (ours / theirs - 1)})
    return out


def bracketed(rows: list[dict]) -> bool:
    """Every span mode between fixed centres within 1 % of the bracket [pinned, clamped]
    (a short span's ends are neither: its bending layer sqrt(EI / T) is a percent or more of
    its length, and the two beams differ by as much)."""
    return all(np.all((r["ours"] >= (1 - TOL["modes"] / 100) * r["pinned"])
                      & (r["ours"] <= (1 + TOL["modes"] / 100) * r["clamped"]))
               for r in rows if not r["moving_end"])


def status(check: Check, rows: list[dict] | None = None) -> str:
    """PASS, DIFFERS (explained) for span modes outside 1 % of the pinned beam but inside
    the pinned-clamped bracket (:func:`bracketed`), else FAIL."""
    if check.passed:
        return "PASS"
    return "DIFFERS (explained)" if rows is not None and bracketed(rows) else "FAIL"


def spectrum_rows(march_peaks: dict | None = None, drive: str = "thesis") -> list[dict]:
    """A drive's span modes (first two per span) against the march's spectral peaks, ours
    carried through the march's period error (:func:`ancf.checks.span_spectrum.
    alpha_frequency` at its step and rho_inf).  ``drive`` "thesis": the thesis drive at
    120 rad/s (peaks of :func:`ancf.checks.span_spectrum.spans`); "thread": THREAD with the
    creep-rate law and its driven centre shifted (:func:`ancf.checks.span_spectrum.
    thread_run`, each peak sought within 5 % of ours).  ``march_peaks`` {span "A -> B":
    peaks Hz} in place of the march."""
    from ancf.checks import span_spectrum as ss
    path, items, dt = SPECTRUM_DRIVES[drive]()
    run = modes(path, items)[1].extra["description"].run
    rows = span_modes(path, items)
    mapped = {r["span"].replace(" → ", " -> "):
              np.array([ss.alpha_frequency(f, dt or run["dt"], run["rho_inf"])
                        for f in r["ours"]])
              for r in rows}
    peaks = march_peaks or _march_peaks(drive, mapped)
    out = []
    for r in rows:
        key = r["span"].replace(" → ", " -> ")
        got = np.asarray(peaks[key], dtype=float)
        k = min(got.size, mapped[key].size)
        out.append({"span": r["span"], "ours Hz": r["ours"][:k],
                    "ours at the march's step Hz": mapped[key][:k], "march peak Hz": got[:k],
                    "error_pct": 100 * (mapped[key][:k] / got[:k] - 1)})
    return out


def _march_peaks(drive: str, mapped: dict) -> dict:
    from ancf.checks import span_spectrum as ss
    if drive == "thesis":
        return {k: v["peaks"] for k, v in ss.spans()["spans"].items()}
    bands = {k: [(0.95 * f, 1.05 * f) for f in v] for k, v in mapped.items()}
    return ss.march_peaks(ss.thread_run()[1], ss.THREAD_FROM, bands)


def _thesis_spectrum() -> tuple:
    from ancf.checks.span_spectrum import DT, overrides
    return THESIS, tuple(o for o in overrides() if not o.startswith("run.dt")), DT


def _thread_spectrum() -> tuple:
    from ancf.checks.span_spectrum import THREAD_FILE, thread_overrides
    return (THREAD_FILE, tuple(o for o in thread_overrides() if not o.startswith("run.")),
            None)


#: the drives whose span modes meet the march's spectrum: name -> (file, overrides, the
#: march's step s or None: the file's)
SPECTRUM_DRIVES = {"thesis": _thesis_spectrum, "thread": _thread_spectrum}
#: their labels in the checks
SPECTRUM_LABELS = {"thesis": "Thesis 120 rad/s", "thread": "THREAD (creep-rate)"}


def spectrum_check(rows: list[dict], drive: str = "thesis") -> Check:
    worst = max(float(np.nanmax(np.abs(r["error_pct"]))) for r in rows)
    return Check(f"{SPECTRUM_LABELS[drive]}: span modes 1-2 within 1 % of the march's "
                 "spectrum", worst,
                 0.0, worst, TOL["modes"], "%", "largest abs(f_h / peak − 1), f_h ours through "
                 "the march's period error (ancf/checks/span_spectrum.py)")
