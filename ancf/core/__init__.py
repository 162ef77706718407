"""The core model: named blocks of global coordinates (``registry``), meshes on any
reference curve (``mesh``), element groups (``assembly``), elimination and Lagrange
constraints, force terms and energies, Gauss quadrature and sections, the reduced
system's sparsity computed once with its compiled scatter (``pattern``) and the
inverted-element check (``validity``).  Knows no element and no solver.
"""
