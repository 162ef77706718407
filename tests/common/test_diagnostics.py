"""ancf/common/diagnostics.py: the non-finite results check."""


def test_nonfinite_names_every_key_with_nan_or_inf():
    """A plain list of floats (the fast path), nested lists, lists with None, scalars."""
    import math
    from ancf.common.diagnostics import nonfinite
    res = {"ok": [1.0, 2.0], "flat": [1.0, math.nan], "inf": math.inf, "fine": 3.0,
           "nested": [[1.0, 2.0], [0.5, -math.inf]], "nulls": [None, 1.0, math.nan],
           "labels": ["a", "nan"], "ints": [1, 2], "empty": [], "good_nested": [[None, 1.0]]}
    assert nonfinite(res) == ["flat", "inf", "nested", "nulls"]
