"""JSON schemas of the public output of ``ancf run SCENE --json``, ``ancf analytic NAME
--json`` and ``ancf modes SCENE --json``: one per scene, per analytic reference and per
scene with modes, generated from declarations.

The top level is the same for all (``scene``, ``params``, ``converged``, ``message``,
``results``, ``cpu_time_s``, ``compile_cpu_s``, ``warnings``); ``params`` follows the scene's parameter
declarations (:class:`ancf.scenes.base.Param`); ``results`` follows the result keys the scene or reference
declares in its own file (``results`` of its :class:`~ancf.scenes.base.Scene`, each an
:func:`ancf.scenes.base.field`: its JSON type, whether it is always present and whether it
is ``null`` when the run does not converge; :data:`RESULTS` collects them) and
:data:`MODES` below for ``ancf modes``.  Result keys not declared are an error of the
schema (``additionalProperties: false``), so a new result key must be declared, which
publishes it (``python -m ancf.study.schemas`` writes ``reports/schemas.md``).  :func:`validate` is a small validator for the subset of JSON
Schema used (type, properties, required, additionalProperties, items), so that the suite
needs no extra dependency.
"""
from __future__ import annotations

import sys
from pathlib import Path

from ancf.common.paths import REPORTS
from ancf.scenes.base import BOOL, INT, NUM, STR, field, nullable
from ancf.solvers.linear import ZERO_EIGENVALUE_REL

def __getattr__(name):
    """``RESULTS``: result keys per scene / analytic reference, as each declares them
    (``results`` of its :class:`~ancf.scenes.base.Scene`), collected on first use."""
    if name != "RESULTS":
        raise AttributeError(name)
    value = {n: sc.results for n, (_, sc) in registries().items()}
    globals()["RESULTS"] = value
    return value


_MODES_NULL = "null when no eigenpairs were found"
#: result keys of ``ancf modes SCENE --json`` (every scene with modes)
MODES = {
    "about": field(STR, "state the tangent stiffness is taken at: reference or equilibrium"),
    "count": field(INT, "number of modes asked for (default 6, or the reduced size - 1)"),
    "method": field(STR, "eigensolver: dense LAPACK eigh, or shift-invert Lanczos (ARPACK) on "
                         "the band LU or SuperLU of K - sigma M", nullable=True),
    "reduced_size": field(INT, "unknowns of the reduced system (constraints eliminated)"),
    "frequencies_hz": field("array", "the lowest count natural frequencies, ascending, Hz "
                            "(negative: -sqrt(-omega^2)/(2 pi) of an unstable mode); "
                            + _MODES_NULL, nullable=True, items=NUM),
    "eigenvalues_rad2_s2": field("array", "their omega^2, rad^2/s^2; " + _MODES_NULL,
                                 nullable=True, items=NUM),
    "rigid_body_modes": field(INT, "zero-frequency modes (rigid motion, a mechanism or a "
                              "zero-energy mode of the integration scheme): |phi^T K phi| <= "
                              "rigid_body_threshold_rel |K|_inf phi^T phi", nullable=True),
    "rigid_body_threshold_rel": field(NUM, "that threshold (the static stability check's zero, "
                                           f"{ZERO_EIGENVALUE_REL:g})"),
    "sampling": field(STR, "where the mode shapes are sampled: centreline (beams, the belt) or "
                           "mid-surface grid (plates: the nodes)"),
    "sample_points": field("array", "positions of the sample points in the state vibrated "
                                    "about, m (one [x, y] or [x, y, z] each)", items="array"),
    "mode_shapes": field("array", "per mode, the displacement [dx, dy(, dz)] of every sample "
                                  "point, scaled to a largest magnitude of 1 (its largest "
                                  "component positive; all zero for a mode that leaves the "
                                  "points in place, e.g. a beam section's torsion); "
                                  + _MODES_NULL, nullable=True, items="array"),
    "mode_direction_shares": field("array", "per mode, the share of the squared sampled "
                                            "displacement along x, y(, z) (all zero where the "
                                            "points stay in place); " + _MODES_NULL,
                                   nullable=True, items="array"),
    "newton_iterations": field(INT, "Newton iterations of the static equilibrium (0 about the "
                                    "reference)"),
    "factorizations": field(INT, "factorisations: inertia counts (the shift, the Sturm check) "
                                 "and the shift-inverted LU or Cholesky", nullable=True),
    "solves": field(INT, "Lanczos steps: solves with the factorisation (dense: 0)",
                    nullable=True),
    "shift_rad2_s2": nullable("the shift sigma, below the lowest eigenvalue"),
    "sturm_count": field(INT, "eigenvalues below the Sturm check's point, by inertia (between "
                              "the highest reported and the next, or above the next where the "
                              "two are one repeated eigenvalue)", nullable=True),
    "missed_modes": field(INT, "sturm_count minus the eigenvalues found below that point (0: "
                               "none missed)", nullable=True),
    "lowest_frequency_reference_hz": field(NUM, "about the equilibrium: the lowest frequency "
                                                "about the reference, Hz", required=False),
}

