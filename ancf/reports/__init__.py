"""The report generator (``python -m ancf.reports``): one module per chapter of
``reports/``, each declaring itself to the chapter registry (``chapter``), ``published`` the
transcribed published values, ``output`` the shared writing helpers.
"""
