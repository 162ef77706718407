"""Closed-form and semi-analytic references, one file each (Timoshenko, Reissner,
Bechtel, Bechtel's belt on N pulleys with its own wrapped path, Navier, the dynamic
references, the natural frequencies of beams, plates and the moving string and beam, the
rotational modes of a serpentine drive (its wraps stuck or creeping), the steady belt
span with bending), and the SymPy generators of the shape functions and of the belt and
plate energy densities.  Imports
nothing of ``ancf`` but the leaf ``ancf.common``.
"""
