"""The shock fronts and detachment lengths of fields.h5 (docs/fields.md, sections 5, 6 and
8): /profile (the stagnation line and every definition of the front), /front (the front
per grid column and the shock angle), /upstream and /lines.

Values are as stored: NaN where summary.json has null (the reason is then a text attribute,
absent when there is none), and counts and flags as float64, as fields.h5 writes them."""
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ._h5 import attributes, in_order

# What /profile stores per definition DEF of the front, as @QUANTITY_DEF (m; the fit's
# levels in phi or J).
PER_DEFINITION = ["y_shock", "delta", "delta_err", "width", "width_err",
                  "fit_low", "fit_high", "fit_end"]
# The definitions in the order of detachment_convergence.csv.
DEFINITION_ORDER = ["temperature_jump", "density_threshold", "density_max_gradient",
                    "sonic_line", "temperature_fit", "density_fit"]


@dataclass(frozen=True)
class Fronts:
    """What fields.h5 stores about the shock.

    primary_definition, delta_over_D, delta_over_D_err: the primary front (as summary.json's
        delta_over_D; NaN where that is null).
    definitions: DataFrame, one row per definition of the front (temperature_jump,
        density_threshold, ...): y_shock, delta, delta_err, width, width_err, fit_low,
        fit_high, fit_end (/profile's @QUANTITY_DEF) and delta_over_D, delta_over_D_err
        (delta / D, D the obstacle's frontal width, as summary.json's detachment.DEF).
    profile: dict, every /profile attribute (the strip, the surface, the primary front,
        the thresholds, the reasons).
    stagnation_line: DataFrame, the profile along the stagnation strip (y, phi, T, T_norm,
        Ma, uy, pressure, mean_count, masked), one row per profile row.
    delta_blocks: numpy array, the primary delta of each block (m).
    columns: DataFrame, the front per grid column (/front: x, y_threshold, y_max_gradient,
        y_temperature, phi_peak, threshold).
    shock_angle: dict, the /front attributes (angle_deg, phi_up, the left_ and right_ flank
        fits, the reasons).
    upstream: dict, {"inlet": {...}, "downstream": {...}}: /upstream/* attributes.
    lines: dict, polyline name (sonic, shock_threshold, shock_max_gradient,
        shock_temperature) -> list of (k, 2) arrays of (x, y) vertices, m.
    """
    primary_definition: str
    delta_over_D: float
    delta_over_D_err: float
    definitions: pd.DataFrame
    profile: dict
    stagnation_line: pd.DataFrame
    delta_blocks: np.ndarray
    columns: pd.DataFrame
    shock_angle: dict
    upstream: dict
    lines: dict


def definitions_table(profile_attributes, frontal_width):
    """One row per definition of the front found in /profile's attributes."""
    names = in_order([key[len("y_shock_"):] for key in profile_attributes
                      if key.startswith("y_shock_")], DEFINITION_ORDER)
    rows = {name: {q: profile_attributes.get(f"{q}_{name}", np.nan) for q in PER_DEFINITION}
            for name in names}
    table = pd.DataFrame.from_dict(rows, orient="index", columns=PER_DEFINITION)
    table.index.name = "definition"
    table["delta_over_D"] = table["delta"] / frontal_width
    table["delta_over_D_err"] = table["delta_err"] / frontal_width
    return table


def polylines(group):
    """The lines of one /lines/NAME group: line i is points[offsets[i]:offsets[i+1]]."""
    points, offsets = group["points"][()], group["offsets"][()]
    return [points[a:b] for a, b in zip(offsets[:-1], offsets[1:])]


def read_fronts(f):
    """The fronts of an open fields.h5."""
    profile = f["profile"]
    profile_attributes = attributes(profile)
    line = {name: profile[name][()] for name in in_order(profile, ["y"])
            if name != "delta_blocks"}
    front = f["front"]
    return Fronts(
        # Files before the definitions were named measured the density threshold alone.
        primary_definition=profile_attributes.get("primary_definition", "density_threshold"),
        delta_over_D=profile_attributes.get("delta_over_D", np.nan),
        delta_over_D_err=profile_attributes.get("delta_over_D_err", np.nan),
        definitions=definitions_table(profile_attributes, float(f.attrs["obstacle_width"])),
        profile=profile_attributes,
        stagnation_line=pd.DataFrame(line),
        delta_blocks=profile["delta_blocks"][()] if "delta_blocks" in profile else np.zeros(0),
        columns=pd.DataFrame({name: front[name][()] for name in in_order(front, ["x"])}),
        shock_angle=attributes(front),
        upstream={name: attributes(g) for name, g in f.get("upstream", {}).items()},
        lines={name: polylines(g) for name, g in f.get("lines", {}).items()},
    )
