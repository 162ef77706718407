"""Command line: ``ancf scenes``, ``ancf run SCENE``, ``ancf analytic NAME``,
``ancf steady belt-drive --file F`` (a drive's steady running state),
``ancf modes SCENE``, ``ancf sweep SCENE --grid k=v1,v2``, ``ancf recommend SCENE --tol TOL``,
``ancf element NAME`` (one of Chrono's ANCF elements' matrices at a stated state).

``--json`` prints one JSON object ``{scene, params, converged, message, results,
cpu_time_s, compile_cpu_s, warnings}``.  Exit codes: 0 ok, 2 bad input (one line on stderr naming the
field and its allowed range), 3 no convergence (the JSON is still printed).

``ancf sweep``: the run count on stderr at once; a grid of more than
:data:`ancf.study.sweep.MAX_RUNS` runs, or more ``--workers`` than cores, only with
``--force``; a ``--scheduler`` where no Dask scheduler answers is bad input (exit 2,
within :data:`ancf.study.sweep_dask.SCHEDULER_TIMEOUT` seconds); a sweep none of whose
runs converged exits 3 (its rows are still written).
"""
from __future__ import annotations

import argparse
import gc
import math
import signal
import sys

from ancf.common.diagnostics import numerical_warnings
from ancf.common.params import InputError
from ancf.common.strict_json import dumps
from ancf.common.threads import one_blas_thread


#: the scenes that read their input from a file (``ancf run NAME --file PATH``)
FILE_SCENES = ("belt-drive",)


def _registries():
    from ancf.scenes.analytic import REFERENCES
    from ancf.scenes import SCENES
    return SCENES, REFERENCES


def _parse_sets(items):
    """``--set key=value`` items as a dict; one key set twice to different values is a
    conflict (InputError naming both), not the last one silently winning."""
    out = {}
    for item in items or []:
        k, eq, v = item.partition("=")
        if not (eq and k.strip()):
            raise InputError(f"--set {item!r}: expected key=value")
        k, v = k.strip(), v.strip()
        if k in out and out[k] != v:
            raise InputError(f"--set {k}: given twice ({k}={out[k]}, {k}={v}); allowed: one "
                             "value per key")
        out[k] = v
    return out


def _list(registry, title):
    print(title)
    for name, sc in registry.items():
        print(f"  {name:20s} {sc.doc}")
        for p in sc.params:
            d = "(depends on other parameters)" if callable(p.default) else repr(p.default)
            print(f"      {p.name:14s} default {d:>22s} {p.unit:4s} {p.allowed()}  {p.doc}")


def _one_entry(text: str, name: str) -> str:
    """The lines of ``name`` (its line and its parameters') in the listing ``text``
    (InputError naming the allowed names if it lists none)."""
    from itertools import takewhile
    lines = text.splitlines(keepends=True)
    heads = {ln.split()[0]: i for i, ln in enumerate(lines)
             if ln.startswith("  ") and not ln.startswith("   ")}
    if name not in heads:
        raise InputError(f"scenes: unknown name {name!r}; allowed: {', '.join(heads)}")
    rest = takewhile(lambda ln: ln.startswith("      "), lines[heads[name] + 1:])
    return "".join([lines[heads[name]], *rest])


def _scenes(name: str | None = None) -> int:
    """``ancf scenes``: the listing is a function of the sources alone, so it is kept beside
    numba's cache in a file named by the hash of every source (:func:`ancf.source_hash`):
    the first listing of a source tree imports every scene and reference (a second),
    later ones read the text.  Any source edit names a new file, so it is never stale."""
    import io
    import os
    from contextlib import redirect_stdout

    from ancf import numba_cache_dir, source_hash
    path = numba_cache_dir() / f"scenes-{source_hash()}.txt"  # the listing: every source
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        scenes, refs = _registries()
        with redirect_stdout(io.StringIO()) as buf:
            _list(scenes, "Scenes (ancf run NAME):")
            _list(refs, "\nAnalytic references (ancf analytic NAME):")
        text = buf.getvalue()
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            tmp = path.with_name(f".{path.name}.{os.getpid()}")
            tmp.write_text(text, encoding="utf-8")
            os.replace(tmp, path)
        except OSError:
            pass  # a read-only cache: list without keeping
    sys.stdout.write(text if name is None else _one_entry(text, name))
    return 0


