"""`make check-reports` (issue 38, item 4): the comparison of a committed and a regenerated
reports folder within each column's tolerance (ancf/reports/check.py), on small synthetic
folders, and one cheap chapter regenerated for real and found within tolerance."""
import subprocess
import sys
import time

import pytest

from ancf.common.paths import REPORTS
from ancf.reports.check import RULES, compare_folders, main, rule_for

RESULT = "tip y [m]"
WORK = "Newton iterations"
TIMING = "timing: CPU s"
#: the chapter regenerated for real: the cheapest measured (about 4 s on a 2-core machine)
CHEAP = "bechtel.md"


def _write(root, table: dict, page: str = "") -> None:
    """A reports folder: ``data/case.csv`` from {column: values}, and ``chapter.md``."""
    (root / "data").mkdir(parents=True)
    lines = [",".join(table)] + [",".join(map(str, r)) for r in zip(*table.values())]
    (root / "data" / "case.csv").write_text("\n".join(lines) + "\n")
    (root / "chapter.md").write_text(page)


def _page(rows) -> str:
    """A chapter with one table under a heading."""
    return "\n".join(["# Chapter", "", "## Cases", "", f"| case | {RESULT} |", "|---|---|",
                      *(f"| {c} | {v} |" for c, v in rows), ""])


def _check(tmp_path, old: dict, new: dict, old_page="", new_page="", capsys=None):
    """Exit status of the check on the two folders, and its stdout."""
    _write(tmp_path / "committed", old, old_page)
    _write(tmp_path / "regenerated", new, new_page)
    rc = main(["--committed", str(tmp_path / "committed"),
               "--regenerated", str(tmp_path / "regenerated")])
    return rc, capsys.readouterr().out if capsys else ""


def test_every_header_has_one_rule_and_timing_is_ignored():
    assert rule_for("anything at all").kind == RULES[-1].kind == "result"
    assert rule_for(TIMING).rtol is None
    assert rule_for(WORK).kind == "counted work" and rule_for(RESULT).kind == "result"


def test_the_docs_page_lists_every_rule():
    page = (REPORTS.parent / "docs" / "reproduce.md").read_text()
    rows = [l.split("|")[1].strip() for l in page.splitlines() if l.startswith("| ")]
    assert [r.kind for r in RULES] == [k for k in rows if k in {r.kind for r in RULES}]


def test_a_percent_cell_gets_its_absolute_tolerance_in_per_cent():
    from ancf.reports.check import in_percent
    rule = rule_for("difference")
    assert in_percent(rule, "difference %", {}).atol == 100 * rule.atol
    assert in_percent(rule, "error_pct", {}).atol == 100 * rule.atol
    assert in_percent(rule, "difference", {"unit": "%"}).atol == 100 * rule.atol
    assert in_percent(rule, "difference", {"unit": "N"}).atol == rule.atol


def test_the_running_drives_marches_are_adaptive():
    assert rule_for("torque_march", "running_drives_thread_ale_march_pulleys.csv").kind == \
        "adaptive result"
    assert rule_for("torque_march", "belt_drives_checks.csv").kind == "result"


def test_a_result_within_its_tolerance_passes(tmp_path, capsys):
    value = 0.75
    near = value * (1 + rule_for(RESULT).rtol / 2)
    rc, out = _check(tmp_path, {"case": ["a"], RESULT: [repr(value)]},
                     {"case": ["a"], RESULT: [repr(near)]}, capsys=capsys)
    assert rc == 0, out
    assert "every table within tolerance" in out


def test_a_result_beyond_its_tolerance_fails_with_its_column_and_why(tmp_path, capsys):
    value = 0.75
    far = value * (1 + 10 * rule_for(RESULT).rtol)
    rc, out = _check(tmp_path, {"case": ["a"], RESULT: [repr(value)]},
                     {"case": ["a"], RESULT: [repr(far)]}, capsys=capsys)
    assert rc == 1
    line = next(l for l in out.splitlines() if l.startswith("data/case.csv"))
    assert RESULT in line and repr(value) in line and repr(far) in line
    assert rule_for(RESULT).why in line and rule_for(RESULT).tolerance() in line


