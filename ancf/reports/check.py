"""``make check-reports``: regenerate the reports and compare every table with the committed one.

``python -m ancf.reports.check [--chapter X.md ...] [--regenerated DIR] [--committed DIR]``
regenerates the chapters (all of them, or those named) into a temporary folder, never over
``reports/``, then compares cell by cell every Markdown table of each chapter and every CSV
under ``data/`` with the committed one (issue 38, item 4). ``--regenerated DIR`` compares a
folder regenerated before instead. Timing pages (``timing/``, ``data/timing/``) and figures
are not compared.

Each column gets the tolerance of the first rule of :data:`RULES` its header matches (one
place, documented in ``docs/reproduce.md``). A number printed rounded (a Markdown cell, a
number inside a message) may also differ by one unit in its last printed digit, taken as at
least the 4th significant one. A text cell must be equal once its numbers are taken out; the
numbers are compared with the column's tolerance (a message's numbers as results).

One line per difference beyond tolerance goes to stdout: file, table and row, column,
committed, regenerated, tolerance and the rule's why. Exit status: 0 every table within
tolerance, 1 a difference, 2 bad input (one ``error:`` line). Progress lines go to stderr
(``progress: ...``) at least every :data:`PROGRESS_S` seconds.
"""
from __future__ import annotations

import argparse
import csv
import math
import queue
import re
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass, replace
from fnmatch import fnmatch
from pathlib import Path

from ancf.common.paths import REPORTS

#: longest silence on stderr while the reports are regenerated (s)
PROGRESS_S = 15.0


@dataclass(frozen=True)
class Rule:
    """A kind of column: headers matching ``pattern`` (a regular expression searched in the
    lower-cased header) are compared within ``rtol`` (relative) + ``atol`` (absolute, the
    column's unit); ``rtol`` None: not compared. ``why``: printed with a difference;
    ``files``: the files (globs of their names) the rule holds in."""
    kind: str
    pattern: str
    rtol: float | None
    atol: float
    why: str
    files: tuple = ("*",)

    def tolerance(self) -> str:
        """The tolerance as printed with a difference."""
        if self.rtol is None:
            return "ignored"
        rel = f"{self.rtol:.0%}" if self.rtol >= 0.01 else f"{self.rtol:g}"
        return (f"rel {rel}" if self.rtol else "equal") + (f" + abs {self.atol:g}"
                                                           if self.atol else "")


#: the files of adaptive runs: time integrators with error control, load and time steps
#: halved on a Newton failure (dynamics, the extremes, the speed-accuracy sweeps), and the
#: running drives' marches (their means over a window move with Newton's stopping point:
#: 2e-6 relative in a march's torque, 3e-7 of the ALE-against-march differences, seen)
ADAPTIVE = ("extremes*", "speed_accuracy*", "pendulum_*", "spinning_*", "constraint_forms*",
            "dynamics.md", "running_drives*")
_DIFF = r"error|difference|diff\b|deviation|\bvs\b|gap|\||max abs\(e"

#: the rules, first match wins (``files`` too); the last one matches every header
RULES = (
    Rule("timing", r"^timing|cpu|wall|\[µs\]|\bns per\b|fit scatter", None, 0.0,
         "CPU and wall times vary per run and machine"),
    Rule("setting", r"^(max_iterations|load_steps|newton_tol|rtol|atol|dt|t_end|n_elements"
                    r"|gauss_points|elastic_points)$", 0.0, 0.0,
         "a setting of the run: the same on every machine"),
    Rule("counted work", r"iteration|tangents|\bsteps\b|rejected|^count_|^work$|^nfev$|^njev$"
                 r"|factorizations", 0.25, 0.0, "an adaptive path steered by round-off"),
    Rule("adaptive message", r"message|diagnosis", 0.25, 1e-12,
         "its words must match; a time of failure in it moves with the adaptive path",
         ADAPTIVE),
    Rule("message", r"message|diagnosis|status|^check$|converged", 1e-6, 1e-12,
         "its words must match and its numbers are results"),
    Rule("adaptive error", _DIFF, 0.25, 1e-6,
         "an error on an adaptive path moves with the path, as its counted work does; "
         "below 1e-6 it is the integrator's tolerance", ADAPTIVE),
    Rule("adaptive result", r"", 1e-4, 1e-6,
         "a time history on an adaptive path agrees to the integrator's tolerance "
         "(3e-5 relative, 1.4e-7 m seen), not to round-off", ADAPTIVE),
    Rule("error", _DIFF, 1e-6, 1e-6,
         "the error of a result held to 1e-6 may move by 1e-6 (of the result, in its unit)"),
    Rule("result", r"", 1e-6, 1e-12, "a result: reproducible to round-off"),
)

