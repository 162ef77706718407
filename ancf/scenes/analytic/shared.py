"""What several analytic references share: a beam's section parameters, the number of
frequencies, the Navier plate's parameters and the check of a derived quantity's range."""
from __future__ import annotations

from dataclasses import replace

from ancf.common.params import InputError, Param

#: a rectangular beam section and its material
SECTION = (
    Param("E", 2.07e11, float, "Pa", "Young's modulus", lo=0, lo_open=True),
    Param("nu", 0.0, float, "-", "Poisson's ratio", lo=0, hi=0.5, hi_open=True),
    Param("L", 2.0, float, "m", "beam length", lo=0, lo_open=True),
    Param("h", 0.1, float, "m", "section height", lo=0, lo_open=True),
    Param("b", 0.1, float, "m", "section width", lo=0, lo_open=True),
    Param("ks", 5.0 / 6.0, float, "-", "shear correction factor", lo=0, lo_open=True, hi=2),
)


def with_defaults(params, **defaults):
    """``params`` with other defaults (by name)."""
    return tuple(replace(p, default=defaults.get(p.name, p.default)) for p in params)


def count_param(default):
    """The number of frequencies computed, ``default`` unless given."""
    return Param("count", default, int, "-", "number of frequencies (the lowest, ascending)",
                 lo=1, hi=100)


#: the simply supported rectangular plate under uniform pressure (Navier)
NAVIER = (
    Param("a", 1.0, float, "m", "plate side along x", lo=0, lo_open=True, hi=1e3),
    Param("b", 1.0, float, "m", "plate side along y", lo=0, lo_open=True, hi=1e3),
    Param("h", 0.01, float, "m", "thickness", lo=0, lo_open=True, hi=1e2),
    Param("E", 2.1e11, float, "Pa", "Young's modulus", lo=0, lo_open=True),
    Param("nu", 0.3, float, "-", "Poisson's ratio", lo=0, hi=0.5, hi_open=True),
    Param("p", 1e3, float, "Pa", "uniform pressure (deflection positive along it)", lo=-1e12, hi=1e12),
    Param("rtol", 1e-10, float, "-", "relative truncation tolerance of the series", lo=1e-14, hi=1e-2),
)


def magnitudes(check, *fields):
    """A scene check: ``check(*p[fields])`` with its ValueError (a derived quantity out of
    double precision, the field named) as InputError."""
    def run(p):
        try:
            check(*(p[f] for f in fields))
        except ValueError as exc:
            raise InputError(str(exc)) from None
    return run
