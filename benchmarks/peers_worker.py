"""Long-lived worker of the side-by-side benchmark: one process per code.

    python -m benchmarks.peers_worker ours|exudyn

Reads one JSON request per line on stdin, ``{"case": NAME, "n": N}``, and answers one
JSON line on its original stdout (anything the codes print goes to stderr).  Cases:

* ours: ``cantilever``, ``pendulum-ga``, ``pendulum-dop853``, ``pendulum-ref`` (DOP853
  rtol 1e-10, untimed reference), ``belt`` (scene ``belt2d``; ``{"pending": ...}`` while
  that scene is not registered), ``belt3d`` (scene ``belt3d``, Model 2),
  ``three-pulleys-3d`` (scene ``belt-drive`` on ``examples/three_pulleys_3d.toml``),
  ``reissner`` (geometrically exact rod; with ``"shear_rigid": true`` the extensible
  Euler-Bernoulli elastica), ``info``;
* exudyn: ``cantilever``, ``pendulum-ga`` (also answers ``pendulum-dop853``: Exudyn runs
  its generalised-alpha there), ``pendulum-ref`` (the same with h = 1e-4, untimed
  reference), ``belt`` (:func:`benchmarks.peers_belt_exudyn.exudyn_belt`; optional
  ``t_end`` and ``step``), ``info``.

Every timed answer has ``cpu_s`` (ours: the scene's ``cpu_time_s``; Exudyn:
``time.process_time`` around its solve call), ``converged``, ``tip_x``, ``tip_y`` and
the run statistics each code reports.
"""
from __future__ import annotations

import json
import os
import platform
import sys

#: run statistics copied from our scene results when present
OUR_STATS = ("newton_iterations", "njev", "nlu", "nfev", "steps", "load_steps_taken",
             "energy_max_deviation_J")
#: scene and parameters of each of our cases (CLI strings, as `ancf run --set` takes them)
OUR_CASES = {
    "cantilever": ("cantilever", {}),
    "pendulum-ga": ("pendulum", {"integrator": "generalized-alpha", "dt": "1e-3"}),
    "pendulum-dop853": ("pendulum", {}),
    "pendulum-ref": ("pendulum", {"rtol": "1e-10"}),
    "belt": ("belt2d", {}),
    "belt3d": ("belt3d", {}),
    "three-pulleys-3d": ("belt-drive", {"file": "examples/three_pulleys_3d.toml"}),
}
SHEAR_RIGID_KS = 1e9
EXUDYN_REF_H = 1e-4


def _ours(case: str, n: int, shear_rigid: bool = False, **extra) -> dict:
    if case == "reissner":
        return _reissner(shear_rigid)
    from ancf.scenes import SCENES
    scene, params = OUR_CASES[case]
    if scene not in SCENES:
        return {"pending": f"scene {scene} not registered"}
    out, _ = SCENES[scene].execute({"n_elements": str(n), **params,
                                    **{k: str(v) for k, v in extra.items()}})
    r = out["results"] or {}
    stats = {k: r[k] for k in OUR_STATS if r.get(k) is not None}
    if scene == "belt2d" and out["converged"]:
        stats |= _belt_summary(r)
    for ours, static in (("njev", "tangent_evaluations"), ("nlu", "factorizations")):
        if r.get(static) is not None:  # the static solver's names for the same counts
            stats.setdefault(ours, r[static])
    return {"cpu_s": out["cpu_time_s"], "converged": bool(out["converged"]),
            "tip_x": r.get("tip_x"), "tip_y": r.get("tip_y"), "params": out["params"], **stats}


def _belt_summary(r: dict) -> dict:
    """Our belt2d results in the shape of :func:`benchmarks.peers_belt_exudyn.exudyn_belt`'s
    answer (angular velocities in rad/s, the mean over the last MEAN_WINDOW s)."""
    import numpy as np
    from benchmarks.peers_belt_exudyn import MEAN_WINDOW
    t, w = np.array(r["times"]), np.array(r["omega_driven"])
    return {"omega_driver": r["omega_driver"][-1], "omega_driven": r["omega_driven"][-1],
            "ratio_driven_driver": r["omega_driven"][-1] / r["omega_driver"][-1],
            "omega_driven_mean_last": float(np.mean(w[t >= t[-1] - MEAN_WINDOW - 1e-12])),
            "t_series": r["times"], "omega_driven_series": r["omega_driven"],
            "integration_cpu_s": r["integration_cpu_s"]}


def _reissner(shear_rigid: bool) -> dict:
    from analytic.reissner import MODELS, tip_position
    res = tip_position(**MODELS["model1"], **({"ks": SHEAR_RIGID_KS} if shear_rigid else {}))
    return {"tip_x": res.tip_x, "tip_y": res.tip_y, "converged": res.converged,
            "ks": SHEAR_RIGID_KS if shear_rigid else 5 / 6}


def _exudyn(case: str, n: int, **kw) -> dict:
    if case == "belt":
        from benchmarks.peers_belt_exudyn import exudyn_belt
        return exudyn_belt(n, **kw)
    from benchmarks import peers_exudyn as pe
    if case == "cantilever":
        return pe.cantilever(n)
    return pe.pendulum(n, h=EXUDYN_REF_H) if case == "pendulum-ref" else pe.pendulum(n)


def blas_info() -> dict:
    """BLAS libraries loaded in this process and the kernel they run (threadpoolctl)."""
    import numpy  # noqa: F401  (loads its BLAS)
    import scipy.linalg  # noqa: F401
    try:
        from threadpoolctl import threadpool_info
    except ImportError:
        return {"kernel": "threadpoolctl not installed: kernel not recorded"}
    libs = [{"library": os.path.basename(d.get("filepath") or ""),
             **{k: d.get(k) for k in ("internal_api", "version", "architecture", "num_threads")}}
            for d in threadpool_info()]
    return {"kernel": sorted({str(d["architecture"]) for d in libs}), "libraries": libs}


def info(side: str) -> dict:
    import numpy
    import scipy
    versions = {"python": platform.python_version(), "numpy": numpy.__version__,
                "scipy": scipy.__version__}
    if side == "exudyn":
        import exudyn
        versions["exudyn"] = exudyn.__version__
    env = {k: os.environ.get(k) for k in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS",
                                          "MKL_NUM_THREADS", "OPENBLAS_CORETYPE",
                                          "OPENBLAS_L2_SIZE")}
    return {"side": side, "pid": os.getpid(), **versions, "env": env, "blas": blas_info()}


def serve(side: str, requests, reply) -> None:
    run = _ours if side == "ours" else _exudyn
    for line in requests:
        req = json.loads(line)
        case = req.pop("case")
        try:
            ans = info(side) if case == "info" else run(case, **req)
        except Exception as exc:  # reported, the benchmark goes on with the other cases
            ans = {"error": f"{type(exc).__name__}: {exc}"}
        reply.write(json.dumps(ans) + "\n")
        reply.flush()


def main(argv=None) -> int:
    side = (sys.argv[1:] if argv is None else argv)[0]
    reply = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)            # whatever the codes print goes to stderr
    sys.stdout = sys.stderr
    serve(side, sys.stdin, reply)
    return 0


if __name__ == "__main__":
    sys.exit(main())
