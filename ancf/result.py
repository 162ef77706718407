"""The result object of the Python API (:mod:`ancf.api`): one run's public JSON as
attributes, the scene's model in ``extra``, and the mesh, coordinates and time histories
as arrays; ParaView and GIF output."""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ancf.common.strict_json import dumps


@dataclass(kw_only=True)
class Result:
    """The outcome of one run, as :func:`ancf.run`, :func:`ancf.analytic` and
    :func:`ancf.modes` return it.

    The public JSON's fields are attributes, the scene's model is in ``extra`` and the
    arrays a user wants are properties (``None`` where the run has none: an analytic
    reference has no mesh, a static run no time history).

    Attributes
    ----------
    command : str
        ``"run"``, ``"analytic"`` or ``"modes"``.
    scene : str
        The scene's or reference's name.
    params : dict
        Every parameter value the run used, defaults included.
    converged : bool
        Whether the solve finished (``ancf`` exits 3 where it is False).
    message : str
        The solver's message.
    results : dict
        The results, keyed as the JSON schema of the output names them.
    cpu_time_s : float
        The run's process CPU seconds, without compiling or loading numba's kernels.
    warnings : list of str
        Why a finished run should not be trusted blindly (empty when nothing is amiss).
    compile_cpu_s : float
        CPU seconds spent compiling or loading kernels.
    extra : dict
        The scene's own model (mesh, solver result, the belt drive).
    q0 : numpy.ndarray or None
        Reference global coordinates (positions and slopes of every node).
    q : numpy.ndarray or None
        Final global coordinates (the belt drives: the belt's, without the pulley).
    reference_nodes : numpy.ndarray or None
        The mesh: reference node positions (n_nodes, dim), m.
    nodes : numpy.ndarray or None
        Final node positions (n_nodes, dim), m.
    times : numpy.ndarray or None
        Output times of a dynamic run (s), None for a static one.
    series : dict
        Every time history of the results as an array (``times`` included), {} when the
        run has none.
    node_history : numpy.ndarray or None
        Node positions at every output time (nt, n_nodes, dim) of a dynamic run, m.

    Examples
    --------
    >>> import ancf
    >>> r = ancf.run("cantilever", n_elements=2)
    >>> r.command, r.scene, r.converged, r.warnings
    ('run', 'cantilever', True, [])
    >>> r.reference_nodes.shape, r.times is None
    ((3, 2), True)
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
        """The JSON object ``ancf run|analytic NAME ... --json`` prints.

        Strict JSON: a value that is not a finite number is ``null``.

        Parameters
        ----------
        **kw : object
            Keywords for ``json.dumps`` (``indent=2``, ...).

        Returns
        -------
        str
            The object, with the keys of :data:`ancf.study.schemas` for this output.

        Examples
        --------
        >>> import ancf, json
        >>> list(json.loads(ancf.run("axial-bar", n_elements=2).to_json()))[:3]
        ['scene', 'params', 'converged']
        """
        return dumps(self._json, **kw)

    def to_dict(self) -> dict:
        """:meth:`to_json` parsed back: plain Python values, ``None`` for a non-finite number.

        Returns
        -------
        dict
            The output object, e.g. for ``ancf.study.schemas.validate``.

        Examples
        --------
        >>> import ancf
        >>> ancf.run("axial-bar", n_elements=2).to_dict()["converged"]
        True
        """
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
        """The deformed mesh per output step (:func:`ancf.scenes.frames.frames`).

        Parameters
        ----------
        per_element : int
            Points sampled along each beam element with its own shape functions (default 8).

        Returns
        -------
        list
            One frame per output step (a static run: one), each with ``points`` (m) and
            ``point_data`` (``displacement``, and per scene ``velocity``, ``axial_force_N``, ...).

        Examples
        --------
        >>> import ancf
        >>> len(ancf.run("cantilever", n_elements=2).frames())
        1
        """
        from ancf.scenes.frames import frames
        return frames(self.scene, self.extra, per_element)

    def write_vtk(self, directory, per_element: int = 8) -> Path:
        """Write the run as a ParaView time series (what ``ancf run SCENE --vtk DIR`` writes).

        Parameters
        ----------
        directory : str or Path
            The folder to write ``SCENE.pvd`` and one ``SCENE_NNNNN.vtu`` per output step into;
            created if missing.
        per_element : int
            Points sampled along each beam element (default 8).

        Returns
        -------
        Path
            The ``.pvd`` file.

        Raises
        ------
        InputError
            For a result without a mesh, or a directory that is a file or cannot be written.

        Examples
        --------
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
        """Write a belt drive's run as an animated GIF (what ``ancf run SCENE --gif PATH`` writes).

        The belt is coloured by its axial force (N), every pulley is named, one frame per
        output step from t = 0 (thinned evenly to at most 80).

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

        Raises
        ------
        InputError
            For a scene other than ``belt2d``, ``belt3d`` and ``belt-drive``, or a bad path.

        Examples
        --------
        >>> import ancf
        >>> run = ancf.run("belt-drive", {"file": "examples/three_pulleys.toml"})  # doctest: +SKIP
        >>> run.write_gif("three_pulleys.gif").name  # doctest: +SKIP
        'three_pulleys.gif'
        """
        from ancf.reports.animations import animate
        from ancf.scenes.vtk import check_gif
        gif = check_gif(self.scene, path)
        return animate(self.scene, gif, self.extra, title=title or f"ancf run {self.scene}").path