_MISSING_WHY = "a table, row or column that one folder has and the other has not"
_NUMBER = re.compile(r"[-+−]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+−]?\d+)?")
_SEPARATOR = re.compile(r"^\|(\s*:?-+:?\s*\|)+\s*$")
_HEADING = re.compile(r"^(#+)\s+(.*)$")


def rule_for(header: str, file: str = "") -> Rule:
    """The first rule of :data:`RULES` matching the column ``header`` of ``file``."""
    name = Path(file).name
    return next(r for r in RULES if re.search(r.pattern, header.strip().lower())
                and any(fnmatch(name, g) for g in r.files))


@dataclass
class Table:
    """A table as text: ``name`` (where it is in its file), ``header``, ``rows``."""
    name: str
    header: list
    rows: list


@dataclass(frozen=True)
class Difference:
    """One difference beyond tolerance, as printed."""
    file: str
    where: str
    column: str
    committed: str
    regenerated: str
    tolerance: str
    why: str

    def line(self) -> str:
        return " | ".join([self.file, self.where, self.column, f"committed {self.committed}",
                           f"regenerated {self.regenerated}", f"tolerance {self.tolerance}",
                           self.why])


def _cells(line: str) -> list:
    """The cells of a Markdown table line (an escaped ``\\|`` stays in its cell)."""
    inner = line.strip()
    inner = inner[1:] if inner.startswith("|") else inner
    inner = inner[:-1] if inner.endswith("|") and not inner.endswith("\\|") else inner
    return [c.strip() for c in re.split(r"(?<!\\)\|", inner)]


def markdown_tables(text: str) -> dict:
    """The tables of a Markdown page by name: ``§ heading, table k`` (k counts the tables
    under that heading)."""
    lines, tables, heading, count = text.splitlines(), {}, "top", {}
    i = 0
    while i < len(lines):
        m = _HEADING.match(lines[i])
        if m:
            heading = m.group(2).strip()
        if (lines[i].startswith("|") and i + 1 < len(lines)
                and _SEPARATOR.match(lines[i + 1].strip())):
            count[heading] = count.get(heading, 0) + 1
            name = f"§ {heading}, table {count[heading]}"
            j = i + 2
            while j < len(lines) and lines[j].startswith("|"):
                j += 1
            tables[name] = Table(name, _cells(lines[i]), [_cells(r) for r in lines[i + 2:j]])
            i = j
            continue
        i += 1
    return tables


