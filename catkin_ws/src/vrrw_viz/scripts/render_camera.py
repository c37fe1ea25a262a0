"""Where the render's camera stands: rviz's orbit view (focal point, yaw, pitch, distance) that frames a set of
points, the corners of the robots' links and the scene's objects."""
import math

# Named directions (yaw, pitch in rad; rviz's orbit camera sits at focal + d (cos y cos p, sin y cos p, sin p)).
CAMERAS = {
    'iso': (1.0, 0.45),            # the shipped config's direction
    'front': (-math.pi / 2, 0.3),  # from -y, where the robots of the shipped cells face
    'side': (0.0, 0.3),            # from +x
    'back': (math.pi / 2, 0.3),
    'top': (-math.pi / 2, 1.45),   # (not quite 90 deg: the orbit camera's up vector is z)
}
FIELD_OF_VIEW = 0.785398  # rad, vertical (the shipped config's)
MARGIN = 0.9              # of the view the scene may fill in its wider direction


def bounds(points):
    """Axis-aligned box (low, high) of (x, y, z) points."""
    low = tuple(min(p[i] for p in points) for i in range(3))
    high = tuple(max(p[i] for p in points) for i in range(3))
    return low, high


def box_corners(low, high):
    return [(x, y, z) for x in (low[0], high[0]) for y in (low[1], high[1]) for z in (low[2], high[2])]


def _axes(yaw, pitch):
    """Unit vectors: back (focal point to camera), right and up (back x right) of the image."""
    back = (math.cos(yaw) * math.cos(pitch), math.sin(yaw) * math.cos(pitch), math.sin(pitch))
    right = (-math.sin(yaw), math.cos(yaw), 0.0)
    up = (-math.sin(pitch) * math.cos(yaw), -math.sin(pitch) * math.sin(yaw), math.cos(pitch))
    return back, right, up


def fit(points, yaw, pitch, aspect, focal=None):
    """The orbit view from direction (yaw, pitch) on `focal` (default: the points' box centre) whose distance puts
    every point inside MARGIN of the view: a point v from the focal point at depth d - v.back fits when
    |v.right| <= tan(hfov / 2) depth and |v.up| <= tan(vfov / 2) depth."""
    low, high = bounds(points)
    focal = focal or tuple((low[i] + high[i]) / 2 for i in range(3))
    back, right, up = _axes(yaw, pitch)
    tan_v = math.tan(FIELD_OF_VIEW / 2) * MARGIN
    tan_h = math.tan(FIELD_OF_VIEW / 2) * aspect * MARGIN
    dot = lambda a, b: sum(x * y for x, y in zip(a, b))
    distance = 0.5
    for p in points:
        v = tuple(p[i] - focal[i] for i in range(3))
        distance = max(distance, abs(dot(v, right)) / tan_h + dot(v, back), abs(dot(v, up)) / tan_v + dot(v, back))
    return {'focal': focal, 'yaw': yaw, 'pitch': pitch, 'distance': distance}


def parse_view(text):
    """'x,y,z,yaw,pitch' -> (focal, yaw, pitch); ValueError naming what is wrong."""
    values = text.split(',')
    if len(values) != 5:
        raise ValueError(f"'{text}': expected x,y,z,yaw,pitch (5 numbers, m and rad)")
    try:
        x, y, z, yaw, pitch = (float(v) for v in values)
    except ValueError:
        raise ValueError(f"'{text}': expected x,y,z,yaw,pitch (5 numbers, m and rad)") from None
    if not all(math.isfinite(v) for v in (x, y, z, yaw, pitch)) or max(abs(x), abs(y), abs(z)) > 100:
        raise ValueError(f"'{text}': the focal point must be finite and within 100 m")
    if abs(pitch) >= math.pi / 2:
        raise ValueError(f"'{text}': pitch {pitch} must be within (-pi/2, pi/2)")
    return (x, y, z), yaw, pitch
