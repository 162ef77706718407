"""Python API: the command line's runs as functions returning result objects.

``import ancf`` is cheap; ``ancf.run``, ``ancf.analytic``, ``ancf.modes``, ``ancf.scenes``,
``ancf.sweep``, ``ancf.recommend``, ``ancf.Result`` and ``ancf.InputError`` load this module
on first use.

A scene run (``ancf run SCENE``) with keyword parameters, which are checked as
``--set`` values are (bad input raises :class:`InputError` with the message the command
line prints after ``error:``):

>>> import ancf
>>> beam = ancf.run("cantilever", n_elements=4)
>>> beam.converged, beam.params["n_elements"], beam.params["h"]
(True, 4, 0.1)
>>> beam  # doctest: +ELLIPSIS
<ancf.Result run cantilever: converged (...); results: newton_iterations, ..., tip_x, tip_y, ...>
>>> sorted(k for k in ("tip_x", "tip_y") if k in beam.results)
['tip_x', 'tip_y']

The mesh and the deformed state: node positions of the reference and of the final
state (n_nodes, dim), and the global coordinate vectors (positions and slopes):

>>> beam.reference_nodes.shape, beam.nodes.shape
((5, 2), (5, 2))
>>> beam.reference_nodes[-1].tolist()  # the free end of the 2 m beam, unloaded
[2.0, 0.0]
>>> bool(beam.nodes[-1, 1] == beam.results["tip_y"] and beam.q.shape == beam.q0.shape)
True

``to_json()`` is what ``ancf run cantilever --set n_elements=4 --json`` prints (the same
keys, values and order; only ``cpu_time_s`` and ``compile_cpu_s`` differ from run to run):

>>> import json
>>> list(json.loads(beam.to_json()))
['scene', 'params', 'converged', 'message', 'results', 'cpu_time_s', 'compile_cpu_s', 'warnings']

The analytic references (``ancf analytic NAME``) the same way; Model 2 of the cantilever
against the geometrically exact rod:

>>> rod = ancf.analytic("reissner", h=0.5, nu=0)
>>> fine = ancf.run("cantilever", h=0.5, nu=0, n_elements=16)
>>> bool(abs(fine.results["tip_y"] / rod.results["tip_y"] - 1) < 1e-2)
True

Dynamic scenes give their time histories: ``times``, every sampled result as an array
(``series``) and the node positions at every sample (``node_history``, (nt, n_nodes, dim)):

>>> swing = ancf.run("pendulum", t_end=0.1, output_dt=0.05)
>>> swing.times.tolist()
[0.0, 0.05, 0.1]
>>> swing.node_history.shape
(3, 5, 2)
>>> bool((swing.series["tip_y"] == swing.node_history[:, -1, 1]).all())
True

Bad input:

>>> ancf.run("cantilever", n_elements=0)
Traceback (most recent call last):
...
ancf.common.params.InputError: n_elements = 0 is out of range; allowed: an integer in [1, 4096]
>>> ancf.run("cantileverr")
Traceback (most recent call last):
...
ancf.common.params.InputError: run: unknown name 'cantileverr'; allowed: simply-supported, cantilever, axial-bar, pendulum, spinning-beam, belt-free-static, belt2d, plate-square, plate-strip, beam3d-cantilever, belt3d, princeton-beam, beam3d-bending, belt-drive
"""
from __future__ import annotations

import json
import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

import ancf.scenes  # noqa: F401 - cheap (loads no scene); makes ``ancf.scenes`` the callable package
from ancf.common.inputs import flag, is_boolean, mapping, merged, number, path, text
from ancf.common.params import InputError
from ancf.common.strict_json import dumps

__all__ = ["InputError", "Result", "analytic", "modes", "recommend", "run", "scenes", "sweep"]


