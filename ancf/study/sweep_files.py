"""The files of a sweep (:mod:`ancf.study.sweep`): the Parquet or CSV table, its journal
of finished rows (an interrupted sweep resumes from it), the checks of an ``--out`` path,
the closing summary line, the order of rows and columns, and the rows of one problem.
"""
from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd

from ancf.common.params import InputError
from ancf.study.cost import row_counts, work

def journal_path(out) -> Path:
    out = Path(out)
    return out.with_name(out.name + ".journal.jsonl")


def read_rows(out) -> pd.DataFrame:
    """Rows of a sweep file plus its journal (an interrupted sweep), deduplicated by key."""
    out = Path(out)
    frames = []
    if out.exists():
        frames.append(_read_table(out))
    jp = journal_path(out)
    if jp.exists():
        rows = []
        for line in jp.read_text().splitlines():
            try:
                rows.append(json.loads(line))
            except ValueError:
                pass  # a line cut by a hard kill
        if rows:
            frames.append(pd.DataFrame(rows))
    frames = [f for f in frames if len(f)]
    if not frames:
        return pd.DataFrame()
    df = pd.concat(frames, ignore_index=True) if len(frames) > 1 else frames[0]
    return df.drop_duplicates("key", keep="last").reset_index(drop=True)


def _read_table(path: Path) -> pd.DataFrame:
    if path.suffix == ".parquet":
        return pd.read_parquet(path)
    return pd.read_csv(path)


