"""A safe library of ground curves for the trajectory editor (CoMA §3 and appendix D.1).

CoMA asks an LLM to write `shape_curve(t)` and runs it; Interplay never runs generated code:
the planner names a shape and a few numbers (a TrajectorySpec) and `make_curve` draws it here.

Every curve is a dense polyline of ground points (N, 2) in metres, columns (x, z), in the
walker's own frame: it starts at the origin heading +Z (forward); +X is the walker's left
(the rest pose faces +Z with the left side at +X). `clockwise` is as seen from above, so a
clockwise circle turns right. Zigzag and S lie along +Z (their first leg leaves at the angle
the shape needs); polylines and free curves keep the points they are given.
Points are spaced about `STEP` apart so straight sides stay straight when the trajectory editor
fits its smoothing spline; corners are exact vertices (the editor rounds them when mapping).
"""

from __future__ import annotations

import numpy as np

from interplay.planner.schema import DEFAULT_DISTANCE, DEFAULT_SIZE, DEFAULT_TURNS, TrajectorySpec

STEP = 0.01  # m between generated points
MAX_CURVE_POINTS = 20_000   # 200 m (MAX_PATH_M) at STEP; longer curves get a coarser step

SHAPES = ("line", "arc", "circle", "zigzag", "s_curve", "heart", "figure_eight", "square",
          "spiral", "polyline", "free")

# make_curve's defaults for a spec's missing size, distance and turns (DEFAULT_SIZE,
# DEFAULT_DISTANCE, DEFAULT_TURNS) live in the planner's schema, so that it can tell a spec's
# path length (schema.spec_length) without drawing it.
ZIGZAG_SEGMENTS = 4


def _positive(name: str, value) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number, got {value!r}") from None
    if not np.isfinite(v) or v <= 0:
        raise ValueError(f"{name} must be a positive number, got {value!r}")
    return v


def _mirror(points: np.ndarray, clockwise: bool) -> np.ndarray:
    """Shapes are built turning left (counterclockwise from above); clockwise mirrors x."""
    return points * np.array([-1.0, 1.0]) if clockwise else points


def _step(length: float) -> float:
    """STEP, or coarser on curves longer than MAX_CURVE_POINTS × STEP (beyond what a request
    may ask for), so that no curve has more than about MAX_CURVE_POINTS points."""
    return max(STEP, length / MAX_CURVE_POINTS)


def _count(length: float) -> int:
    return max(int(np.ceil(length / _step(length))) + 1, 16)


def _densify(vertices: np.ndarray) -> np.ndarray:
    """Points about STEP apart along the straight legs between vertices (N, 2); every vertex kept."""
    step = _step(float(np.linalg.norm(np.diff(vertices, axis=0), axis=1).sum()))
    pieces = []
    for a, b in zip(vertices[:-1], vertices[1:]):
        n = max(int(np.ceil(np.linalg.norm(b - a) / step)), 1)
        pieces.append(a + (b - a) * (np.arange(n) / n)[:, None])
    return np.concatenate(pieces + [vertices[-1:]])


def _start_forward(points: np.ndarray) -> np.ndarray:
    """Rotate and shift a curve so it starts at the origin heading +Z (direction to the first
    point at least 1 cm away)."""
    points = points - points[0]
    far = np.flatnonzero(np.linalg.norm(points, axis=1) > 0.01)
    d = points[far[0]] if len(far) else np.array([0.0, 1.0])
    a = np.arctan2(d[0], d[1])                        # heading of d: 0 along +Z, + towards +X
    c, s = np.cos(a), np.sin(a)
    rot = np.array([[c, -s], [s, c]])                 # rotates by -a: d onto +Z
    return points @ rot.T


def line(length: float) -> np.ndarray:
    """Straight ahead for `length` metres."""
    length = _positive("length", length)
    return np.stack([np.zeros(_count(length)), np.linspace(0.0, length, _count(length))], axis=1)


def arc(radius: float, angle_deg: float, clockwise: bool = False) -> np.ndarray:
    """An arc of a circle of `radius` turning through `angle_deg` degrees (left unless clockwise)."""
    radius, angle = _positive("radius", radius), np.radians(_positive("angle_deg", angle_deg))
    phi = np.linspace(0.0, angle, _count(radius * angle))
    # Centre at (radius, 0), the walker's left: leaving the origin along +Z, bending to +X.
    return _mirror(np.stack([radius * (1 - np.cos(phi)), radius * np.sin(phi)], axis=1), clockwise)


