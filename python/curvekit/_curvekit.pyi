"""Type stubs of the native module (the classes and functions `curvekit` re-exports)."""

from os import PathLike
from typing import Any, Literal, Optional, Union

import numpy as np
import numpy.typing as npt

class InputError(ValueError):
    """Bad input: the message names the file (or the name given), the field and the problem."""

class CurvekitError(Exception):
    """A computation that could not be carried out (the tool's exit status 1)."""

class Curve:
    """A curve, profile or region as the tool reads it; immutable; pickles as its source."""

    @staticmethod
    def from_json(text: str, name: str = "curve") -> Curve: ...
    @property
    def kind(self) -> str: ...
    @property
    def name(self) -> str: ...
    @property
    def closed(self) -> bool: ...
    @property
    def domain(self) -> tuple[float, float]: ...
    def evaluate(self, u: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
        """Points at the parameters `u`, an (n, 2) array."""
    def to_json(self) -> str:
        """The curve's JSON document (a drawing: what it was read as)."""
    def to_dict(self) -> dict[str, Any]:
        """The curve's JSON document."""
    @property
    def outer(self) -> Curve:
        """The outer boundary of the region the curve is or encloses."""
    @property
    def holes(self) -> list[Curve]:
        """The holes of the region the curve is."""
    @property
    def parts(self) -> list[Curve]:
        """The disjoint regions of the curve."""
    @property
    def __geo_interface__(self) -> dict[str, Any]:
        """GeoJSON geometry, flattened within 1e-3 of the size."""

class PreparedCurve:
    """A curve prepared once for many antipodal and inflection runs (they answer warm)."""

    @property
    def curve(self) -> Curve: ...

class _Result:
    skipped: Optional[list[dict[str, Any]]]
    """What the input drawing held and was not read: [{"type", "count"}] (None for a curve file)."""
    units: Optional[str]
    """The unit of the input drawing's coordinates, where it says ("mm", "in", …)."""
    def to_json(self) -> str:
        """The tool's --json document, as one JSON text."""
    def to_dict(self) -> dict[str, Any]:
        """The tool's --json document."""

class _Certified(_Result):
    """What the results that say whether they are certified share (in the stubs only, as `_Result`)."""

    certified: bool

class _Verdict(_Certified):
    """What the results that also say whether they are complete, and why not certified, share."""

    complete: bool
    reason: Optional[str]

class Antipodal(_Verdict):
    pairs: npt.NDArray[np.float64]
    """(n, 2): the parameters (s, t) of each pair, sorted by s."""
    points: npt.NDArray[np.float64]
    """(n, 2, 2): the points (p, q) of each pair."""
    distances: npt.NDArray[np.float64]
    types: list[Optional[str]]
    inflections: npt.NDArray[np.float64]
    families: npt.NDArray[np.float64]
    """(k, 2, 2): [[s0, s1], [t0, t1]] of each family of non-isolated pairs."""
    def __len__(self) -> int: ...

class Inflections(_Certified):
    params: npt.NDArray[np.float64]
    points: npt.NDArray[np.float64]
    corners: npt.NDArray[np.float64]
    def __len__(self) -> int: ...

class Tangents(_Certified):
    params: npt.NDArray[np.float64]
    points: npt.NDArray[np.float64]
    def __len__(self) -> int: ...

class Bisector(_Result):
    complete: bool
    branches: list[tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]]
    """Each branch as (tr, xy): foot-point parameters and bisector points, (k, 2) each."""
    def __len__(self) -> int: ...

class MedialAxis(_Verdict):
    nodes: npt.NDArray[np.float64]
    node_radii: npt.NDArray[np.float64]
    node_kinds: list[str]
    node_parts: npt.NDArray[np.uintp]
    """(n,): the part of a multi-part input each node belongs to (0 for one part)."""
    edge_parts: npt.NDArray[np.uintp]
    edges: list[tuple[int, int, npt.NDArray[np.float64], npt.NDArray[np.float64]]]
    """Each edge as (from, to, xy (k, 2), radius (k,))."""
    def dxf(self) -> bytes:
        """The axis as a DXF file's bytes (edges as splines or polylines, nodes as points)."""
    def svg_paths(self) -> str:
        """The axis as plain SVG paths in the input's coordinates."""

class VCarve(_Verdict):
    angle: float
    max_depth: Optional[float]
    paths: list[npt.NDArray[np.float64]]
    """Each tool path as an (n, 3) array of (x, y, z), z <= 0 the depth: over the axis, then
    along each flat pass at -max_depth."""
    path_parts: list[int]
    def flats(self, arc_points: int = 32) -> list[npt.NDArray[np.float64]]:
        """The flat passes at depth -max_depth as closed (n, 2) polylines."""
    def dxf(self) -> bytes:
        """The paths as a DXF file's bytes (3D polylines; the flats at their depth)."""
    def __len__(self) -> int: ...

class Offsets(_Verdict):
    distances: npt.NDArray[np.float64]
    def polylines(self, k: int, arc_points: int = 32) -> list[npt.NDArray[np.float64]]:
        """The loops at the k-th distance as closed (n, 2) polylines."""
    def parts(self, k: int) -> list[int]:
        """The part of a multi-part input each loop at the k-th distance belongs to."""
    def regions(self, k: int) -> list[Curve]:
        """The loops at the k-th distance grouped into regions (outer loops with their holes)."""
    def geometry(self, k: int) -> dict[str, Any]:
        """GeoJSON MultiPolygon of the region inside the loops at the k-th distance."""
    @property
    def __geo_interface__(self) -> dict[str, Any]:
        """GeoJSON: one distance's MultiPolygon, or a GeometryCollection of them."""
    def dxf(self) -> bytes:
        """The offsets as a DXF file's bytes (lines, arcs, splines; a layer per distance)."""
    def svg_paths(self) -> str:
        """The offsets as plain SVG paths in the input's coordinates."""
    def __len__(self) -> int: ...

