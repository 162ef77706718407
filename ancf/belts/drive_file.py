"""Reading a drive file: TOML (the standard library's :mod:`tomllib`) into the validated
:class:`ancf.belts.drive_data.DriveDescription` (the keys, units and ranges are
declared in :mod:`ancf.belts.drive_data`).

``load(path, overrides)`` reads the file, applies the overrides and validates.  An
override is ``key=value``: ``section.key=value`` (``friction.mu=1.0``,
``contact.k_p=4e8``), ``pulleys.<index or name>.key=value`` (``pulleys.1.inertia=0.5``,
``pulleys.driven.load=constant``) or ``gravity=[0, -9.81]``; the value is read as a TOML
value (numbers, arrays, quoted strings) or else taken as a bare string.  Every error is
an :class:`InputError` of one line naming the file key and its allowed range: a file
that does not exist or is no TOML (with the line tomllib gives), an unknown key, a
missing one, a value out of range, an unknown law or one missing a parameter, and a
layout the belt cannot be laid on (overlapping pulleys, a pulley it cannot wrap, a belt
shorter than half its path or longer than the path; the same at every pulley centre's
``centre_shift``), a friction law the belt's element does not carry (``plate36`` with a
tensioner arm: no law with a state), a ``belt.formulation = 'ale'`` the ALE march does
not carry (the plate belt, a friction law with a state), and a misaligned pulley axis
(``axis_tilt_deg``, ``axis_roll_deg``) on the 2D belt, a tilt the belt cannot wrap
(:func:`wrap_walk`), and flanges (``flanges``, ``face_width_m``, ``flange_height_m``) on the
2D belt, on a tensioner or inside the belt (a face narrower than the belt's width).
"""
from __future__ import annotations

import copy
import math
import tomllib
from dataclasses import replace
from pathlib import Path

from ancf.belts import drive_data as dd
from ancf.belts import flange3d
from ancf.belts.friction import ALL_PARAMS as FRICTION_LAWS
from ancf.belts.friction import PARAMS as FRICTION_PARAMS
from ancf.belts.path import Pulley, PulleyPath
from ancf.common.inputs import MAX_INTERVALS, MAX_STEPS, intervals
from ancf.common.params import InputError, Param, is_boolean

TOP_KEYS = ("gravity", "belt", "pulleys", "friction", "contact", "run")


def load(path, overrides=()) -> dd.DriveDescription:
    """The drive of the TOML file at ``path`` with ``overrides`` ("key=value") applied."""
    return describe(override(read(path), overrides))


def read(path) -> dict:
    """The TOML file at ``path`` as a dict."""
    try:
        with Path(path).open("rb") as f:
            return tomllib.load(f)
    except FileNotFoundError:
        raise InputError(f"{path}: no such file; allowed: a TOML drive file") from None
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{path}: malformed TOML: {exc}; allowed: a TOML drive file") from None
    except UnicodeDecodeError:
        raise InputError(f"{path}: not UTF-8 text; allowed: a TOML drive file") from None
    except OSError as exc:
        raise InputError(f"{path}: cannot be read ({exc.strerror}); allowed: a readable "
                         "TOML drive file") from None


def _value(text: str):
    """``text`` as a TOML value, or the bare string."""
    try:
        return tomllib.loads(f"v = {text}")["v"] if "\n" not in text else text
    except tomllib.TOMLDecodeError:
        return text


def _pulley(data: dict, ref: str) -> dict:
    """The pulley table of ``data`` named by index or name ``ref``."""
    pulleys = data.get("pulleys")
    tables = pulleys if isinstance(pulleys, list) else []
    for i, p in enumerate(tables):
        if isinstance(p, dict) and (ref == str(i) or ref == p.get("name")):
            return p
    names = [str(p.get("name")) for p in tables if isinstance(p, dict)]
    raise InputError(f"pulleys.{ref}: no such pulley; allowed: an index 0-{len(tables) - 1} "
                     f"or a name ({', '.join(names)})")


