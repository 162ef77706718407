"""Regenerate ``reports/`` (the main job): ``python -m ancf.reports [--out DIR] [--quick]``."""
from __future__ import annotations

import multiprocessing
import os
import re
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from ancf.common.threads import one_blas_thread

one_blas_thread()  # before numpy: reproducible numbers and single-thread CPU times

from ancf.reports.chapter import chapters, groups  # noqa: E402
from ancf.reports.output import (configure, heartbeat, heartbeat_stop, progress,  # noqa: E402
                                 take_timing)
from ancf.scenes.store import ENV as STORE_ENV  # noqa: E402

#: the chapter files in report order (:func:`ancf.reports.chapter.chapters`)
CHAPTERS = tuple(chapters())

#: the pages of reports/ besides the chapters, as rows of the index below them
_OTHER_PAGES = [
    "| `timing/CHAPTER.md` (linked from each chapter) | What varies per run: CPU and wall "
    "times, the machine (CPU, kernel, versions), the calibration of work to seconds; whole "
    "tables with their timing columns in `data/timing/`, plots against CPU time in "
    "`figures/timing/` |",
    "| [benchmarks/README.md](benchmarks/README.md) | `make bench`: static solves, Newton kernels, "
    "pendulum per element × n × integrator, Table 2.5 ratio, cost per simulated second |",
    "| [benchmarks/peers.md](benchmarks/peers.md), [before/after](benchmarks/peers_before_after.md) "
    "| side by side with Exudyn: CPU-time ratios, counts and accuracy of each code |",
    "| [benchmarks/core_profile.md](benchmarks/core_profile.md) | one Newton iteration split "
    "(gather, kernel, scatter, factor, solve), scaling exponents, stability-check share |",
    "| [schemas.md](schemas.md) | JSON schema of every scene's and analytic reference's "
    "`--json` output |"]


def index() -> list[str]:
    """The index table of reports/README.md: a row per chapter, then the other pages."""
    return ["| report | contents |", "|---|---|",
            *(c.index_row() for c in chapters().values()), *_OTHER_PAGES]


def write_chapters(root: Path, only: str | None = None) -> dict:
    """Write every chapter (or the chapter ``only``) into ``root``; returns the acceptance
    statuses of the chapters written."""
    status = {}
    for name, chapter in chapters().items():
        if only in (None, name):
            take_timing()
            text, st = chapter.generate()
            (root / name).write_text(text + timing_page(root, name, take_timing()))
            status.update(st)
    if only is None:
        _write_schemas(root)
    return status


def _write_schemas(root: Path) -> None:
    """The schemas page (``ancf.study.schemas``, loaded only for it)."""
    from ancf.study.schemas import schemas_markdown
    (root / "schemas.md").write_text(schemas_markdown())


#: the two processes of a full generation, each writing its chapters in this order: the
#: speed-accuracy sweeps (two sweep workers of their own; the 3D belt's first,
#: ancf.reports.speed_accuracy.FIRST), and every other chapter, the 3D belt's last: it reads
#: the belt3d sweep's Model 2 runs (:func:`ancf.reports.chapter.groups`)
GROUPS = groups()


def _write_group(root: str, quick: bool, names: tuple) -> dict:
    """Write the chapters ``names`` (in a process of its own); {chapter: statuses}."""
    configure(root, quick)
    heartbeat(" + ".join(n.removesuffix(".md") for n in names[:2])
              + (" + ..." if len(names) > 2 else ""))
    written = {n: write_chapters(Path(root), n) for n in names}
    progress(f"{names[0].removesuffix('.md')}{' + ...' if len(names) > 1 else ''}: done")
    heartbeat_stop()  # the process idles until the other one is done
    return written


def write_all(root: Path, quick: bool, jobs: int = 2) -> dict:
    """Every chapter and the schemas page: in the :data:`GROUPS` processes (``jobs`` = 2) or
    in this one (1), runs shared through a run store of this generation; the acceptance
    statuses in chapter order, as a single process writes them."""
    with tempfile.TemporaryDirectory(prefix="ancf-runs-") as store:
        os.environ[STORE_ENV] = store
        try:
            if jobs == 1:
                per = _write_group(str(root), quick, CHAPTERS)
            else:
                # by its module's name: under `python -m` this module is __main__, which a
                # spawned process cannot look the function up in
                from ancf.reports.__main__ import _write_group as target
                ctx = multiprocessing.get_context("spawn")
                with ProcessPoolExecutor(len(GROUPS), mp_context=ctx) as ex:
                    futures = [ex.submit(target, str(root), quick, g) for g in GROUPS]
                    per = {k: v for f in futures for k, v in f.result().items()}
        finally:
            os.environ.pop(STORE_ENV, None)
    _write_schemas(root)
    return {k: v for name in CHAPTERS for k, v in per[name].items()}


