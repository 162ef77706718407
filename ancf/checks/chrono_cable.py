"""Chrono's spinning cable pendulum (issue 35): our ``cable3d`` element on
:mod:`ancf.models.chrono_cable` against Chrono's stored history ``UT_ANCFBeam.txt``
(``tests/data/chrono/README.md``, section "Spinning cable pendulum").  Rows for the chapter
``chrono_elements`` and ``tests/checks/test_chrono_cable.py``.

Chrono's unit test compares the mid node's y and the tip's z after each of its first 200
steps (h = 1e-4 s) with the file within 1e-6 m; the file holds 20000 steps (2 s).  The rows:
our whole history with Chrono's parameters; the same 200 steps with g = 9.81 m/s^2 instead
of Chrono's 9.8, to show that the check sees a 0.1 % change of a constant; and what remains
of each of the file's six columns beyond its rounding (6 significant digits).
"""
from __future__ import annotations

import time

import numpy as np

from ancf.checks.chrono_matrices import load
from ancf.models import chrono_cable as cc

TOL = 1e-6            # m, utest_FEA_ANCFCable.cpp: precision
CHRONO_STEPS = 200    # its num_steps
STEPS = 20000         # rows of the file
STEP = 1e-4           # s, its DoStepDynamics(0.0001)
G_OTHER = 9.81        # m/s^2: the sensitivity row's gravity (Chrono's SetGravityY: 9.8)
HISTORY = "histories/UT_ANCFBeam"
#: the file's columns after t, as :func:`ancf.models.chrono_cable.file_columns` returns them
COLUMNS = ("node 0 slope x", "node 0 slope y", "node 0 slope z", "mid node y", "tip x",
           "tip z")
CHECKED = (3, 5)      # the columns Chrono's test compares: mid node y, tip z

NAMES = (f"Spinning cable pendulum: first {CHRONO_STEPS} steps' mid y and tip z within "
         f"{TOL:g} m of Chrono's history (its unit test)",
         f"Spinning cable pendulum: all {STEPS} steps' mid y and tip z within {TOL:g} m of "
         "Chrono's history")


def reference() -> tuple:
    """(t (20000,) s, columns (20000, 6)) of ``histories/UT_ANCFBeam.txt``."""
    data = load(HISTORY, (STEPS, 7))
    return data[:, 0], data[:, 1:]


def rounding(values: np.ndarray) -> np.ndarray:
    """Half a unit of the 6th significant digit of each printed value (m or -)."""
    mag = np.floor(np.log10(np.maximum(np.abs(values), 1e-300)))
    return 0.5 * 10.0 ** (mag - 5)


def history_rows() -> dict:
    """``t``, ``file`` and ``ours`` (20000, 6), ``g other`` (200, 6): the first 200 steps
    with g = :data:`G_OTHER`, ``cpu s`` of our 20000 steps."""
    t, file = reference()
    p = cc.Pendulum()
    start = time.process_time()
    ours = cc.file_columns(p, cc.history(p, STEP, STEPS))
    cpu = time.process_time() - start
    q = cc.Pendulum(g=G_OTHER)
    other = cc.file_columns(q, cc.history(q, STEP, CHRONO_STEPS))
    return {"t": t, "file": file, "ours": ours, "g other": other, "cpu s": cpu}


def summary(rows: dict) -> dict:
    """Largest |ours - file| (m): over the first 200 and all steps in the checked columns,
    with g = 9.81 over the first 200; per column over all steps, and beyond the file's
    rounding."""
    file, d = rows["file"], np.abs(rows["ours"] - rows["file"])
    first = np.abs(rows["g other"] - file[:CHRONO_STEPS])
    return {"first": float(d[:CHRONO_STEPS, CHECKED].max()),
            "all": float(d[:, CHECKED].max()),
            "g other": float(first[:, CHECKED].max()),
            "columns": d.max(axis=0), "beyond rounding": (d - rounding(file)).max(axis=0),
            "cpu s": rows["cpu s"]}


def checks(rows: dict | None = None) -> tuple:
    """Chrono's own check (first 200 steps) and the same bound over the whole history."""
    from ancf.checks.belt2d import Check
    s = summary(history_rows() if rows is None else rows)
    return tuple(Check(name, s[key], 0.0, s[key], TOL, "m", "largest abs(ours − file), "
                       "mid y and tip z") for name, key in zip(NAMES, ("first", "all")))