def circle(radius: float, clockwise: bool = False, turns: float = 1.0) -> np.ndarray:
    """`turns` times round a circle of `radius`, back to the origin after each full turn."""
    return arc(radius, 360.0 * _positive("turns", turns), clockwise)


def zigzag(length: float, amplitude: float, segments: int = ZIGZAG_SEGMENTS,
           clockwise: bool = False) -> np.ndarray:
    """Straight legs along +Z over `length`, corners alternately `amplitude` to the left and
    right of the axis (first to the left unless clockwise); starts and ends on the axis."""
    length, amplitude = _positive("length", length), _positive("amplitude", amplitude)
    if int(segments) != segments or segments < 2:
        raise ValueError(f"a zigzag needs at least 2 segments, got {segments!r}")
    segments = int(segments)
    # Corner i at z = (i + 0.5) * pitch; half legs at both ends to start and end on the axis.
    pitch = length / segments
    z = np.concatenate([[0.0], (np.arange(segments) + 0.5) * pitch, [length]])
    x = np.concatenate([[0.0], amplitude * (-1.0) ** np.arange(segments), [0.0]])
    return _mirror(_densify(np.stack([x, z], axis=1)), clockwise)


def s_curve(length: float, amplitude: float, clockwise: bool = False) -> np.ndarray:
    """One sine period along +Z over `length`: bulging `amplitude` to the left then to the right
    (right then left if clockwise), ending on the axis."""
    length, amplitude = _positive("length", length), _positive("amplitude", amplitude)
    z = np.linspace(0.0, length, _count(length * (1 + 4 * amplitude / length)))
    return _mirror(np.stack([amplitude * np.sin(2 * np.pi * z / length), z], axis=1), clockwise)


