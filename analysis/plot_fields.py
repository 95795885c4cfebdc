#!/usr/bin/python3
"""Figures of one run from its fields.h5 (written by `granshock fields`), like the
paper's Figs. 3-5: solid fraction, normalised temperature and Mach number on the bin
grid (axes in units of the particle diameter d, the obstacle drawn, the sonic line and the
shock front over the Mach field), and the stagnation-line profiles of phi, T and Ma.

Usage: plot_fields.py FIELDS_H5 FIGURES_DIR [FIELDS_H5 FIGURES_DIR ...]

Writes FIGURES_DIR/{solid_fraction,temperature,mach,stagnation_profiles}.png, each whole
and never through a symbolic link (figure_files.py); FIGURES_DIR is created when absent
and must not be a link. Several runs are drawn in one call, in the order given (starting
Python and matplotlib takes longer than drawing one run). Needs
numpy, h5py and matplotlib (Debian: python3-numpy python3-h5py python3-matplotlib).
"""
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")  # files only, no display

import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402
from matplotlib.patches import Circle, Polygon, Rectangle  # noqa: E402

from figure_files import FigureDirectory  # noqa: E402


def read_lines(f, name):
    """The polylines stored as /lines/NAME/{points,offsets}, as a list of (k, 2) arrays."""
    group = f.get("lines/" + name)
    if group is None:
        return []
    points, offsets = group["points"][...], group["offsets"][...]
    return [points[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]


class Run:
    def __init__(self, path):
        with h5py.File(path, "r") as f:
            attrs = f.attrs
            self.d = float(attrs["d"])
            self.u_inf = float(attrs["U"])
            self.xc = float(attrs["obstacle_xc"])
            self.yc = float(attrs["obstacle_yc"])
            self.diameter = float(attrs["obstacle_width"])  # D: the frontal width
            self.face = float(attrs["obstacle_face"])
            self.back = float(attrs["obstacle_back"])
            shape = attrs.get("obstacle_shape", "cylinder")
            self.shape = shape.decode() if isinstance(shape, bytes) else str(shape)
            # The shape's own outline (format 1 files have none: drawn from the sizes).
            self.outline = f["obstacle/outline"][...] if "obstacle/outline" in f else None
            mass_definition = attrs["mass_definition"]
            self.mass_definition = (mass_definition.decode() if isinstance(mass_definition, bytes)
                                    else str(mass_definition))
            self.x_nodes = f["grid/x_nodes"][...] / self.d
            self.y_nodes = f["grid/y_nodes"][...] / self.d
            self.fields = {name: f["fields/" + name][...] for name in ("phi", "T_norm", "Ma", "masked")}
            # A masked bin holds too few particle samples for any field, phi included: blank.
            self.fields["phi"] = np.where(self.fields["masked"] != 0, np.nan, self.fields["phi"])
            self.sonic = [line / self.d for line in read_lines(f, "sonic")]
            # The density threshold per column (what the shock angle is fitted to) and the
            # primary definition's front, the T half-rise (what delta/D measures; files
            # before it was written have none).
            self.front = [line / self.d for line in read_lines(f, "shock_threshold")]
            self.front_temperature = [line / self.d for line in read_lines(f, "shock_temperature")]
            profile = f["profile"]
            self.profile = {name: profile[name][...] for name in ("y", "phi", "T_norm", "Ma")}
            self.profile["y"] = self.profile["y"] / self.d
            self.profile["phi"] = np.where(profile["masked"][...] != 0, np.nan, self.profile["phi"])
            self.y_shock = float(profile.attrs["y_shock"]) / self.d
            # Every definition's front (docs/fields.md, section 6); files before 0.9 have one.
            self.fronts = {name: float(profile.attrs["y_shock_" + name]) / self.d
                           for name in FRONT_STYLES if "y_shock_" + name in profile.attrs}
            self.surface = float(profile.attrs["surface"]) / self.d
            # The fitted steps (y_s, w, levels, cut) in the panels' units; files before the
            # fitted fronts have none.
            self.steps = {}
            t_scale = float(attrs["m_av"]) * self.u_inf ** 2 if "m_av" in attrs else np.nan
            for panel, name in FITTED_PANELS.items():
                keys = [k + "_" + name for k in ("y_shock", "width", "fit_low", "fit_high", "fit_end")]
                if all(k in profile.attrs for k in keys):
                    y_s, w, low, high, end = (float(profile.attrs[k]) for k in keys)
                    scale = t_scale if panel == "T_norm" else 1.0
                    if all(np.isfinite(v) for v in (y_s, w, low, high, end, scale)):
                        self.steps[panel] = (y_s / self.d, w / self.d, low / scale, high / scale,
                                             end / self.d)
            primary = profile.attrs.get("primary_definition", "density_threshold")
            self.primary = primary.decode() if isinstance(primary, bytes) else str(primary)
            self.delta_over_d = float(profile.attrs["delta_over_D"])
            self.delta_over_d_err = float(profile.attrs["delta_over_D_err"])
            summary = f["summary"].attrs
            self.ma_target = float(summary["ma_inf_target"])
            self.ma_measured = float(summary["ma_inf_measured"])
            # Why delta/D could not be determined (absent when it could).
            reason = summary.get("delta_over_D_reason", "")
            self.delta_reason = reason.decode() if isinstance(reason, bytes) else str(reason)
            self.all_masked = bool(np.all(self.fields["masked"] != 0))

    def has_obstacle(self):
        return np.isfinite(self.diameter) and self.diameter > 0

    def draw_obstacle(self, ax):
        if not self.has_obstacle():
            return
        style = dict(facecolor="0.75", edgecolor="k", linewidth=0.8, zorder=3)
        x, half = self.xc / self.d, self.diameter / (2 * self.d)
        face, back = self.face / self.d, self.back / self.d
        if self.outline is not None:
            ax.add_patch(Polygon(self.outline / self.d, closed=True, **style))
        elif self.shape == "wedge":
            ax.add_patch(Polygon([(x, face), (x + half, back), (x - half, back)], **style))
        elif self.shape == "plate":
            ax.add_patch(Rectangle((x - half, face), 2 * half, back - face, **style))
        else:
            ax.add_patch(Circle((x, self.yc / self.d), half, **style))

    def title(self, what):
        parts = [what]
        if self.has_obstacle():
            parts.append(f"D = {self.diameter / self.d:.0f} d")
        if np.isfinite(self.ma_target):
            parts.append(f"Ma$_\\infty$ = {self.ma_target:.3g}")
        return ", ".join(parts)


def joined(line_set):
    """The polylines of one set (the sonic line, one definition's front) as one (k, 2)
    array with a NaN row between consecutive lines, or None when none has two points.
    matplotlib breaks a line at NaN, so the lines stay apart, as the analysis stored them
    (a front's polyline runs over consecutive columns with a front; a column without one
    ends it, docs/fields.md section 5), and one artist draws the set: its legend entry does
    not depend on which line comes first. A line of one point (a front in a single column
    between columns without one) draws nothing and is left out; a set of only such lines
    draws nothing and has no legend entry."""
    drawn = [line for line in line_set if len(line) > 1]
    if not drawn:
        return None
    gap = np.full((1, 2), np.nan)
    return np.concatenate([part for line in drawn for part in (gap, line)][1:])


def field_figure(run, values, label, title, figures, png, norm=None, cmap="viridis", lines=(),
                 ticks=None):
    """One field on the bin grid; masked (NaN) bins show a hatched background, named in
    the legend (a note under the axes overlapped the x label). `lines`: (polylines, plot
    style) pairs, each style with its legend label and as gid the name of its /lines
    dataset (tests/fields/check_figure_fronts.py finds each set's artist by it)."""
    width = run.x_nodes[-1] - run.x_nodes[0]
    height = run.y_nodes[-1] - run.y_nodes[0]
    fig_w = 6.0
    fig_h = min(max(fig_w * height / width * 0.85, 3.0), 10.0)
    fig, ax = plt.subplots(figsize=(fig_w, fig_h), constrained_layout=True)
    ax.set_facecolor("white")
    ax.add_patch(Rectangle((run.x_nodes[0], run.y_nodes[0]), width, height, hatch="///", fill=False,
                           edgecolor="0.6", linewidth=0, zorder=0))
    data = np.ma.masked_invalid(values)
    mesh = ax.pcolormesh(run.x_nodes, run.y_nodes, data, shading="flat", cmap=cmap, norm=norm)
    bar = fig.colorbar(mesh, ax=ax, label=label, shrink=0.9)
    if ticks is not None:
        bar.set_ticks(ticks)
    for line_set, style in lines:
        points = joined(line_set)
        if points is not None:  # one artist per set: one legend entry, whichever lines it has
            ax.plot(points[:, 0], points[:, 1], **style)
    handles, labels = ax.get_legend_handles_labels()
    if not run.all_masked and np.isnan(values).any():
        handles.append(Rectangle((0, 0), 1, 1, hatch="///", fill=False, edgecolor="0.6"))
        labels.append("masked: too few particles")
    if handles:
        ax.legend(handles, labels, loc="lower left", fontsize=7, framealpha=0.8)
    run.draw_obstacle(ax)
    ax.set_xlim(run.x_nodes[0], run.x_nodes[-1])
    ax.set_ylim(run.y_nodes[0], run.y_nodes[-1])
    ax.set_aspect("equal")
    ax.set_xlabel("x / d (crosswise)")
    ax.set_ylabel("y / d (streamwise)")
    ax.set_title(title, fontsize=10)
    if run.all_masked:
        ax.text(0.5, 0.5, "every bin is masked:\ntoo few particle samples", transform=ax.transAxes,
                ha="center", va="center", fontsize=11, color="0.2",
                bbox=dict(facecolor="white", edgecolor="0.5"), zorder=5)
    figures.save(fig, png, dpi=150)
    plt.close(fig)


def positive_norm(values):
    """Log colour scale when a positive field spans more than two decades, else linear."""
    finite = values[np.isfinite(values) & (values > 0)]
    if finite.size == 0:
        return None
    lo, hi = np.percentile(finite, 1), finite.max()
    return LogNorm(vmin=lo, vmax=hi) if hi > 100 * lo else None


# The definitions of the front on the stagnation line: colour, line style, label.
FRONT_STYLES = {
    "temperature_jump": ("C3", "--", "front: T half-rise (primary)"),
    "sonic_line": ("C2", "-.", "front: sonic point Ma = 1"),
    "density_threshold": ("C0", "--", "front: phi half-way"),
    "density_max_gradient": ("C0", ":", "front: steepest phi rise"),
    "temperature_fit": ("C1", "-", "front: fitted T step"),
    "density_fit": ("C4", "-", "front: fitted phi step"),
}
# The panel each fitted step is drawn on (docs/fields.md, "The fitted front").
FITTED_PANELS = {"T_norm": "temperature_fit", "phi": "density_fit"}


def profile_range(run):
    """The y range around the fronts and the surface: the whole line from the inlet put
    a front 5 d from the face into the last 5 % of the axis. With the layer from the first
    front to the surface (at least 5 d thick): from three layers upstream of the front to
    0.3 of a layer past the surface, so the fronts sit at about three quarters of the
    axis; None (the whole line) without a front."""
    fronts = [y for y in (run.fronts or {"density_threshold": run.y_shock}).values()
              if np.isfinite(y)]
    if not fronts or not np.isfinite(run.surface):
        return None
    first = min(fronts)
    layer = max(run.surface - first, 5.0)
    y = run.profile["y"]
    return max(first - 3 * layer, y[0] - 0.5), run.surface + 0.3 * layer


def profile_figure(run, figures, png):
    p = run.profile
    fig, axes = plt.subplots(3, 1, figsize=(6.0, 7.0), sharex=True, constrained_layout=True)
    for ax, (name, label) in zip(axes, (("phi", "$\\phi$"), ("T_norm", "$T/(m_{av}U_\\infty^2)$"),
                                        ("Ma", "Ma"))):
        ax.plot(p["y"], p[name], "-o", markersize=2.5, linewidth=1.0)
        if name in run.steps:  # the fitted step, up to the cut
            y_s, w, low, high, end = run.steps[name]
            yy = np.linspace(p["y"][0], end, 600)
            ax.plot(yy, low + (high - low) * 0.5 * (1 + np.tanh((yy - y_s) / w)),
                    color=FRONT_STYLES[FITTED_PANELS[name]][0], linewidth=1.2,
                    label=f"fitted {'T' if name == 'T_norm' else 'phi'} step, w = {w:.2g} d")
            if ax is not axes[0]:
                ax.legend(handles=[ax.get_lines()[-1]], fontsize=7, loc="upper left")
        fronts = run.fronts or {"density_threshold": run.y_shock}
        for front, y in fronts.items():
            if np.isfinite(y):
                color, style, front_label = FRONT_STYLES[front]
                ax.axvline(y, color=color, linestyle=style, linewidth=0.9, label=front_label)
        if np.isfinite(run.surface):
            ax.axvline(run.surface, color="k", linewidth=0.9, label="cylinder surface")
        if name == "Ma":
            ax.axhline(1.0, color="0.5", linestyle=":", linewidth=0.9)
        if name == "T_norm" and np.nanmax(p[name], initial=0) > 0:
            positive = p[name][np.isfinite(p[name]) & (p[name] > 0)]
            if positive.size and positive.max() > 100 * positive.min():
                ax.set_yscale("log")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    if axes[0].get_legend_handles_labels()[0]:
        axes[0].legend(fontsize=7)
    axes[-1].set_xlabel("y / d (along the stagnation line)")
    if p["y"].size and not np.isfinite(p["phi"]).any():  # every bin masked: the whole profile
        axes[-1].set_xlim(p["y"][0], max(p["y"][-1], np.nan_to_num(run.surface, nan=p["y"][-1])))
    else:
        limits = profile_range(run)
        if limits is not None:
            axes[-1].set_xlim(*limits)
    title = run.title("Stagnation line")
    if np.isfinite(run.delta_over_d):
        title += f", $\\delta/D$ = {run.delta_over_d:.3g}"
        if np.isfinite(run.delta_over_d_err):
            title += f" $\\pm$ {run.delta_over_d_err:.2g}"
    else:
        title += ", $\\delta/D$ n/a"
        if run.delta_reason:
            axes[-1].text(0.0, -0.3, textwrap.fill("delta/D n/a: " + run.delta_reason, 100),
                          transform=axes[-1].transAxes, fontsize=7, color="0.3", va="top")
    axes[0].set_title(title, fontsize=10)
    figures.save(fig, png, dpi=150)
    plt.close(fig)


def main():
    args = sys.argv[1:]
    if not args or len(args) % 2 != 0:
        print(__doc__, file=sys.stderr)
        return 2
    for fields_h5, figures_dir in zip(args[0::2], args[1::2]):
        run = Run(fields_h5)
        with FigureDirectory(figures_dir) as out:
            draw_figures(run, out)
    return 0


def front_lines(run, color):
    """The fronts the field figures draw, each named by its definition: the T half-rise
    (the primary definition, which delta/D measures) and the phi half-way rule (what the
    shock angle is fitted to), docs/fields.md sections 5-6."""
    lines = []
    if run.front_temperature:
        lines.append((run.front_temperature,
                      dict(color=color, linestyle="-", linewidth=1.3, gid="shock_temperature",
                           label="shock front: T half-rise (primary, as $\\delta$/D)")))
    lines.append((run.front, dict(color=color, linestyle=":", linewidth=1.1, gid="shock_threshold",
                                  label="shock front: $\\phi$ half-way (angle fit)")))
    return lines


def mach_ticks(vmax):
    """Colour-bar ticks of the Mach field: 0, 1 (the sonic value, white) and a few above."""
    above = [t for t in matplotlib.ticker.MaxNLocator(5).tick_values(1.0, vmax)
             if 1.0 < t <= vmax]
    return [0.0, 1.0] + above


def draw_figures(run, out):
    f = run.fields
    field_figure(run, f["phi"], "solid fraction $\\phi$", run.title("Solid fraction"),
                 out, "solid_fraction.png", cmap="viridis", lines=front_lines(run, "r"))
    field_figure(run, f["T_norm"], "$T/(m_{av}U_\\infty^2)$", run.title("Granular temperature"),
                 out, "temperature.png", norm=positive_norm(f["T_norm"]), cmap="inferno")
    ma = f["Ma"]
    finite = ma[np.isfinite(ma)]
    # The 95th percentile: the few sparse bins of the wake still reach Ma 20-30.
    vmax = max(np.percentile(finite, 95) if finite.size else 1.0, 2.0)
    field_figure(run, ma, f"Ma ({run.mass_definition})", run.title("Mach number"),
                 out, "mach.png", cmap="coolwarm",
                 norm=matplotlib.colors.TwoSlopeNorm(vmin=0.0, vcenter=1.0, vmax=vmax),
                 ticks=mach_ticks(vmax),
                 lines=((run.sonic, dict(color="k", linewidth=1.4, gid="sonic",
                                         label="sonic line Ma = 1")),
                        *front_lines(run, "w")))
    profile_figure(run, out, "stagnation_profiles.png")


if __name__ == "__main__":
    sys.exit(main())
