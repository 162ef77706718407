"""The belt drive in one place: the wrapped path round any sequence of pulleys and the laid
belt (``path``), a drive as data (``drive_data``) read from a TOML drive file
(``drive_file``) and its steady reference (``drive_steady``: ``analytic/belt_steady.py``
on it), the pulley laws (``pulleys``, Eqs 3.29-3.30, 4.46-4.47), distributed penalty
contact in 2D and 3D (``contact2d``, ``contact3d``) with its friction laws (``friction/``,
one module each), a tensioner's arm in 2D (``arm2d``), the assembled drive models
(``drive2d``, ``drive3d``), their compiled forces as named
records (``forces``) and the bordered system they form for the shared generalised-alpha
march (``system``), time integration (``dynamics``; ``bdf`` the scipy cross-check), the
static pre-tension (``pretension``), the axially moving (ALE) 2D belt (``ale2d``) and its
steady running state by Newton (``steady2d``), post-processing (``post2d``, ``post3d``)
and the axial strain measures of thesis 4.2 (``strains``).
"""