def _run(registry, kind, args) -> int:
    if args.name not in registry:
        raise InputError(f"{kind}: unknown name {args.name!r}; allowed: {', '.join(registry)}")
    vtk, gif = getattr(args, "vtk", None), getattr(args, "gif", None)
    if vtk is not None or gif is not None:  # the input, then the paths, checked before the run
        from ancf.scenes.vtk import check_directory, check_gif
        registry[args.name].resolve(_overrides(args))
        if vtk is not None:
            check_directory(vtk)
        if gif is not None:
            gif = check_gif(args.name, gif)
    out, res = registry[args.name].execute(_overrides(args))
    if vtk is not None:
        from ancf.scenes.vtk import write_run
        pvd, steps = write_run(args.name, res.extra, vtk)
        if not args.json:  # stdout stays one JSON object; stderr errors and warnings only
            print(f"vtk: wrote {pvd} ({steps} step{'s' if steps != 1 else ''})")
    if gif is not None:
        _write_gif(args, out, res, gif)
    return _print(out, args)


def _write_gif(args, out: dict, res, gif: Path) -> None:
    """The run's animation (``ancf.reports.animations.animate``) into ``gif``; a run that
    did not converge writes none and says so on stderr."""
    if not out["converged"]:
        print(f"warning: --gif: not written ({args.name} did not converge)", file=sys.stderr)
        return
    from ancf.reports.animations import animate
    a = animate(args.name, gif, res.extra, title=f"ancf run {args.name}")
    if not args.json:
        print(f"gif: wrote {a.path} ({a.frames} frames, t = {a.t0:.3f}-{a.t1:.3f} s)")


def _overrides(args) -> dict:
    """The --set overrides, with ``file`` from --file (the belt-drive scene only)."""
    sets = _parse_sets(args.set)
    path = getattr(args, "file", None)
    if path is not None:
        if args.name not in FILE_SCENES:
            raise InputError(f"--file: scene {args.name!r} takes no file; allowed: the scenes "
                             f"{', '.join(FILE_SCENES)}")
        if sets.get("file", path) != path:
            raise InputError(f"--file {path} and --set file={sets['file']}: two drive files; "
                             "allowed: one of them")
        sets["file"] = path
    return sets


def _modes(args) -> int:
    if args.name in FILE_SCENES:  # a running drive: about its steady state
        from ancf.scenes.belt_modes import execute as running
        about = "steady" if args.about is None else args.about
        out, _ = running(_overrides(args), args.count, about)
        return _print(out, args)
    if getattr(args, "file", None) is not None:
        raise InputError(f"--file: {args.name!r} takes no file; allowed: the scenes "
                         f"{', '.join(FILE_SCENES)}")
    from ancf.scenes.modes import execute
    about = "reference" if args.about is None else args.about
    out, _ = execute(args.name, _parse_sets(args.set), args.count, about)
    return _print(out, args)


def _element(args) -> int:
    """``ancf element NAME``: one element's M, Q_g, Q, K, R (:mod:`ancf.elements.chrono`)."""
    import numpy as np
    from ancf.elements.chrono import element
    out = element(args.name).execute(_parse_sets(args.set))
    for w in out["warnings"]:
        print(f"warning: {w}", file=sys.stderr)
    if args.json:
        print(dumps(out))
        return 0
    print(f"{out['element']}: {len(out['coordinates'])} coordinates, cpu "
          f"{out['cpu_time_s']:.3f} s")
    for k in ("mass_matrix", "gravity", "internal_force", "stiffness", "damping"):
        a = np.asarray(out[k], dtype=float)
        print(f"  {k:15s} {'x'.join(map(str, a.shape)):8s} max |entry| {np.abs(a).max():.6g}")
    return 0


def _print(out: dict, args) -> int:
    """Print a run's warnings (stderr) and its JSON or summary; the exit code."""
    for w in out["warnings"]:
        print(f"warning: {w}", file=sys.stderr)
    if args.json:
        print(dumps(out))
    else:
        print(f"{out['scene']}: {'converged' if out['converged'] else 'NOT CONVERGED'} "
              f"({out['message']}), cpu {out['cpu_time_s']:.3f} s"
              + (f" (+ {out['compile_cpu_s']:.3f} s compiling or loading kernels)"
                 if out.get("compile_cpu_s") else ""))
        for k, v in out["results"].items():
            if not isinstance(v, list) or k == "frequencies_hz":
                print(f"  {k} = {v}")
    return 0 if out["converged"] else 3


