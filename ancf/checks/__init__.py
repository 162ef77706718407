"""Acceptance checks computed from runs, each returning rows a report prints and a
test pins: the belt element on its own (``belt_element``), the 2D belt drive
(``belt2d``), the thin plate and 3D beam (``elements3d``), the 3D belt drive
(``belt3d``) and its tracking on a tilted pulley (``belt_tracking3d``), the 3D beam benchmarks: Princeton beam, 3D general bending, tip moments
(``beam3d_benchmarks``); Chrono's ANCF elements: its stored element matrices
(``chrono_matrices``), its textbook static cases and the shells' square plate
(``chrono_elements``), the Princeton beam on its 3243/3333 beams against ANSYS
(``chrono_princeton``), why the beams' u_z and the 3443's f4-f6 miss at the acceptance
mesh (``chrono_locking``), its stored time histories of the 3423 plate
(``chrono_shell3423``) and of the spinning cable (``chrono_cable``).
"""
