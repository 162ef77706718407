"""The study layer: sweeps over parameter grids (processes or Dask, ``sweep``),
per-scene references (``references``), the cheapest configuration meeting a
tolerance (``recommend``, ``selection``) by counted work (``cost``), the extremes
study (``extremes``) and the JSON schemas of every output (``schemas``).
"""