def override(data: dict, items) -> dict:
    """A copy of ``data`` with each "key=value" of ``items`` set."""
    data = copy.deepcopy(data)
    for item in items:
        key, sep, text = item.partition("=")
        parts = key.strip().split(".")
        if not sep or not all(parts):
            raise InputError(f"--set {item!r}: expected key=value")
        value = _value(text.strip())
        if len(parts) == 1:
            data[parts[0]] = value
        elif len(parts) == 2 and parts[0] != "pulleys":
            section = data.setdefault(parts[0], {})
            if not isinstance(section, dict):
                raise InputError(f"{parts[0]}: {section!r} is not a table; allowed: a table")
            section[parts[1]] = value
        elif len(parts) == 3 and parts[0] == "pulleys":
            _pulley(data, parts[1])[parts[2]] = value
        else:
            raise InputError(f"{key.strip()}: not a key; allowed: gravity, section.key or "
                             "pulleys.<index or name>.key")
    return data


def _table(data: dict, key: str) -> dict:
    value = data.get(key, {})
    if not isinstance(value, dict):
        raise InputError(f"{key}: {value!r} is not a table; allowed: a table [{key}]")
    return value


def _missing(key, prefix: str, why: str = "") -> InputError:
    unit = f" {key.unit}" if getattr(key, "unit", "") else ""
    return InputError(f"{prefix}{key.name}: missing{why}; allowed: {key.allowed()}{unit}")


def _values(table: dict, prefix: str, keys: dict, optional=(), why: str = "") -> dict:
    """Each of ``keys`` parsed from ``table`` (absent: its default; absent without one:
    missing, unless ``optional``); any other key of ``table`` refused."""
    for name in table:
        if name not in keys:
            raise InputError(f"{prefix}{name}: unknown key{why}; allowed: {', '.join(keys)}")
    out = {}
    for name, key in keys.items():
        if name in table:
            _no_boolean(prefix + name, table[name], key)
            out[name] = replace(key, name=prefix + name).parse(table[name])
        elif key.default is not dd.REQUIRED or name in optional:
            out[name] = key.default
        else:
            raise _missing(key, prefix, why)
    return out


def _no_boolean(name: str, value, key) -> None:
    """TOML's true / false, as a key's value or an entry of a vector or table, is not a
    number (Python would read it as 1 or 0: ``E = true`` as 1 Pa); a
    :class:`ancf.belts.drive_data.Switch` takes them."""
    if isinstance(key, dd.Switch):
        return
    rows = value if isinstance(value, (list, tuple)) else [value]
    entries = [x for row in rows for x in (row if isinstance(row, (list, tuple)) else [row])]
    if any(is_boolean(x) for x in entries):
        raise InputError(f"{name} = {value!r} is not valid (a boolean); allowed: "
                         f"{key.allowed()}")


def _one_of(values: dict, prefix: str, keys: dict) -> None:
    for a, b in dd.ONE_OF:
        if values[a] is None and values[b] is None:
            raise _missing(keys[a], prefix, f" (or {prefix}{b})")
        if values[a] is not None and values[b] is not None:
            raise InputError(f"{prefix}{a}, {prefix}{b}: both given; allowed: exactly one")


def _element(data: dict) -> str:
    """The belt's element, which decides the keys of [belt], [contact] and [friction]."""
    key = dd.BELT["element"]
    table = _table(data, "belt")
    return replace(key, name="belt.element").parse(table.get("element", key.default))


def _refuse(key: str, value, element: str, allowed, why: str) -> InputError:
    return InputError(f"{key} = {value!r} is out of range for belt.element = {element!r}; "
                      f"allowed: one of {', '.join(allowed)} ({why})")


def _belt(data: dict, element: str) -> dict:
    keys = dd.BELT_KEYS[element]
    belt = _values(_table(data, "belt"), "belt.", keys, optional=sum(dd.ONE_OF, ()),
                   why=f" (element {element!r})")
    _one_of(belt, "belt.", keys)
    area = belt["b"] * belt["h"]
    if belt["E"] is None:
        belt["E"] = belt["EA"] / area
        replace(dd.BELT["E"], name="belt.EA / (b h)").check(belt["E"])
    else:
        belt["EA"] = belt["E"] * area
    return belt


def _law_keys(table: dict, prefix: str) -> tuple:
    """(law, the pulley's keys under that law, why) of a pulley table."""
    law = dd.PULLEY["law"]
    if "law" not in table:
        raise _missing(law, prefix)
    name = replace(law, name=prefix + "law").parse(table["law"])
    names = list(dd.PULLEY) + list(dd.LAW_KEYS[name])
    sub = dd.ROLES[name].law_key
    if sub in table:
        choice = replace(dd.LAW_PARAMS[sub], name=prefix + sub).parse(table[sub])
        names += [k for k in dd.ROLES[name].laws[choice].keys if k not in names]
    keys = {k: dd.PULLEY.get(k) or dd.LAW_PARAMS[k] for k in names}
    why = f" (law {name!r}: {', '.join(names[len(dd.PULLEY):])})"
    return name, {**keys, **dd.MOTION, **dd.ALIGNMENT, **dd.FLANGES}, why


