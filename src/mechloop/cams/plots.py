"""Figures of a cam design (matplotlib, no pyplot state): the motion program, the profile,
the pressure angle and the radius of curvature over the turn, the position plan of cam and
follower at a cam angle, and its animation over the turn.

Lengths are drawn in the design file's length unit, angles in degrees.
"""

from __future__ import annotations

import math
import os
import textwrap
from collections.abc import Callable
from pathlib import Path

import numpy as np
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from mechloop.cams.design import CamDesign
from mechloop.cams.followers import (
    OscillatingFlat,
    OscillatingRoller,
    TranslatingFlat,
    TranslatingRoller,
    follower_point,
)
from mechloop.cams.profile import _rotate
from mechloop.model.units import unit_factor
from mechloop.views.figure import ViewError, new_figure

#: The figures :func:`plot_cam` draws, by name.
CAM_VIEWS = ("program", "profile", "pressure", "curvature", "plan")


def _length(design: CamDesign) -> tuple[float, str]:
    """Divisor from m to the file's length unit, and its name."""
    return unit_factor(design.units[0], "length"), design.units[0]


def _title(design: CamDesign, what: str) -> str:
    return f"{design.name or 'cam'}: {what}"


def plot_program(design: CamDesign) -> Figure:
    """Displacement, velocity, acceleration and jerk over the cam angle: at the cam speed
    when the design has one, else the analogs per radian; segment joins marked."""
    g = design.cycle()
    m = g.motion
    rocker = design.follower.oscillating
    scale, unit = (1.0, "deg") if rocker else _length(design)
    conv = (180 / math.pi) if rocker else 1.0 / scale
    w = design.omega
    rows = [("s", m.s, ""), ("v", m.ds, "/s" if w else "/rad"),
            ("a", m.dds, "/s²" if w else "/rad²"), ("j", m.ddds, "/s³" if w else "/rad³")]
    figure = new_figure(8.0, 8.0)
    axes = figure.subplots(4, 1, sharex=True)
    phi = np.degrees(m.phi)
    for k, (ax, (name, values, per)) in enumerate(zip(axes, rows, strict=True)):
        factor = (w**k if w else 1.0) * conv
        ax.plot(phi, values * factor, color="tab:blue", linewidth=1.2)
        ax.set_ylabel(f"{name} [{unit}{per}]" if w or k == 0 else
                      f"d{'' if k == 1 else k}s/dφ{'' if k == 1 else k} [{unit}{per}]")
        for edge in np.degrees(design.program.edges[1:-1]):
            ax.axvline(edge, color="0.7", linewidth=0.6)
        ax.grid(True, linewidth=0.3)
    axes[-1].set_xlabel("cam angle φ [deg]")
    axes[-1].set_xlim(0, 360)
    speed = f" at {w * 30 / math.pi:.6g} rpm" if w else " (analogs per radian of cam angle)"
    axes[0].set_title(_title(design, "follower motion" + speed))
    return figure


