"""Every function and method on the Python API page (docs/reference/api.md) has a NumPy
docstring with Parameters (naming exactly the signature's parameters), Returns and
Examples, parsed as mkdocstrings parses it (griffe's NumPy parser, the docstring attached
to griffe's own model of the function, so that a parameter the signature lacks or an
untyped one is a warning) without a warning (issue 38: the API reference is generated
from the docstrings)."""
import dataclasses
import importlib
import inspect
import logging
import re

import pytest

griffe = pytest.importorskip("griffe")

from ancf.common.paths import REPO  # noqa: E402

PAGE = REPO / "docs" / "reference" / "api.md"


def _page() -> tuple[list, list]:
    """The page's ``::: ancf.api`` members and the classes it renders whole (``::: X.Y``
    with no ``members:`` list), as dotted paths."""
    text = PAGE.read_text()
    block = text.split("::: ancf.api\n", 1)[1].split(":::", 1)[0]
    members = re.findall(r"^\s+- (\w+)\s*$", block.split("members:", 1)[1], flags=re.M)
    classes = [p for p in re.findall(r"^::: ([\w.]+)\s*$", text, flags=re.M)
               if p != "ancf.api" and inspect.isclass(_runtime(p))]
    return [f"ancf.api.{m}" for m in members], classes


def _runtime(dotted: str):
    """The object a dotted path names (module, then attributes)."""
    parts = dotted.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        for name in parts[i:]:
            obj = getattr(obj, name)
        return obj
    raise LookupError(dotted)


def _documented() -> list:
    """(label, function) for the page's functions and its classes' public methods."""
    functions, classes = _page()
    out = [(p, _runtime(p)) for p in functions]
    for p in classes:
        cls = _runtime(p)
        out += [(f"{cls.__name__}.{n}", f) for n, f in vars(cls).items()
                if inspect.isfunction(f) and not n.startswith("_")]
    return out


def _griffe_model(fn):
    """griffe's model of ``fn``, from its module's source (the model mkdocstrings renders)."""
    module = inspect.getmodule(fn)
    path = inspect.getsourcefile(module)
    model = griffe.visit(module.__name__, filepath=path, code=open(path).read())
    for name in fn.__qualname__.split("."):
        model = model[name]
    return model


def _parameters(fn) -> list:
    """The signature's parameter names as a NumPy docstring writes them (without self)."""
    star = {inspect.Parameter.VAR_KEYWORD: "**", inspect.Parameter.VAR_POSITIONAL: "*"}
    return [star.get(p.kind, "") + p.name for p in inspect.signature(fn).parameters.values()
            if p.name != "self"]


def _sections(doc: str, parent, caplog) -> tuple[dict, list]:
    """The docstring's sections by kind and the warnings griffe logged parsing it."""
    with caplog.at_level(logging.DEBUG):
        caplog.clear()
        sections = griffe.Docstring(doc, parser="numpy", parent=parent).parse()
        warned = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
    return {s.kind.value: s for s in sections}, warned


def problems(fn, caplog, parent=None) -> list:
    """What the docstring of ``fn`` lacks or gets wrong, one line each."""
    kinds, warned = _sections(inspect.getdoc(fn) or "", parent, caplog)
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
    assert problems(fn, caplog, _griffe_model(fn)) == []


def test_the_page_lists_the_api_and_the_result_methods():
    names = [n for n, _ in _documented()]
    api = ("run", "analytic", "modes", "scenes", "sweep", "recommend")
    methods = ("to_json", "to_dict", "frames", "write_vtk", "write_gif")
    assert set(names) == {f"ancf.api.{n}" for n in api} | {f"Result.{n}" for n in methods}


def test_result_attributes_name_its_fields(caplog):
    """The class docstring's Attributes: every public field, in order, then (optionally)
    properties; nothing that is not an attribute."""
    from ancf.result import Result
    kinds, warned = _sections(inspect.getdoc(Result), _griffe_model(Result), caplog)
    assert warned == [] and "examples" in kinds
    names = [a.name for a in kinds["attributes"].value]
    fields = [f.name for f in dataclasses.fields(Result) if not f.name.startswith("_")]
    props = {n for n, v in vars(Result).items() if isinstance(v, property)}
    assert names[:len(fields)] == fields and set(names[len(fields):]) <= props


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
    assert "parameters ['a'] != signature ['a', 'b', '**kw']" in found


def test_the_checker_sees_a_griffe_warning(caplog):
    def g(a):
        """Identity.

        Parameters
        ----------
          a : int
              Mis-indented, so not parsed.

        Returns
        -------
        int
            ``a``.

        Examples
        --------
        >>> g(1)
        1
        """
    found = problems(g, caplog)
    assert any(line.startswith("griffe: ") and "a : int" in line for line in found)
    assert "parameters [] != signature ['a']" in found


def test_the_checker_sees_a_parameter_the_signature_lacks(caplog):
    """Parsed against griffe's model of the function (as mkdocstrings parses it), a
    documented parameter the signature does not have is a griffe warning too."""
    import ancf.api
    right = inspect.getdoc(ancf.api.sweep)
    wrong = right.replace("\n\nReturns\n", "\nnu : float\n    Poisson's ratio.\n\nReturns\n", 1)
    assert wrong != right and _sections(right, _griffe_model(ancf.api.sweep), caplog)[1] == []
    _, warned = _sections(wrong, _griffe_model(ancf.api.sweep), caplog)
    assert any("'nu'" in w and "signature" in w for w in warned)