def csv_table(path: Path) -> Table:
    """A CSV file as one table of text cells."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return Table("", rows[0] if rows else [], rows[1:])


def _value(s: str) -> float:
    return float(s.replace("−", "-"))


def _quantum(a: str, b: str) -> float:
    """One unit in the last printed digit of the coarser of two printed numbers, counting
    at least 4 significant digits (a short number is taken as exact to them)."""
    def step(s):
        mant, _, exp = s.replace("−", "-").lower().partition("e")
        digits = mant.lstrip("+-").replace(".", "").lstrip("0") or "0"
        decimals = len(mant.partition(".")[2])
        scale = 10.0 ** int(exp or 0)
        if not float(mant):  # a printed zero: exact unless it has decimals
            return 10.0 ** -decimals * scale if decimals else 0.0
        lead = math.floor(math.log10(abs(float(mant))))
        return min(10.0 ** -decimals, 10.0 ** (lead - max(len(digits), 4) + 1)) * scale
    return max(step(a), step(b))


def numbers_within(a: str, b: str, rule: Rule, rounded: bool = True) -> bool:
    """Two printed numbers within the rule's tolerance, plus one unit of the last printed
    digit if they were printed ``rounded`` (not a CSV's full-precision cell)."""
    x, y = _value(a), _value(b)
    if math.isnan(x) or math.isnan(y):
        return math.isnan(x) and math.isnan(y)
    if math.isinf(x) or math.isinf(y):
        return x == y
    return abs(x - y) <= rule.rtol * max(abs(x), abs(y)) + rule.atol + (_quantum(a, b) if rounded else 0.0)


def _parts(cell: str) -> tuple:
    """A text cell as (its words with each number replaced by ``#``, its numbers)."""
    return _NUMBER.sub("#", cell), _NUMBER.findall(cell)


def cell_within(a: str, b: str, rule: Rule, rounded: bool = True) -> bool:
    """Two cells within the column's rule: equal text, the numbers within tolerance; not
    ``rounded``: a cell that is one number holds it to full precision (a CSV's)."""
    if a == b or rule.rtol is None:
        return True
    (wa, na), (wb, nb) = _parts(a), _parts(b)
    if wa != wb or len(na) != len(nb):
        return False
    whole = wa == "#"
    return all(numbers_within(x, y, rule, rounded or not whole) for x, y in zip(na, nb))


def _relative(a: str, b: str) -> str:
    """How far apart two single numbers are, for the printed line ('' if not numbers)."""
    try:
        x, y = _value(a), _value(b)
    except ValueError:
        return ""
    if x == 0 or not math.isfinite(x - y):
        return ""
    return f" (rel {(y - x) / abs(x):+.2g})"


def _keyed(rows: list) -> dict:
    """Rows by (first cell, occurrence), for tables whose lengths differ."""
    seen, out = {}, {}
    for row in rows:
        first = row[0] if row else ""
        seen[first] = seen.get(first, 0) + 1
        out[(first, seen[first])] = row
    return out


def _pairs(old: Table, new: Table, where) -> tuple:
    """The rows to compare as (label, committed, regenerated), and the rows one table
    lacks (as Differences' (where, committed, regenerated))."""
    if len(old.rows) == len(new.rows):
        return [(f"row {i + 1} ({r[0] if r else ''})", r, n)
                for i, (r, n) in enumerate(zip(old.rows, new.rows))], []
    a, b = _keyed(old.rows), _keyed(new.rows)
    label = {k: f"row '{k[0]}'" + (f" #{k[1]}" if k[1] > 1 else "") for k in {**a, **b}}
    lack = [(where(label[k]), "present" if k in a else "absent",
             "present" if k in b else "missing") for k in {**a, **b} if (k in a) != (k in b)]
    return [(label[k], a[k], b[k]) for k in a if k in b], lack


def in_percent(rule: Rule, header: str, row: dict) -> Rule:
    """``rule`` for a cell in per cent (a header with ``%`` or ``pct``, or a row whose
    ``unit`` is ``%``): its absolute tolerance, stated in the result's own unit, times 100."""
    percent = "%" in header or "pct" in header.lower() or row.get("unit", "").strip() == "%"
    return replace(rule, atol=100 * rule.atol) if percent and rule.atol else rule


def compare_tables(file: str, old: Table, new: Table, rounded: bool = False) -> list:
    """The differences beyond tolerance between a committed and a regenerated table;
    ``rounded``: its numbers are printed rounded (Markdown), not to full precision (CSV)."""
    def where(row):
        return f"{old.name}, {row}" if old.name else row
    out = [Difference(file, where("header"), c, "present" if c in old.header else "absent",
                      "present" if c in new.header else "missing", "equal", _MISSING_WHY)
           for c in dict.fromkeys(old.header + new.header)
           if (c in old.header) != (c in new.header)]
    pairs, lack = _pairs(old, new, where)
    out += [Difference(file, w, "—", a, b, "equal", _MISSING_WHY) for w, a, b in lack]
    cols = [(c, old.header.index(c), new.header.index(c)) for c in old.header
            if c in new.header]
    if old.header == new.header:
        cols = [(c, i, i) for i, c in enumerate(old.header)]
    for label, r, n in pairs:
        for col, i, j in cols:
            a, b = (r[i] if i < len(r) else ""), (n[j] if j < len(n) else "")
            rule = in_percent(rule_for(col, file), col, dict(zip(old.header, r)))
            if not cell_within(a, b, rule, rounded):
                out.append(Difference(file, where(label), col, a, b + _relative(a, b),
                                      rule.tolerance(), f"{rule.kind}: {rule.why}"))
    return out


def compare_markdown(file: str, old: Path, new: Path) -> list:
    """Every table of a Markdown page, committed ``old`` against regenerated ``new``."""
    a, b = markdown_tables(old.read_text()), markdown_tables(new.read_text())
    out = [Difference(file, name, "—", "present" if name in a else "absent",
                      "present" if name in b else "missing", "equal", _MISSING_WHY)
           for name in {**a, **b} if (name in a) != (name in b)]
    for name in a:
        if name in b:
            out += compare_tables(file, a[name], b[name], rounded=True)
    return out


def files_to_compare(committed: Path, regenerated: Path, chapters=None) -> list:
    """The files compared (relative paths): the chapters named (or every top-level page),
    and the CSVs of ``data/`` (with chapters named, those the regeneration wrote)."""
    pages = ([f"{c}" for c in chapters] if chapters else
             sorted({p.name for d in (committed, regenerated) for p in d.glob("*.md")}))
    data = [regenerated / "data"] + ([] if chapters else [committed / "data"])
    csvs = sorted({f"data/{p.name}" for d in data for p in d.glob("*.csv")})
    return pages + csvs


def compare_folders(committed, regenerated, chapters=None, report=None) -> list:
    """Every table of the committed reports folder against the regenerated one: the list
    of differences beyond tolerance. ``chapters``: compare only these pages (``X.md``) and
    the CSVs the regenerated folder holds; ``report``: called with each file compared."""
    committed, regenerated = Path(committed), Path(regenerated)
    out = []
    for rel in files_to_compare(committed, regenerated, chapters):
        old, new = committed / rel, regenerated / rel
        if not (old.exists() and new.exists()):
            out.append(Difference(rel, "file", "—", "present" if old.exists() else "absent",
                                  "present" if new.exists() else "missing", "equal",
                                  _MISSING_WHY))
        elif rel.endswith(".md"):
            out += compare_markdown(rel, old, new)
        else:
            out += compare_tables(rel, csv_table(old), csv_table(new))
        if report:
            report(rel)
    return out


def progress(msg: str) -> None:
    print(f"progress: {msg}", file=sys.stderr, flush=True)


def _relay(stream, lines: queue.Queue) -> None:
    for line in stream:
        lines.put(line.rstrip("\n"))
    lines.put(None)


def regenerate(out: Path, chapter: str | None) -> int:
    """Run ``python -m ancf.reports --out OUT [--chapter X.md]``, relaying its stderr as
    progress lines (and one of ours after :data:`PROGRESS_S` s of silence); its exit status."""
    cmd = [sys.executable, "-m", "ancf.reports", "--out", str(out)]
    cmd += ["--chapter", chapter] if chapter else []
    label = chapter or "every chapter"
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    lines: queue.Queue = queue.Queue()
    threading.Thread(target=_relay, args=(proc.stderr, lines), daemon=True).start()
    t0 = last = time.time()
    while True:
        try:
            line = lines.get(timeout=1.0)
        except queue.Empty:
            if time.time() - last >= PROGRESS_S:
                progress(f"regenerating {label}: {time.time() - t0:.0f} s")
                last = time.time()
            continue
        if line is None:
            return proc.wait()
        progress(f"{label}: {line}")
        last = time.time()


def _chapter_names(names) -> list:
    """The chapter files named (``X`` or ``X.md``); ValueError for an unknown one."""
    from ancf.reports.chapter import chapters
    known = chapters()
    out = [n if n.endswith(".md") else f"{n}.md" for n in names]
    bad = [n for n in out if n not in known]
    if bad:
        raise ValueError(f"unknown chapter {', '.join(bad)} (chapters: {', '.join(known)})")
    return out


def run(committed: Path, regenerated: Path, chapters: list | None) -> int:
    """Compare and print; the exit status (0 within tolerance, 1 a difference)."""
    diffs = compare_folders(committed, regenerated, chapters,
                            report=lambda rel: progress(f"compared {rel}"))
    for d in diffs:
        print(d.line(), flush=True)
    files = len({d.file for d in diffs})
    print(f"{len(diffs)} difference(s) beyond tolerance in {files} file(s)" if diffs
          else "every table within tolerance", flush=True)
    return 1 if diffs else 0


class _Parser(argparse.ArgumentParser):
    """Bad arguments raise ValueError (one ``error:`` line, exit status 2, in :func:`main`)."""
    def error(self, message):
        raise ValueError(message)


def main(argv=None) -> int:
    ap = _Parser(prog="python -m ancf.reports.check",
                                 description=__doc__.split("\n\n")[0])
    ap.add_argument("--chapter", nargs="+", metavar="X.md",
                    help="regenerate and compare these chapters only")
    ap.add_argument("--regenerated", metavar="DIR",
                    help="compare this folder, regenerated before, instead of regenerating")
    ap.add_argument("--committed", metavar="DIR", default=str(REPORTS),
                    help="the committed reports (default: reports/)")
    try:
        args = ap.parse_args(argv)
        chapters = _chapter_names(args.chapter) if args.chapter else None
        committed = Path(args.committed)
        for d in [committed] + ([Path(args.regenerated)] if args.regenerated else []):
            if not d.is_dir():
                raise ValueError(f"{d} is not a folder")
    except ValueError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    if args.regenerated:
        return run(committed, Path(args.regenerated), chapters)
    with tempfile.TemporaryDirectory(prefix="ancf-check-reports-") as tmp:
        for chapter in chapters or [None]:
            rc = regenerate(Path(tmp), chapter)
            if rc:
                print(f"error: regenerating {chapter or 'the reports'} failed (exit {rc})",
                      file=sys.stderr)
                return 2
        return run(committed, Path(tmp), chapters)


if __name__ == "__main__":
    sys.exit(main())
