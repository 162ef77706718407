"""The package's structural invariants (issue 32), read from the source of ``ancf/`` with
``ast``: no integer literal indexes a parameter vector (``prm[0]``: parameters go by name),
no class is built from more than 8 positional arguments, no module outside
``ancf/elements/`` imports a generated module (``_*generated``), and no hand-written module
exceeds 600 lines.  Each checker takes source text and returns the offending line numbers;
the tests of the checkers show that each one flags a violation."""
from __future__ import annotations

import ast
import re

import pytest

from ancf.common.paths import REPO

PACKAGE = REPO / "ancf"
MAX_POSITIONAL = 8
MAX_LINES = 600
GENERATED = re.compile(r"_\w*generated")


def _name(node) -> str:
    """The last name of ``a``, ``a.b``; '' for any other expression."""
    return node.id if isinstance(node, ast.Name) else getattr(node, "attr", "")


def _int_literal(node) -> bool:
    """An integer literal (``3``, ``-1``), a slice or a tuple holding one."""
    if isinstance(node, ast.Slice):
        return any(_int_literal(n) for n in (node.lower, node.upper, node.step) if n)
    if isinstance(node, ast.Tuple):
        return any(_int_literal(n) for n in node.elts)
    if isinstance(node, ast.UnaryOp):
        node = node.operand
    return isinstance(node, ast.Constant) and type(node.value) is int


def literal_prm_index(src: str) -> list[int]:
    """Lines indexing a parameter vector with an integer literal: ``prm[0]``, ``x.prm[1:]``."""
    return [n.lineno for n in ast.walk(ast.parse(src)) if isinstance(n, ast.Subscript)
            and _name(n.value) == "prm" and _int_literal(n.slice)]


def many_positional(src: str) -> list[int]:
    """Lines building a class (``Foo(...)``, ``mod.Foo(...)``) from more than
    MAX_POSITIONAL positional arguments."""
    return [n.lineno for n in ast.walk(ast.parse(src)) if isinstance(n, ast.Call)
            and _name(n.func)[:1].isupper() and len(n.args) > MAX_POSITIONAL]


def generated_imports(src: str) -> list[int]:
    """Lines importing a generated module (``import a._generated``,
    ``from a import _plate_generated``, ``from ._dufva_generated import f``)."""
    lines = []
    for n in ast.walk(ast.parse(src)):
        if isinstance(n, ast.ImportFrom):
            names = (n.module or "").split(".") + [a.name for a in n.names]
        elif isinstance(n, ast.Import):
            names = [part for a in n.names for part in a.name.split(".")]
        else:
            continue
        if any(GENERATED.fullmatch(name) for name in names):
            lines.append(n.lineno)
    return lines


def too_long(src: str) -> list[int]:
    """The first line past MAX_LINES, if the module has one."""
    return [MAX_LINES + 1] if len(src.splitlines()) > MAX_LINES else []


def _hand_written(path) -> bool:
    return not GENERATED.fullmatch(path.stem)


def _outside_elements(path) -> bool:
    return path.relative_to(PACKAGE).parts[0] != "elements"


@pytest.mark.parametrize("check, applies", [
    (literal_prm_index, lambda path: True),
    (many_positional, lambda path: True),
    (generated_imports, _outside_elements),
    (too_long, _hand_written),
], ids=["no-prm-literal-index", "at-most-8-positional", "generated-only-in-elements",
        "at-most-600-lines"])
def test_the_package_keeps_the_invariant(check, applies):
    found = [f"{path.relative_to(REPO)}:{line}" for path in sorted(PACKAGE.rglob("*.py"))
             if applies(path) for line in check(path.read_text())]
    assert found == [], f"{check.__name__}: {', '.join(found)}"


@pytest.mark.parametrize("check, src, lines", [
    (literal_prm_index, "k = prm[K_P]\nx = prm[3]\ny = self.prm[1:]\nz = prm[-1, i]\n",
     [2, 3, 4]),
    (many_positional, "a = f(*range(9))\nb = Spec(1, 2, 3, 4, 5, 6, 7, 8, c=9)\n"
                      "c = m.Spec(1, 2, 3, 4, 5, 6, 7, 8, 9)\n", [3]),
    (generated_imports, "from ancf.elements import plate\nimport ancf.elements._generated\n"
                        "from ancf.elements import _plate_generated as g\n"
                        "from .._belt3d_generated import f\n", [2, 3, 4]),
    (too_long, "x = 1\n" * MAX_LINES, []),
    (too_long, "x = 1\n" * (MAX_LINES + 1), [MAX_LINES + 1]),
])
def test_each_checker_flags_a_violation(check, src, lines):
    assert sorted(check(src)) == lines
