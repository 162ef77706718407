"""Command line: ``ancf scenes``, ``ancf run SCENE``, ``ancf analytic NAME``.

``--json`` prints one JSON object ``{scene, params, converged, message, results,
cpu_time_s}``.  Exit codes: 0 ok, 2 bad input (one line on stderr naming the
field and its allowed range), 3 no convergence (the JSON is still printed).
"""
from __future__ import annotations

import argparse
import json
import signal
import sys

from ancf.scenes.base import InputError


def _registries():
    from analytic.references import REFERENCES
    from ancf.scenes import SCENES
    return SCENES, REFERENCES


def _parse_sets(items):
    out = {}
    for item in items or []:
        if "=" not in item:
            raise InputError(f"--set {item!r}: expected key=value")
        k, v = item.split("=", 1)
        out[k.strip()] = v.strip()
    return out


def _list(registry, title):
    print(title)
    for name, sc in registry.items():
        print(f"  {name:20s} {sc.doc}")
        for p in sc.params:
            d = "(depends on other parameters)" if callable(p.default) else repr(p.default)
            print(f"      {p.name:14s} default {d:>22s} {p.unit:4s} {p.allowed()}  {p.doc}")


def _run(registry, kind, args) -> int:
    if args.name not in registry:
        raise InputError(f"{kind}: unknown name {args.name!r}; allowed: {', '.join(registry)}")
    out, _ = registry[args.name].execute(_parse_sets(args.set))
    if args.json:
        print(json.dumps(out))
    else:
        print(f"{out['scene']}: {'converged' if out['converged'] else 'NOT CONVERGED'} "
              f"({out['message']}), cpu {out['cpu_time_s']:.3f} s")
        for k, v in out["results"].items():
            if not isinstance(v, list):
                print(f"  {k} = {v}")
    return 0 if out["converged"] else 3


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="ancf", description="ANCF benchmark suite")
    sub = ap.add_subparsers(dest="cmd", required=True)
    sub.add_parser("scenes", help="list the scenes and their parameters")
    for cmd, what in (("run", "scene"), ("analytic", "analytic reference")):
        p = sub.add_parser(cmd, help=f"run a {what}")
        p.add_argument("name")
        p.add_argument("--set", action="append", metavar="KEY=VALUE", help="override a parameter")
        p.add_argument("--json", action="store_true", help="print one JSON object")
    args = ap.parse_args(argv)
    if hasattr(signal, "SIGPIPE"):
        signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # `ancf scenes | head` ends quietly
    try:
        scenes, refs = _registries()
        if args.cmd == "scenes":
            _list(scenes, "Scenes (ancf run NAME):")
            _list(refs, "\nAnalytic references (ancf analytic NAME):")
            return 0
        return _run(scenes if args.cmd == "run" else refs, args.cmd, args)
    except InputError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    raise SystemExit(main())
