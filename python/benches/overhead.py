"""The Python call's overhead over the Rust call, on warm prepared curves of the papers'
shapes: the median time of `curvekit.antipodal(prepared)` against the median the tool's
`--time` reports for the same warm run (both release builds).

    python benches/overhead.py [path/to/curvekit]
"""

from __future__ import annotations

import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

import curvekit

ROOT = Path(__file__).resolve().parents[2]
SHAPES = [
    "antipodal-limacon.json",
    "antipodal-ellipse.json",
    "antipodal-lemniscate.json",
    "antipodal-convexities-3.json",
    "antipodal-convexities-4.json",
    "antipodal-bspline-interfaces.json",
    "antipodal-bspline-wavy.json",
    "periodic_cubic.json",
    "periodic_nurbs.json",
]


def python_median_us(prepared: curvekit.PreparedCurve, budget: float = 0.5) -> float:
    times = []
    start = time.perf_counter()
    while len(times) < 3 or time.perf_counter() - start < budget:
        t0 = time.perf_counter()
        curvekit.antipodal(prepared)
        times.append(time.perf_counter() - t0)
    return statistics.median(times) * 1e6


def rust_median_us(tool: str, path: str) -> float:
    done = subprocess.run(
        [tool, "antipodal", path, "--time", "--json"], capture_output=True, text=True, check=True
    )
    return json.loads(done.stdout)["stats"]["median_us"]


def main(tool: str, rounds: int = 5) -> None:
    """The least median of `rounds` alternating measurements of each (a busy moment of the
    machine only ever slows one down)."""
    print(f"{'shape':<36} {'rust µs':>9} {'python µs':>10} {'overhead':>9}")
    for name in SHAPES:
        path = str(ROOT / "fixtures" / name)
        prepared = curvekit.prepare(curvekit.read(path))
        rust, py = float("inf"), float("inf")
        for _ in range(rounds):
            rust = min(rust, rust_median_us(tool, path))
            py = min(py, python_median_us(prepared))
        print(f"{name:<36} {rust:>9.2f} {py:>10.2f} {100 * (py / rust - 1):>8.1f}%")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "target" / "release" / "curvekit"))