def _pulley_spec(i: int, table) -> dd.PulleySpec:
    prefix = f"pulleys.{i}."
    if not isinstance(table, dict):
        raise InputError(f"pulleys.{i}: {table!r} is not a table; allowed: a table [[pulleys]]")
    law, keys, why = _law_keys(table, prefix)
    v = _values(table, prefix, keys, why=why)
    if "t1" in v and not v["t1"] > v["t0"]:
        raise InputError(f"{prefix}t1 = {v['t1']!r} is out of range; allowed: a number > "
                         f"t0 = {v['t0']:g} s")
    dd.ROLES[law].derive(v, prefix)
    params = {k: v[k] for k in v if k not in dd.PULLEY}
    return dd.PulleySpec(v["name"], v["centre"], v["radius"], v["side"], law, params)


def _pulleys(data: dict) -> tuple:
    tables = data.get("pulleys")
    count = f"{len(tables)} given" if isinstance(tables, list) else "missing or not an array"
    if not isinstance(tables, list) or len(tables) < 2:
        raise InputError(f"pulleys: {count}; allowed: an array of at least 2 tables [[pulleys]]")
    pulleys = tuple(_pulley_spec(i, t) for i, t in enumerate(tables))
    for i, p in enumerate(pulleys):
        first = next(j for j, q in enumerate(pulleys) if q.name == p.name)
        if first != i:
            raise InputError(f"pulleys.{i}.name = {p.name!r} is the name of pulley {first}; "
                             "allowed: a name used once")
    if not any(p.law == "prescribed" for p in pulleys):
        raise InputError("pulleys: no pulley has law = 'prescribed'; allowed: at least one "
                         "(the driver)")
    return pulleys


def _path(pulleys: tuple, offset: float) -> PulleyPath:
    """The centreline's path at radius + offset round every pulley."""
    try:
        return PulleyPath([Pulley(p.name, p.centre, p.radius + offset, p.side) for p in pulleys])
    except ValueError as exc:
        at = f" (the belt's centreline at radius + belt.contact_offset = {offset:g} m)"
        raise InputError(f"pulleys: {exc}{at if offset else ''}") from None


def _moved(pulleys: tuple, belt: dict) -> None:
    """The layout with every centre at the end of its prescribed motion: a path the belt
    can be laid on, at most twice the belt's length (as :func:`_length`)."""
    keys = [f"pulleys.{i}.centre_shift = {list(p.params['centre_shift'])!r}"
            for i, p in enumerate(pulleys) if any(p.params["centre_shift"])]
    if not keys:
        return
    moved = tuple(replace(p, centre=dd.shifted(p)) for p in pulleys)
    try:
        P = _path(moved, belt["contact_offset"]).length
    except InputError as exc:
        raise InputError(f"{', '.join(keys)}: the shifted layout cannot be wrapped "
                         f"({str(exc).removeprefix('pulleys: ')}); allowed: shifts that keep "
                         "the pulleys apart and the belt wrapping each") from None
    if belt["length"] < 0.5 * P:
        raise InputError(f"{', '.join(keys)}: the shifted path ({P:.6g} m) is more than twice "
                         f"the belt ({belt['length']:.6g} m); allowed: shifts that keep the "
                         f"path within {2 * belt['length']:.6g} m")


def _length(belt: dict, P: float) -> None:
    """L0 from length or prestretch, within [P/2, P]; both keys filled in."""
    if belt["length"] is None:
        belt["length"] = (1.0 + belt["prestretch"]) * P
    elif not 0.5 * P <= belt["length"] <= P:
        raise InputError(f"belt.length = {belt['length']!r} is out of range for the wrapped "
                         f"path ({P:.6g} m); allowed: a number in [{0.5 * P:.6g}, {P:.6g}] m "
                         "(from half the path up to the path: a longer belt hangs slack)")
    belt["prestretch"] = belt["length"] / P - 1.0


