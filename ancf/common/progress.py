"""Progress lines of one long run on stderr: a line at most every :data:`TTY_EVERY_S`
seconds on a terminal and at least every :data:`PIPED_EVERY_S` seconds of a run whose
stderr is piped or logged (issue 38: a 66 s THREAD run printed nothing when piped), so
a run that takes less than that prints nothing and its stderr stays errors and warnings.
The caller calls the ticker at points of the run (a march's chunks); it prints when
enough wall time has passed since its last line."""
from __future__ import annotations

import sys
import time

#: seconds between lines on a terminal
TTY_EVERY_S = 2.0
#: seconds between lines when stderr is not a terminal (below the 20 s a reader waits)
PIPED_EVERY_S = 15.0


class Ticker:
    """``ticker(t)`` at simulated time t (s) of a run ending at ``t_end`` (s) prints
    ``progress: label: t = ... / t_end s (elapsed s)`` (stderr's lines are ``error:``,
    ``warning:`` or ``progress:``) when ``every`` wall seconds have passed since
    the last line (or the start)."""

    def __init__(self, label: str, t_end: float, every: float | None = None, stream=None):
        self.stream = sys.stderr if stream is None else stream
        tty = getattr(self.stream, "isatty", lambda: False)()
        self.label, self.t_end = label, float(t_end)
        self.every = every if every is not None else (TTY_EVERY_S if tty else PIPED_EVERY_S)
        self.start = self.last = time.monotonic()

    def __call__(self, t: float) -> None:
        now = time.monotonic()
        if now - self.last >= self.every:
            print(f"progress: {self.label}: t = {t:.4g} / {self.t_end:g} s "
                  f"({now - self.start:.0f} s)",
                  file=self.stream, flush=True)
            self.last = now