def _write_table(df: pd.DataFrame, path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.tmp{os.getpid()}")
    if path.suffix == ".parquet":
        df.to_parquet(tmp, index=False)
    else:
        df.to_csv(tmp, index=False)
    os.replace(tmp, path)


SWEEP_COLUMNS = ("key", "status")  # every sweep file has them


def check_table(path, what: str = "--out") -> pd.DataFrame:
    """The rows of an existing sweep file, or InputError (one line naming ``what`` and the
    path) when it cannot be read or is not a sweep file (no ``key`` / ``status`` column)."""
    path = Path(path)
    if path.is_dir():
        raise InputError(f"{what} {str(path)!r}: is a directory; allowed: a .parquet or .csv file")
    try:
        df = _read_table(path)
    except pd.errors.EmptyDataError:
        raise InputError(f"{what} {str(path)!r}: the file is empty, not a sweep file") from None
    except PermissionError:
        raise InputError(f"{what} {str(path)!r}: the file cannot be read (permission "
                         "denied)") from None
    except Exception as exc:  # noqa: BLE001 - pyarrow / parser errors: not the format
        kind = "Parquet" if path.suffix == ".parquet" else "CSV"
        first = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
        raise InputError(f"{what} {str(path)!r}: not a readable {kind} file ({first[:200]})") from None
    missing = [c for c in SWEEP_COLUMNS if c not in df]
    if missing:
        raise InputError(f"{what} {str(path)!r}: not a sweep file (no {', '.join(missing)} "
                         f"column{'s' if len(missing) > 1 else ''}); allowed: a file written by "
                         "`ancf sweep`" + (", or a new file name" if what == "--out" else ""))
    return df


def _check_out(out) -> Path:
    """``out`` as a Path, checked before any run: its suffix, a writable place for it
    (every existing ancestor a directory, the nearest one writable) and, when it exists, a
    readable sweep file of the same format.  Errors: one line naming the path."""
    out = Path(out)
    if out.suffix not in (".parquet", ".csv"):
        raise InputError(f"--out {str(out)!r}: the file name must end in .parquet or .csv")
    parent = out.parent if str(out.parent) else Path(".")
    anc = parent
    while not anc.exists():
        if anc.is_symlink() or anc == anc.parent:
            break
        anc = anc.parent
    if anc.exists() and not anc.is_dir():
        raise InputError(f"--out {str(out)!r}: {str(anc)!r} is a file, not a directory")
    if not anc.exists():
        raise InputError(f"--out {str(out)!r}: no existing directory to create it in")
    try:  # a real write, not os.access: root, read-only mounts and /proc answer honestly
        parent.mkdir(parents=True, exist_ok=True)
        fd, probe = tempfile.mkstemp(prefix=f".{out.name}.", suffix=".probe", dir=parent)
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        raise InputError(f"--out {str(out)!r}: cannot write in {str(parent)!r} "
                         f"({exc.strerror or exc})") from None
    if out.exists() or out.is_symlink():
        if out.is_dir():
            raise InputError(f"--out {str(out)!r}: is a directory; allowed: a .parquet or .csv "
                             "file")
        if not os.access(out, os.W_OK) and os.access(out, os.F_OK):
            raise InputError(f"--out {str(out)!r}: the file is not writable")
        check_table(out, "--out")
    return out


_FRONT = ("key", "scene")
_BACK = ("status", "converged", "message", "error", "reference", "cpu_time_s", "compile_cpu_s",
         "wall_time_s", "steps", "iterations", "work", "session")


def _with_work(df: pd.DataFrame) -> pd.DataFrame:
    """``df`` with its ``work`` column (re)computed from each row's parameters and counters
    (:func:`ancf.study.cost.with_work` also adds a column per counted feature)."""
    return df.assign(work=[work(row_counts(r)) for _, r in df.iterrows()])


def summary(df: pd.DataFrame, scene: str, out, seconds: float, session: str,
            lost: dict | None = None) -> str:
    """The closing line of a sweep: rows, converged, not converged, failed, time, and the
    Dask workers lost and runs retried (``lost``: sweep_dask.lost_and_retried's counts)."""
    st = df["status"].value_counts().to_dict() if len(df) else {}
    failed = {k: v for k, v in st.items() if k not in ("ok", "not-converged")}
    mine = df[df["session"] == session] if "session" in df else df.iloc[0:0]
    cpu = float(pd.to_numeric(mine["cpu_time_s"], errors="coerce").sum()) if len(mine) else 0.0
    kinds = f" ({', '.join(f'{k} {v}' for k, v in failed.items())})" if failed else ""
    return (f"sweep {scene}: {len(df)} rows in {out}: {st.get('ok', 0)} converged, "
            f"{st.get('not-converged', 0)} not converged, {sum(failed.values())} failed{kinds}; "
            f"{len(mine)} run now in {seconds:.1f} s wall ({cpu:.2f} s CPU in the runs)"
            + _lost_words(lost or {}))


def _lost_words(lost: dict) -> str:
    """``; 1 Dask worker lost, 2 runs retried`` (nothing when none was)."""
    w, r = lost.get("lost_workers", 0), lost.get("retried_runs", 0)
    return f"; {w} Dask worker(s) lost, {r} run(s) retried" if w or r else ""


def _order(df: pd.DataFrame, param_names, keys_in_order) -> pd.DataFrame:
    rank = {k: i for i, k in enumerate(keys_in_order)}
    df = df.assign(_o=df["key"].map(lambda k: rank.get(k, len(rank))))
    df = df.sort_values("_o", kind="stable").drop(columns="_o").reset_index(drop=True)
    cols = [c for c in _FRONT if c in df] + [c for c in param_names if c in df]
    cols += [c for c in _BACK if c in df]
    cols += sorted(c for c in df.columns if c not in cols)
    df = df[cols]
    for c in ("converged",):
        df[c] = df[c].astype(bool)
    for c in ("error", "cpu_time_s", "compile_cpu_s", "wall_time_s", "work"):
        if c not in df:  # rows written before the column existed
            df[c] = float("nan")
        df[c] = pd.to_numeric(df[c], errors="coerce").astype(float)
    return df


def rows_for(df: pd.DataFrame, scene: str, physical: dict) -> pd.DataFrame:
    """Rows of ``df`` whose physical parameters equal ``physical``."""
    m = pd.Series(True, index=df.index)
    for k, v in physical.items():
        if k not in df:
            return df.iloc[0:0]
        col = df[k]
        if v is None:  # a parameter computed by the scene (stored as null)
            m &= col.isna()
        elif isinstance(v, float):
            m &= np.isclose(pd.to_numeric(col, errors="coerce"), v, rtol=1e-12, atol=0)
        else:
            m &= col.astype(str) == str(v)
    return df[m]