def _friction(data: dict, element: str, pulleys: tuple) -> dict:
    table = _table(data, "friction")
    law = Param("law", dd.REQUIRED, str, doc="friction law", choices=tuple(FRICTION_LAWS))
    if "law" not in table:
        raise _missing(law, "friction.")
    name = replace(law, name="friction.law").parse(table["law"])
    laws = dd.ELEMENT_FRICTION[element]
    arms = any(p.law == "tensioner" for p in pulleys)
    if element == "plate36" and arms and name not in FRICTION_PARAMS:
        raise _refuse("friction.law", name, element, FRICTION_PARAMS, "a law with a state per "
                      "contact point is not carried by the plate belt's tensioner arms")
    keys = {"law": law, **laws[name]}
    return _values(table, "friction.", keys, why=f" (law {name!r})")


def _run(data: dict) -> dict:
    run = _values(_table(data, "run"), "run.", dd.RUN)
    t_end, out = run["t_end"], run["output_dt"]
    if out > t_end or intervals(t_end, out) > MAX_INTERVALS:
        raise InputError(f"run.output_dt = {out!r} is out of range; allowed: a number in "
                         f"[t_end/{MAX_INTERVALS}, t_end] = [{t_end / MAX_INTERVALS:g}, "
                         f"{t_end:g}] s")
    if run["dt"] > out or t_end / run["dt"] > MAX_STEPS:
        raise InputError(f"run.dt = {run['dt']!r} is out of range; allowed: a number in "
                         f"[t_end/{MAX_STEPS}, output_dt] = [{t_end / MAX_STEPS:g}, {out:g}] s")
    if run["steady_window"] > t_end:
        raise InputError(f"run.steady_window = {run['steady_window']!r} is out of range; "
                         f"allowed: a number in (0, t_end = {t_end:g}] s")
    return run


def describe(data: dict) -> dd.DriveDescription:
    """The validated drive of a drive file's ``data`` (a dict as tomllib reads it)."""
    for key in data:
        if key not in TOP_KEYS:
            raise InputError(f"{key}: unknown key; allowed: {', '.join(TOP_KEYS)}")
    gravity = _values({k: data[k] for k in dd.TOP if k in data}, "", dd.TOP)["gravity"]
    element = _element(data)
    belt = _belt(data, element)
    pulleys = _pulleys(data)
    path = _path(pulleys, belt["contact_offset"])
    _length(belt, path.length)
    _moved(pulleys, belt)
    contact = _values(_table(data, "contact"), "contact.", dd.CONTACT_KEYS[element],
                      why=f" (element {element!r})")
    friction = _friction(data, element, pulleys)
    _formulation(belt, element, friction)
    _alignment(pulleys, element)
    _flanges(pulleys, belt, element)
    _wraps(pulleys, belt, element, path)
    return dd.DriveDescription(belt, pulleys, friction, contact, _run(data), tuple(gravity),
                               path)


def _alignment(pulleys: tuple, element: str) -> None:
    """A misaligned pulley axis (:data:`ancf.belts.drive_data.ALIGNMENT`) on the plate belt
    only: the 2D belt's axes are its plane's normal."""
    if element == "plate36":
        return
    for i, p in enumerate(pulleys):
        for key in dd.ALIGNMENT:
            if p.params[key] != 0:
                raise InputError(f"pulleys.{i}.{key} = {p.params[key]!r} is out of range for "
                                 f"belt.element = {element!r}; allowed: 0 (a misaligned axis "
                                 "needs belt.element = 'plate36')")


def _formulation(belt: dict, element: str, friction: dict) -> None:
    """``belt.formulation = 'ale'`` (:mod:`ancf.belts.ale_march2d`) on the 2D belt only,
    with a friction law without a state."""
    if belt["formulation"] != "ale":
        return
    if element != "dufva2d":
        raise _refuse("belt.formulation", "ale", element, ("lagrangian",),
                      "the axially moving march is the 2D belt's")
    if friction["law"] not in FRICTION_PARAMS:
        raise InputError(f"belt.formulation = 'ale' with friction.law = {friction['law']!r}: "
                         "a friction state per material point is not carried by the ALE "
                         f"march; allowed: friction.law one of {', '.join(FRICTION_PARAMS)}, "
                         "or belt.formulation = 'lagrangian'")


