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

import os
import tempfile

import numpy as np

import ancf.scenes  # noqa: F401 - cheap (loads no scene); makes ``ancf.scenes`` the callable package
from ancf.common.inputs import flag, is_boolean, mapping, merged, number, path, text
from ancf.common.params import InputError
from ancf.result import Result

__all__ = ["InputError", "Result", "analytic", "modes", "recommend", "run", "scenes", "sweep"]


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
    """Run a scene, as ``ancf run SCENE --set k=v ...``.

    Parameters
    ----------
    scene : str
        The scene's name (``ancf.scenes()`` lists them with their parameters).
    overrides : dict, optional
        Parameters as a dict (``{"n_elements": 8}``, or a drive file's ``"file"`` and its
        ``"section.key"`` overrides), merged with ``**params``.
    vtk : str or Path, optional
        A folder to write the ParaView series into; checked before the run starts.
    **params : str, int, float or bool
        Parameters as keywords: Python values or the strings ``--set`` takes.

    Returns
    -------
    Result
        The run's outcome; ``to_json()`` is what ``--json`` prints.

    Raises
    ------
    InputError
        An unknown scene or parameter, or a value out of its range (the message
        ``ancf run`` prints after ``error:``).

    Examples
    --------
    >>> import ancf
    >>> r = ancf.run("axial-bar", {"n_elements": 2})
    >>> r.converged, r.scene, r.command
    (True, 'axial-bar', 'run')
    """
    return _execute("run", scene, overrides, params, vtk)


def modes(scene: str, overrides: dict | None = None, /, *, count=None, about="reference",
          **params) -> Result:
    """Natural frequencies and mode shapes of a static scene, as ``ancf modes SCENE``.

    As ``ancf modes SCENE --set k=v ... --count K --about STATE``: the parameters are
    checked as ``--set`` values are.

    Parameters
    ----------
    scene : str
        A static scene (``cantilever``, ``simply-supported``, ``axial-bar``, the plates,
        the 3D beams, ``belt-drive`` with a file).
    overrides : dict, optional
        Parameters as a dict, merged with ``**params``.
    count : int or str, optional
        The number of modes, lowest first (``--count``; default 6, or the reduced size - 1
        if smaller).
    about : {"reference", "equilibrium"}
        The tangent stiffness at the reference state (default) or at the scene's static
        equilibrium under its load, pre-stressed (``--about``).
    **params : str, int, float or bool
        The scene's parameters as keywords, as ``--set`` takes them.

    Returns
    -------
    Result
        ``results["frequencies_hz"]`` ascending; ``extra["vectors"]`` the global mode
        vectors (n_dofs, count); ``q`` the state vibrated about.

    Raises
    ------
    InputError
        A scene without modes, a bad ``count`` or ``about``, or a bad parameter.

    Examples
    --------
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

    Parameters
    ----------
    name : str
        The reference's name (``ancf.scenes()`` lists those with ``command`` ``"analytic"``).
    overrides : dict, optional
        Parameters as a dict, merged with ``**params``.
    **params : str, int, float or bool
        Parameters as keywords, as ``--set`` takes them.

    Returns
    -------
    Result
        ``results`` only (an analytic reference has no mesh: ``nodes`` is ``None``).

    Raises
    ------
    InputError
        An unknown name or parameter, or a value out of its range.

    Examples
    --------
    >>> import ancf
    >>> t = ancf.analytic("timoshenko", F=-2000.0)
    >>> t.params["F"], t.results["mid_deflection_m"] < 0
    (-2000.0, True)
    """
    return _execute("analytic", name, overrides, params)


def scenes() -> list[dict]:
    """Every scene and analytic reference with its description and parameters.

    As ``ancf scenes`` lists them. ``ancf.scenes`` is also the package of the scenes, made
    callable: ``ancf.scenes()`` and ``ancf.api.scenes()`` are the same list.

    Returns
    -------
    list of dict
        One dict per entry: ``name``, ``command`` (``"run"`` or ``"analytic"``), ``doc``
        and ``params``: ``{name: {default, unit, allowed, doc}}`` (``default`` None where it
        depends on other parameters).

    Examples
    --------
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
    """Run the cartesian product of a parameter grid, as ``ancf sweep``.

    Every argument is checked as the command line checks its own (InputError naming it).

    Parameters
    ----------
    scene : str
        The scene's name.
    grid : dict or list of dict, optional
        ``{param: value or [values]}``, or a list of such grids (their union); default the
        scene's speed-accuracy grid.
    fixed : dict, optional
        Overrides held fixed in every run.
    out : str or Path, optional
        A ``.parquet`` or ``.csv`` file keeping the rows; an interrupted sweep resumes from
        it. Without it the rows go to a temporary file that is removed.
    reference : str, optional
        The reference the error is measured against (default: the scene's).
    workers : int, optional
        Worker processes (default: the cores).
    scheduler : str, optional
        A Dask scheduler's address (``tcp://127.0.0.1:8786``) to run on instead.
    time_limit : float
        Seconds one run may take before it is stopped (default 600).
    retry_failed : bool
        Run again the rows of ``out`` that failed (default False).
    progress : bool
        Print progress lines on stderr (default False).
    log : callable, optional
        A function of one line of text (default: silent).
    quantity : {"results", "frequency"}
        ``"results"`` (default): the scene's runs. ``"frequency"``: ``ancf modes`` runs
        (``fixed={"count": K}``: the lowest K bending frequencies) against the analytic
        frequencies (cantilever, simply-supported, plate-square).
    force : bool
        Run more than :data:`ancf.study.sweep.MAX_RUNS` runs, or more ``workers`` than cores
        (as ``--force``; default False).

    Returns
    -------
    pandas.DataFrame
        One row per run: parameters, status, results, the error against ``reference``
        and the counted work; ``df.attrs["sweep"]`` holds the call's counts.

    Raises
    ------
    InputError
        A bad scene, grid entry or argument.

    Examples
    --------
    >>> import ancf
    >>> df = ancf.sweep("axial-bar", grid={"n_elements": [1, 2]}, workers=1)  # doctest: +SKIP
    >>> len(df)  # doctest: +SKIP
    2
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
    """The cheapest configuration of a scene meeting an error tolerance.

    As ``ancf recommend SCENE --tol TOL --json``.

    Parameters
    ----------
    scene : str
        The scene's name.
    tol : float
        The error tolerance, relative (as the scene's reference measures it).
    fixed : dict, optional
        Parameters held fixed (physical ones define the problem).
    reference : str, optional
        The reference the error is measured against (default: the scene's).
    data : str or Path, optional
        Answer from this sweep file (:func:`sweep`'s ``out``) instead of running the scene's
        recommendation sweep (cached under ``reports/.cache/``).
    workers : int, optional
        Worker processes of that sweep.
    scheduler : str, optional
        A Dask scheduler's address to run it on.
    time_limit : float
        Seconds one run may take (default 300).
    progress : bool
        Print progress lines on stderr (default False).
    log : callable, optional
        A function of one line of text (default: silent).
    quantity : {"results", "frequency"}
        ``"results"`` (default): the scene's results. ``"frequency"``: the cheapest model
        whose lowest K (``fixed={"count": K}``, default 3) bending frequencies are within
        ``tol`` of the analytic ones.

    Returns
    -------
    dict
        The dict ``ancf recommend ... --json`` prints: ``params`` (that :func:`run`
        accepts as they are), ``error``, ``work``, ``cpu_time_s``, ``found``, ``message``,
        ``evidence``.

    Raises
    ------
    InputError
        A bad scene, data file or argument.

    Examples
    --------
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
