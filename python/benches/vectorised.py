"""A vectorised call over N curves (`curvekit.antipodal(list)`, parallel on rayon with the GIL
released) against `curvekit batch antipodal` over the same curves (a JSON-lines file), on every
core; the curves are the random periodic cubics of examples/outlines.py. Each side is timed from
its inputs at hand to its answers: the Python call from the list of Curves to the list of
results, the batch from the file to its JSON lines written. Median of REPEATS runs.

    python benches/vectorised.py [N] [path/to/curvekit]
"""

from __future__ import annotations

import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "python" / "examples"))
from outlines import outline_documents  # noqa: E402

import curvekit  # noqa: E402

REPEATS = 5


def main(n: int, tool: str) -> None:
    documents = outline_documents(n)
    curves = [curvekit.from_dict(d, f"outline {k}") for k, d in enumerate(documents)]
    with tempfile.TemporaryDirectory() as tmp:
        inputs = Path(tmp) / "outlines.jsonl"
        inputs.write_text("".join(json.dumps(d) + "\n" for d in documents))
        batch, python = [], []
        for _ in range(REPEATS):
            t0 = time.perf_counter()
            subprocess.run([tool, "batch", "antipodal", str(inputs), "--out", str(Path(tmp) / "out.jsonl")], check=True)
            batch.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            found = curvekit.antipodal(curves)
            python.append(time.perf_counter() - t0)
            assert len(found) == n
    b, p = statistics.median(batch), statistics.median(python)
    print(f"{n} curves: batch {b:.3f} s, vectorised Python {p:.3f} s: {100 * (p / b - 1):+.1f} %")


if __name__ == "__main__":
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 10_000
    main(count, sys.argv[2] if len(sys.argv) > 2 else str(ROOT / "target" / "release" / "curvekit"))