def _flanges(pulleys: tuple, belt: dict, element: str) -> None:
    """Flanges (:data:`ancf.belts.drive_data.FLANGES`) on the plate belt only, not on a
    tensioner (its pulley moves with its arm), their face at least the belt's width."""
    for i, p in enumerate(pulleys):
        prefix = f"pulleys.{i}."
        if element != "plate36":
            for key in dd.FLANGES.values():
                if p.params[key.name] != key.default:
                    raise InputError(f"{prefix}{key.name} = {_toml(p.params[key.name])} is out "
                                     f"of range for belt.element = {element!r}; allowed: "
                                     f"{_toml(key.default)} (a pulley's face keys: flanges, "
                                     "crown and face offset, need belt.element = 'plate36')")
            continue
        if p.params["flanges"] and dd.ROLES[p.law].arm:
            raise InputError(f"{prefix}flanges = true is out of range for law = {p.law!r}; "
                             "allowed: false (a tensioner's flanges would move with its arm)")
        face = p.params["face_width_m"]
        if 0 < face < belt["b"]:
            raise InputError(f"{prefix}face_width_m = {face!r} is out of range: the flanges "
                             f"would be inside the belt (belt.b = {belt['b']:g} m); allowed: "
                             f"0 (1.1 b) or a number in [{belt['b']:g}, 1] m")
        _face_offset(prefix, p.params, belt["b"])


def _face_offset(prefix: str, params: dict, b: float) -> None:
    """The face's offset keeps the belt's mid-line on the face (|offset| <= W / 2, W the
    face width) and, between flanges, the belt between them (|offset| <= (W - b) / 2)."""
    off, face = params["face_offset_m"], flange3d.face_width(params, b)
    room, why = ((0.5 * (face - b), "a flange would be inside the belt") if params["flanges"]
                 else (0.5 * face, "the belt's mid-line would be off the face"))
    if abs(off) > room + 1e-15:
        raise InputError(f"{prefix}face_offset_m = {off!r} is out of range: {why} (face "
                         f"width {face:g} m, belt.b = {b:g} m); allowed: a number in "
                         f"[{-room:.4g}, {room:.4g}] m")


def _toml(value) -> str:
    """A key's value as a drive file writes it (true / false for a boolean)."""
    return str(value).lower() if isinstance(value, bool) else repr(value)


def wrap_walk(radius: float, wrap: float, tilt_deg: float, roll_deg: float) -> float:
    """How far (m) a belt entering a tilted pulley walks along its axis over its wrap: the
    belt keeps its direction of travel where it meets the surface (tracking3d, Eq. 2), so on
    the cylinder, developed flat, it runs straight at the angle a_e to the circumference,
    sin a_e = d . p = cos(roll) sin(tilt), and over the wrap angle ``wrap`` (rad) of the
    radius ``radius`` (m) it moves R wrap tan a_e along the axis.  The belt cannot wrap the
    pulley when that exceeds its width w: entering at mid-face, it would leave a face of its
    own width before its wrap ends, and flanges would have to push every point of it a full
    width back."""
    s = abs(math.cos(math.radians(roll_deg)) * math.sin(math.radians(tilt_deg)))
    return radius * wrap * s / math.sqrt(1.0 - s * s)


def _wraps(pulleys: tuple, belt: dict, element: str, path) -> None:
    """Every tilted plate-belt pulley one the belt can wrap: :func:`wrap_walk` <= belt.b;
    the message gives the tilts allowed at the pulley's roll (within MAX_ALIGN_DEG)."""
    if element != "plate36":
        return
    w = belt["b"]
    for i, (p, wrap) in enumerate(zip(pulleys, path.wraps)):
        tilt, roll = p.params["axis_tilt_deg"], p.params["axis_roll_deg"]
        R = p.radius + belt["contact_offset"]
        walk = wrap_walk(R, wrap, tilt, roll)
        if walk <= w:
            continue
        s = math.sin(math.atan(w / (R * wrap))) / math.cos(math.radians(roll))
        limit = min(math.degrees(math.asin(min(1.0, s))), dd.MAX_ALIGN_DEG)
        raise InputError(f"pulleys.{i}.axis_tilt_deg = {tilt!r} is out of range: the belt "
                         f"cannot wrap the tilted pulley (it would walk {walk:.3g} m along the "
                         f"axis over its {math.degrees(wrap):.4g} deg wrap, more than its "
                         f"width belt.b = {w:g} m); allowed: a number in [-{limit:.4g}, "
                         f"{limit:.4g}] deg")
