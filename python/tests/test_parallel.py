"""Pickling round trips, GIL release (threads run faster than one), and the Dask example."""

from __future__ import annotations

import os
import pickle
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

import curvekit
from conftest import FIXTURES

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "examples"))
import dask_antipodal  # noqa: E402


@pytest.mark.parametrize(
    "name, pick",
    [
        ("periodic_cubic.json", None),
        ("drawing-glyph-d.svg", 1),
        ("drawing-plate.dxf", 0),
        ("profile-cam.json", None),
    ],
)
def test_curves_pickle_as_their_source(name, pick):
    curve = curvekit.read(str(FIXTURES / name), pick=pick)
    again = pickle.loads(pickle.dumps(curve))
    assert (again.kind, again.name, again.domain) == (curve.kind, curve.name, curve.domain)
    assert curvekit.antipodal(again) == curvekit.antipodal(curve)
    prepared = pickle.loads(pickle.dumps(curvekit.prepare(curve)))
    assert curvekit.antipodal(prepared) == curvekit.antipodal(curve)


def test_results_pickle_as_their_documents():
    cubic = curvekit.read(str(FIXTURES / "periodic_cubic.json"))
    cam = curvekit.read(str(FIXTURES / "profile-cam.json"))
    circle = curvekit.read(str(FIXTURES / "circle.json"))
    results = [
        curvekit.antipodal(cubic),
        curvekit.antipodal(cam),
        curvekit.inflections(cubic),
        curvekit.inflections(cam),
        curvekit.tangents(cubic, circle),
        curvekit.tangents(cam, curvekit.read(str(FIXTURES / "open_quadratic.json"))),
        curvekit.bisector(cubic, chord_tol=1e-2),
        curvekit.bisector(cam),
        curvekit.medial(cubic, fit=True),
        curvekit.offset(cubic, step=0.2),
    ]
    for result in results:
        again = pickle.loads(pickle.dumps(result))
        assert type(again) is type(result)
        assert again == result
        assert again.to_dict() == result.to_dict()


def test_threads_run_faster_than_one():
    """The GIL is released while a curve is computed: two threads beat one on two cores."""
    if (os.cpu_count() or 1) < 2:
        pytest.skip("one core")
    n = 300

    def timed(workers: int) -> float:
        curves = dask_antipodal.outlines(n, seed=3)
        t0 = time.perf_counter()
        with ThreadPoolExecutor(max_workers=workers) as pool:
            list(pool.map(dask_antipodal.grasp_count, curves))
        return time.perf_counter() - t0

    # (Best of five each, alternating, so that a busy moment of the machine does not decide;
    # with the GIL held, two threads could not beat one at all.)
    serial, threaded = float("inf"), float("inf")
    for _ in range(5):
        serial = min(serial, timed(1))
        threaded = min(threaded, timed(2))
    assert serial / threaded > 1.25, f"one thread {serial:.3f} s, two {threaded:.3f} s"


def test_the_dask_example_gives_the_serial_answers():
    report = dask_antipodal.main(n=60, workers=2)
    assert report["curves"] == 60
    assert report["pairs"] > 0
