"""Runs shared between processes of one report generation: the public output dict of a
finished scene run, kept in the folder named by ``ANCF_RUN_STORE`` (unset: nothing kept).

The report generator runs chapters in parallel processes and the speed-accuracy sweeps in
worker processes; the 3D belt chapter needs the same Model 2 runs that the belt3d sweep
already made (each about a minute).  A sweep worker keeps each converged run's output
(:func:`keep`); a chapter asks for it (:func:`stored`) before running again.  The key is
the scene and its resolved parameters, so overrides spelled differently meet; the store
lives for one generation (the generator makes and removes the folder), so the sources
cannot change under it.  Outputs are pickled whole: every number comes back bit for bit.
"""
from __future__ import annotations

import hashlib
import json
import os
import pickle
from pathlib import Path

ENV = "ANCF_RUN_STORE"


#: the runs of this process by :func:`run_key` (:func:`execute_once`)
_DONE: dict = {}


def _scene(name: str):
    """The registered scene ``name`` (the registry imported on first use, not with this
    module: the report generator imports it before it needs any scene)."""
    from ancf.scenes import scene
    return scene(name)


def run_key(scene: str, overrides: dict) -> str:
    """The scene and its resolved parameters as one string: overrides spelled differently
    (1e5 and 100000.0, a default named or left out) give the same key."""
    params = _scene(scene).resolve(dict(overrides))
    return json.dumps({"scene": scene, "params": params}, sort_keys=True, default=repr)


def execute_once(scene: str, overrides: dict) -> tuple:
    """``SCENES[scene].execute(overrides)``, (public JSON dict, SceneResult), run once per
    process for each :func:`run_key`: the checks and chapters that ask for the same run
    under different spellings share it (the 120 rad/s belt once, not three times)."""
    key = run_key(scene, overrides)
    if key not in _DONE:
        _DONE[key] = _scene(scene).execute(dict(overrides))
    return _DONE[key]


def _path(scene: str, overrides: dict) -> Path | None:
    root = os.environ.get(ENV)
    if not root:
        return None
    key = run_key(scene, overrides)
    return Path(root) / f"{hashlib.sha1(key.encode()).hexdigest()}.pkl"


def keep(scene: str, overrides: dict, out: dict) -> None:
    """Keep a converged run's public output dict (nothing when no store is set)."""
    path = _path(scene, overrides)
    if path is None or not out.get("converged"):
        return
    tmp = path.with_suffix(f".{os.getpid()}.tmp")
    tmp.write_bytes(pickle.dumps(out))
    tmp.replace(path)  # atomic: a reader sees the whole file or none


def stored(scene: str, overrides: dict) -> dict | None:
    """The kept output dict of this run, or None."""
    path = _path(scene, overrides)
    return pickle.loads(path.read_bytes()) if path is not None and path.exists() else None