def plot_profile(design: CamDesign, *, rollers: int = 12) -> Figure:
    """The working profile, the pitch curve, the base circle, and the roller (or the face)
    at ``rollers`` cam angles over the turn."""
    g = design.cycle()
    scale, unit = _length(design)
    figure = new_figure(7.0, 7.0)
    ax = figure.add_subplot()
    ax.plot(*(g.profile / scale).T, color="black", linewidth=1.6, label="working profile")
    flat = design.follower.flat
    base = design.cam.base_radius
    t = np.linspace(0, 2 * math.pi, 361)
    if not flat:
        r = design.follower.roller_radius  # type: ignore[union-attr]
        ax.plot(*(g.pitch / scale).T, color="tab:red", linewidth=0.9, linestyle="--",
                label="pitch curve")
        ax.plot(base / scale * np.cos(t), base / scale * np.sin(t), color="tab:green",
                linewidth=0.7, linestyle=":", label=f"base circle of the pitch curve "
                f"R0 = {base / scale:.4g} {unit}")
        step = max(1, design.positions // rollers)
        for k in range(0, design.positions, step):
            cx, cy = g.pitch[k] / scale
            ax.plot(cx + r / scale * np.cos(t), cy + r / scale * np.sin(t), color="0.6",
                    linewidth=0.5, label="roller" if k == 0 else None)
    else:
        ax.plot(base / scale * np.cos(t), base / scale * np.sin(t), color="tab:green",
                linewidth=0.7, linestyle=":", label=f"base circle R0 = {base / scale:.4g} "
                f"{unit}")
        step = max(1, design.positions // rollers)
        low, high = _face_span(design, g)
        for k in range(0, design.positions, step):
            tangent = _face_tangent(design, g.normal[k])
            foot = g.profile[k] - g.contact_along[k] * tangent
            ends = np.stack([foot + low * tangent, foot + high * tangent])
            ax.plot(*(ends / scale).T, color="0.6", linewidth=0.5,
                    label="face" if k == 0 else None)
    ax.plot([0], [0], marker="+", color="black", markersize=10, linestyle="none")
    ax.set_aspect("equal")
    ax.set_xlabel(f"x [{unit}]")
    ax.set_ylabel(f"y [{unit}]")
    ax.set_title(textwrap.fill(_title(design, "profile in the cam's frame (the cam "
                                            "turns counter-clockwise)"), 60))
    ax.grid(True, linewidth=0.3)
    ax.legend(loc="upper right", fontsize="small")
    return figure


def _face_tangent(design: CamDesign, normal: np.ndarray) -> np.ndarray:
    """Unit vector along a flat face, the way its contact coordinate grows."""
    turned = np.stack([-normal[..., 1], normal[..., 0]], axis=-1)
    return turned if design.follower.oscillating else -turned


def _face_span(design: CamDesign, g, *, to_pivot: bool = False) -> tuple[float, float]:
    """The stretch of the face to draw (m along it from its foot): the contact's travel
    with a margin (``to_pivot``: from the foot at a rocker's pivot)."""
    along = g.contact_along
    margin = 0.15 * max(float(np.ptp(along)), 0.2 * design.cam.base_radius)
    low = min(float(along.min()), 0.0) if to_pivot else float(along.min()) - margin
    return low, float(along.max()) + margin


def plot_pressure(design: CamDesign) -> Figure:
    """The pressure angle over the cam angle, with the allowed limits."""
    g = design.cycle()
    figure = new_figure(8.0, 4.0)
    ax = figure.add_subplot()
    phi = np.degrees(g.motion.phi)
    ax.plot(phi, np.degrees(g.pressure), color="tab:blue", label="pressure angle α")
    limits = {"allowed": design.allowed, "allowed on returns": design.allowed_return}
    for (label, value), style in zip(limits.items(), ("--", ":"), strict=True):
        if value is not None:
            for sign in (1, -1):
                ax.axhline(sign * math.degrees(value), color="tab:red", linestyle=style,
                           linewidth=0.8, label=label if sign == 1 else None)
    for edge in np.degrees(design.program.edges[1:-1]):
        ax.axvline(edge, color="0.7", linewidth=0.6)
    ax.set_xlabel("cam angle φ [deg]")
    ax.set_ylabel("α [deg]")
    ax.set_xlim(0, 360)
    ax.grid(True, linewidth=0.3)
    ax.legend(loc="best", fontsize="small")
    ax.set_title(_title(design, "pressure angle"))
    return figure


def plot_curvature(design: CamDesign) -> Figure:
    """The radius of curvature of the working profile (and of the pitch curve) over the
    cam angle; the roller radius or the allowed radius marked; a logarithmic-free scale
    clipped to a few base radii (straight parts have an infinite radius)."""
    g = design.cycle()
    scale, unit = _length(design)
    figure = new_figure(8.0, 4.0)
    ax = figure.add_subplot()
    phi = np.degrees(g.motion.phi)
    cap = 4 * design.cam.base_radius
    clip = lambda v: np.clip(v, -cap, cap) / scale  # noqa: E731
    ax.plot(phi, clip(g.rho), color="black", label="working profile ρ")
    if g.pitch_rho is not None:
        ax.plot(phi, clip(g.pitch_rho), color="tab:red", linestyle="--", linewidth=0.9,
                label="pitch curve ρ")
    ax.axhline(0, color="0.3", linewidth=0.6)
    if design.follower.flat:
        if design.min_curvature > 0:
            ax.axhline(design.min_curvature / scale, color="tab:green", linestyle=":",
                       label="allowed ρ")
    else:
        ax.axhline(design.follower.roller_radius / scale, color="tab:green",  # type: ignore[union-attr]
                   linestyle=":", label="roller radius")
    for edge in np.degrees(design.program.edges[1:-1]):
        ax.axvline(edge, color="0.7", linewidth=0.6)
    ax.set_xlim(0, 360)
    ax.set_xlabel("cam angle φ [deg]")
    ax.set_ylabel(f"ρ [{unit}] (clipped at ±{cap / scale:.4g})")
    ax.grid(True, linewidth=0.3)
    ax.legend(loc="best", fontsize="small")
    ax.set_title(_title(design, "radius of curvature (positive: convex)"))
    return figure


def _plan_limits(design: CamDesign) -> tuple[float, float, float, float]:
    """Fixed drawing limits (m) that hold the cam and the follower at every angle."""
    g = design.cycle()
    reach = float(np.max(np.hypot(*g.profile.T)))
    f = design.follower
    top = 1.6 * reach
    lo_x, hi_x, lo_y, hi_y = -reach, reach, -reach, top
    if isinstance(f, OscillatingRoller | OscillatingFlat):
        hi_x = max(hi_x, f.pivot_distance + 0.15 * reach)
        hi_y = max(hi_y, getattr(f, "arm", 0.0) + 0.1 * reach)
    pad = 0.08 * reach
    return lo_x - pad, hi_x + pad, lo_y - pad, hi_y + pad


def draw_plan(ax: Axes, design: CamDesign, phi: float) -> None:
    """Cam and follower at cam angle ``phi`` (rad) in the fixed frame: the cam turned by
    ``phi``, the follower in its position, the contact normal and the pressure angle."""
    scale, unit = _length(design)
    g = design.cycle()
    here = design.cam.at(np.array([phi]))
    turn = np.full(g.profile.shape[0], -phi)  # R(φ) = R(−(−φ))
    cam = _rotate(g.profile, turn) / scale
    ax.fill(*cam.T, facecolor="0.88", edgecolor="black", linewidth=1.2)
    ax.plot([0], [0], marker="o", color="black", markersize=4)
    m = here.motion
    b, _, _, _ = follower_point(design.follower, design.cam.base_radius, m.s, m.ds, m.dds)
    b = b[0] / scale
    contact = _rotate(here.profile, np.array([-phi]))[0] / scale
    normal = _rotate(here.normal, np.array([-phi]))[0]
    f = design.follower
    t = np.linspace(0, 2 * math.pi, 121)
    reach = float(np.max(np.hypot(*cam.T)))
    if f.flat:
        low, high = _face_span(design, g, to_pivot=f.oscillating)
        tangent = _face_tangent(design, normal)
        foot = contact - float(here.contact_along[0]) / scale * tangent
        face = np.stack([foot + low / scale * tangent, foot + high / scale * tangent])
        ax.plot(*face.T, color="tab:blue", linewidth=2.5)
        if isinstance(f, TranslatingFlat):
            ax.plot([0, 0], [foot[1], foot[1] + 0.5 * reach], color="tab:blue", linewidth=2.5)
        else:
            pivot = np.array([f.pivot_distance, 0.0]) / scale
            ax.plot([pivot[0], foot[0]], [pivot[1], foot[1]], color="tab:blue", linewidth=2.5)
            ax.plot(*pivot, marker="o", color="tab:blue", markersize=6)
    else:
        r = f.roller_radius / scale
        ax.fill(b[0] + r * np.cos(t), b[1] + r * np.sin(t), facecolor="white",
                edgecolor="tab:blue", linewidth=1.5)
        if isinstance(f, TranslatingRoller):
            ax.plot([b[0], b[0]], [b[1], b[1] + 0.6 * reach], color="tab:blue", linewidth=2.5)
            ax.axvline(f.offset / scale, color="tab:blue", linestyle="-.", linewidth=0.5)
        else:
            pivot = np.array([f.pivot_distance, 0.0]) / scale
            ax.plot([pivot[0], b[0]], [pivot[1], b[1]], color="tab:blue", linewidth=2.5)
            ax.plot(*pivot, marker="o", color="tab:blue", markersize=6)
    length = 0.35 * reach
    ax.annotate("", xy=contact + length * normal, xytext=contact,
                arrowprops={"arrowstyle": "->", "color": "tab:red"})
    alpha = math.degrees(float(here.pressure[0]))
    ax.set_title(f"{_title(design, 'position plan')}\nφ = {math.degrees(phi) % 360:.1f} deg, "
                 f"s = {_s_text(design, float(m.s[0]))}, α = {alpha:.2f} deg", fontsize=9)
    ax.set_aspect("equal")
    ax.set_xlabel(f"x [{unit}]")
    ax.set_ylabel(f"y [{unit}]")


def _s_text(design: CamDesign, s: float) -> str:
    if design.follower.oscillating:
        return f"{math.degrees(s):.3f} deg"
    scale, unit = _length(design)
    return f"{s / scale:.4g} {unit}"


def plot_plan(design: CamDesign, phi: float) -> Figure:
    """The position plan at cam angle ``phi`` (rad)."""
    limits = _plan_limits(design)
    scale, _ = _length(design)
    figure = new_figure(6.5, 6.5 * (limits[3] - limits[2]) / (limits[1] - limits[0]) + 0.6)
    ax = figure.add_subplot()
    draw_plan(ax, design, phi)
    ax.set_xlim(limits[0] / scale, limits[1] / scale)
    ax.set_ylim(limits[2] / scale, limits[3] / scale)
    ax.grid(True, linewidth=0.3)
    return figure


def plot_cam(design: CamDesign, view: str, *, phi: float = 0.0) -> Figure:
    """The figure ``view`` (one of :data:`CAM_VIEWS`)."""
    if view == "program":
        return plot_program(design)
    if view == "profile":
        return plot_profile(design)
    if view == "pressure":
        if isinstance(design.follower, TranslatingFlat):  # a rocker's face has one
            raise ViewError("a flat face perpendicular to its axis has a pressure angle of "
                            "0", "draw the program, profile, curvature or plan instead")
        return plot_pressure(design)
    if view == "curvature":
        return plot_curvature(design)
    if view == "plan":
        return plot_plan(design, phi)
    raise ViewError(f"no cam view {view!r}", f"use one of {', '.join(CAM_VIEWS)}")


def animate_cam(design: CamDesign, path: str | os.PathLike[str], *, frames: int = 72,
                fps: float | None = None, dpi: int = 80,
                progress: Callable[[int, int], object] | None = None) -> Path:
    """The position plan over one turn at ``frames`` equal steps, as GIF, MP4 or HTML
    (the writers of :mod:`mechloop.views.animation`).  The frame time is the time of a
    step at the cam speed (at least 20 ms), 100 ms without a speed; ``fps`` overrides."""
    from mechloop.views.animation import (
        ANIMATION_SUFFIXES,
        DEFAULT_INTERVAL_MS,
        MIN_INTERVAL_MS,
        _counted,
        _even,
        _save_gif,
        _save_html,
        _save_mp4,
        gif_delay,
    )

    target = Path(path)
    suffix = target.suffix.lower()
    if suffix not in ANIMATION_SUFFIXES:
        raise ViewError(f"{target}: cannot save an animation as '{suffix or 'no suffix'}'",
                        "use a file name ending in .gif, .mp4 or .html")
    if fps is not None:
        interval = 1000.0 / fps
    elif design.omega is not None:
        interval = max(2 * math.pi / design.omega / frames * 1000.0, MIN_INTERVAL_MS)
    else:
        interval = DEFAULT_INTERVAL_MS
    limits = _plan_limits(design)
    scale, _ = _length(design)
    width = 6.0
    height = width * (limits[3] - limits[2]) / (limits[1] - limits[0]) + 0.6
    size = (_even(width, dpi), _even(height, dpi))
    figure = Figure(figsize=(size[0] / dpi, size[1] / dpi), dpi=dpi)
    canvas = FigureCanvasAgg(figure)
    ax = figure.add_axes((0.12, 0.08, 0.84, 0.82))

    def render(k: int) -> np.ndarray:
        ax.clear()
        draw_plan(ax, design, 2 * math.pi * k / frames)
        ax.set_xlim(limits[0] / scale, limits[1] / scale)
        ax.set_ylim(limits[2] / scale, limits[3] / scale)
        canvas.draw()
        return np.array(canvas.buffer_rgba(), dtype=np.uint8)

    images = _counted((render(k) for k in range(frames)), frames, progress)
    if suffix == ".gif":
        _save_gif(images, target, gif_delay(interval))
    elif suffix == ".mp4":
        _save_mp4(images, size, target, interval)
    else:
        _save_html(images, size, target, interval)
    return target
