"""Elements: a basis (a generated shape-function family bound to a mesh at elements x
quadrature points, ``basis``) plus a strain model (``green2d``, ``green3d``, Dufva's
belt densities, the thin plate) plus a material (``material``): the papers' planar
beams (``linear2d``, ``omar_shabana``), Dufva's 2D and 3D belt elements (``dufva2d``,
``belt3d``), the 3D beam (``linear3d``) and the thin plate (``plate36``); ``contract``
what every element provides, ``catalogue`` the one list of them.  ``_*generated.py``
are written by the generators in ``analytic/``.
"""