def heart(size: float, clockwise: bool = False) -> np.ndarray:
    """A heart `size` metres wide, walked from its tip: a straight side, a round lobe, the notch
    (a 90° corner), the other lobe and the other side back to the tip. The classic heart is a
    square standing on a corner with half circles on its two upper sides; the walker leaves the
    tip heading +Z, so the heart's axis is 45° to the left of that heading (right if
    clockwise). CoMA's example heart (16 sin³t, …) has cusps at the tip and the notch, where a
    walker would have to spin on the spot; this one only has the notch corner, which the
    editor's spline rounds."""
    size = _positive("size", size)
    # Built in a frame with the heart's axis along +Z and the tip at the origin, counterclockwise:
    # up the right side (-x) at 45°, round the right lobe, notch, left lobe, down the left side.
    side = 1.0
    right, left = np.array([-1.0, 1.0]) / np.sqrt(2), np.array([1.0, 1.0]) / np.sqrt(2)
    top = np.array([0.0, np.sqrt(2)])

    def lobe(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        # Half circle on the side a→b, bulging away from the square's centre, turning left.
        centre, r = (a + b) / 2, side / 2
        start = np.arctan2(*(a - centre)[::-1])
        phi = start - np.linspace(0.0, np.pi, _count(np.pi * r * size))
        return centre + r * np.stack([np.cos(phi), np.sin(phi)], axis=1)

    pts = np.concatenate([_densify(np.stack([np.zeros(2), right]))[:-1], lobe(right, top),
                          lobe(top, left)[1:], _densify(np.stack([left, np.zeros(2)]))[1:]])
    width = np.ptp(pts[:, 0])
    return _mirror(_start_forward(pts * (size / width)), clockwise)


def figure_eight(size: float, clockwise: bool = False) -> np.ndarray:
    """A figure eight `size` metres from end to end (lemniscate of Bernoulli), starting at its
    crossing heading +Z, first loop to the left (right if clockwise), back through the crossing
    at the middle and at the end."""
    a = _positive("size", size) / 2
    t = np.linspace(0.0, 2 * np.pi, _count(2.7 * a * 2))
    # Parametrised from the crossing (t = 0) round the +x loop, then the -x loop.
    den = 1 + np.cos(t) ** 2
    pts = np.stack([a * np.sin(t) / den, a * np.sin(t) * np.cos(t) / den], axis=1)
    pts = _start_forward(pts)
    # _start_forward leaves the first loop on whichever side; put it on the left (+x).
    if pts[len(pts) // 4, 0] < 0:
        pts = pts * np.array([-1.0, 1.0])
    return _mirror(pts, clockwise)


def square(side: float, clockwise: bool = False) -> np.ndarray:
    """A square of `side` metres: ahead, then three 90° turns (left unless clockwise), back to
    the origin; the corners are exact vertices."""
    s = _positive("side", side)
    corners = np.array([[0.0, 0.0], [0.0, s], [s, s], [s, 0.0], [0.0, 0.0]])
    return _mirror(_densify(corners), clockwise)


def spiral(turns: float, growth: float, clockwise: bool = False,
           start_radius: float | None = None) -> np.ndarray:
    """An Archimedean spiral outwards: radius start_radius + growth * (turns so far) metres,
    `turns` times round (turning left unless clockwise); it starts at the origin heading +Z.
    start_radius defaults to growth / 2: a spiral from radius 0 begins with a turn a few cm wide,
    which nobody walks."""
    turns, growth = _positive("turns", turns), _positive("growth", growth)
    start_radius = growth / 2 if start_radius is None else float(start_radius)
    if not np.isfinite(start_radius) or start_radius < 0:
        raise ValueError(f"start_radius must be >= 0, got {start_radius!r}")
    phi_end = 2 * np.pi * turns
    outer = start_radius + growth * turns
    phi = np.linspace(0.0, phi_end, _count(phi_end * outer))
    r = start_radius + growth * phi / (2 * np.pi)
    # Increasing angle in (x, z) turns right seen from above (+x is the walker's left).
    pts = np.stack([r * np.cos(phi), r * np.sin(phi)], axis=1)
    return _mirror(_start_forward(pts), not clockwise)


def polyline(waypoints) -> np.ndarray:
    """Straight legs from the origin through waypoints [[x, z], …] (metres, walker's frame;
    a first waypoint at the origin is not repeated)."""
    pts = _points("waypoints", waypoints, minimum=1)
    if np.linalg.norm(pts[0]) > 1e-9:
        pts = np.concatenate([np.zeros((1, 2)), pts])
    pts = drop_repeats(pts)
    if len(pts) < 2:
        raise ValueError("waypoints must lead away from the origin")
    return _densify(pts)


def free(points) -> np.ndarray:
    """A curve drawn by hand (e.g. in the browser): ground points [[x, z], …] as given, in
    order, possibly noisy and unevenly spaced; repeated points are dropped. Not moved: the
    trajectory editor decides where it starts."""
    pts = drop_repeats(_points("points", points, minimum=2))
    if len(pts) < 2:
        raise ValueError("a free curve needs at least two distinct points")
    return pts


def _points(name: str, value, minimum: int) -> np.ndarray:
    try:
        pts = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a list of [x, z] pairs") from None
    if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < minimum:
        raise ValueError(f"{name} must be a list of at least {minimum} [x, z] pairs, "
                         f"got shape {pts.shape}")
    if not np.all(np.isfinite(pts)):
        raise ValueError(f"{name} contain NaN or infinite values")
    return pts


def drop_repeats(pts: np.ndarray, tol: float = 1e-6) -> np.ndarray:
    keep = np.concatenate([[True], np.linalg.norm(np.diff(pts, axis=0), axis=1) > tol])
    return pts[keep]


def length(points: np.ndarray) -> float:
    """Path length (metres) of a polyline (N, 2)."""
    return float(np.linalg.norm(np.diff(points, axis=0), axis=1).sum())


# ---- from a TrajectorySpec -------------------------------------------------------------

def _spec_dict(spec: dict | TrajectorySpec) -> dict:
    if isinstance(spec, TrajectorySpec):
        spec = spec.model_dump()
    if not isinstance(spec, dict):
        raise ValueError(f"a trajectory spec must be a dict or a TrajectorySpec, "
                         f"got {type(spec).__name__}")
    return {k: v for k, v in spec.items() if v is not None}


# Heading of a straight walk per TrajectorySpec.direction: (x, z), +x is the walker's left.
DIRECTIONS = {"forward": (0.0, 1.0), "backward": (0.0, -1.0), "left": (1.0, 0.0), "right": (-1.0, 0.0)}


def _clock_turn(distance: float, turn_at) -> np.ndarray:
    """Ahead, then towards `clock` o'clock (3 = right, 9 = left, 6 = back, as the walker sees
    it, CoMA appendix D.1) for the rest of `distance`: the turn comes after `after_m` metres,
    half-way when not given (or when after_m leaves nothing to walk after the turn)."""
    hour = turn_at.get("clock") if isinstance(turn_at, dict) else None
    if isinstance(hour, bool) or not isinstance(hour, (int, float)) or hour != int(hour) \
            or not 1 <= hour <= 12:
        raise ValueError(f"turn_at needs {{'clock': 1..12}}, got {turn_at!r}")
    after = turn_at.get("after_m")
    first = _positive("turn_at.after_m", after) if after is not None else distance / 2
    second = distance - first if distance - first > 0.1 else distance / 2
    a = -np.radians(30.0 * hour)               # heading: + towards the walker's left (+x)
    corner = np.array([0.0, first])
    return _densify(np.stack([np.zeros(2), corner, corner + second * np.array([np.sin(a), np.cos(a)])]))


def make_curve(spec) -> np.ndarray:
    """Ground points (N, 2) for a TrajectorySpec-like dict (or the planner's pydantic model):
    {shape, clockwise?, size_m?, distance_m?, turns?, waypoints?, turn_at?, direction?}.
    None or missing values take the shape's defaults; other keys (text) are ignored.

    size_m is the shape's size: circle/arc diameter, square side, heart width, figure-eight
    length, spiral outer diameter, zigzag/S width from side to side. distance_m is the
    forward length of line/zigzag/S; for the other shapes, given without size_m, the shape is
    scaled so its path is distance_m long. turns: circle turns (1), arc fraction of a turn
    (0.25), spiral turns (2). waypoints: [[x, z], …] for polyline (from the origin, walker's
    frame) and free (as drawn). turn_at {"clock": h, "after_m"?} on a line (or a polyline
    without waypoints): after_m (default half the distance) ahead, the rest towards h o'clock.
    direction (forward, backward, left, right) points a line that way."""
    s = _spec_dict(spec)
    shape = s.get("shape")
    if shape not in SHAPES:
        raise ValueError(f"unknown trajectory shape {shape!r}; expected one of {list(SHAPES)}")
    cw = s.get("clockwise", False)
    if not isinstance(cw, (bool, np.bool_)):
        raise ValueError(f"clockwise must be true or false, got {cw!r}")
    cw = bool(cw)
    size = _positive("size_m", s["size_m"]) if "size_m" in s else None
    distance = _positive("distance_m", s["distance_m"]) if "distance_m" in s else None
    # Only arc, circle and spiral read turns, and each of them has a default.
    turns = _positive("turns", s["turns"]) if "turns" in s else DEFAULT_TURNS.get(shape, 1.0)
    forward = distance or (size if shape == "line" and size else DEFAULT_DISTANCE.get(shape, 4.0))

    if shape in ("line", "polyline") and "turn_at" in s and "waypoints" not in s:
        return _clock_turn(forward, s["turn_at"])
    if shape in ("polyline", "free"):
        if "waypoints" not in s:
            raise ValueError(f"a {shape} trajectory needs waypoints [[x, z], …]")
        return polyline(s["waypoints"]) if shape == "polyline" else free(s["waypoints"])
    if shape == "line":
        way = s.get("direction", "forward")
        if way not in DIRECTIONS:
            raise ValueError(f"direction must be one of {list(DIRECTIONS)}, got {way!r}")
        return line(forward) if way == "forward" else polyline([[forward * c for c in DIRECTIONS[way]]])
    if shape in DEFAULT_DISTANCE:              # zigzag, s_curve: along +Z, size_m wide
        width = size or DEFAULT_SIZE[shape]
        if shape == "zigzag":
            return zigzag(forward, width / 2, max(2, int(round(forward))), cw)
        return s_curve(forward, width / 2, cw)

    d = size or DEFAULT_SIZE[shape]
    build = {
        "arc": lambda: arc(d / 2, 360.0 * turns, cw),
        "circle": lambda: circle(d / 2, cw, turns),
        "heart": lambda: heart(d, cw),
        "figure_eight": lambda: figure_eight(d, cw),
        "square": lambda: square(d, cw),
        "spiral": lambda: spiral(turns, d / 2 / (turns + 0.5), cw),   # start radius growth / 2
    }
    pts = build[shape]()
    if size is None and distance is not None:
        pts = pts * (distance / length(pts))
    return pts
