"""Start-up time of the command line: the median wall time of `mechloop --help`.

Runs the installed `mechloop` (next to this Python) several times and prints each time and
the median. The figure depends on the machine and its load; the target is under 0.5 s.

    .venv/bin/python benchmarks/bench_startup.py
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import time
from pathlib import Path

RUNS = 9


def main() -> None:
    script = Path(sys.executable).with_name("mechloop")
    times = []
    for _ in range(RUNS):
        start = time.perf_counter()
        subprocess.run([str(script), "--help"], check=True, capture_output=True)
        times.append(time.perf_counter() - start)
    print("runs [s]: " + " ".join(f"{t:.3f}" for t in times))
    print(f"mechloop --help, median of {RUNS}: {statistics.median(times):.2f} s")


if __name__ == "__main__":
    main()
