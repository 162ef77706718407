"""The leaf every layer may use: scene and reference parameters with their ranges
(``params``), the input-error type, shared input rules (``inputs``), strict JSON,
floating-point warnings as one line, the CPU time spent compiling or loading numba kernels
(``compile_time``), the BLAS thread pin, numba's BLAS module loaded without the rest of
scipy.linalg (``blas``), numba loaded without PyYAML and a run's process ended without
the interpreter's shutdown (``process_start``), the machine record, the checkout's folders
(``paths``, with the modules a folder declares in order), progress lines of long runs (``progress``), the layer rule (``layers``), compile-time dispatch on a record's type
for compiled code with records as struct references (``dispatch``) and the compiled
leaf functions that skip reference counting (``leaf``).  Imports nothing of the project.
"""
