"""The report generator's heartbeat: ``python -m ancf.reports.heartbeat LABEL EVERY``.

A small process beside each generator process reads that process's progress lines on
stdin and, whenever no line came for ``EVERY`` seconds, prints to stderr what is running
and for how long.  A separate process, because a compiled belt march holds the GIL for
minutes: a thread of the generator itself could not speak then.  It ends when its stdin
closes (the generator ended, however it ended).
"""
from __future__ import annotations

import os
import select
import sys
import time


def beat(label: str, every: float, stream=sys.stdin, out=sys.stderr) -> None:
    """Relay nothing, but report ``label``'s current step after ``every`` s of silence."""
    t0 = last = since = time.time()
    step = "starting"
    fd = stream.fileno()
    while True:
        ready, _, _ = select.select([fd], [], [], 1.0)
        now = time.time()
        if ready:
            line = os.read(fd, 65536).decode(errors="replace")
            if not line:
                return
            step = line.strip().splitlines()[-1] or step
            last = since = now
        elif now - last >= every:
            print(f"[{time.strftime('%H:%M:%S')}] {label}: still running {step} "
                  f"({now - since:.0f} s in this step, {now - t0:.0f} s in all)",
                  file=out, flush=True)
            last = now


if __name__ == "__main__":
    beat(sys.argv[1], float(sys.argv[2]))
