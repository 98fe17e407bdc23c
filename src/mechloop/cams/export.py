"""The cam as files: the table over the turn (CSV and the other table formats), and the
profile as a drawing for CAD/CAM — DXF (ezdxf) and SVG — in millimetres.

Both drawings hold the working profile as one closed polyline (``positions`` points over
the turn, in the cam's frame, centre at the origin), and on their own layers (DXF) or
groups (SVG) the pitch curve (roller followers), the base circle and the centre.  The
files are written atomically.
"""

from __future__ import annotations

import io
import os
from pathlib import Path

import numpy as np

from mechloop.cams.design import CamDesign
from mechloop.output.atomic import atomic_write_bytes, atomic_write_text
from mechloop.output.tables import write_frame

MM = 1000.0


def write_table(design: CamDesign, path: str | os.PathLike[str]) -> Path:
    """The table of :meth:`CamDesign.table` by the file's suffix (.csv, .json, ...)."""
    return write_frame(design.table(), path, sheet="cam")


def _curves(design: CamDesign) -> tuple[np.ndarray, np.ndarray | None, float]:
    """Profile and pitch curve (mm, without the repeated last point) and the base circle
    radius of the profile (mm)."""
    g = design.cycle()
    profile = g.profile[:-1] * MM
    flat = design.follower.flat
    pitch = None if flat else g.pitch[:-1] * MM
    base = design.cam.base_radius * MM
    if not flat:
        base -= design.follower.roller_radius * MM  # type: ignore[union-attr]
    return profile, pitch, base


def write_dxf(design: CamDesign, path: str | os.PathLike[str]) -> Path:
    """The profile as a DXF drawing (mm): layers PROFILE (closed polyline), PITCH (the
    pitch curve), BASE (the profile's base circle) and CENTER (a point at the centre)."""
    import ezdxf

    profile, pitch, base = _curves(design)
    doc = ezdxf.new("R2010", setup=False)
    doc.units = ezdxf.units.MM
    for name, colour in (("PROFILE", 7), ("PITCH", 1), ("BASE", 3), ("CENTER", 2)):
        doc.layers.add(name, color=colour)
    space = doc.modelspace()
    space.add_lwpolyline(profile.tolist(), close=True, dxfattribs={"layer": "PROFILE"})
    if pitch is not None:
        space.add_lwpolyline(pitch.tolist(), close=True, dxfattribs={"layer": "PITCH"})
    if base > 0:
        space.add_circle((0.0, 0.0), base, dxfattribs={"layer": "BASE"})
    space.add_point((0.0, 0.0), dxfattribs={"layer": "CENTER"})
    stream = io.StringIO()
    doc.write(stream)
    target = Path(path)
    atomic_write_bytes(target, stream.getvalue().encode("utf-8"))
    return target


def _points(xy: np.ndarray) -> str:
    # SVG's y runs down: the drawing is mirrored so that it reads as the cam's frame
    return " ".join(f"{x:.6f},{-y:.6f}" for x, y in xy)


def write_svg(design: CamDesign, path: str | os.PathLike[str]) -> Path:
    """The profile as an SVG drawing, 1 user unit = 1 mm (width and height in mm)."""
    profile, pitch, base = _curves(design)
    everything = profile if pitch is None else np.vstack([profile, pitch])
    reach = float(np.max(np.abs(everything))) * 1.05
    size = 2 * reach
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{size:.3f}mm" '
             f'height="{size:.3f}mm" viewBox="{-reach:.6f} {-reach:.6f} {size:.6f} '
             f'{size:.6f}">',
             f"<title>{design.name or 'cam'}: profile (mm)</title>",
             f'<polygon id="profile" points="{_points(profile)}" fill="none" '
             'stroke="black" stroke-width="0.3"/>']
    if pitch is not None:
        parts.append(f'<polygon id="pitch" points="{_points(pitch)}" fill="none" '
                     'stroke="red" stroke-width="0.15" stroke-dasharray="2,1"/>')
    if base > 0:
        parts.append(f'<circle id="base" cx="0" cy="0" r="{base:.6f}" fill="none" '
                     'stroke="green" stroke-width="0.15" stroke-dasharray="1,1"/>')
    parts.append('<circle id="center" cx="0" cy="0" r="0.5" fill="black"/>')
    parts.append("</svg>")
    target = Path(path)
    atomic_write_text(target, "\n".join(parts) + "\n")
    return target