def test_a_markdown_cell_may_differ_in_its_last_printed_digit(tmp_path, capsys):
    """6 significant digits printed: 1.23456 and 1.23457 may be one round-off apart; a
    difference of two units in the 4th digit is not."""
    base = 1.23456
    last = f"{base + 1e-5:.6g}"
    fourth = f"{base + 2e-3:.6g}"
    table = {"case": ["a"], RESULT: ["0.5"]}
    rc, out = _check(tmp_path, table, table, _page([("a", base)]), _page([("a", last)]),
                     capsys=capsys)
    assert rc == 0, out
    rc, out = _check(tmp_path / "2", table, table, _page([("a", base)]),
                     _page([("a", fourth)]), capsys=capsys)
    assert rc == 1 and "§ Cases, table 1" in out and RESULT in out


@pytest.mark.parametrize("factor, status", [(1.10, 0), (1.40, 1)])
def test_counted_work_passes_at_plus_10_and_fails_at_plus_40_percent(tmp_path, capsys,
                                                                     factor, status):
    rule = rule_for(WORK)
    assert 0.10 < rule.rtol < 0.40  # the premise: an adaptive path may add 10 %, not 40 %
    count = 4310
    rc, out = _check(tmp_path, {"case": ["a"], WORK: [count]},
                     {"case": ["a"], WORK: [round(count * factor)]}, capsys=capsys)
    assert rc == status, out
    assert (rule.why in out) == bool(status)


def test_a_timing_column_is_ignored(tmp_path, capsys):
    cpu = 1.5
    rc, out = _check(tmp_path, {"case": ["a"], TIMING: [cpu]},
                     {"case": ["a"], TIMING: [cpu * 7]}, capsys=capsys)
    assert rc == 0, out


def test_a_message_must_match_in_words_and_numbers(tmp_path, capsys):
    t = 0.2597
    said = f"Newton failed at t = {t} s"
    rc, out = _check(tmp_path, {"message": [said]}, {"message": [said.replace("Newton",
                                                                                "Solver")]},
                     capsys=capsys)
    assert rc == 1 and "message" in out
    rc, out = _check(tmp_path / "2", {"message": [said]},
                     {"message": [f"Newton failed at t = {t * 0.99:.4g} s"]}, capsys=capsys)
    assert rc == 1 and rule_for("message").why in out


def test_a_missing_row_table_and_file_are_reported(tmp_path):
    old, new = tmp_path / "committed", tmp_path / "regenerated"
    _write(old, {"case": ["a", "b"], RESULT: [1, 2]}, _page([("a", 1)]) + _page([("b", 2)]))
    _write(new, {"case": ["a"], RESULT: [1]}, _page([("a", 1)]))
    (old / "data" / "gone.csv").write_text("case\na\n")
    found = {(d.file, d.where, d.regenerated) for d in compare_folders(old, new)}
    assert ("data/case.csv", "row 'b'", "missing") in found
    assert ("chapter.md", "§ Cases, table 2", "missing") in found
    assert ("data/gone.csv", "file", "missing") in found


@pytest.mark.parametrize("args", [["--regenerated", "/nonexistent/reports"],
                                  ["--chapter", "no_such_chapter.md", "--regenerated", "."],
                                  ["--no-such-option"]])
def test_bad_input_exits_2_with_one_error_line(args, capsys):
    rc = main(args)
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and err[0].startswith("error: ")


def test_a_cheap_chapter_regenerated_is_within_tolerance():
    """The whole path: regenerate one chapter into a temporary folder and compare it with
    the committed one (reports/ untouched)."""
    before = (REPORTS / CHEAP).stat().st_mtime
    t0 = time.time()
    done = subprocess.run([sys.executable, "-m", "ancf.reports.check", "--chapter", CHEAP],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "every table within tolerance" in done.stdout
    assert f"progress: compared {CHEAP}" in done.stderr
    assert (REPORTS / CHEAP).stat().st_mtime == before
    assert time.time() - t0 < 300
