"""Antipodal grasps of a few thousand generated outlines: one call on the whole list (the
vectorised call, parallel in Rust), scaled out with Dask, and over Python threads.

    python examples/dask_antipodal.py [N] [WORKERS]

The curves are pickled to the workers (as their JSON documents) and ``curvekit.antipodal``
releases the GIL, so the same code runs on a process pool, a thread pool, or a Dask cluster
(``dask.distributed.Client(address)`` in place of the local scheduler).
"""

from __future__ import annotations

import sys
import time
from concurrent.futures import ThreadPoolExecutor

import dask.bag as db

import curvekit
from outlines import outline_documents


def grasp_count(curve: curvekit.Curve) -> tuple[int, bool]:
    """The number of antipodal pairs of one outline, and whether the answer is certified."""
    try:
        r = curvekit.antipodal(curve)
    except curvekit.InputError:
        # (A generated polygon may cross itself: such an outline has no grasps to report.)
        return (0, False)
    return (len(r), r.certified)


def with_dask(curves: list, workers: int) -> list:
    """Grasp counts on Dask's local process pool (the curves travel pickled)."""
    bag = db.from_sequence(curves, npartitions=max(1, 4 * workers))
    return bag.map(grasp_count).compute(scheduler="processes", num_workers=workers)


def with_threads(curves: list, workers: int) -> list:
    """Grasp counts on Python threads (the GIL is released while each curve is computed)."""
    with ThreadPoolExecutor(max_workers=workers) as pool:
        return list(pool.map(grasp_count, curves))


def vectorised(curves: list) -> list:
    """Grasp counts from one call on the whole list (rayon's threads, the GIL released)."""
    return [(len(r), r.certified) for r in curvekit.antipodal(curves)]


def outlines(n: int, seed: int) -> list:
    """``n`` generated outlines as curves (each way of running gets its own, made alike)."""
    return [curvekit.from_dict(doc) for doc in outline_documents(n, seed)]


def main(n: int = 2000, workers: int = 2, seed: int = 1) -> dict:
    curves = outlines(n, seed)
    t0 = time.perf_counter()
    serial = [grasp_count(c) for c in curves]
    curves = outlines(n, seed)
    t1 = time.perf_counter()
    threaded = with_threads(curves, workers)
    curves = outlines(n, seed)
    t2 = time.perf_counter()
    dasked = with_dask(curves, workers)
    t3 = time.perf_counter()
    curves = outlines(n, seed)
    t4 = time.perf_counter()
    listed = vectorised(curves)
    t5 = time.perf_counter()
    assert serial == threaded == dasked == listed, "the same answers whatever runs them"
    return {
        "curves": n,
        "pairs": sum(p for p, _ in serial),
        "certified": sum(c for _, c in serial),
        "serial_s": t1 - t0,
        "threads_s": t2 - t1,
        "dask_s": t3 - t2,
        "vectorised_s": t5 - t4,
    }


if __name__ == "__main__":
    args = [int(a) for a in sys.argv[1:3]]
    report = main(*args)
    for key, value in report.items():
        print(f"{key:>10}: {value:.3f}" if isinstance(value, float) else f"{key:>10}: {value}")
    print(f"   speed-up: threads {report['serial_s'] / report['threads_s']:.2f}x, "
          f"dask {report['serial_s'] / report['dask_s']:.2f}x, "
          f"vectorised {report['serial_s'] / report['vectorised_s']:.2f}x")
