"""A typed use of the package, checked by `mypy --strict` (python/tests/test_typing.py): the
stubs must describe what the wrapper takes and gives, one curve or a list of them."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

import curvekit


def widest_grasp(outline: curvekit.Curve) -> float:
    grasps: curvekit.Antipodal = curvekit.antipodal(outline)
    distances: npt.NDArray[np.float64] = grasps.distances
    return float(distances.max()) if len(grasps) else 0.0


def most_robust(outlines: list[curvekit.Curve], friction: float) -> list[float]:
    found: list[curvekit.Grasps] = curvekit.grasps(outlines, friction, max_width=5.0)
    best: list[float] = []
    for g in found:
        regions: list[curvekit.GraspRegion] = g.regions
        best.append(min((r.best.min_friction for r in regions), default=float("inf")))
    one: curvekit.Grasps = curvekit.grasps(outlines[0], friction)
    contact: curvekit.ContactRegion | None = one.regions[0].contact if one.regions else None
    if contact is not None:
        best.append(float(contact.s[1] - contact.s[0]))
    return best


def carve_all(paths: list[str]) -> list[curvekit.VCarve]:
    carved: list[curvekit.VCarve] = curvekit.vcarve(paths, angle=60.0, max_depth=2.0)
    return carved


def passes(region: curvekit.Curve) -> bytes:
    found: curvekit.Offsets = curvekit.offset(region, step=0.25)
    return found.dxf()


def main() -> None:
    outline = curvekit.BSpline([[0, 0], [2, -1], [4, 0], [4, 2], [2, 1.2], [0, 2]], periodic=True)
    print(widest_grasp(outline), curvekit.__version__, most_robust([outline], 0.3))
    axes: list[curvekit.MedialAxis] = curvekit.medial([outline, curvekit.Circle(1.0)])
    print([a.certified for a in axes])
    bisectors: list[curvekit.Bisector] = curvekit.bisector([outline], method="f3")
    print(len(bisectors), len(passes(curvekit.Circle(2.0))))


if __name__ == "__main__":
    main()