@dataclass(kw_only=True)
class Result:
    """The outcome of one run: the public JSON's fields as attributes, the scene's model in
    ``extra`` and the arrays a user wants as properties (``None`` where the run has none:
    an analytic reference has no mesh, a static run no time history).

    ``command`` is ``"run"``, ``"analytic"`` or ``"modes"``, ``scene`` the name.
    """

    command: str
    scene: str
    params: dict
    converged: bool
    message: str
    results: dict
    cpu_time_s: float
    warnings: list
    compile_cpu_s: float = 0.0
    extra: dict = field(default_factory=dict, repr=False)
    _json: dict = field(default_factory=dict, repr=False)

    def __repr__(self) -> str:  # short: the results may hold long time histories
        return (f"<ancf.Result {self.command} {self.scene}: "
                f"{'converged' if self.converged else 'NOT CONVERGED'} ({self.message}); "
                f"results: {', '.join(self.results)}>")

    # --- the JSON -------------------------------------------------------------------
    def to_json(self, **kw) -> str:
        """The JSON object ``ancf run|analytic NAME ... --json`` prints (strict: a value
        that is not a finite number is ``null``); keywords go to ``json.dumps``."""
        return dumps(self._json, **kw)

    def to_dict(self) -> dict:
        """:meth:`to_json` parsed back: plain Python values, ``None`` for non-finite."""
        return json.loads(self.to_json())

    # --- arrays ---------------------------------------------------------------------
    def _geometry(self) -> bool:
        from ancf.scenes.frames import has_geometry
        return has_geometry(self.extra)

    def _states(self):
        from ancf.scenes.frames import states
        return states(self.extra) if self._geometry() else (None, None, None)

    @property
    def q0(self) -> np.ndarray | None:
        """Reference global coordinates (positions and slopes of every node)."""
        return None if not self._geometry() else np.asarray(self._states()[2], float)

    @property
    def q(self) -> np.ndarray | None:
        """Final global coordinates (the belt drives: the belt's, without the pulley)."""
        if not self._geometry():
            return None
        qs = self._states()[1]
        return np.asarray(qs[-1], float) if len(qs) else None

    def _nodes(self, q):
        from ancf.scenes.frames import node_positions
        return None if q is None else node_positions(self.extra, q)

    @property
    def reference_nodes(self) -> np.ndarray | None:
        """The mesh: reference node positions (n_nodes, dim), m."""
        return self._nodes(self.q0)

    @property
    def nodes(self) -> np.ndarray | None:
        """Final node positions (n_nodes, dim), m."""
        return self._nodes(self.q)

    @property
    def times(self) -> np.ndarray | None:
        """Output times of a dynamic run (s), None for a static one."""
        t = self.results.get("times")
        return None if t is None else np.array([np.nan if v is None else v for v in t], float)

    @property
    def series(self) -> dict:
        """Every time history of the results as an array (``times`` included), {} when
        the run has none."""
        t = self.results.get("times")
        if not isinstance(t, list):
            return {}
        return {k: np.array([np.nan if x is None else x for x in v], float)
                for k, v in self.results.items()
                if isinstance(v, list) and len(v) == len(t)
                and all(x is None or isinstance(x, (int, float)) for x in v)}

    @property
    def node_history(self) -> np.ndarray | None:
        """Node positions at every output time (nt, n_nodes, dim) of a dynamic run, m."""
        if not self._geometry():
            return None
        times, qs, _ = self._states()
        if times is None:
            return None
        return np.stack([self._nodes(q) for q in qs]) if len(qs) else None

    # --- ParaView -------------------------------------------------------------------
    def frames(self, per_element: int = 8) -> list:
        """The deformed mesh per output step (:func:`ancf.scenes.frames.frames`)."""
        from ancf.scenes.frames import frames
        return frames(self.scene, self.extra, per_element)

    def write_vtk(self, directory, per_element: int = 8) -> Path:
        """Write the run as a ParaView time series, ``directory/SCENE.pvd`` plus one
        ``.vtu`` per output step (what ``ancf run SCENE --vtk DIR`` writes); returns the
        ``.pvd`` path.  Raises InputError for a result without a mesh.

        >>> import ancf, pathlib, tempfile
        >>> with tempfile.TemporaryDirectory() as d:
        ...     pvd = ancf.run("cantilever", n_elements=2).write_vtk(d)
        ...     sorted(p.name for p in pathlib.Path(d).iterdir()), pvd.name
        (['cantilever.pvd', 'cantilever_00000.vtu'], 'cantilever.pvd')
        """
        from ancf.scenes.vtk import check_directory, write_run
        check_directory(directory)
        return write_run(self.scene, self.extra, directory, per_element)[0]

    def write_gif(self, path, *, title: str = "") -> Path:
        """Write a belt drive's run (``belt2d``, ``belt3d``, ``belt-drive``) as an animated
        GIF at ``path`` (what ``ancf run SCENE --gif PATH`` writes: the belt coloured by
        its axial force in N, the pulleys named, one frame per output step from t = 0, at
        most 80); returns the path.  Raises InputError for another scene or a bad path.

        Parameters
        ----------
        path : str or Path
            The file to write, ending in ``.gif``; its folder is created if missing.
        title : str
            The title over the animation (default ``ancf run SCENE``).

        Returns
        -------
        Path
            ``path``.
        """
        from ancf.reports.animations import animate
        from ancf.scenes.vtk import check_gif
        gif = check_gif(self.scene, path)
        return animate(self.scene, gif, self.extra, title=title or f"ancf run {self.scene}").path


