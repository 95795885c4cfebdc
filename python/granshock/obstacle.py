"""The obstacle's cross-section in the x-y plane (docs/scene_format.md, "Obstacle shapes";
models/cylinder.hpp, wedge.hpp, plate.hpp, square.hpp, sphere.hpp): a prism along z (a
sphere: its cut through the centre), symmetric
about x = centre[0], spanning centre +- half its size along x and y. The flow runs along
+y. A fields.h5 holds the outline granshock collided with (/obstacle/outline); where it
is there, it is used as it is, so that only a scene without fields needs the shapes
below."""
import math
from dataclasses import dataclass

import numpy as np

# Segments of a cylinder's outline: granshock's own (outline_points in
# models/shape_outline.hpp, what fields.h5's /obstacle/outline holds), a multiple
# of 4, so that it holds the points at its widest (x = xc +- R) and on the axis (y = yc +- R).
CYLINDER_SEGMENTS = 72


@dataclass(frozen=True)
class Obstacle:
    """An obstacle, in m.

    shape: "cylinder", "wedge", "plate", "square" or "sphere" (its cut through the centre).
    centre: (x, y), the middle of the shape's extent along x and y.
    frontal_width: D, the width across the flow (what delta/D divides by).
    length: the extent along the flow.
    sizes: the scene's size keys of the shape: {"diameter"}, {"half_angle" (degrees),
        "length"}, {"width", "thickness"} or {"side", "rotation" (degrees)}.
    outline: (N, 2) array of (x, y), counter-clockwise and closed (the last row repeats
        the first), ready for plotting.
    face, back: y of the upstream and downstream faces on the axis.
    """
    shape: str
    centre: tuple
    frontal_width: float
    length: float
    sizes: dict
    outline: np.ndarray

    @property
    def face(self):
        """y of the upstream face on the axis (a wedge's tip)."""
        return self.centre[1] - 0.5 * self.length

    @property
    def back(self):
        """y of the downstream face on the axis."""
        return self.centre[1] + 0.5 * self.length


def corners(shape, sizes):
    """The outline about the centre, counter-clockwise, not yet closed."""
    if shape in ("cylinder", "sphere"):  # a sphere: its cut through the centre
        angle = np.linspace(0.0, 2 * np.pi, CYLINDER_SEGMENTS, endpoint=False)
        radius = 0.5 * sizes["diameter"]
        return np.column_stack([radius * np.cos(angle), radius * np.sin(angle)])
    if shape == "wedge":
        # The tip upstream on the axis, the base closing it (models/wedge.hpp).
        half_length = 0.5 * sizes["length"]
        half_base = sizes["length"] * math.tan(math.radians(sizes["half_angle"]))
        return np.array([[0.0, -half_length], [half_base, half_length],
                         [-half_base, half_length]])
    if shape == "plate":
        w, t = 0.5 * sizes["width"], 0.5 * sizes["thickness"]
        return np.array([[-w, -t], [w, -t], [w, t], [-w, t]])
    if shape == "square":
        # The square turned counter-clockwise by its rotation (models/square.hpp).
        h, a = 0.5 * sizes["side"], math.radians(sizes.get("rotation", 0.0))
        c, s = math.cos(a), math.sin(a)
        return np.array([[c * x - s * y, s * x + c * y]
                         for x, y in ((-h, -h), (h, -h), (h, h), (-h, h))])
    raise ValueError(
        f"unknown obstacle shape {shape!r} (cylinder, wedge, plate, square or sphere)")


def make_obstacle(shape, centre, sizes, outline=None):
    """An Obstacle of `shape` at `centre` with the scene's size keys `sizes`; its outline
    (N, 2, not closed, in m) the given one, or else the shape's. Its frontal width and
    length are the outline's extents, as granshock derives them
    (models/shape_outline.hpp)."""
    centre = (float(centre[0]), float(centre[1]))
    if outline is None:
        outline = corners(shape, sizes) + np.array(centre)
    outline = np.asarray(outline, dtype=float)
    width = float(outline[:, 0].max() - outline[:, 0].min())
    length = float(outline[:, 1].max() - outline[:, 1].min())
    if shape == "cylinder":  # the circle's own extent, not its polygon's
        width = length = float(sizes["diameter"])
    return Obstacle(shape, centre, width, length, dict(sizes),
                    np.vstack([outline, outline[:1]]))


SIZE_KEYS = {"cylinder": ["diameter"], "wedge": ["half_angle", "length"],
             "plate": ["width", "thickness"], "square": ["side", "rotation"]}


def obstacle_from_scene(scene):
    """The obstacle of a resolved scene (a dict, as Run.scene gives it), or None when the
    scene has none."""
    table = scene.get("obstacle")
    if table is None:
        return None
    shape = table.get("shape", "cylinder")
    if shape not in SIZE_KEYS:
        raise ValueError(f"unknown obstacle shape {shape!r} ({', '.join(SIZE_KEYS)})")
    return make_obstacle(shape, table["centre"],
                         {k: float(table[k]) for k in SIZE_KEYS[shape] if k in table})


def obstacle_from_fields_attributes(attributes, outline=None):
    """The obstacle described by fields.h5's root attributes (@obstacle_shape, _xc, _yc,
    _width, _face, _back) and its /obstacle/outline (`outline`, None in format 1 files),
    or None when it has none: what a fields directory without the scene knows of it."""
    shape = attributes.get("obstacle_shape", "cylinder")
    width = attributes.get("obstacle_width", math.nan)
    if shape == "none" or not width > 0:
        return None
    length = attributes["obstacle_back"] - attributes["obstacle_face"]
    centre = (attributes["obstacle_xc"], attributes["obstacle_yc"])
    if outline is not None:  # format 2: the outline granshock collided with; sizes as known
        sizes = {"diameter": width} if shape == "cylinder" else {}
        return make_obstacle(shape, centre, sizes, outline)
    sizes = {"cylinder": {"diameter": width},
             "wedge": {"half_angle": math.degrees(math.atan(0.5 * width / length)),
                       "length": length},
             "plate": {"width": width, "thickness": length}}[shape]
    return make_obstacle(shape, centre, sizes)
