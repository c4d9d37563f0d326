"""Exact plane curve pieces for the independent oracle: lines, Béziers, elliptic arcs and NURBS.

Written from the textbook formulas, not from curvekit, so that the oracle's answers do not share
curvekit's mistakes. Every piece is parametrised on [0, 1] and gives its point and first two
derivatives there; `flatten` samples it so that no chord strays more than a given distance from it.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.interpolate import BSpline


class Piece:
    """A parametric curve piece on t in [0, 1]."""

    def points(self, t: np.ndarray) -> np.ndarray:
        raise NotImplementedError

    def derivatives(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """First and second derivatives (each len(t) x 2)."""
        raise NotImplementedError

    def second_derivative_bound(self) -> float | None:
        """An upper bound of |C''(t)| on [0, 1], or None when there is no cheap one."""
        return None

    def flatten(self, tol: float) -> np.ndarray:
        """Parameters whose chords stay within `tol` of the piece (chord error <= h^2 max|C''| / 8)."""
        bound = self.second_derivative_bound()
        if bound is None:
            probe = np.linspace(0.0, 1.0, 257)
            _, second = self.derivatives(probe)
            bound = 4.0 * float(np.max(np.hypot(second[:, 0], second[:, 1]))) + 1e-300
        count = max(2, int(math.ceil(math.sqrt(bound / (8.0 * tol)))) + 1)
        return np.linspace(0.0, 1.0, min(count, 200_000))

    @property
    def start(self) -> np.ndarray:
        return self.points(np.array([0.0]))[0]

    @property
    def end(self) -> np.ndarray:
        return self.points(np.array([1.0]))[0]

    def tangent(self, t: float) -> np.ndarray:
        """Unit tangent at t, taking the limit direction where the derivative vanishes."""
        first, second = self.derivatives(np.array([t]))
        direction = first[0]
        if np.hypot(*direction) < 1e-12 * (np.hypot(*second[0]) + 1e-300):
            step = 1e-6 if t < 0.5 else -1e-6
            direction = (self.points(np.array([t + step]))[0] - self.points(np.array([t]))[0]) * np.sign(step)
        return direction / np.hypot(*direction)


class Line(Piece):
    def __init__(self, start, end):
        self.p0 = np.asarray(start, float)
        self.p1 = np.asarray(end, float)

    def points(self, t):
        t = np.asarray(t, float)[:, None]
        return self.p0 * (1.0 - t) + self.p1 * t

    def derivatives(self, t):
        n = len(t)
        return np.tile(self.p1 - self.p0, (n, 1)), np.zeros((n, 2))

    def second_derivative_bound(self):
        return 0.0

    def flatten(self, tol):
        return np.array([0.0, 1.0])


class Bezier(Piece):
    """A polynomial Bézier piece of any degree (the SVG and font pieces are 2 and 3)."""

    def __init__(self, control):
        self.control = np.asarray(control, float)

    @staticmethod
    def _evaluate(control: np.ndarray, t: np.ndarray) -> np.ndarray:
        """de Casteljau on every t at once."""
        t = np.asarray(t, float)[:, None, None]
        work = np.broadcast_to(control, (len(t),) + control.shape).copy()
        for _ in range(len(control) - 1):
            work = work[:, :-1] * (1.0 - t) + work[:, 1:] * t
        return work[:, 0]

    def points(self, t):
        return self._evaluate(self.control, t)

    def derivatives(self, t):
        degree = len(self.control) - 1
        first_control = degree * np.diff(self.control, axis=0)
        first = self._evaluate(first_control, t)
        if degree < 2:
            return first, np.zeros_like(first)
        second = self._evaluate((degree - 1) * np.diff(first_control, axis=0), t)
        return first, second

    def second_derivative_bound(self):
        degree = len(self.control) - 1
        if degree < 2:
            return 0.0
        second = degree * (degree - 1) * np.diff(self.control, n=2, axis=0)
        return float(np.max(np.hypot(second[:, 0], second[:, 1])))


class EllipticArc(Piece):
    """center + u cos(phi) + v sin(phi) for phi from phi0 to phi1 (u, v conjugate semi-diameters).

    This form survives any affine map exactly, so SVG arcs under transforms and DXF arcs in an
    object coordinate system become the same piece.
    """

    def __init__(self, center, u, v, phi0: float, phi1: float):
        self.center = np.asarray(center, float)
        self.u = np.asarray(u, float)
        self.v = np.asarray(v, float)
        self.phi0 = float(phi0)
        self.phi1 = float(phi1)

    def _angles(self, t):
        return self.phi0 + np.asarray(t, float) * (self.phi1 - self.phi0)

    def points(self, t):
        phi = self._angles(t)[:, None]
        return self.center + self.u * np.cos(phi) + self.v * np.sin(phi)

    def derivatives(self, t):
        phi = self._angles(t)[:, None]
        sweep = self.phi1 - self.phi0
        first = sweep * (-self.u * np.sin(phi) + self.v * np.cos(phi))
        second = -sweep * sweep * (self.u * np.cos(phi) + self.v * np.sin(phi))
        return first, second

    def second_derivative_bound(self):
        sweep = self.phi1 - self.phi0
        return sweep * sweep * (np.hypot(*self.u) + np.hypot(*self.v))

    def angle_of(self, point) -> float:
        """The angle phi at which the full ellipse passes through `point`."""
        matrix = np.column_stack([self.u, self.v])
        cosine, sine = np.linalg.solve(matrix, np.asarray(point, float) - self.center)
        return math.atan2(sine, cosine)


class Nurbs(Piece):
    """A (rational) B-spline on [knots[p], knots[n]], or on a sub-range of it, mapped to [0, 1]."""

    def __init__(self, degree: int, knots, control, weights=None, domain=None):
        self.degree = int(degree)
        self.knots = np.asarray(knots, float)
        control = np.asarray(control, float)
        weights = np.ones(len(control)) if weights is None else np.asarray(weights, float)
        homogeneous = np.column_stack([control * weights[:, None], weights])
        self.spline = BSpline(self.knots, homogeneous, self.degree, extrapolate=False)
        n = len(control)
        self.domain = domain or (float(self.knots[self.degree]), float(self.knots[n]))

    def _u(self, t):
        """Knot values, kept a rounding step inside the domain so that each end takes its
        derivatives from its own knot span (scipy's spans are closed on the left)."""
        low, high = self.domain
        u = low + np.asarray(t, float) * (high - low)
        return np.clip(u, np.nextafter(low, high), np.nextafter(high, low))

    def points(self, t):
        h = self.spline(self._u(t))
        return h[:, :2] / h[:, 2:3]

    def derivatives(self, t):
        u = self._u(t)
        scale = self.domain[1] - self.domain[0]
        h = self.spline(u)
        h1 = self.spline(u, nu=1)
        h2 = self.spline(u, nu=2) if self.degree >= 2 else np.zeros_like(h)
        w, w1, w2 = h[:, 2:3], h1[:, 2:3], h2[:, 2:3]
        point = h[:, :2] / w
        first = (h1[:, :2] - w1 * point) / w
        second = (h2[:, :2] - 2.0 * w1 * first - w2 * point) / w
        return first * scale, second * scale * scale

    def flatten(self, tol):
        """Uniform in each knot span, as dense as that span's sampled second derivative needs."""
        low, high = self.domain
        breaks = np.unique(np.clip(self.knots, low, high))
        params = [np.array([0.0])]
        for a, b in zip(breaks[:-1], breaks[1:]):
            if b <= a:
                continue
            local = np.linspace(0.0, 1.0, 65)
            t = (a + local * (b - a) - low) / (high - low)
            _, second = self.derivatives(t)
            bound = 4.0 * float(np.max(np.hypot(second[:, 0], second[:, 1]))) * ((b - a) / (high - low)) ** 2
            count = max(2, int(math.ceil(math.sqrt(bound / (8.0 * tol)))) + 1)
            params.append(((a - low) + np.linspace(0.0, 1.0, min(count, 50_000))[1:] * (b - a)) / (high - low))
        return np.concatenate(params)

    def c0_breaks(self) -> list[float]:
        """Interior knots of multiplicity >= degree, as t in [0, 1]: where the curve may turn a corner."""
        low, high = self.domain
        values, counts = np.unique(self.knots, return_counts=True)
        return [
            float((value - low) / (high - low))
            for value, count in zip(values, counts)
            if low < value < high and count >= self.degree
        ]

    def restricted(self, t0: float, t1: float) -> "Nurbs":
        low, high = self.domain
        piece = Nurbs.__new__(Nurbs)
        piece.__dict__.update(self.__dict__)
        piece.domain = (low + t0 * (high - low), low + t1 * (high - low))
        return piece


def curvature_numerator(piece: Piece, t: np.ndarray) -> np.ndarray:
    """cross(C', C''): its sign is the sign of the curvature."""
    first, second = piece.derivatives(t)
    return first[:, 0] * second[:, 1] - first[:, 1] * second[:, 0]


class Ring:
    """A closed chain of pieces, each starting where the previous one ends."""

    def __init__(self, pieces: list[Piece], label: str):
        self.pieces = pieces
        self.label = label
        self._flat: dict[float, tuple[np.ndarray, np.ndarray, np.ndarray]] = {}

    def flatten(self, tol: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Points (closed: the first is not repeated), and each point's piece index and parameter."""
        if tol not in self._flat:
            points, owners, params = [], [], []
            for index, piece in enumerate(self.pieces):
                t = piece.flatten(tol)[:-1]
                points.append(piece.points(t))
                owners.append(np.full(len(t), index))
                params.append(t)
            self._flat[tol] = (np.concatenate(points), np.concatenate(owners), np.concatenate(params))
        return self._flat[tol]

    def signed_area(self, tol: float) -> float:
        points, _, _ = self.flatten(tol)
        x, y = points[:, 0], points[:, 1]
        return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))

    def project(self, point, tol: float) -> tuple[int, float, float]:
        """(piece index, t, distance) of the point of the ring nearest `point` (Newton-refined)."""
        points, owners, params = self.flatten(tol)
        point = np.asarray(point, float)
        nearest = np.argsort(self.chord_distances(point, tol))[:4]
        best = None
        for index in nearest:
            for owner, t in ((int(owners[index]), float(params[index])), (int(owners[index - 1]), 1.0)):
                piece = self.pieces[owner]
                t = refine_foot(piece, point, t)
                distance = float(np.hypot(*(piece.points(np.array([t]))[0] - point)))
                if best is None or distance < best[2]:
                    best = (owner, t, distance)
        return best

    def chord_distances(self, point, tol: float) -> np.ndarray:
        """Distance from `point` to each chord of the flattened ring (chord i starts at point i)."""
        points = self.flatten(tol)[0]
        starts, ends = points, np.roll(points, -1, axis=0)
        along = ends - starts
        length2 = np.maximum(np.einsum("ij,ij->i", along, along), 1e-300)
        s = np.clip(np.einsum("ij,ij->i", np.asarray(point, float) - starts, along) / length2, 0.0, 1.0)
        return np.hypot(*(starts + along * s[:, None] - point).T)

    def joint_turn(self, index: int) -> float:
        """Signed angle from the tangent at the end of piece index-1 to the start of piece index."""
        incoming = self.pieces[index - 1].tangent(1.0)
        outgoing = self.pieces[index].tangent(0.0)
        return math.atan2(incoming[0] * outgoing[1] - incoming[1] * outgoing[0], float(incoming @ outgoing))


def refine_foot(piece: Piece, point: np.ndarray, t: float) -> float:
    """Newton's method on (C(t) - P) . C'(t) = 0, kept in [0, 1]."""
    for _ in range(30):
        at = np.array([t])
        position = piece.points(at)[0]
        first, second = piece.derivatives(at)
        first, second = first[0], second[0]
        residual = (position - point) @ first
        slope = first @ first + (position - point) @ second
        if slope <= 0.0:
            break
        step = residual / slope
        t_new = min(1.0, max(0.0, t - step))
        if abs(t_new - t) < 1e-15:
            t = t_new
            break
        t = t_new
    return t