def _result(command: str, scene: str, out: dict, res) -> Result:
    """The :class:`Result` of a run's public JSON ``out`` and its scene result ``res``."""
    return Result(command=command, scene=scene, params=out["params"],
                  converged=out["converged"], message=out["message"], results=out["results"],
                  cpu_time_s=out["cpu_time_s"], warnings=out["warnings"],
                  compile_cpu_s=out.get("compile_cpu_s", 0.0), extra=res.extra, _json=out)


def _as_set(value):
    """A number as the text ``--set`` would carry (``repr``: exact for floats), so that the
    parsed values and the messages of bad ones are the command line's; others unchanged."""
    if isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool):
        return repr(float(value)) if isinstance(value, (float, np.floating)) else str(int(value))
    return value


def _sets(overrides, params: dict) -> dict:
    """The parameters of a call: the positional dict ``overrides`` and the keywords, as the
    texts ``--set`` would carry; a name given in both with different values is refused
    (as the command line refuses two different ``--set`` of one name)."""
    both = merged(mapping("overrides", overrides), params, ("overrides", "a keyword"))
    return {k: _as_set(v) for k, v in both.items()}


def _known(command: str, name, registry) -> str:
    """``name`` if it names an entry of ``registry`` (any other type or name: InputError)."""
    if not isinstance(name, str) or name not in registry:
        raise InputError(f"{command}: unknown name {name!r}; allowed: {', '.join(registry)}")
    return name


def _execute(command: str, name: str, overrides, params: dict, vtk=None) -> Result:
    from ancf.scenes import SCENES
    if command == "run":
        registry = SCENES
    else:
        from ancf.scenes.analytic import REFERENCES as registry
    sc = registry[_known(command, name, registry)]
    sets = _sets(overrides, params)
    if vtk is not None:  # bad input first, then the directory, then the run
        from ancf.scenes.vtk import check_directory
        path("vtk", vtk)
        sc.resolve(sets)
        check_directory(vtk)
    out, res = sc.execute(sets)
    result = _result(command, name, out, res)
    if vtk is not None:
        result.write_vtk(vtk)
    return result


def run(scene: str, overrides: dict | None = None, /, *, vtk=None, **params) -> Result:
    """Run a scene, as ``ancf run SCENE --set k=v ...``: parameters as keywords (or a
    dict; values as Python values or as the strings ``--set`` takes).  ``vtk``: a
    directory to write the ParaView series into (checked before the run starts).

    >>> import ancf
    >>> r = ancf.run("axial-bar", {"n_elements": 2})
    >>> r.converged, r.scene, r.command
    (True, 'axial-bar', 'run')
    """
    return _execute("run", scene, overrides, params, vtk)


