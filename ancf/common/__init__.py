"""The leaf every layer may use: scene and reference parameters with their ranges
(``params``), the input-error type, shared input rules (``inputs``), strict JSON,
floating-point warnings as one line, the CPU time spent compiling or loading numba kernels
(``compile_time``), the BLAS thread pin and the machine record.
Imports nothing of the project.
"""
