"""Elements: a basis (a generated shape-function family bound to a mesh at elements x
quadrature points, ``basis``, which also gives the layers above the generated shape
functions) plus a strain model (``green2d``, ``green3d``, Dufva's belt densities, the
thin plate) plus a material (``material``): the papers' planar beams (``linear2d``,
``omar_shabana``), Dufva's 2D and 3D belt elements (``dufva2d``, ``belt3d``), the 3D
beam (``linear3d``) and the thin plate (``plate36``); Chrono's ANCF family
(``ancf3243``, ``ancf3333`` beams, ``ancf3443``, ``ancf3833`` shells, ``ancf3843`` brick:
their shape functions on ``continuum3d``'s Green-Lagrange continuum, mass, gravity,
internal force and its Jacobians checked against Chrono's stored matrices,
``tests/data/chrono``; in the registry through ``chrono_element``) and its gradient-deficient
cable (``cable3d``); ``registry`` the one
table of them (with the field at points), ``catalogue`` its views by use, ``contract`` what every
element provides.  ``_*generated.py`` are written by the generators in ``analytic/``
and imported only here.
"""
