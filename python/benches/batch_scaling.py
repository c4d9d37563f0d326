"""`curvekit batch antipodal` over random periodic cubics of 8 to 20 points (the outlines of
examples/dask_antipodal.py), on one thread and on two: curves per second and the speed-up.

    python benches/batch_scaling.py [N] [path/to/curvekit]
"""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "python" / "examples"))
from outlines import outline_documents  # noqa: E402


def main(n: int, tool: str) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        inputs = Path(tmp) / "outlines.jsonl"
        inputs.write_text("".join(json.dumps(d) + "\n" for d in outline_documents(n)))
        seconds = {}
        for jobs in (1, 2):
            t0 = time.perf_counter()
            subprocess.run(
                [tool, "batch", "antipodal", str(inputs), "--jobs", str(jobs),
                 "--out", str(Path(tmp) / f"out{jobs}.jsonl")],
                check=True,
            )
            seconds[jobs] = time.perf_counter() - t0
            print(f"--jobs {jobs}: {seconds[jobs]:.2f} s, {n / seconds[jobs]:.0f} curves/s")
        same = (Path(tmp) / "out1.jsonl").read_bytes() == (Path(tmp) / "out2.jsonl").read_bytes()
        print(f"speed-up on two threads: {seconds[1] / seconds[2]:.2f}x; same output: {same}")


if __name__ == "__main__":
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 10_000
    main(count, sys.argv[2] if len(sys.argv) > 2 else str(ROOT / "target" / "release" / "curvekit"))