_PARAM_TYPES = {float: NUM, int: INT, str: STR, bool: BOOL}


def _type(kind: str, nullable: bool):
    return [kind, "null"] if nullable else kind


def _result_schema(decl: dict) -> dict:
    props = {}
    for k, f in decl.items():
        props[k] = {"type": _type(f["kind"], f["nullable"]), "description": f["doc"]}
        if f["items"] and f["keys"]:  # an array of objects
            props[k]["items"] = _result_schema(f["keys"])
        elif f["items"]:
            props[k]["items"] = {"type": [f["items"], "null"]}
        elif f["keys"]:
            props[k].update({kk: v for kk, v in _result_schema(f["keys"]).items() if kk != "type"})
    return {"type": "object", "properties": props, "additionalProperties": False,
            "required": [k for k, f in decl.items() if f["required"]]}


def _params_schema(scene) -> dict:
    props = {p.name: {"type": _type(_PARAM_TYPES[p.kind], p.default is None),
                      "description": f"{p.doc} ({p.unit})" if p.unit else p.doc}
             for p in scene.params}
    return {"type": "object", "properties": props, "additionalProperties": False,
            "required": list(props)}


def registries() -> dict:
    """{name: (command, Scene)} of every scene and analytic reference."""
    from ancf.scenes.analytic import REFERENCES
    from ancf.scenes import SCENES
    return {**{n: ("run", s) for n, s in SCENES.items()},
            **{n: ("analytic", s) for n, s in REFERENCES.items()}}


