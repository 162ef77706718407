"""Assembled structural models shared by scenes, checks and reports: the spatial beam
models (``beam3d``: one builder per 3D element, clamp, pins, tip force and tip moment,
St-Venant's torsion constant, static solve) and the
thin-plate models (``plate``: simply supported rectangle, clamped strip, edge load;
meshes in ``plate_mesh``); Chrono's static formulation checks on its ANCF elements
(``chrono_beam``: clamped 3243/3333 beams; ``chrono_continuum``: the 3843 brick;
``chrono_shell``: plates of 3443/3833 shells, statics and modes), small numpy meshes with
a Newton solve, held to Chrono's own tolerances in ``tests/models``; Chrono's time
histories (``plate3423``: the corner-loaded 3423 plate; ``chrono_cable``: the spinning
cable pendulum, with Chrono's linearised implicit Euler).
"""