def _sweep(args) -> int:
    from ancf.scenes import SCENES
    from ancf.study.references import runner, spec
    from ancf.common.inputs import validate_fixed
    from ancf.study.sweep import parse_grid, run_sweep
    if args.name not in SCENES:
        raise InputError(f"sweep: unknown scene {args.name!r}; allowed: {', '.join(SCENES)}")
    grid = parse_grid(args.name, args.grid, args.quantity) if args.grid else None
    sets = _overrides(args)
    if args.name in FILE_SCENES:  # the file's keys: the file validates them
        runner(args.name, args.quantity).resolve(sets)
    else:
        validate_fixed(runner(args.name, args.quantity), sets)
    out = args.out or f"sweep-{args.name}.parquet"

    def _term(signum, frame):
        raise KeyboardInterrupt
    signal.signal(signal.SIGTERM, _term)  # like Ctrl-C: keep the finished rows, then stop
    try:
        df = run_sweep(args.name, grid, out=out, fixed=sets,
                       reference=args.reference, workers=args.workers, scheduler=args.scheduler,
                       time_limit=args.time_limit, retry_failed=args.retry_failed,
                       progress=not args.no_progress, quantity=args.quantity, force=args.force)
    except KeyboardInterrupt:
        print(_interrupted(out), file=sys.stderr)
        return 130
    counts = {k: int(v) for k, v in df["status"].value_counts().items()} if len(df) else {}
    this = df.attrs.get("sweep", {})
    if args.json:
        print(dumps({"scene": args.name, "out": str(out), "rows": int(len(df)),
                     "status": counts,
                     "reference": args.reference
                     or spec(args.name, args.quantity).default_reference,
                     "lost_workers": this.get("lost_workers", 0),
                     "retried_runs": this.get("retried_runs", 0)}))
    else:
        print(out)
    if this.get("runs") and not this.get("succeeded"):
        print(f"error: sweep {args.name}: none of its {this['runs']} runs converged (each one "
              f"not converged, failed, timed out or invalid; rows: "
              f"{', '.join(f'{k} {v}' for k, v in counts.items())}; see the "
              f"message column of {out})", file=sys.stderr)
        return 3
    return 0


def _interrupted(out) -> str:
    """The line of an interrupted sweep, naming its rows file only where it exists."""
    from pathlib import Path
    if Path(out).exists():
        return f"interrupted: the finished rows are in {out}; the same command resumes"
    return "interrupted: no run had finished, nothing was written; the same command starts again"


def _recommend(args) -> int:
    from ancf.study.recommend import public, recommend
    res = recommend(args.name, args.tol, fixed=_overrides(args), reference=args.reference,
                    data=args.data, workers=args.workers, scheduler=args.scheduler,
                    time_limit=args.time_limit, progress=not args.no_progress,
                    quantity=args.quantity)
    if args.json:
        print(dumps(public(res)))
    else:
        print(res["message"])
        if res["params"]:
            print(_command(args, res["params"]))
    return res["exit_code"]


def _command(args, params: dict) -> str:
    """The command that runs a recommended model: ``ancf modes`` for the frequencies (its
    own --count: modes computed), a drive file's overrides one --set each."""
    from ancf.scenes.belt_drive import SEP
    command = "modes" if args.quantity == "frequency" else "run"
    params = dict(params)
    words = [f"  ancf {command} {args.name}"]
    if args.name in FILE_SCENES:
        words.append(f"--file {params.pop('file')}")
        words += [f"--set {item}" for item in params.pop("set").split(SEP) if item]
    elif command == "run":
        from ancf.study.recommend import command_sets
        params = command_sets(args.name, params)
    return " ".join(words + [f"--set {k}={v}" for k, v in params.items()
                             if v is not None and not (command == "modes" and k == "count")])


