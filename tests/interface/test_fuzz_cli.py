"""Replays the CLI fuzz in-process: issue 15's (tests/data/fuzz_cli.json) and every later
held-out fuzz beside it (tests/data/fuzz_*.json, one file per area, same format).

Every case: the exit code, the expected substrings, no traceback, stdout JSON that a
strict parser accepts (no NaN / Infinity), and stderr made only of one-line
``error:`` / ``warning:`` messages (plus the sweep's own progress log), one
``error:`` line for bad input.  A case's optional ``files`` ({name: text}) are written
into ``{tmp}`` first.  The cases marked ``"slow": true`` (a run of 2 s or more) are
replayed by test_fuzz_cli_slow.py, so that pytest-xdist's ``--dist loadfile`` can give
the two halves to two workers.
"""
import json
from pathlib import Path

import pytest

from ancf.cli import main

DATA = Path(__file__).parents[1] / "data"
#: issue 15's fuzz; the later files add cases of their own, one area each
FIRST = DATA / "fuzz_cli.json"
CASES = [c for f in sorted(DATA.glob("fuzz_*.json")) for c in json.loads(f.read_text())["cases"]]
STDERR_PREFIXES = ("error: ", "warning: ", "sweep ", "progress: ")


def strict_loads(text):
    def reject(name):
        raise ValueError(f"non-standard JSON constant {name}")
    return json.loads(text, parse_constant=reject)


def _id(case):
    return f"{case['class']}:{' '.join(case['argv'])}"


def test_fuzz_covers_every_class_and_command():
    first = json.loads(FIRST.read_text())["cases"]
    classes = {c["class"] for c in first}
    assert {f"{i}-" for i in range(1, 11)} <= {c.split("-")[0] + "-" for c in classes}
    commands = {c["argv"][0] for c in CASES if c["argv"]}
    assert {"run", "analytic", "sweep", "recommend", "scenes"} <= commands
    from ancf.cli import _registries
    scenes, refs = _registries()
    named = {(c["argv"][0], c["argv"][1]) for c in CASES if len(c["argv"]) > 1}
    assert {("run", s) for s in scenes} | {("analytic", r) for r in refs} <= named
    assert len(first) >= 100


@pytest.mark.parametrize("case", [c for c in CASES if not c.get("slow")], ids=_id)
def test_fuzz_case(case, capsys, tmp_path):
    check_case(case, capsys, tmp_path)


def check_case(case, capsys, tmp_path):
    """Runs ``case`` in-process and checks its exit code, streams and JSON."""
    for name, text in case.get("files", {}).items():  # files the case needs, in {tmp}
        (tmp_path / name).write_text(text)
    argv = [a.replace("{tmp}", str(tmp_path)) for a in case["argv"]]
    try:
        code = main(argv)
    except SystemExit as exc:  # argparse's syntax errors (one line, see ancf.cli._Parser)
        code = exc.code
    out, err = capsys.readouterr()
    assert code == case["exit"], err
    assert "Traceback" not in err
    lines = err.splitlines()
    assert all(line.startswith(STDERR_PREFIXES) for line in lines), err
    if code == 2:
        assert sum(line.startswith("error: ") for line in lines) == 1, err
    if case["stderr"] is not None:
        assert case["stderr"].replace("{tmp}", str(tmp_path)) in err
    if case["stdout"] is not None:
        assert case["stdout"] in out
    if "--json" in argv and code != 2:
        strict_loads(out)
