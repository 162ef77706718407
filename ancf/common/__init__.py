"""The leaf every layer may use: scene and reference parameters with their ranges
(``params``), the input-error type, shared input rules (``inputs``), strict JSON,
floating-point warnings as one line, the CPU time spent compiling or loading numba kernels
(``compile_time``), the BLAS thread pin, the machine record, the checkout's folders
(``paths``), the layer rule (``layers``) and compile-time dispatch on a record's type
for compiled code (``dispatch``).  Imports nothing of the project.
"""