class SchemaNameError(KeyError, ValueError):
    """An unknown schema name; the message lists the allowed ones (a ``KeyError``, as
    before, and a ``ValueError``; printed without ``KeyError``'s quotes)."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


def names() -> list[str]:
    """Every schema name in the docs' form (docs/guide/scenes.md): ``run SCENE``, ``analytic NAME`` and
    ``modes SCENE``."""
    from ancf.scenes.modes import MODAL
    return [f"{command} {n}" for n, (command, _) in registries().items()] + [
        f"modes {n}" for n in MODAL] + list(RUNNING)


def _steady_scene():
    from ancf.scenes.belt_steady import SCENE
    return SCENE


def _running_modes_scene():
    from ancf.scenes.belt_modes import SCENE
    return SCENE


#: the running drive's commands: ``ancf steady belt-drive``, ``ancf modes belt-drive``
#: (about its steady state): name -> () -> its Scene, with its own result keys
RUNNING = {"steady belt-drive": _steady_scene, "modes belt-drive": _running_modes_scene}


def _lookup(name: str) -> tuple[str, str, object]:
    """(command, bare name, Scene) of ``run SCENE``, ``analytic NAME``, ``modes SCENE``
    (also with a leading ``ancf``) or the bare ``SCENE`` / ``NAME`` (its run)."""
    from ancf.scenes.modes import MODAL, modal_scene
    regs = registries()
    words = name.split() if isinstance(name, str) else []
    if words[:1] == ["ancf"]:
        words = words[1:]
    if " ".join(words) in RUNNING:
        return words[0], words[1], RUNNING[" ".join(words)]()
    if len(words) == 2 and words[0] in ("run", "analytic", "modes"):
        command, bare = words
    elif len(words) == 1:
        command, bare = None, words[0]
    else:
        command, bare = None, None
    if command == "modes" and bare in MODAL:
        return command, bare, modal_scene(bare)
    if bare in regs and command in (None, regs[bare][0]):
        return regs[bare][0], bare, regs[bare][1]
    raise SchemaNameError(f"schema: unknown name {name!r}; allowed: {', '.join(names())} "
                          "(or the bare scene or reference name)")


#: ``ancf element NAME --json``: the arrays of :mod:`ancf.elements.chrono` (n coordinates)
ELEMENT_ARRAYS = {
    "coordinates": (1, "the element's coordinates e (n): the reference with the stated "
                       "displacement, m (dimensionless on gradient entries)"),
    "mass_matrix": (2, "the consistent mass matrix M (n x n), kg (kg m, kg m^2 on gradient "
                       "entries)"),
    "gravity": (1, "the generalised gravity force Q_g (n), N (N m on gradient entries)"),
    "internal_force": (1, "the internal force Q (n) of M e'' + Q(e, e') = Q_ext, N (Chrono's "
                          "ComputeInternalForces stores -Q)"),
    "stiffness": (2, "K = dQ/de (n x n), N/m"),
    "damping": (2, "R = dQ/de' (n x n), N s/m"),
}


def element_names() -> list[str]:
    """``element NAME`` of every element of ``ancf element``."""
    from ancf.elements.chrono import ELEMENTS
    return [f"element {n}" for n in ELEMENTS]


def element_schema(name: str) -> dict:
    """The JSON schema of ``ancf element NAME --json`` (``name`` bare, or ``element NAME``,
    also with a leading ``ancf``); an unknown name raises :class:`SchemaNameError`."""
    from ancf.elements.chrono import ELEMENTS
    words = name.split() if isinstance(name, str) else []
    bare = words[-1] if words[:-1] in ([], ["element"], ["ancf", "element"]) and words else None
    if bare not in ELEMENTS:
        raise SchemaNameError(f"schema: unknown element {name!r}; allowed: "
                              f"{', '.join(element_names())}")
    num = {"type": [NUM, "null"]}  # null: a non-finite entry, named in warnings
    row = {"type": "array", "items": num}
    props = {"element": {"type": STR, "const": bare}, "params": _params_schema(ELEMENTS[bare])}
    for k, (rank, doc) in ELEMENT_ARRAYS.items():
        props[k] = {"type": "array", "description": doc,
                    "items": row if rank == 2 else num}
    props["cpu_time_s"] = {"type": NUM, "description": "process CPU seconds of the evaluation"}
    props["warnings"] = {"type": "array", "items": {"type": STR},
                         "description": "non-finite arrays (their entries null), empty when none"}
    return {"$schema": "https://json-schema.org/draft/2020-12/schema",
            "title": f"ancf element {bare} --json", "type": "object", "properties": props,
            "required": list(props), "additionalProperties": False}


def schema(name: str) -> dict:
    """The JSON schema of ``ancf run|analytic|modes NAME --json``; ``name`` as the docs
    writes it (``"run cantilever"``, ``"analytic reissner"``, ``"modes cantilever"``) or
    bare (``"cantilever"``: its run).  An unknown name raises :class:`SchemaNameError` (a
    ``KeyError``) listing the allowed ones.  ``"element ancf3243"``: :func:`element_schema`."""
    if isinstance(name, str) and "element" in name.split()[:2]:
        return element_schema(name)
    command, name, sc = _lookup(name)
    props = {"scene": {"type": STR, "const": name}, "params": _params_schema(sc),
             "converged": {"type": BOOL}, "message": {"type": STR},
             "results": _result_schema(MODES if command == "modes"
                                       and f"modes {name}" not in RUNNING else sc.results),
             "cpu_time_s": {"type": NUM, "description": "process CPU seconds of the run, without "
                            "compiling or loading numba kernels"},
             "compile_cpu_s": {"type": NUM, "description": "process CPU seconds spent compiling "
                               "numba kernels or loading them from numba's cache during the run "
                               "(0 when all were loaded before)"},
             "warnings": {"type": "array", "items": {"type": STR},
                          "description": "accuracy warnings, empty when none"}}
    return {"$schema": "https://json-schema.org/draft/2020-12/schema",
            "title": f"ancf {command} {name} --json", "type": "object", "properties": props,
            "required": list(props), "additionalProperties": False}


#: the JSON Schema keywords this module writes and :func:`validate` understands
KEYWORDS = frozenset(("$schema", "title", "type", "properties", "required",
                      "additionalProperties", "items", "const", "description"))


def _check_schema(sch, value) -> dict:
    """``sch`` as a schema dict (a name is looked up), or a TypeError saying what is wrong
    (above all: the output and the schema passed the wrong way round)."""
    if isinstance(sch, str):
        return schema(sch)
    swapped = isinstance(value, dict) and "$schema" in value
    if not isinstance(sch, dict):
        raise TypeError(f"validate(value, schema): the schema is a {type(sch).__name__}, not a "
                        "dict or a schema name")
    unknown = sorted(set(sch) - KEYWORDS)
    if swapped or unknown:
        why = ("the first argument is a schema" if swapped
               else f"the second argument has key(s) {', '.join(map(repr, unknown[:3]))} that "
                    "are no JSON Schema keywords")
        raise TypeError(f"validate(value, schema): {why}; call validate(output, schema(name)), "
                        "the output first")
    return sch


_CHECK = {NUM: lambda v: isinstance(v, (int, float)) and not isinstance(v, bool),
          INT: lambda v: isinstance(v, int) and not isinstance(v, bool),
          STR: lambda v: isinstance(v, str), BOOL: lambda v: isinstance(v, bool),
          "null": lambda v: v is None, "array": lambda v: isinstance(v, list),
          "object": lambda v: isinstance(v, dict)}


def validate(value, sch, path: str = "$") -> list[str]:
    """Violations of ``sch`` by ``value`` (empty when valid), one line each with its path.

    ``sch`` is a schema (:func:`schema`) or its name (``"run cantilever"``).  Arguments
    passed the wrong way round (``validate(schema, output)``) raise a TypeError instead of
    passing silently.
    """
    return _validate(value, _check_schema(sch, value), path)


def _validate(value, sch: dict, path: str) -> list[str]:
    types = sch.get("type")
    types = [types] if isinstance(types, str) else types
    if types and not any(_CHECK[t](value) for t in types):
        return [f"{path}: {type(value).__name__} is not {' or '.join(types)}"]
    if "const" in sch and value != sch["const"]:
        return [f"{path}: {value!r} is not {sch['const']!r}"]
    errors = []
    if isinstance(value, dict):
        props = sch.get("properties", {})
        errors += [f"{path}: missing key {k!r}" for k in sch.get("required", ()) if k not in value]
        for k, v in value.items():
            if k in props:
                errors += _validate(v, props[k], f"{path}.{k}")
            elif sch.get("additionalProperties") is False:
                errors.append(f"{path}: undeclared key {k!r}")
    if isinstance(value, list) and "items" in sch:
        for i, v in enumerate(value):
            errors += _validate(v, sch["items"], f"{path}[{i}]")
    return errors


def _type_text(s: dict) -> str:
    t = s["type"]
    text = " or ".join(t) if isinstance(t, list) else t
    if "items" not in s:
        return text
    item = s["items"]["type"]
    return f"{text} of {item if isinstance(item, str) else ' or '.join(item)}"


def schemas_markdown() -> str:
    """reports/schemas.md: every schema as a table, and as JSON."""
    import json
    parts = ["# JSON output schemas\n",
             "Generated from `ancf/study/schemas.py` (`python -m ancf.study.schemas`); do not edit. One "
             "schema per `ancf run SCENE --json`, `ancf analytic NAME --json` and `ancf modes "
             "SCENE --json`; the suite validates every scene's and reference's default run "
             "(and every scene's modes) against it "
             "(`tests/study/test_schemas.py`). Top level: `scene`, `params` (every parameter used), "
             "`converged`, `message`, `results`, `cpu_time_s` (the run's process CPU seconds "
             "without compiling or loading numba kernels), `compile_cpu_s` (those), "
             "`warnings` (a list of strings, "
             "empty when none). Result keys marked nullable are `null` where the run did not "
             "converge; optional keys are absent when the solver did not get that far.\n"]
    for full in names():
        command, name = full.split()
        s = schema(full)
        res = s["properties"]["results"]
        parts += [f"## `ancf {command} {name}`\n", "| result key | type | required | meaning |",
                  "|---|---|---|---|"]
        parts += [f"| `{k}` | {_type_text(v)} | {'yes' if k in res['required'] else 'no'} | "
                  f"{v['description']} |" for k, v in res["properties"].items()]
        parts += ["", "<details><summary>JSON schema</summary>\n", "```json",
                  json.dumps(s, indent=1, ensure_ascii=False), "```", "</details>\n"]
    parts += ["## `ancf element NAME`\n",
              "One of Chrono's ANCF elements at a stated state (`ancf/elements/chrono.py`; "
              "`tests/interface/test_element_cli.py` validates every element's output). Top "
              "level: `element`, `params` (every parameter used), the arrays below (n = the "
              "element's coordinates; `null` entries only with a warning), `cpu_time_s`, "
              "`warnings`.\n", "| key | type | meaning |", "|---|---|---|"]
    parts += [f"| `{k}` | {'array of array of number' if r == 2 else 'array of number'} | {d} |"
              for k, (r, d) in ELEMENT_ARRAYS.items()]
    first, *rest = element_names()
    parts += ["", "The schemas differ only in `element` and `params`: "
              + "; ".join(f"`{full.split()[1]}`: "
                          + ", ".join(element_schema(full)["properties"]["params"]["properties"])
                          for full in [first, *rest]) + ".", "",
              f"<details><summary>JSON schema of `ancf {first} --json`</summary>\n",
              "```json", json.dumps(element_schema(first), indent=1, ensure_ascii=False),
              "```", "</details>\n"]
    return "\n".join(parts)


def main(argv=None) -> int:
    """``python -m ancf.study.schemas [FILE]``: write the Markdown (default reports/schemas.md)."""
    argv = sys.argv[1:] if argv is None else argv
    out = Path(argv[0]) if argv else REPORTS / "schemas.md"
    out.write_text(schemas_markdown())
    print(out)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
