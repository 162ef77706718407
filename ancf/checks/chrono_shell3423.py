"""Chrono's corner-loaded ANCF 3423 plate (issue 35): our ``ancf3423`` shell on
:mod:`ancf.models.plate3423` against Chrono's stored tip history ``UT_ANCFShellIso.txt``
(``tests/data/chrono/README.md``, section "ANCF 3423 shell").  Rows for the chapter
``chrono_elements`` and ``tests/checks/test_chrono_shell3423.py``.

Chrono's unit test compares the tip's z-position after each of its first 10 steps with the
file within 5e-5 m; the file holds 4000 steps (4 s), generated in 2015.  The rows: the
first 10 steps and the whole history with the consistent ANS order (``ans="paper"``, the
element as the file was made: its shape functions then ran A, B, D, C like its ANS knots),
the first 10 with Chrono's present order (``ans="chrono"``), the Newton tolerance's effect
on our history (1e-6 against 1e-12) and the static equilibrium under the full load, the
steady state the damped history must reach.
"""
from __future__ import annotations

import time

import numpy as np

from ancf.checks.chrono_matrices import load
from ancf.models import plate3423 as pm

TOL = 5e-5            # m, utest_FEA_ANCFShell_Iso.cpp line 52
CHRONO_STEPS = 10     # its num_steps (line 53)
STEPS = 4000          # rows of the file
LOOSE = 1e-6          # Newton tolerance of the sensitivity row (ours: 1e-12)
#: the stored history, below ``tests/data/chrono/`` (a subfolder: the folder's ``UT_*.txt`` are
#: element matrices)
HISTORY = "histories/UT_ANCFShellIso"
SETTLED = 3.6         # s: from here to the end the file's tip moves by less than 3e-5 m

NAMES = (f"Corner-loaded 3423 plate: first {CHRONO_STEPS} steps within {TOL:g} m of "
         "Chrono's history (its unit test)",
         f"Corner-loaded 3423 plate: all {STEPS} steps within {TOL:g} m of Chrono's history")


def reference() -> tuple:
    """(t (4000,) s, tip z (4000,) m) of ``histories/UT_ANCFShellIso.txt``."""
    data = load(HISTORY, (STEPS, 2))
    return data[:, 0], data[:, 1]


def history_rows() -> dict:
    """Our histories and what explains their distance from the file: ``t``, ``file``,
    ``paper`` (4000 steps, tol 1e-12), ``chrono`` (Chrono's ANS order, 10 steps),
    ``loose`` (tol :data:`LOOSE`), ``static`` (tip z at equilibrium, m), ``cpu s`` of the
    4000-step run, ``iterations`` of it."""
    t, file = reference()
    start = time.process_time()
    _, paper, iters = pm.history(pm.Plate(ans="paper"), steps=STEPS)
    cpu = time.process_time() - start
    _, chrono, _ = pm.history(pm.Plate(ans="chrono"), steps=CHRONO_STEPS)
    _, loose, _ = pm.history(pm.Plate(ans="paper"), steps=STEPS, tol=LOOSE)
    return {"t": t, "file": file, "paper": paper, "chrono": chrono, "loose": loose,
            "static": pm.static_tip(pm.Plate(ans="paper")), "cpu s": cpu,
            "iterations": iters}


def summary(rows: dict) -> dict:
    """The numbers the chapter quotes (m unless said): the first-10 and whole-history
    maxima of |ours - file| for both ANS orders, the first time beyond :data:`TOL` (s),
    the tolerance row's largest change, and the mean and range of the tip z after
    :data:`SETTLED` s of the file and of ours, next to the static equilibrium."""
    t, file, paper = rows["t"], rows["file"], rows["paper"]
    d = np.abs(paper - file)
    late = t >= SETTLED
    beyond = np.flatnonzero(d > TOL)
    return {"first paper": float(d[:CHRONO_STEPS].max()),
            "first chrono": float(np.abs(rows["chrono"] - file[:CHRONO_STEPS]).max()),
            "all paper": float(d.max()), "at": float(t[np.argmax(d)]),
            "first beyond": float(t[beyond[0]]) if beyond.size else None,
            "loose change": float(np.abs(rows["loose"] - paper).max()),
            "file late": float(file[late].mean()), "ours late": float(paper[late].mean()),
            "file range": float(np.ptp(file[late])), "ours range": float(np.ptp(paper[late])),
            "static": rows["static"]}


def checks(rows: dict | None = None) -> tuple:
    """Chrono's own check (first 10 steps) and the same bound over the whole history."""
    from ancf.checks.belt2d import Check
    s = summary(history_rows() if rows is None else rows)
    return (Check(NAMES[0], s["first paper"], 0.0, s["first paper"], TOL, "m",
                  "largest abs(z_tip − z_file)"),
            Check(NAMES[1], s["all paper"], 0.0, s["all paper"], TOL, "m",
                  "largest abs(z_tip − z_file)"))
