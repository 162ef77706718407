"""Every function and method on the Python API page (docs/reference/api.md) has a NumPy
docstring with Parameters (naming exactly the signature's parameters), Returns and
Examples, parsed as mkdocstrings parses it (griffe's NumPy parser) without a warning
(issue 38: the API reference is generated from the docstrings)."""
import inspect
import logging
import re

import pytest

griffe = pytest.importorskip("griffe")

from ancf.common.paths import REPO  # noqa: E402

PAGE = REPO / "docs" / "reference" / "api.md"


def _documented() -> list:
    """The functions the page lists under ``::: ancf.api``'s members, and the public
    methods of the classes it renders whole (``::: ancf.result.Result``)."""
    import ancf.api
    import ancf.result
    text = PAGE.read_text()
    block = text.split("::: ancf.api", 1)[1].split(":::", 1)[0]
    names = re.findall(r"^\s+- (\w+)$", block, flags=re.M)
    out = [(f"ancf.api.{n}", getattr(ancf.api, n)) for n in names]
    assert "::: ancf.result.Result" in text
    out += [(f"Result.{n}", f) for n, f in vars(ancf.result.Result).items()
            if inspect.isfunction(f) and not n.startswith("_")]
    return out


def _parameters(fn) -> list:
    """The signature's parameter names as a NumPy docstring writes them."""
    star = {inspect.Parameter.VAR_KEYWORD: "**", inspect.Parameter.VAR_POSITIONAL: "*"}
    return [star.get(p.kind, "") + p.name for p in inspect.signature(fn).parameters.values()
            if p.name != "self"]


def problems(fn, caplog) -> list:
    """What the docstring of ``fn`` lacks or gets wrong, one line each."""
    with caplog.at_level(logging.DEBUG):
        caplog.clear()
        sections = griffe.Docstring(inspect.getdoc(fn) or "", parser="numpy").parse()
        warned = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
    kinds = {s.kind.value: s for s in sections}
    wanted = _parameters(fn)
    out = [f"griffe: {w}" for w in warned]
    out += [f"no {k} section" for k in ("returns", "examples") if k not in kinds]
    if wanted:
        documented = [p.name for p in kinds["parameters"].value] if "parameters" in kinds else []
        if documented != wanted:
            out.append(f"parameters {documented} != signature {wanted}")
    return out


@pytest.mark.parametrize("name,fn", _documented(), ids=[n for n, _ in _documented()])
def test_the_docstring_has_parameters_returns_and_examples(name, fn, caplog):
    assert problems(fn, caplog) == []


def test_the_page_lists_the_api_and_the_result_methods():
    names = [n for n, _ in _documented()]
    assert {"ancf.api.run", "ancf.api.sweep", "ancf.api.recommend", "Result.write_gif",
            "Result.to_json"} <= set(names)


def test_the_checker_sees_a_missing_parameter_and_section(caplog):
    def f(a, b=1, **kw):
        """Sum.

        Parameters
        ----------
        a : int
            First.

        Returns
        -------
        int
            The sum.
        """
    found = problems(f, caplog)
    assert "no examples section" in found
    assert any(line.startswith("parameters ['a'] != signature ['a', 'b', '**kw']")
               for line in found)