def _positive(kind):
    """argparse type: a finite number > 0 (an integer for ``int``); the error names the range."""
    allowed = f"allowed: {'an integer' if kind is int else 'a number'} in (0, inf)"

    def parse(text):
        try:
            v = kind(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not valid; {allowed}") from None
        if not (v > 0 and math.isfinite(v)):
            raise argparse.ArgumentTypeError(f"{text!r} is out of range; {allowed}")
        return v
    return parse


def _quantity(p) -> None:
    p.add_argument("--file", metavar="PATH", help="the drive file of the belt-drive scene "
                   "(TOML; as --set file=PATH)")
    p.add_argument("--quantity", default="results", metavar="Q", help="results (default: the "
                   "scene's results against its reference) or frequency (the lowest --set "
                   "count=K bending frequencies of `ancf modes` against the analytic ones: "
                   "cantilever, simply-supported, plate-square)")


class _NamesHelp(str):
    """The help of ``ancf run NAME`` / ``ancf analytic NAME``: the names allowed, listed
    only when the help is printed (argparse formats it with ``%``), so a run reads no
    other scene's file."""

    def __new__(cls, cmd: str):
        obj = super().__new__(cls, "one of the names `ancf scenes` lists")
        obj.cmd = cmd
        return obj

    def __mod__(self, params):
        from pathlib import Path

        from ancf.common.paths import declared
        folder = Path(__file__).parent / "scenes" / ("" if self.cmd == "run" else "analytic")
        names = (m.replace("_", "-") for m in declared(folder))  # files read, none imported
        return f"one of: {', '.join(names)} (parameters: ancf scenes NAME)"


class _Parser(argparse.ArgumentParser):
    """argparse with its errors as one line instead of a usage block (still exit 2;
    ``--help`` unchanged)."""

    def error(self, message):
        self.exit(2, f"error: {message} (see '{self.prog} --help')\n")


def build_parser() -> argparse.ArgumentParser:
    """The command line's parser (the docs' CLI reference reads it too)."""
    ap = _Parser(prog="ancf", description="ANCF benchmark suite")
    sub = ap.add_subparsers(dest="cmd", required=True)
    p = sub.add_parser("scenes", help="list the scenes and their parameters")
    p.add_argument("name", nargs="?", help="list this scene or reference only")
    for cmd, what in (("run", "a scene"), ("analytic", "an analytic reference")):
        p = sub.add_parser(cmd, help=f"run {what}")
        p.add_argument("name", help=_NamesHelp(cmd))
        p.add_argument("--set", action="append", metavar="KEY=VALUE", help="override a parameter")
        p.add_argument("--json", action="store_true", help="print one JSON object")
    p = sub.add_parser("steady", help="the steady running state of a belt drive (Newton in "
                       "the axially moving description, no march)")
    p.add_argument("name", help="belt-drive")
    p.add_argument("--file", metavar="PATH", help="the drive file (TOML); --set "
                   "section.key=value overrides its keys")
    p.add_argument("--set", action="append", metavar="KEY=VALUE", help="override a key")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    sub.choices["run"].add_argument(
        "--vtk", metavar="DIR", help="write the deformed mesh as a ParaView time series: "
        "DIR/SCENE.pvd and one .vtu per output step")
    sub.choices["run"].add_argument(
        "--gif", metavar="PATH", help="a belt drive's run as an animated GIF: the belt "
        "coloured by its axial force, the pulleys named (belt2d, belt3d, belt-drive)")
    sub.choices["run"].add_argument(
        "--file", metavar="PATH", help="the drive file of the belt-drive scene (TOML); --set "
        "section.key=value overrides its keys")
    p = sub.add_parser("modes", help="natural frequencies and mode shapes of a static scene")
    p.add_argument("name")
    p.add_argument("--set", action="append", metavar="KEY=VALUE", help="override a parameter")
    p.add_argument("--count", metavar="K", help="number of modes, lowest first (default 6, "
                   "or the reduced size - 1 if smaller)")
    p.add_argument("--about", default=None, metavar="STATE",
                   help="reference (default) or equilibrium: the tangent stiffness at the "
                        "scene's static equilibrium under its load (pre-stressed); "
                        "belt-drive: steady (its default), the running drive linearised "
                        "about its steady state")
    p.add_argument("--file", metavar="PATH", help="belt-drive: the drive file (TOML)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p = sub.add_parser("element", help="one of Chrono's ANCF elements: its mass, gravity, "
                       "internal force, K and R at a stated state")
    p.add_argument("name", help="ancf3243, ancf3333 (beams), ancf3423, ancf3443, ancf3833 "
                                "(shells), ancf3843 (brick)")
    p.add_argument("--set", action="append", metavar="KEY=VALUE", help="override a parameter "
                   "(dimensions, rho, E, nu, alpha, gx/gy/gz, node, component, displacement, "
                   "velocity; beams k1, k2)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p = sub.add_parser("sweep", help="run the cartesian product of parameter values")
    p.add_argument("name")
    p.add_argument("--grid", action="append", metavar="KEY=V1,V2,...",
                   help="values of one parameter (';' separates values that contain commas); "
                        "default: the scene's speed-accuracy grid")
    p.add_argument("--set", action="append", metavar="KEY=VALUE", help="fix a parameter")
    p.add_argument("--reference", help="reference for the error column (default: the scene's)")
    p.add_argument("--out", help="output .parquet or .csv (default sweep-SCENE.parquet); "
                                 "an existing file is resumed")
    p.add_argument("--workers", type=_positive(int), help="local worker processes (default: cores)")
    p.add_argument("--scheduler", metavar="ADDRESS", help="run on a Dask cluster instead")
    p.add_argument("--time-limit", type=_positive(float), default=600.0, metavar="SECONDS",
                   help="per run; a run over it is killed and recorded (default 600)")
    p.add_argument("--retry-failed", action="store_true", help="rerun failed / timed-out rows")
    p.add_argument("--force", action="store_true", help="run a grid above the run limit "
                   "(100 000) and start more --workers than cores")
    _quantity(p)
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.add_argument("--json", action="store_true", help="print a JSON summary")
    p = sub.add_parser("recommend", help="cheapest model meeting an error tolerance")
    p.add_argument("name")
    p.add_argument("--tol", type=_positive(float), required=True, help="error tolerance")
    p.add_argument("--set", action="append", metavar="KEY=VALUE",
                   help="fix a parameter (physical ones define the problem)")
    p.add_argument("--reference", help="reference (default: the scene's)")
    p.add_argument("--data", help="answer from this sweep file instead of running a sweep")
    _quantity(p)
    p.add_argument("--workers", type=_positive(int), help="local worker processes")
    p.add_argument("--scheduler", metavar="ADDRESS", help="run the sweep on a Dask cluster")
    p.add_argument("--time-limit", type=_positive(float), default=300.0, metavar="SECONDS")
    p.add_argument("--no-progress", action="store_true")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    return ap


def main(argv=None) -> int:
    if "numpy" not in sys.modules:  # the console script: pin BLAS before it loads (free)
        one_blas_thread()
    args = build_parser().parse_args(argv)
    # A process running one scene: the collector is held while the modules load, and the
    # loaded objects frozen out of its passes (they live as long as the process); its
    # full passes over numba's objects would otherwise cost 0.07 s CPU (see _dispatch).
    args.hold_gc = argv is None and args.cmd == "run" and gc.isenabled()
    if args.hold_gc:
        gc.disable()
    if hasattr(signal, "SIGPIPE"):
        signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # `ancf scenes | head` ends quietly
    with numerical_warnings() as noted:
        code = _dispatch(args)
    for w in noted:
        print(f"warning: {w}", file=sys.stderr)
    if argv is None:  # the command line: the process ends next; its final garbage collections
        gc.freeze()   # would walk every object numba loaded (0.1 s CPU), to free nothing
        if args.cmd == "run":  # and its shutdown would tear down numba's modules (25 ms)
            from ancf.common.process_start import end_process
            end_process(code)
    return code


def _ready_numba() -> None:
    """Numba readies its compiler on the first kernel call of a process, a cache load too
    (0.1 s CPU): loads here ready its runtime alone (:func:`ancf.common.process_start.
    lean_cache_loads`; a kernel not in the cache is compiled as before).  Its BLAS check,
    where a kernel needs it, takes scipy's BLAS module without scipy.linalg's package
    (:mod:`ancf.common.blas`, 0.09 s)."""
    if "numba" in sys.modules:
        from ancf.common.blas import preload_cython_blas
        from ancf.common.process_start import lean_cache_loads
        preload_cython_blas()
        lean_cache_loads()


def _dispatch(args) -> int:
    try:
        if args.cmd == "run":  # this scene's modules only: no sympy, pandas, dask or matplotlib
            from ancf.common.process_start import metadata_on_first_use, numba_without_yaml
            metadata_on_first_use()
            with numba_without_yaml():  # numba loads with the scene's modules
                from ancf.scenes import module_of, scene
                if module_of(args.name) is None:
                    from ancf.scenes import MODULES
                    raise InputError(f"run: unknown name {args.name!r}; allowed: "
                                     f"{', '.join(MODULES)}")
                sc = scene(args.name)
            _ready_numba()
            if getattr(args, "hold_gc", False):
                gc.freeze()
                gc.enable()
            return _run({args.name: sc}, "run", args)
        if args.cmd == "steady":
            from ancf.scenes.belt_steady import SCENE as steady
            return _run({"belt-drive": steady}, "steady", args)
        if args.cmd == "modes":  # the scene's modules and the eigensolver only
            return _modes(args)
        if args.cmd == "scenes":
            return _scenes(args.name)
        if args.cmd == "element":  # numpy and the element modules only
            return _element(args)
        if args.cmd == "sweep":
            return _sweep(args)
        if args.cmd == "recommend":
            return _recommend(args)
        from ancf.scenes.analytic import REFERENCES  # the references alone: no kernel
        return _run(REFERENCES, args.cmd, args)
    except InputError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    raise SystemExit(main())
