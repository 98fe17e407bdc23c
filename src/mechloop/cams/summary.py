"""The figures of a cam design as rows of text (quantity, value, unit) in the design file's
units, for the command line: every figure decided over the continuous cam angle
(:meth:`mechloop.cams.design.CamDesign.summary`)."""

from __future__ import annotations

import math

from mechloop.cams.design import CamDesign
from mechloop.model.units import unit_factor

Row = tuple[str, str, str]


def _at(phi: float) -> str:
    return f" at φ = {math.degrees(phi):.3f} deg"


def summary_rows(design: CamDesign) -> tuple[list[Row], list[Row], list[str]]:
    """``(figures, segments, verdicts)``: the design's figures; one row per segment (its
    law and peak coefficients ``C_v, C_a, C_j``); and the checks in words."""
    s = design.summary()
    length = design.units[0]
    to = 1.0 / unit_factor(length, "length")
    rocker = design.follower.oscillating
    flat = design.follower.flat
    lift_unit = "deg" if rocker else length
    lift = (180 / math.pi) if rocker else to
    rows: list[Row] = []
    what = "profile" if flat else "pitch curve"
    rows.append((f"base radius R0 ({what})", f"{s.base_radius * to:.6g}", length))
    if s.minimum is not None:
        why = "convex profile" if flat else "allowed pressure angle"
        rows.append((f"smallest base radius ({why})", f"{s.minimum * to:.6g}", length))
    if not flat:
        r = design.follower.roller_radius  # type: ignore[union-attr]
        rows.append(("base radius of the working profile R0 − r",
                     f"{(s.base_radius - r) * to:.6g}", length))
    rows.append(("stroke" if not rocker else "swing", f"{s.stroke * lift:.6g}", lift_unit))
    if s.pressure is not None:
        rows.append(("largest |pressure angle|" + _at(s.pressure.phi),
                     f"{math.degrees(s.pressure.value):.6g}", "deg"))
    rows.append(("smallest radius of curvature of the profile (convex)" + _at(s.rho.phi),
                 "∞ (nowhere convex)" if math.isinf(s.rho.value) else
                 f"{s.rho.value * to:.6g}", length))
    if s.face is not None:
        origin = "the pivot's foot" if rocker else "the axis"
        rows.append((f"contact on the face, from {origin}", f"{s.face.low.value * to:.6g} to "
                     f"{s.face.high.value * to:.6g}", length))
        rows.append(("smallest face width", f"{s.face.width * to:.6g}", length))
    w = design.omega
    per = "/rad" if w is None else "/s"
    for name, label, k in (("v", "velocity", 1), ("a", "acceleration", 2), ("j", "jerk", 3)):
        factor = lift * (1.0 if w is None else w**k)
        unit = f"{lift_unit}{per}" + ("" if k == 1 else f"^{k}")
        analog = "" if w is not None else " analog"
        rows.append((f"largest |{label}{analog}|", f"{s.peak(name) * factor:.6g}", unit))
    segments: list[Row] = []
    for seg, peak in zip(design.program.segments, s.peaks, strict=True):
        head = f"{seg.kind} {math.degrees(seg.angle):.6g} deg"
        if peak is None:
            segments.append((head, "—", ""))
            continue
        segments.append((f"{head}, {seg.lift * lift:.6g} {lift_unit}", seg.law.name,  # type: ignore[union-attr]
                         f"{peak.velocity:.5g}, {peak.acceleration:.5g}, {peak.jerk:.5g}"))
    verdicts: list[str] = []
    if s.pressure_ratio is not None:
        ok = s.pressure_ratio <= 1 + 1e-9
        verdicts.append("pressure angle within the allowed over the whole turn" if ok else
                         f"pressure angle exceeds the allowed (by a factor "
                         f"{s.pressure_ratio:.4g})" + ("" if s.minimum is None else
                                                        f": raise the base radius to at least "
                                                        f"{s.minimum * to:.6g} {length}"))
    if flat:
        verdicts.append("profile convex (its radius of curvature at least the allowed)"
                        if not s.undercut else "profile not convex: its radius of curvature "
                        "falls below the allowed; raise the base radius")
    else:
        verdicts.append("no undercut: the pitch curve's radius exceeds the roller's where "
                        "convex" if not s.undercut else "undercut / pointed profile: the "
                        "pitch curve's radius falls to the roller radius; use a smaller "
                        "roller or a larger base radius")
    return rows, segments, verdicts
