"""The chapter registry (``ancf.reports.chapter``, issue 32 item 4): every chapter is one
module declaring its page, index row, generator, checks, process and the chapters whose runs
it reads; the registry reads the declarations without importing the modules, and the index
of ``reports/README.md`` is the one derived from it."""
import ast
import importlib
import subprocess
import sys
from pathlib import Path

import pytest

from ancf.common.paths import REPO
from ancf.reports.__main__ import GROUPS, index
from ancf.reports.chapter import PROCESSES, Chapter, Generator, chapters, declared

REGISTERED = chapters()
PACKAGE = REPO / "ancf"


def _imported(module: str) -> set[str]:
    """The modules ``module``'s source imports (``from X import Y``: X and X.Y)."""
    tree = ast.parse((PACKAGE.parent / (module.replace(".", "/") + ".py")).read_text())
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module:
            out |= {node.module, *(f"{node.module}.{a.name}" for a in node.names)}
        elif isinstance(node, ast.Import):
            out |= {a.name for a in node.names}
    return out


def test_the_registry_holds_every_chapter_in_report_order():
    assert len(REGISTERED) >= 12
    orders = [c.order for c in REGISTERED.values()]
    assert orders == sorted(orders) and len(set(orders)) == len(orders)


@pytest.mark.parametrize("name", list(REGISTERED))
def test_a_chapter_is_one_module_that_declares_itself(name):
    listed = REGISTERED[name]
    module = f"ancf.reports.{name.removesuffix('.md')}"
    assert isinstance(listed.generate, Generator) and listed.generate.module == module
    own = importlib.import_module(module).CHAPTER
    assert own.generate.__module__ == module and own.generate.__name__ == listed.generate.name
    for field in ("file", "contents", "checks", "order", "process", "reads"):
        assert getattr(own, field) == getattr(listed, field), field
    assert listed.contents.strip() == listed.contents and "|" not in listed.contents
    assert listed.process in PROCESSES


@pytest.mark.parametrize("name", list(REGISTERED))
def test_a_chapter_declares_the_modules_of_its_checks(name):
    """Each is the chapter's own module or one it imports (``ancf.checks.*`` mostly)."""
    listed = REGISTERED[name]
    module = listed.generate.module
    assert listed.checks
    for checks in listed.checks:
        assert checks == module or checks in _imported(module), checks
        assert (PACKAGE.parent / (checks.replace(".", "/") + ".py")).exists(), checks


def test_every_module_of_ancf_checks_belongs_to_a_chapter():
    declared_checks = {m for c in REGISTERED.values() for m in c.checks}
    present = {f"ancf.checks.{p.stem}" for p in (PACKAGE / "checks").glob("*.py")
               if p.stem != "__init__"}
    assert present <= declared_checks


def test_a_chapter_reads_only_chapters_written_before_it():
    """A one-process generation (``--jobs 1``) writes in report order: what a chapter reads
    is there by then."""
    for c in REGISTERED.values():
        for read in c.reads:
            assert REGISTERED[read].order < c.order, (c.file, read)


def test_the_processes_write_every_chapter_once_readers_last():
    assert sorted(f for g in GROUPS for f in g) == sorted(REGISTERED)
    for process, group in zip(PROCESSES, GROUPS):
        assert {REGISTERED[f].process for f in group} == {process}
        readers = [f for f in group
                   if any(REGISTERED[r].process != process for r in REGISTERED[f].reads)]
        assert list(group[len(group) - len(readers):]) == readers


def test_the_committed_index_is_the_registry_s():
    text = (REPO / "reports" / "README.md").read_text()
    table = text.split("\n| report | contents |", 1)[1].split("\n\n## Acceptance summary")[0]
    assert "| report | contents |" + table == "\n".join(index())
    assert index()[2:2 + len(REGISTERED)] == [c.index_row() for c in REGISTERED.values()]


