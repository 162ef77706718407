"""Running drives (issue 34): steady states by Newton in the axially moving description
against the march, hubloads, the running drive's modes against the moving beam, the march
and the discrete model, a Campbell diagram and each route's time:
``running_drives_chapter() -> (markdown, status)``.  Everything from
:mod:`ancf.checks.running_drives`; its rows are pinned by
``tests/checks/test_running_drives.py``.  ``--quick`` leaves the marches out.
"""
from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from ancf.checks import running_drives as rd  # noqa: E402
from ancf.checks import serpentine_creep as scc  # noqa: E402
from ancf.reports.chapter import Chapter  # noqa: E402
from ancf.reports.output import (checks_section, markdown_table, progress, save_figure,  # noqa: E402
                                 settings, timing_note, write_csv)

TIED = "`tests/checks/test_running_drives.py` (the steady states against this chapter's " \
       "stored march numbers, `data/running_drives_*.csv`)"


def _thesis_items() -> tuple:
    from ancf.checks.span_spectrum import overrides
    return tuple(o for o in overrides() if not o.startswith("run.dt"))


def _against_march(label, path, driven=None, items=()) -> tuple[list, list]:
    """A drive's steady state against its march (``items``: the file's overrides): tables,
    CSV files, rows."""
    progress(f"running drives: {label}, steady and march")
    cmp = rd.against_march(path, items)
    stem = "_".join(w.strip("()").lower() for w in label.split(" ") if w != "(creep-rate)")
    pulleys, spans = pd.DataFrame(cmp["pulleys"]), pd.DataFrame(cmp["spans"])
    write_csv(pulleys, f"running_drives_{stem}_pulleys")
    write_csv(spans, f"running_drives_{stem}_spans")
    if cmp["arms"]:
        write_csv(pd.DataFrame(cmp["arms"]), f"running_drives_{stem}_arms")
    arms = [f"- arm of `{a['name']}`: {a['steady_deg']:.4f}° steady, {a['march_deg']:.4f}° "
            f"march ({a['error_deg']:+.4f}°)" for a in cmp["arms"]]
    ratio = cmp["cpu_steady_s"] / cmp["cpu_march_s"]
    timing_note(f"{label}: time to answer",
                f"CPU of the steady state {cmp['cpu_steady_s']:.2f} s, of the whole `ancf "
                f"steady` (with the largest-load continuation) {cmp['cpu_command_s']:.2f} s, "
                f"of `ancf run` {cmp['cpu_march_s']:.1f} s: steady / march {ratio:.4f} "
                f"({'within' if ratio <= rd.TOL['cpu'] else 'above'} the issue's 1/30).\n")
    text = [f"### {label}\n", markdown_table(pulleys.rename(columns={
        "name": "pulley", "steady": "ω steady rad/s", "march": "ω march (window mean)",
        "error_pct": "difference %", "torque_steady": "torque steady N m",
        "torque_march": "torque march"}), 6), "",
            markdown_table(spans.rename(columns={"steady": "tension steady N",
                                                 "march": "march N",
                                                 "error_pct": "difference %"}), 6), "",
            *arms, ""]
    return text, rd.march_checks(label, cmp, driven)


#: the drives whose span modes meet the march's spectrum, and how their march was excited
SPECTRUM = {
    "thesis": "the thesis drive at 120 rad/s marched with a shifted driven centre "
              "(`frequencies.md`, `ancf/checks/span_spectrum.py`)",
    "thread": "THREAD with the creep-rate law, its driven centre moved 5 mm normal to the "
              "spans by 1.6 s and marched on to 3.6 s (`ancf/checks/span_spectrum.py`; each "
              "peak sought within 5 % of ours)"}


