"""The cost of a run as counted work, and its calibration to seconds on this machine.

Why counted work and not seconds.  CPU times of identical runs scatter by 10-60 % within
one sweep on a shared machine and shift by factors of 2-3 between machines, while many
configurations of the small scenes cost the same within that scatter.  Any rule that
decides on measured times (the least time, or repeated timings with a statistical tie
band) flips wherever two candidates sit near the rule's threshold: fewer flips with more
repeats, never none, and never the same answer on another machine.  The counts a run
reports (Newton iterations, tangent evaluations, factorisations, force evaluations,
steps) are the same on every machine and every repeat (one BLAS thread per run), so a
cost computed from them ranks runs identically everywhere.

The model.  From a run's parameters and results, :func:`counts` takes

* ``runs``: 1 (set-up: mesh, quadrature, mass matrix, the result's post-processing);
* ``forces``, ``tangents``, ``factorizations``, ``steps``: force-only evaluations, tangent
  evaluations, factorisations and time steps, each a vectorised pass with a fixed
  interpreter and array-call overhead;
* ``kernel_points``: element-kernel work, (force evaluations x d + tangent evaluations
  x d^2) x elements x quadrature points per element, d = the element's coordinates;
* ``factor_dofs``: factorisations x global coordinates (banded sparse LU is linear in
  the size);
* ``stability_dofs``: global coordinates when the stability check of a static
  equilibrium ran (inertia by band LDL^T factorisations, linear in the size).

:data:`WEIGHTS` turns the counts into one number, ``work``, in units of one
``kernel_points`` item.  The weights are a fixed model, not a measurement: the ratios of
least-squares calibrations on the development machine (the recommend sweeps of the
cantilever, the simply supported beam and the pendulum, after the compiled core:
scatter 4 % median / 13 % at the 90th percentile for statics, 6 % / 16 % for scipy's
integrators, 12 % / 22 % for generalised-alpha), rounded to one significant digit, one
table per kind of run: static Newton (compiled kernel and band LU per iteration),
scipy's integrators (a Python call per force evaluation) and the compiled
generalised-alpha loop (modified Newton: tangents and factorisations are rare).
Where the data cannot separate two counts (a static Newton iteration is one tangent and
one factorisation), the fitted cost is split evenly.  Ranking by them is exact and
machine-independent; whether they describe *this* machine is reported by
:func:`calibrate`: seconds ~ sum_k c_k count_k fitted by non-negative least squares on
relative residuals over a sweep's rows, with the scatter of the fit and the seconds per
work unit that the weighted model implies.

Chrono's elements (``ancf3243`` ... ``ancf3843``) count their own coordinates and quadrature
points (:func:`chrono_type`; their exact rules are large: 50 points per beam, 147 per 3443
shell, 8 per ANS/EAS 3423) and their meshes' nodes (:func:`mesh_size`).

The belt scenes have no ``element`` knob: their kernel is the Dufva belt element
(:func:`belt_shape`: 12 coordinates, elastic plus contact points; the 3D belt's
plate: :func:`plate_belt_shape`, 36 coordinates, 16 elastic plus contact points).  The plate scenes
have none either: 36 coordinates and ``ng`` x ``ng`` points per element, n x n_width
elements (n x n for the square), 27 coordinates per node; the 3D beams count 9
coordinates per node.  Their weights are the static table's, not refitted.  belt2d's
generalised-alpha runs keep the ``alpha`` table: on the 38 runs of its report grid the
seconds per work unit scatter by 8 % median / 17 % at the 90th percentile (one cold
first run 1.8x), as good as a refit (NNLS: 8 % / 17 %), so no belt table was added.
(That cold first run included loading the compiled kernels from numba's cache; a run's
``cpu_time_s`` now leaves compiling and loading out, as ``compile_cpu_s``, so :func:`calibrate`
fits the solves alone.)

``ancf modes`` runs (``--quantity frequency``) count as static ones: the equilibrium's
Newton iterations (none about the reference), two tangent evaluations (stiffness and
mass) and the eigensolver's factorisations.

Missing counters degrade gracefully: static runs use ``tangent_evaluations`` and
``factorizations`` when the solver reports them, else ``newton_iterations``; a run whose
results carry none of the counters has ``work`` NaN and ranks after every counted run.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

FEATURES = ("runs", "forces", "tangents", "factorizations", "steps", "kernel_points",
            "factor_dofs", "stability_dofs")

#: work units per counted item (unit: one kernel_points item), per kind of run
WEIGHTS = {
    "static": {"runs": 4e5, "forces": 0.0, "tangents": 7e3, "factorizations": 3e3,
               "steps": 0.0, "kernel_points": 1.0, "factor_dofs": 60.0, "stability_dofs": 2e3},
    "dynamic": {"runs": 0.0, "forces": 4e3, "tangents": 5e4, "factorizations": 1e4,
                "steps": 6e3, "kernel_points": 1.0, "factor_dofs": 2e3, "stability_dofs": 0.0},
    "alpha": {"runs": 1e6, "forces": 600.0, "tangents": 0.0, "factorizations": 0.0,
              "steps": 0.0, "kernel_points": 1.0, "factor_dofs": 150.0, "stability_dofs": 0.0},
}

#: the elastic Gauss points of a drive file's belt (``belt-drive``: the file's
#: belt.elastic_points default; the scene's parameters do not carry it)
DRIVE_ELASTIC_POINTS = 5

#: integrators whose force evaluations (nfev) include the tangent evaluations (njev)
TANGENT_WITHIN_FORCE = ("generalized-alpha",)


def _num(v) -> float | None:
    """A finite count, or None (missing, None, NaN)."""
    if v is None or isinstance(v, bool):
        return None
    try:
        v = float(v)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def _first(results, *keys) -> float | None:
    for k in keys:
        v = _num(results.get(k))
        if v is not None:
            return v
    return None


def belt_shape(params) -> tuple[int, int]:
    """(coordinates, points) per Dufva belt element (the belt scenes: no ``element``
    knob): 12 coordinates (r, r_x, r_y at two nodes), elastic plus contact points."""
    from ancf.elements.dufva2d import DufvaBelt2D
    contact = _num(params.get("gauss_points")) or 0
    elastic = _num(params.get("elastic_points")) or DRIVE_ELASTIC_POINTS
    return 4 * len(DufvaBelt2D.slots), int(elastic + contact)


def plate_belt_shape(params) -> tuple[int, int]:
    """(coordinates, points) per plate of the 3D belt (belt3d): 36 coordinates, the
    4 x 4 elastic rule plus the contact points."""
    return 36, 16 + int(_num(params.get("contact_points")))


def chrono_type(params):
    """The registry's record of the run's element when it is one of Chrono's (its own
    quadrature, :meth:`points_per_element`), else None."""
    from ancf.elements.registry import ELEMENTS
    t = ELEMENTS.get(str(params.get("element")))
    return t if t is not None and hasattr(t.cls, "points_per_element") else None


def element_shape(params) -> tuple[int, int]:
    """(coordinates per element, quadrature points per element) of the run's element and
    integration scheme (or of the belt element, :func:`belt_shape`); (0, 0) for an element
    family this module does not know."""
    from ancf.models.beam3d import BUILDERS
    from ancf.elements.catalogue import ELEMENTS
    chrono = chrono_type(params)
    if chrono is not None:
        return chrono.cls.module.NDOF, chrono.cls.points_per_element()
    cls = ELEMENTS.get(str(params.get("element")))
    if cls is None and _num(params.get("contact_points")):
        return plate_belt_shape(params)
    if cls is None and str(params.get("element")) in BUILDERS:  # the 3D beams: 3-vector slots
        cls = BUILDERS[str(params.get("element"))]({"ks": 1.0, **params})[0]
        spec = cls.schemes.get(params.get("integration"), params.get("integration"))
        return 6 * len(cls.slots), quadrature_points(str(spec))
    if cls is None and _num(params.get("ng")):  # the thin plate: 36 coordinates, ng x ng points
        return 36, int(_num(params.get("ng"))) ** 2
    if cls is None:
        return belt_shape(params) if (_num(params.get("elastic_points"))
                                      or params.get("file") is not None) else (0, 0)
    spec = getattr(cls, "schemes", {}).get(params.get("integration"), params.get("integration"))
    return 4 * len(cls.slots), quadrature_points(str(spec))


def quadrature_points(spec: str) -> int:
    """Points per element of a scheme spec 'normal=2x2,shear=1xe' (terms with the same rule
    are one kernel pass; 'e', closed form across y, counts as the 3-point rule it equals)."""
    total = 0
    for rule in {part.split("=", 1)[-1].strip().lower() for part in spec.split(",")}:
        nx, _, ny = rule.partition("x")
        try:
            total += int(nx) * (3 if ny in ("e", "exact") else int(ny))
        except ValueError:
            return 1
    return max(total, 1)


def _stability_checked(results) -> bool:
    return _num(results.get("negative_tangent_eigenvalues")) is not None


def _modal(results) -> bool:
    """An ``ancf modes`` run (its stiffness and mass assembled once each: counted as two
    tangent evaluations beside the equilibrium's Newton iterations)."""
    return _num(results.get("reduced_size")) is not None


def _integrator(params) -> str | None:
    """The run's integrator; a drive file's (``file``) is generalised-alpha."""
    if params.get("integrator") is None and params.get("file") is not None:
        return "generalized-alpha"
    return params.get("integrator")


def _evaluations(params, results) -> tuple | None:
    """(kind, force evaluations, tangent evaluations, factorisations, steps) or None."""
    if _num(results.get("nfev")) is not None:
        nfev, njev = _num(results.get("nfev")), _first(results, "njev") or 0.0
        nlu, steps = _first(results, "nlu") or 0.0, _first(results, "steps") or 0.0
        if _integrator(params) in TANGENT_WITHIN_FORCE:
            return "alpha", max(nfev - njev, 0.0), njev, nlu, steps
        return "dynamic", nfev, njev, nlu, steps
    its = _first(results, "newton_iterations")
    tangents = _first(results, "tangent_evaluations")
    if tangents is None and its is not None:
        tangents = its + _stability_checked(results) + 2 * _modal(results)
    factors = _first(results, "factorizations", "newton_iterations")
    if tangents is None or factors is None:
        return None
    return "static", 0.0, tangents, factors, 0.0


def mesh_size(params, d: int) -> tuple[float, float]:
    """(elements, global coordinates) of the run's mesh: a beam's n_elements in a row, a
    plate's n x n_width (n x n for the square; 27 per node of the 36-coordinate plate), a
    Chrono shell's n x n_width with its 4 or 8 nodes per element, a Chrono beam's or
    brick's n in a row (the brick's four nodes per cross-section)."""
    n = _num(params.get("n_elements")) or 0.0
    chrono = chrono_type(params)
    per_node = chrono.cls.module.NDOF / chrono.nodes if chrono is not None else 0
    if chrono is not None and chrono.kind == "shell":
        ny = _num(params.get("n_width")) or n
        corners = (n + 1) * (ny + 1)
        mid = n * (ny + 1) + (n + 1) * ny if chrono.nodes == 8 else 0.0
        return n * ny, (corners + mid) * per_node
    if chrono is not None:
        return n, ((chrono.nodes - 1) * n + 1 if chrono.kind == "beam" else 4 * (n + 1)) * per_node
    if d == 36:  # a plate mesh: n x n_width elements (n x n for the square), 27 per node
        ny = _num(params.get("n_width")) or n
        return n * ny, (n + 1) * (ny + 1) * 27
    return n, (n + 1) * d / 2


def counts(params, results) -> dict | None:
    """The counted work of one run (:data:`FEATURES` and its ``kind``, a key of
    :data:`WEIGHTS`), or None without counters."""
    results = results or {}
    ev = _evaluations(params, results)
    if ev is None:
        return None
    kind, forces, tangents, factors, steps = ev
    d, qp = element_shape(params)
    n, size = mesh_size(params, d)
    stab = size if _stability_checked(results) else 0.0
    return {"kind": kind, "runs": 1.0, "forces": forces, "tangents": tangents, "factorizations": factors,
            "steps": steps, "kernel_points": (forces * d + tangents * d * d) * n * qp,
            "factor_dofs": factors * size, "stability_dofs": stab}


def work(c: dict | None) -> float:
    """Weighted work of ``counts`` (NaN when not counted)."""
    if c is None:
        return float("nan")
    w = WEIGHTS[c["kind"]]
    return float(sum(w[k] * c[k] for k in FEATURES))


def row_counts(row) -> dict | None:
    """``counts`` of a sweep row (parameters as columns, results as ``res_*``)."""
    results = {k[4:]: v for k, v in row.items() if isinstance(k, str) and k.startswith("res_")}
    return counts(row, results)


def with_work(df: pd.DataFrame) -> pd.DataFrame:
    """``df`` (sweep rows) with a ``work`` column and one column per counted feature."""
    rows = [row_counts(r) for _, r in df.iterrows()]
    feats = {f"count_{k}": [np.nan if c is None else c[k] for c in rows] for k in FEATURES}
    return df.assign(work=[work(c) for c in rows], **feats)


@dataclass(frozen=True)
class Calibration:
    """seconds ~ sum_k seconds_per[k] x count_k over ``rows`` runs; ``scatter_median`` and
    ``scatter_p90``: quantiles of |predicted / measured - 1|; ``seconds_per_work``: the
    median of measured seconds / work (the fixed-weight model's unit on this machine)."""

    rows: int
    seconds_per: dict
    scatter_median: float
    scatter_p90: float
    seconds_per_work: float

    def as_dict(self) -> dict:
        return {"rows": self.rows, "seconds_per": dict(self.seconds_per),
                "scatter_median": self.scatter_median, "scatter_p90": self.scatter_p90,
                "seconds_per_work": self.seconds_per_work}


def calibrate(df: pd.DataFrame) -> Calibration | None:
    """Fit seconds to the counts of ``df``'s counted, finished rows (None if fewer rows
    than features)."""
    from scipy.optimize import nnls
    if "work" not in df:
        df = with_work(df)
    cols = [f"count_{k}" for k in FEATURES]
    d = df[np.isfinite(df["work"].astype(float)) & (df["cpu_time_s"].astype(float) > 0)]
    if len(d) < len(FEATURES):
        return None
    X, y = d[cols].to_numpy(float), d["cpu_time_s"].to_numpy(float)
    c, _ = nnls(X / y[:, None], np.ones_like(y))
    dev = np.abs(X @ c / y - 1.0)
    return Calibration(int(len(d)), dict(zip(FEATURES, map(float, c))),
                       float(np.median(dev)), float(np.quantile(dev, 0.9)),
                       float(np.median(y / d["work"].to_numpy(float))))