def test_a_declaration_is_read_without_importing_its_module(tmp_path):
    """Adding a chapter is adding its module: the registry reads the declaration from the
    source (this module's import would fail)."""
    path = tmp_path / "new_chapter.py"
    path.write_text('from ancf.no_such_module import x\n\n\ndef new_chapter():\n    return "", {}\n'
                    '\n\nCHAPTER = Chapter(\n    file="new_chapter.md", order=5, '
                    'generate=new_chapter,\n    checks=("ancf.reports.new_chapter",),\n'
                    '    contents="A new " "chapter")\n')
    assert declared(path) == Chapter(file="new_chapter.md", order=5, contents="A new chapter",
                                     generate=Generator("ancf.reports.new_chapter",
                                                        "new_chapter"),
                                     checks=("ancf.reports.new_chapter",))
    assert declared(Path(importlib.import_module("ancf.reports.output").__file__)) is None


def test_the_generator_loads_no_chapter_it_does_not_write():
    """Listing the chapters (``--help``, ``--chapter X``) imports none of their modules."""
    code = ("import sys, ancf.reports.__main__ as m; "
            "print(sorted(set(m.CHAPTERS) & {f'{k.rsplit(\".\", 1)[-1]}.md' for k in sys.modules"
            " if k.startswith('ancf.reports.')}))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, cwd=REPO).stdout
    assert out.strip() == "[]"


def test_one_chapter_rewritten_drops_its_old_rows(tmp_path):
    """``--chapter X.md`` keeps README.md's other rows and drops the rows X.md listed
    before (a check X renamed or dropped does not linger in the summary)."""
    from ancf.reports.__main__ import _previous_statuses
    (tmp_path / "README.md").write_text(
        "## Acceptance summary\n\n| check | status |\n|---|---|\n| kept row | PASS |\n"
        "| renamed row | FAIL |\n")
    (tmp_path / "x.md").write_text("| check | value |\n|---|---|\n| renamed row | 1 |\n")
    assert _previous_statuses(tmp_path, "x.md") == {"kept row": "PASS", "x.md": None}
    assert _previous_statuses(tmp_path, "y.md") == {"kept row": "PASS", "renamed row": "FAIL",
                                                    "y.md": None}


def test_one_chapter_rewritten_keeps_the_summary_order(tmp_path):
    """The chapter's new rows take the place of its old ones: regenerating one chapter
    leaves the other rows where they were (no reshuffled summary in the diff)."""
    from ancf.reports.__main__ import _previous_statuses, _with_chapter
    (tmp_path / "README.md").write_text(
        "## Acceptance summary\n\n| check | status |\n|---|---|\n| a | PASS |\n"
        "| x old | PASS |\n| x two | FAIL |\n| b | PASS |\n")
    (tmp_path / "x.md").write_text("| check | value |\n|---|---|\n| x old | 1 |\n"
                                   "| x two | 2 |\n")
    new = {"x new": "PASS", "x two": "PASS"}
    merged = _with_chapter(_previous_statuses(tmp_path, "x.md"), "x.md", new)
    assert list(merged.items()) == [("a", "PASS"), ("x new", "PASS"), ("x two", "PASS"),
                                    ("b", "PASS")]
    fresh = _with_chapter(_previous_statuses(tmp_path, "z.md"), "z.md", {"z": "PASS"})
    assert list(fresh)[-1] == "z"


def test_rows_the_chapter_file_does_not_list_keep_their_place(tmp_path):
    """A chapter whose acceptance rows are not table rows of its own file (the
    speed-accuracy chapter's 'Pareto plot + table' rows) keeps them where they stood, not
    appended at the end of the summary."""
    from ancf.reports.__main__ import _previous_statuses, _with_chapter
    (tmp_path / "README.md").write_text(
        "## Acceptance summary\n\n| check | status |\n|---|---|\n| a | PASS |\n"
        "| s one | PASS |\n| s two | PASS |\n| b | PASS |\n")
    (tmp_path / "s.md").write_text("no table rows\n")
    merged = _with_chapter(_previous_statuses(tmp_path, "s.md"), "s.md",
                           {"s one": "PASS", "s two": "FAIL"})
    assert list(merged.items()) == [("a", "PASS"), ("s one", "PASS"), ("s two", "FAIL"),
                                    ("b", "PASS")]
