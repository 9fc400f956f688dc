"""Footprint geometry for the generator: boxes (turned about z), discs and
axis-aligned rectangles seen from above. numpy and the standard library only."""

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Foot:
    """A footprint: a disc (`half` = (r, r), yaw ignored) or a box."""

    kind: str  # "box" or "disc"
    center: tuple
    half: tuple
    yaw: float = 0.0

    def moved(self, center, yaw=None):
        return Foot(self.kind, tuple(center), self.half, self.yaw if yaw is None else yaw)

    def vertices(self):
        c, s = np.cos(self.yaw), np.sin(self.yaw)
        hx, hy = self.half
        local = np.array([[hx, hy], [-hx, hy], [-hx, -hy], [hx, -hy]])
        return local @ np.array([[c, s], [-s, c]]) + np.array(self.center)

    def aabb(self):
        """(xmin, ymin, xmax, ymax)."""
        if self.kind == "disc":
            r = self.half[0]
            x, y = self.center
            return (x - r, y - r, x + r, y + r)
        v = self.vertices()
        return (v[:, 0].min(), v[:, 1].min(), v[:, 0].max(), v[:, 1].max())

    def radius(self):
        """The circle around the footprint."""
        return float(np.hypot(*self.half)) if self.kind == "box" else self.half[0]


def rect(xmin, ymin, xmax, ymax):
    return Foot("box", ((xmin + xmax) / 2, (ymin + ymax) / 2), ((xmax - xmin) / 2, (ymax - ymin) / 2))


def _point_segment(p, a, b):
    ab = b - a
    t = np.clip(np.dot(p - a, ab) / max(np.dot(ab, ab), 1e-12), 0.0, 1.0)
    return float(np.linalg.norm(p - (a + t * ab)))


def _inside_convex(p, poly):
    n = len(poly)
    signs = [np.cross(poly[(i + 1) % n] - poly[i], p - poly[i]) for i in range(n)]
    return all(s >= 0 for s in signs) or all(s <= 0 for s in signs)


def _point_poly(p, poly):
    """Signed distance of a point to a convex polygon (negative inside)."""
    d = min(_point_segment(p, poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly)))
    return -d if _inside_convex(p, poly) else d


def _sat_overlap(a, b):
    for poly in (a, b):
        for i in range(len(poly)):
            e = poly[(i + 1) % len(poly)] - poly[i]
            n = np.array([-e[1], e[0]])
            pa, pb = a @ n, b @ n
            if pa.max() < pb.min() or pb.max() < pa.min():
                return False
    return True


def distance(f, g):
    """Gap between two footprints; negative (not exact depth) when they overlap."""
    if f.kind == "disc" and g.kind == "disc":
        return float(np.linalg.norm(np.subtract(f.center, g.center)) - f.half[0] - g.half[0])
    if f.kind == "disc" or g.kind == "disc":
        disc, box = (f, g) if f.kind == "disc" else (g, f)
        return _point_poly(np.array(disc.center), box.vertices()) - disc.half[0]
    a, b = f.vertices(), g.vertices()
    if _sat_overlap(a, b):
        return -1.0
    d = min(_point_segment(p, a[i], a[(i + 1) % 4]) for p in b for i in range(4))
    return min(d, min(_point_segment(p, b[i], b[(i + 1) % 4]) for p in a for i in range(4)))


def inside(f, container, slack=0.0):
    """Whether footprint f lies inside the box `container` (shrunk by slack)."""
    poly = container.vertices()
    if f.kind == "disc":
        return _point_poly(np.array(f.center), poly) <= -(f.half[0] + slack)
    return all(_point_poly(v, poly) <= -slack for v in f.vertices())


def radial_range(f):
    """Least and largest distance of the footprint from the origin."""
    if f.kind == "disc":
        d = float(np.hypot(*f.center))
        return d - f.half[0], d + f.half[0]
    v = f.vertices()
    far = float(np.max(np.hypot(v[:, 0], v[:, 1])))
    return max(_point_poly(np.zeros(2), v), 0.0), far


def bearing_range(f):
    """Least and largest bearing (rad) of the footprint's corners from the origin."""
    pts = f.vertices() if f.kind == "box" else rect(*f.aabb()).vertices()
    ang = np.arctan2(pts[:, 1], pts[:, 0])
    return float(ang.min()), float(ang.max())


def gap_along(target, other, direction, gap):
    """`other` moved along `direction` from target's centre to leave `gap` between them."""
    u = np.array(direction) / np.linalg.norm(direction)
    c = np.array(target.center)
    lo, hi = 0.0, 1.0
    for _ in range(50):
        mid = (lo + hi) / 2
        if distance(target, other.moved(c + mid * u)) < gap:
            lo = mid
        else:
            hi = mid
    return other.moved(c + hi * u)