def timing_page(root: Path, chapter: str, parts: list) -> str:
    """Write the chapter's timing parts to ``timing/CHAPTER`` (CPU times, the machine: they
    vary per run) and return the page's closing line that links it ('' without timing)."""
    if not parts:
        return ""
    path = root / "timing" / chapter
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join([f"# Timing of {chapter} (varies per run)\n",
                               "Generated by `python -m ancf.reports` with the chapter: CPU and "
                               "wall times of the machine and run that generated it. Unlike the "
                               f"chapter [{chapter}](../{chapter}) and `data/*.csv`, these "
                               "change on every regeneration; they are not results.\n", *parts]))
    return (f"\n\nTiming (varies per run): [timing/{chapter}](timing/{chapter}) (CPU times "
            "and the machine; whole tables in `data/timing/`).\n")


def _previous_statuses(root: Path, chapter: str) -> dict:
    """The acceptance rows of an existing README.md in root (none if there is none), with
    the rows the chapter's previous file listed (a check it renamed or dropped goes) as
    one placeholder, ``chapter: None``, where the first of them stood (at the end if none
    did): :func:`_with_chapter` puts the chapter's new rows there."""
    path = root / "README.md"
    if not path.exists():
        return {chapter: None}
    text = path.read_text().split("## Acceptance summary", 1)[-1]
    rows = re.findall(r"^\| (.+?) \| (.+?) \|$", text, flags=re.M)
    old = root / chapter
    own = set(re.findall(r"^\| (.+?) \|", old.read_text(), flags=re.M)) if old.exists() else set()
    out = {}
    for k, v in rows:
        if k == "check":
            continue
        if k in own:
            out.setdefault(chapter, None)
        else:
            out[k] = v
    out.setdefault(chapter, None)
    return out


def _with_chapter(previous: dict, chapter: str, rows: dict) -> dict:
    """``previous`` (:func:`_previous_statuses`) with the chapter's ``rows`` in its place
    (the placeholder, or the first of its rows the summary already held, whichever comes
    first), so that regenerating one chapter leaves the summary's order as it was."""
    out, placed = {}, False
    for k, v in previous.items():
        if not placed and (k in rows or (k == chapter and v is None)):
            out.update(rows)
            placed = True
        elif k not in rows and not (k == chapter and v is None):
            out[k] = v
    return out


def main(argv=None) -> int:
    import argparse
    ap = argparse.ArgumentParser(prog="python -m ancf.reports", description=__doc__)
    ap.add_argument("--out", metavar="DIR", help="output folder (default: reports/)")
    ap.add_argument("--quick", action="store_true",
                    help="reduced configuration (smaller grids and element counts, shorter "
                         "simulated times): a smoke run of every chapter, not the published data")
    ap.add_argument("--jobs", type=int, choices=(1, 2), default=2,
                    help="processes writing chapters (default 2: the speed-accuracy sweeps in "
                         "one, every other chapter in the other)")
    ap.add_argument("--chapter", choices=CHAPTERS,
                    help="write this chapter only; README.md keeps the acceptance rows it "
                         "has and takes this chapter's")
    args = ap.parse_args(argv)
    t0 = time.time()
    root = configure(args.out, args.quick).root
    root.mkdir(parents=True, exist_ok=True)
    if args.chapter:
        heartbeat(args.chapter.removesuffix(".md"))
        previous = _previous_statuses(root, args.chapter)  # before the chapter is rewritten
        status = _with_chapter(previous, args.chapter, write_chapters(root, args.chapter))
    else:
        status = write_all(root, args.quick, args.jobs)
    note = (" Reduced configuration (`--quick`): not the published data." if args.quick else "")
    idx = ["# ancf-bench reports\n", "Generated by `make reports` (`python -m ancf.reports`); do "
           "not edit by hand." + note + "\n", *index(),
           "", "## Acceptance summary\n", "| check | status |", "|---|---|"]
    idx += [f"| {k} | {v} |" for k, v in status.items()]
    (root / "README.md").write_text("\n".join(idx) + "\n")
    progress(f"reports written to {root} in {time.time() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
