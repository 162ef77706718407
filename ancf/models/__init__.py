"""Assembled structural models shared by scenes, checks and reports: the spatial beam
models (``beam3d``: one builder per 3D element, clamp, pins, tip force and tip moment,
St-Venant's torsion constant, static solve) and the
thin-plate models (``plate``: simply supported rectangle, clamped strip, edge load;
meshes in ``plate_mesh``).
"""
