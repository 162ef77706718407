"""The report generator (``python -m ancf.reports``): one module per chapter of
``reports/``, ``published`` the transcribed published values, ``output`` the shared
writing helpers.
"""
