"""Griffe extension (mkdocstrings' ``extensions`` in mkdocs.yml): the docstrings as Markdown.

The package's docstrings are written for reading in the source and for doctest: Sphinx
roles (``:func:`ancf.run```) and bare doctest blocks (``>>> ...`` lines). Markdown would
show the roles' colons and read ``>>>`` as nested block quotes, so before rendering each
role becomes inline code and each doctest block a fenced ``pycon`` block (its
``# doctest:`` flags removed). The source is not changed.
"""
from __future__ import annotations

import re

import griffe

ROLE = re.compile(r":(?:func|data|mod|class|meth|attr|exc):`~?([^`]+)`")
FLAGS = re.compile(r"\s*# doctest:.*$")


def markdown(doc: str) -> str:
    """``doc`` with its roles as code and its doctest blocks fenced."""
    out, block = [], False
    for line in ROLE.sub(r"`\1`", doc).splitlines():
        starts = line.lstrip().startswith(">>>")
        if starts and not block:
            indent = line[:len(line) - len(line.lstrip())]
            out.append(f"{indent}```pycon")
            block = True
        elif block and not line.strip():
            out.append(f"{indent}```")
            block = False
        out.append(FLAGS.sub("", line) if block else line)
    if block:
        out.append(f"{indent}```")
    return "\n".join(out)


class DoctestMarkdown(griffe.Extension):
    """Rewrite every loaded object's docstring with :func:`markdown`."""

    def on_instance(self, *, obj, **kwargs) -> None:
        if obj.docstring is not None:
            obj.docstring.value = markdown(obj.docstring.value)