def _spectrum(drive: str, what: str, checks: list) -> list[str]:
    """One drive's span modes against its march's spectral peaks: table, CSV, check."""
    progress(f"running drives: {drive}'s span modes against the march's spectrum")
    srows = rd.spectrum_rows(drive=drive)
    checks.append(rd.spectrum_check(srows, drive))
    sdf = pd.DataFrame([{"span": r["span"], "mode": k + 1, "ours Hz": r["ours Hz"][k],
                         "ours at the march's step Hz": r["ours at the march's step Hz"][k],
                         "march peak Hz": r["march peak Hz"][k],
                         "difference %": r["error_pct"][k]}
                        for r in srows for k in range(len(r["error_pct"]))])
    write_csv(sdf, "running_drives_spectrum" + ("" if drive == "thesis" else f"_{drive}"))
    return [f"Against the march itself: {what}, its span spectrum's peaks against ours "
            "carried through the generalised-α period error at the march's step.\n",
            markdown_table(sdf, 5), ""]


def _kong_parker(checks: list) -> list[str]:
    """The thesis drive's steady state against Kong & Parker's bending belt."""
    from ancf.checks import kong_parker as kp
    progress("running drives: the thesis drive against Kong & Parker's BVP")
    table = kp.compare()
    df = pd.DataFrame([{"EI": label, "quantity": q, "ours": a, "BVP": b,
                        "difference %": 100 * e} for label, tab in table.items()
                       for q, a, b, e in tab])
    write_csv(df, "running_drives_kong_parker")
    checks.extend(kp.checks(table))
    return ["## Against Kong & Parker's steady belt with bending\n",
            "The thesis drive at 120 rad/s, at its EI and ten times it, against "
            "`analytic/belt_bending_steady.py` (the spans as steady moving elasticas meeting "
            "the rims with position, tangent and curvature 1/R; the wraps and torques the "
            "string's). Ours with the reference's linear law and a rigid-rim penalty "
            f"(`{'`, `'.join(kp.SETTINGS)}`); departure points where the centreline leaves "
            "the rim's radius, their difference over the wrap π (`ancf/checks/"
            "kong_parker.py`).\n", markdown_table(df, 6), ""]


def _span_table(label, rows) -> str:
    df = pd.DataFrame([{"drive": label, "span": r["span"], "mode": k + 1, "ours Hz": r["ours"][k],
                        "pinned beam Hz": r["pinned"][k], "clamped beam Hz": r["clamped"][k],
                        "difference %": r["error_pct"][k],
                        "end on an arm": "yes" if r["moving_end"] else "no"}
                       for r in rows for k in range(2)])
    return df


def _worst(path, items) -> float:
    """The span mode (between fixed centres) farthest from the pinned beam, signed %."""
    errs = np.concatenate([r["error_pct"] for r in rd.span_modes(path, items, 20)
                           if not r["moving_end"]])
    return float(errs[np.argmax(np.abs(errs))])


def _campbell() -> str:
    rows = rd.campbell()
    fig, ax = plt.subplots(figsize=(8, 5))
    kinds = {}
    for r in rows:
        for f, label in zip(r["frequencies_hz"], r["labels"]):
            kind = label.split(" ")[0]
            kinds.setdefault(kind, ([], []))
            kinds[kind][0].append(r["omega"] * 30 / np.pi)
            kinds[kind][1].append(f)
    for (kind, (x, y)), m in zip(sorted(kinds.items()), "osd^v<>"):
        ax.plot(x, y, m, ls="none", label=kind)
    rpm = np.array([r["omega"] for r in rows]) * 30 / np.pi
    for order in (1, 2, 3, 4):  # engine orders: crank speed / 60 x order
        ax.plot(rpm, order * rpm / 60, color="0.7", lw=0.8)
        ax.annotate(f"{order}×", (rpm[-1], order * rpm[-1] / 60), fontsize=8, color="0.5")
    ax.set(xlabel="crank speed [rpm]", ylabel="frequency [Hz]",
           title="Serpentine drive: running modes against crank speed")
    ax.grid(alpha=0.3), ax.legend(fontsize=8)
    save_figure(fig, "running_drives_campbell")
    write_csv(pd.DataFrame([{"crank rad/s": r["omega"], "mode": k + 1, "Hz": f, "label": label}
                            for r in rows for k, (f, label)
                            in enumerate(zip(r["frequencies_hz"], r["labels"]))]),
              "running_drives_campbell")
    return "![Campbell diagram](figures/running_drives_campbell.png)\n"