def modes(scene: str, overrides: dict | None = None, /, *, count=None, about="reference",
          **params) -> Result:
    """Natural frequencies and mode shapes of a static scene, as ``ancf modes SCENE --set
    k=v ... --count K --about STATE``: ``count`` modes (default 6, or the reduced size - 1),
    the tangent stiffness at the ``"reference"`` state or at the static ``"equilibrium"``.
    ``results["frequencies_hz"]`` ascending; ``extra["vectors"]`` the global mode vectors
    (n_dofs, count); ``q`` the state vibrated about.

    >>> import ancf
    >>> m = ancf.modes("cantilever", n_elements=4, count=2)
    >>> m.command, m.results["about"], len(m.results["frequencies_hz"])
    ('modes', 'reference', 2)
    >>> m.params["rho"], m.extra["vectors"].shape
    (7850.0, (20, 2))
    """
    from ancf.scenes.modes import execute
    if not isinstance(scene, str):
        raise InputError(f"modes: unknown name {scene!r}; allowed: a scene name (see "
                         "ancf.scenes())")
    if count is not None and (is_boolean(count) or not isinstance(count, (int, str, np.integer))):
        raise InputError(f"count: {count!r} is not valid; allowed: an integer >= 1 (below "
                         "the reduced size of the model), or None")
    text("about", about, "one of reference, equilibrium")
    out, res = execute(scene, _sets(overrides, params), count, about)
    return _result("modes", scene, out, res)


def analytic(name: str, overrides: dict | None = None, /, **params) -> Result:
    """Evaluate an analytic reference, as ``ancf analytic NAME --set k=v ...``.

    >>> import ancf
    >>> t = ancf.analytic("timoshenko", F=-2000.0)
    >>> t.params["F"], t.results["mid_deflection_m"] < 0
    (-2000.0, True)
    """
    return _execute("analytic", name, overrides, params)


def scenes() -> list[dict]:
    """Every scene (``command`` ``"run"``) and analytic reference (``"analytic"``) with its
    one-line description and parameters: ``{name: {default, unit, allowed, doc}}``
    (``default`` is None where it depends on other parameters), as ``ancf scenes`` lists.
    ``ancf.scenes`` is also the package of the scenes, made callable: ``ancf.scenes()`` and
    ``ancf.api.scenes()`` are the same list.

    >>> import ancf
    >>> info = {s["name"]: s for s in ancf.scenes()}
    >>> info["cantilever"]["command"], info["reissner"]["command"]
    ('run', 'analytic')
    >>> info["cantilever"]["params"]["n_elements"]["default"]
    8
    >>> info["cantilever"]["params"]["n_elements"]["allowed"]
    'an integer in [1, 4096]'
    """
    from ancf.scenes import catalogue
    return catalogue()


GRID_ALLOWED = ("a dict {parameter: value or [values]}, a list of such dicts, or None (the "
                "scene's grid)")


def _grid(scene: str, grid, quantity: str = "results") -> list | dict | None:
    """``grid`` ({param: value or [values]} or a list of them) parsed by the scene's
    parameters (InputError naming the field, as ``--grid``)."""
    if grid is None:
        return None
    from ancf.study.references import runner
    params = {p.name: p for p in runner(scene, quantity).params}
    if isinstance(grid, dict):
        grids = [grid]
    elif isinstance(grid, (list, tuple)) and grid:
        grids = list(grid)
    else:
        raise InputError(f"grid: {grid!r} is not valid; allowed: {GRID_ALLOWED}")
    out = []
    for g in grids:
        if not isinstance(g, dict) or not g:
            raise InputError(f"grid: {g!r} is not valid; allowed: {GRID_ALLOWED}, each naming "
                             "at least one parameter")
        parsed = {}
        for k, vals in g.items():
            if k not in params:
                raise InputError(f"{k}: unknown parameter of scene {scene!r}; allowed: "
                                 f"{', '.join(params)}")
            parsed[k] = list(dict.fromkeys(params[k].parse(v) for v in _values(k, vals)))
        out.append(parsed)
    return out[0] if isinstance(grid, dict) else out


def _values(name: str, vals) -> list:
    """A grid entry's values: one value (a number or a string) or a list / tuple / range /
    array of them, at least one (None, a dict or a set is refused, naming ``name``)."""
    if isinstance(vals, (str, int, float, np.integer, np.floating)):
        return [vals]
    if isinstance(vals, (list, tuple, range, np.ndarray)) and len(vals):
        return list(vals)
    raise InputError(f"grid {name}: {vals!r} is not valid; allowed: a value or a non-empty "
                     "list of values")


