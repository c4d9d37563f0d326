"""The generated outlines of the examples and benchmarks: periodic cubic B-splines on 8 to 20
points around a star-shaped polygon (plain documents, so that anything can read them)."""

from __future__ import annotations

import math
import random


def outline_document(rng: random.Random) -> dict:
    """One outline as a curve document of the tool's format."""
    k = rng.randint(8, 20)
    points = []
    for i in range(k):
        a = 2 * math.pi * (i + rng.uniform(-0.3, 0.3)) / k
        r = rng.uniform(0.6, 1.4)
        points.append([r * math.cos(a), r * math.sin(a)])
    return {"kind": "bspline", "degree": 3, "periodic": True, "points": points}


def outline_documents(n: int, seed: int = 1) -> list:
    """``n`` outlines drawn from ``seed``."""
    rng = random.Random(seed)
    return [outline_document(rng) for _ in range(n)]