def _shapes() -> str:
    """The serpentine's first four running modes drawn on the drive."""
    out, res = rd.modes(rd.SERPENTINE)
    r = out["results"]
    problem, state = res.extra["problem"], res.extra["steady"]
    q = problem.drive.belt(state.x).reshape(problem.drive.mesh.n_nodes, 3, 2)[:, 0]
    fig, axs = plt.subplots(1, 4, figsize=(14, 4))
    for k, ax in enumerate(axs):
        sh = r["mode_shapes"][k]
        d = np.column_stack([sh["belt_dx_m"], sh["belt_dy_m"]]) * 0.03
        ax.plot(*np.vstack([q, q[:1]]).T, color="0.75", lw=1)
        ax.plot(*np.vstack([q + d, q[:1] + d[:1]]).T, color="C0", lw=1.4)
        for c, R in zip(problem.drive.centres, problem.drive.radii):
            ax.add_patch(plt.Circle(c, R, fill=False, color="0.4", lw=0.8))
        ax.set(aspect="equal", title=f"{r['frequencies_hz'][k]:.1f} Hz: {r['labels'][k]}")
        ax.axis("off")
    save_figure(fig, "running_drives_shapes")
    return "![Mode shapes](figures/running_drives_shapes.png)\n"


def running_drives_chapter() -> tuple[str, dict]:
    quick = settings().quick
    text = ["# Running drives: steady states and modes\n",
            "Generated by `python -m ancf.reports`; do not edit. `ancf steady belt-drive --file "
            "F` solves a drive file's steady running state by Newton in the axially moving "
            "(ALE) description of the Dufva belt (`ancf/belts/ale2d.py`, `steady2d.py`); "
            "`ancf modes belt-drive --file F --about steady` linearises it about that state "
            "(`ancf/belts/modes2d.py`: gyroscopic, damped, first-order in the pulley speeds "
            "and the transport speed). Rows and references: `ancf/checks/running_drives.py`.\n"]
    checks = []
    text.append("## Steady state against the march\n")
    if quick:
        text.append("Not computed by `--quick` (the marches); `tests/checks/"
                    "test_running_drives.py` holds the steady states to the stored numbers.\n")
    else:
        for label, path, driven, items in (
                ("THREAD (creep-rate)", rd.THREAD, "driven", ()),
                ("THREAD (creep-rate) ALE march", rd.THREAD, "driven", rd.ALE),
                ("Serpentine", rd.SERPENTINE, None, ()),
                ("Serpentine ALE march", rd.SERPENTINE, None, rd.ALE)):
            part, rows = _against_march(label, path, driven, items)
            text += part
            checks += rows
    progress("running drives: hubloads and span modes")
    text.append("## Hubloads\n")
    hub = []
    for label, path in (("THREAD (creep-rate)", rd.THREAD), ("Serpentine", rd.SERPENTINE)):
        rows = rd.hubloads(path)
        hub += [{"drive": label, "pulley": r["pulley"], "hubload x N": r["hubload_N"][0],
                 "hubload y N": r["hubload_N"][1], "spans x N": r["spans_N"][0],
                 "spans y N": r["spans_N"][1], "difference %": r["error_pct"]} for r in rows]
        checks.append(rd.hub_check(label, rows))
    text += ["The belt's resultant force on each pulley (the contact forces integrated) "
             "against its two spans' true tensions less ρAv², summed along the spans' "
             "directions.\n", markdown_table(pd.DataFrame(hub), 5), ""]
    text.append("## Span modes against the axially moving beam\n")
    spans, explained = [], {}
    drives = [("Thesis 120 rad/s", rd.THESIS, _thesis_items(), 12),
              ("THREAD (creep-rate)", rd.THREAD, (), 12)]
    if not quick:  # twice the serpentine's elements
        drives.append(("Serpentine (120 elements)", rd.SERPENTINE, rd.SERPENTINE_FINE, 20))
    for label, path, items, count in drives:
        rows = rd.span_modes(path, items, count)
        spans.append(_span_table(label, rows))
        checks.append(rd.span_check(label, rows))
        explained[checks[-1].name] = rows
    df = pd.concat(spans)
    write_csv(df, "running_drives_span_modes")
    text += ["Each span's first two modes (labelled by the share of kinetic energy across "
             "the belt) against `analytic/moving_beam.py` at the span's true tension, its "
             "mass per current length and its speed, on the laid path's tangent-to-tangent "
             "length. A span ending on the tensioner (its pulley moves with the arm) is "
             "shown, not held to the pinned beam. `--quick` leaves the serpentine out. "
             "The serpentine's spans are short against "
             "the bending layer √(EI/T), so its pinned and clamped beams differ by more than "
             "1 % (the table); its row is DIFFERS (explained) where every mode lies within 1 % "
             "of that bracket but not of the pinned beam (`bracketed` in the checks module). "
             + ("" if quick else f"Its worst span mode is {_worst(rd.SERPENTINE, ()):+.2f} % "
                "from the pinned beam on the file's 60 elements and "
                f"{_worst(rd.SERPENTINE, rd.SERPENTINE_FINE):+.2f} % on 120.")
             + "\n", markdown_table(df, 5), ""]
    if not quick:
        for drive, what in SPECTRUM.items():
            text += _spectrum(drive, what, checks)
    text += _kong_parker(checks)
    text.append("## Serpentine rotational modes\n")
    rot = rd.rotational(march_too=not quick)
    if not quick:
        checks.append(rd.rotational_check(rot))
    effect = rd.mass_effect(rot)
    creep = scc.rows()
    checks.append(scc.check(creep))
    text += ["Ours (the linearised running drive) against the sticking discrete model "
             "(`analytic/serpentine_rotational.py`: the belt stuck to every rim, massless "
             "and with the belt's ρA, eqs. 5-6) and, in a full report, the march's "
             "matrix-pencil poles (`frequencies.md`).\n",
             markdown_table(pd.DataFrame(rot), 5), "",
             "The belt's inertia alone: ours against ours with a belt 1000 times lighter, "
             "and the sticking model with its belt mass against without. The two ratios "
             "agree within 1 %: the belt's mass acts alike in both, and the rest is "
             "stiffness.\n",
             markdown_table(pd.DataFrame(effect), 5), "",
             "That stiffness is the wraps'. Under the creep-rate law the belt is held to a "
             "rim by a viscous layer (f = −ν_s v), not stuck: a tension change runs about "
             "sqrt(EA / (ω ν_s)) ≈ 2 cm into each wrap, and where the steady state "
             "saturates the law (|f| = μ p) the layer holds nothing. "
             "`analytic/serpentine_creep.py` is the discrete model with that layer: each "
             "wrap's belt solved exactly in its viscous and saturated zones (the latter "
             "read off our steady state), each span at its tangent stiffness λ dT/dλ of "
             "the element's strain law, the bearings', arm's and belt's damping, the same "
             "belt mass. Ours on 240 elements with a contact penalty of 1e9 (the model's "
             "rims are rigid and its layer resolved; `ancf/checks/serpentine_creep.py`) "
             "against it, frequencies and damping ratios:\n",
             markdown_table(pd.DataFrame(creep), 5), "", _shapes()]
    text += ["## Against Exudyn's ALE belt\n",
             "Exudyn's ALE belt (`ALECable2D`) on THREAD against our steady solve, CPU "
             "side by side in one run: `benchmarks/peers_ale.py` (`make bench`), "
             "[benchmarks/peers_ale.md](benchmarks/peers_ale.md).\n"]
    text += ["## Campbell diagram\n",
             "Not computed by `--quick`.\n" if quick else _campbell()]
    status = {c.name: rd.status(c, explained.get(c.name))
              for c in checks}
    text += checks_section(checks, status, "running_drives", TIED)
    return "\n".join(text), status


CHAPTER = Chapter(
    file="running_drives.md", order=125, generate=running_drives_chapter,
    checks=("ancf.checks.running_drives", "ancf.checks.kong_parker",
            "ancf.checks.serpentine_creep"),
    contents="Running drives: steady states by Newton in the ALE description against the "
             "march (THREAD with creep-rate, serpentine), hubloads, running modes against "
             "the moving beam, the march and the discrete model, Campbell diagram, time to "
             "answer")