def sweep(scene: str, grid=None, *, fixed: dict | None = None, out=None,
          reference: str | None = None, workers: int | None = None, scheduler=None,
          time_limit: float = 600.0, retry_failed: bool = False, progress: bool = False,
          log=None, quantity: str = "results", force: bool = False):
    """Run the cartesian product of ``grid`` ({param: [values]}, or a list of such grids;
    default: the scene's speed-accuracy grid) with ``fixed`` overrides, as ``ancf sweep``;
    returns a pandas DataFrame, one row per run (parameters, status, results, the error
    against ``reference`` and the counted work).  ``out`` (.parquet or .csv) keeps the rows
    and resumes an interrupted sweep; without it the rows go to a temporary file that is
    removed.  ``log``: a function of one line (default: silent).  ``quantity="frequency"``:
    ``ancf modes`` runs (``fixed={"count": K}``: the lowest K bending frequencies) against
    the analytic frequencies (cantilever, simply-supported, plate-square).  ``force``: run
    more than :data:`ancf.study.sweep.MAX_RUNS` runs, or more ``workers`` than cores (as
    ``--force``).  Every argument is checked as the command line checks its own
    (InputError naming it); ``df.attrs["sweep"]`` holds the call's counts.

    >>> import ancf
    >>> df = ancf.sweep("axial-bar", grid={"n_elements": [1, 2]}, workers=1)  # doctest: +SKIP
    """
    from ancf.scenes import SCENES
    from ancf.study.sweep import run_sweep
    _known("sweep", scene, SCENES)
    from ancf.study.references import runner
    text("quantity", quantity, "results or frequency")
    grids = _grid(scene, grid, quantity)
    fixed = mapping("fixed", fixed)
    if fixed:
        runner(scene, quantity).resolve(fixed)
    kw = dict(fixed=fixed, reference=reference, workers=workers, scheduler=scheduler,
              time_limit=time_limit, retry_failed=retry_failed, progress=progress,
              log=log or (lambda msg: None), quantity=quantity, force=force)
    if out is not None:
        return run_sweep(scene, grids, out=path("out", out), **kw)
    with tempfile.TemporaryDirectory(prefix="ancf-sweep-") as tmp:
        return run_sweep(scene, grids, out=os.path.join(tmp, f"sweep-{scene}.parquet"), **kw)


def recommend(scene: str, tol: float, *, fixed: dict | None = None, reference: str | None = None,
              data=None, workers: int | None = None, scheduler=None, time_limit: float = 300.0,
              progress: bool = False, log=None, quantity: str = "results") -> dict:
    """The cheapest configuration of ``scene`` meeting the error tolerance ``tol``, as
    ``ancf recommend SCENE --tol TOL --json``: the same dict (``params`` that
    :func:`run` accepts as they are, ``error``, ``work``, ``cpu_time_s``, ``found``,
    ``message``, ``evidence``).  ``data``: answer from a sweep file (:func:`sweep`'s
    ``out``) instead of running the scene's recommendation sweep (cached under
    ``reports/.cache/``).  ``quantity="frequency"``: the cheapest model whose lowest K
    (``fixed={"count": K}``, default 3) bending frequencies are within ``tol`` of the
    analytic ones.

    >>> import ancf
    >>> rec = ancf.recommend("cantilever", 1e-3)  # doctest: +SKIP
    >>> ancf.run("cantilever", **rec["params"]).converged  # doctest: +SKIP
    True
    """
    from ancf.scenes import SCENES
    from ancf.study.recommend import public, recommend as _recommend
    _known("recommend", scene, SCENES)
    if data is not None:
        path("data", data)
    if workers is not None:
        number("workers", workers, lo=1, lo_open=False, integer=True)
    flag("progress", progress)
    res = _recommend(scene, tol, fixed=fixed, reference=reference, data=data, workers=workers,
                     scheduler=scheduler, time_limit=time_limit, progress=progress,
                     log=log or (lambda msg: None), quantity=quantity)
    return public(res)