class ContactRegion:
    """An independent contact region: every pair of [s0, s1] x [t0, t1] is force closure (an
    interval may run beyond the domain across the seam: read it modulo the period)."""

    s: npt.NDArray[np.float64]
    """(2,): the first finger's stretch [s0, s1]."""
    t: npt.NDArray[np.float64]
    """(2,): the second finger's stretch [t0, t1]."""
    p: npt.NDArray[np.float64]
    """(2, 2): the ends of the first stretch."""
    q: npt.NDArray[np.float64]
    """(2, 2): the ends of the second stretch."""

class BestGrasp:
    """A region's most robust grasp."""

    s: float
    t: float
    p: npt.NDArray[np.float64]
    """(2,): the first contact."""
    q: npt.NDArray[np.float64]
    """(2,): the second contact."""
    min_friction: float
    """The least friction for which the pair is force closure (0 at an antipodal pair)."""
    toward: npt.NDArray[np.float64]
    """(k, 2): stretches [u0, u1] round corners the region does not reach, toward which its
    least friction falls unattained: pairs with a finger there may need less friction than
    this one, no other pair of the region does (empty where the least is attained)."""

class GraspRegion:
    """A connected region of force-closure pairs (s, t), s < t."""

    boundary: npt.NDArray[np.float64]
    """(n, 2): a closed polyline of pairs (s, t), the region on its left."""
    parts: list[npt.NDArray[np.float64]]
    """Every part in the square (several across the seam), boundary first."""
    holes: list[npt.NDArray[np.float64]]
    contact: Optional[ContactRegion]
    best: BestGrasp
    certified: bool

class Grasps(_Verdict):
    friction: float
    min_width: Optional[float]
    max_width: Optional[float]
    regions: list[GraspRegion]
    def __len__(self) -> int: ...

OneCurve = Union[Curve, PreparedCurve]

__version__: str

def read(path: Union[str, PathLike[str]], *, pick: Optional[int] = None) -> Curve: ...
def prepare(curve: Curve) -> PreparedCurve: ...
def antipodal(curve: OneCurve, *, tol: float = 1e-12) -> Antipodal: ...
def inflections(curve: OneCurve, *, tol: float = 1e-12) -> Inflections: ...
def grasps(
    curve: OneCurve,
    friction: float,
    *,
    min_width: Optional[float] = None,
    max_width: Optional[float] = None,
) -> Grasps: ...
def tangents(curve1: Curve, curve2: Curve, *, tol: float = 1e-12) -> Tangents: ...
def bisector(
    curve1: Curve,
    curve2: Optional[Curve] = None,
    *,
    method: Literal["f1", "f2", "f3"] = "f3",
    trimmed: bool = False,
    chord_tol: float = 1e-3,
    tol: float = 1e-12,
) -> Bisector: ...
def medial(
    region: Curve,
    *,
    chord_tol: float = 1e-3,
    fit: bool = False,
    exterior: bool = False,
    tol: float = 1e-12,
) -> MedialAxis: ...
def offset(
    region: Curve,
    *,
    distance: Optional[float] = None,
    distances: Optional[list[float]] = None,
    step: Optional[float] = None,
    outward: bool = False,
    chord_tol: float = 1e-3,
    tol: float = 1e-12,
) -> Offsets: ...
def vcarve(
    region: Curve,
    *,
    angle: float,
    max_depth: Optional[float] = None,
    chord_tol: float = 1e-3,
    tol: float = 1e-12,
) -> VCarve: ...
def antipodal_many(curves: list[OneCurve], *, tol: float = 1e-12) -> list[Antipodal]: ...
def inflections_many(curves: list[OneCurve], *, tol: float = 1e-12) -> list[Inflections]: ...
def grasps_many(
    curves: list[OneCurve],
    friction: float,
    *,
    min_width: Optional[float] = None,
    max_width: Optional[float] = None,
) -> list[Grasps]: ...
def tangents_many(
    curves1: list[Curve], curves2: list[Curve], *, tol: float = 1e-12
) -> list[Tangents]: ...
def bisector_many(
    curves1: list[Curve],
    curves2: Optional[list[Curve]] = None,
    *,
    method: Literal["f1", "f2", "f3"] = "f3",
    trimmed: bool = False,
    chord_tol: float = 1e-3,
    tol: float = 1e-12,
) -> list[Bisector]: ...
def medial_many(
    regions: list[Curve],
    *,
    chord_tol: float = 1e-3,
    fit: bool = False,
    exterior: bool = False,
    tol: float = 1e-12,
) -> list[MedialAxis]: ...
def offset_many(
    regions: list[Curve],
    *,
    distance: Optional[float] = None,
    distances: Optional[list[float]] = None,
    step: Optional[float] = None,
    outward: bool = False,
    chord_tol: float = 1e-3,
    tol: float = 1e-12,
) -> list[Offsets]: ...
def vcarve_many(
    regions: list[Curve],
    *,
    angle: float,
    max_depth: Optional[float] = None,
    chord_tol: float = 1e-3,
    tol: float = 1e-12,
) -> list[VCarve]: ...
