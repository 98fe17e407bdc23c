"""A cam design as the command line and the files see it: the cam, how its base radius was
chosen, the limits it is held to, its speed, and the figures that describe it."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from mechloop.cams.base_radius import (
    CamDesignError,
    max_pressure_ratio,
    minimum_base_radius,
    minimum_flat_base_radius,
)
from mechloop.cams.checks import (
    Extreme,
    FaceWidth,
    face_width,
    max_pressure_angle,
    min_curvature_radius,
    motion_max,
)
from mechloop.cams.followers import (
    Follower,
    OscillatingRoller,
    TranslatingFlat,
    TranslatingRoller,
)
from mechloop.cams.laws import PeakCoefficients
from mechloop.cams.profile import Cam, Geometry
from mechloop.cams.program import MotionProgram


@dataclass(frozen=True)
class CamDesign:
    """``cam`` with its base radius; ``minimum``: the smallest base radius allowed by the
    pressure angle (roller) or by the convexity (flat face), None when not asked for;
    ``allowed``/``allowed_return``: the allowed pressure angles (rad) or None;
    ``min_curvature``: the flat face's smallest radius of curvature (m); ``omega``: cam
    speed (rad/s) or None; ``positions``: points over the turn in tables and drawings;
    ``units``: the file's (length, angle) units for display."""

    cam: Cam
    minimum: float | None
    allowed: float | None
    allowed_return: float | None
    min_curvature: float
    omega: float | None
    name: str = ""
    positions: int = 360
    units: tuple[str, str] = ("mm", "deg")

    @classmethod
    def build(cls, follower: Follower, program: MotionProgram, *,
              base_radius: float | None = None, allowed: float | None = None,
              allowed_return: float | None = None, min_curvature: float = 0.0,
              omega: float | None = None, name: str = "", positions: int = 360,
              units: tuple[str, str] = ("mm", "deg")) -> CamDesign:
        """The design with ``base_radius`` (m), or with the smallest one allowed when it
        is None (raises :class:`~mechloop.cams.base_radius.CamDesignError` when there is
        none)."""
        check_face_turn(follower, program)
        if follower.flat:
            minimum = (minimum_flat_base_radius(program, min_curvature, follower=follower)
                       if base_radius is None else None)
        elif allowed is not None:
            try:
                minimum = minimum_base_radius(follower, program, allowed,
                                              allowed_return=allowed_return)
            except CamDesignError:
                if base_radius is None:
                    raise
                minimum = None  # the given radius is checked against the limit all the same
        else:
            minimum = None
        radius = base_radius if base_radius is not None else minimum
        assert radius is not None
        check_placement(follower, program, radius)
        return cls(Cam(follower, program, radius), minimum, allowed, allowed_return,
                   min_curvature, omega, name, positions, units)

    @property
    def follower(self) -> Follower:
        return self.cam.follower

    @property
    def program(self) -> MotionProgram:
        return self.cam.program

    def cycle(self) -> Geometry:
        """The cam at ``positions + 1`` angles over the turn (both ends)."""
        return self.cam.cycle(self.positions)

    def summary(self) -> Summary:
        """The figures of the design, each decided over the continuous cam angle."""
        program = self.program
        rho = min_curvature_radius(self.cam)
        flat = self.follower.flat
        if flat:  # at the smallest base radius ρ equals the allowed but for rounding
            undercut = rho.value < self.min_curvature - 1e-9 * self.cam.base_radius
        else:
            undercut = rho.value <= 0
        pressure = (None if isinstance(self.follower, TranslatingFlat)
                    else max_pressure_angle(self.cam))
        ratio = (None if flat or self.allowed is None
                 else max_pressure_ratio(self.cam, self.allowed, self.allowed_return))
        return Summary(
            base_radius=self.cam.base_radius, minimum=self.minimum,
            stroke=program.stroke, pressure=pressure, pressure_ratio=ratio,
            rho=rho, undercut=undercut,
            face=face_width(self.cam) if flat else None,
            peaks=program.peaks(),
            extremes={name: (motion_max(program, lambda m, k=k: getattr(m, k)),
                             motion_max(program, lambda m, k=k: -getattr(m, k)))
                      for name, k in (("s", "s"), ("v", "ds"), ("a", "dds"), ("j", "ddds"))})

    def table(self) -> pd.DataFrame:
        """One row per cam angle of :meth:`cycle`: the motion (SI analogs per rad, and at
        the cam speed when given), the pitch curve and profile (m, the cam's frame), the
        pressure angle (deg) and the radii of curvature (m)."""
        g = self.cycle()
        m = g.motion
        rocker = self.follower.oscillating
        unit = "rad" if rocker else "m"
        cols: dict[str, np.ndarray] = {
            "phi [deg]": np.degrees(m.phi), f"s [{unit}]": m.s,
            f"ds/dphi [{unit}/rad]": m.ds, f"d2s/dphi2 [{unit}/rad^2]": m.dds,
            f"d3s/dphi3 [{unit}/rad^3]": m.ddds}
        if self.omega is not None:
            w = self.omega
            cols.update({f"v [{unit}/s]": m.ds * w, f"a [{unit}/s^2]": m.dds * w * w,
                         f"j [{unit}/s^3]": m.ddds * w**3})
        cols.update({"x_pitch [m]": g.pitch[:, 0], "y_pitch [m]": g.pitch[:, 1],
                     "x_profile [m]": g.profile[:, 0], "y_profile [m]": g.profile[:, 1],
                     "pressure angle [deg]": np.degrees(g.pressure)})
        if g.pitch_rho is not None:
            cols["rho_pitch [m]"] = g.pitch_rho
        if g.contact_along is not None:
            cols["contact on the face [m]"] = g.contact_along
        cols["rho_profile [m]"] = g.rho
        return pd.DataFrame(cols)


@dataclass(frozen=True)
class Summary:
    """Figures of a design (SI: m or rad): base radius and the smallest allowed; stroke;
    the largest ``|α|`` and the largest ``|α|/α_allow`` (roller followers); the smallest
    radius of curvature of the working profile where convex and whether it is undercut
    or pointed (a roller: ``ρ_pitch ≤ r``; a flat face: ``ρ`` below the allowed); the
    flat face's contact travel; the peak coefficients of each segment; and the extremes
    of ``s`` and its analogs ``(max, −min)`` per rad."""

    base_radius: float
    minimum: float | None
    stroke: float
    pressure: Extreme | None
    pressure_ratio: float | None
    rho: Extreme
    undercut: bool
    face: FaceWidth | None
    peaks: list[PeakCoefficients | None]
    extremes: dict[str, tuple[Extreme, Extreme]]

    def peak(self, name: str) -> float:
        """Largest ``|value|`` of ``s``, ``v``, ``a`` or ``j`` (analog per rad^k)."""
        high, low = self.extremes[name]
        return max(high.value, low.value)


def check_placement(follower: Follower, program: MotionProgram, radius: float) -> None:
    """Raise :class:`~mechloop.cams.base_radius.CamDesignError` unless the follower stays
    where its geometry holds over the whole (continuous) turn: a translating roller's
    centre and a flat face above the cam centre (``s₀ + s > 0``, ``R₀ + s > 0``), a
    rocker's arm at ``0 < β < 180°``, a rocker's face at ``0 < β < 90°`` and turning
    slower than the cam the other way (``ψ' > −1``: the contact ``u = a cos β/(1 + ψ')``
    stays finite)."""
    high = motion_max(program, lambda m: m.s).value
    low = -motion_max(program, lambda m: -m.s).value
    if isinstance(follower, TranslatingRoller):
        ok = math.sqrt(radius**2 - follower.offset**2) + low > 0
    elif isinstance(follower, TranslatingFlat):
        ok = radius + low > 0
    else:
        start = follower.start_angle(radius)
        ok = 0 < start + low and start + high < (math.pi if isinstance(
            follower, OscillatingRoller) else math.pi / 2)
    if not ok:
        raise CamDesignError(
            f"with the base radius {radius:.6g} m the follower leaves its geometry over the "
            "turn (it passes the cam centre, or the rocker swings past its limit)",
            "raise the base radius, or start the program at its lowest displacement")
    check_face_turn(follower, program)


def check_face_turn(follower: Follower, program: MotionProgram) -> None:
    """A rocker's face must turn back slower than the cam (``ψ' > −1``)."""
    if follower.flat and follower.oscillating and \
            motion_max(program, lambda m: -m.ds).value >= 1:
        raise CamDesignError(
            "the rocker's face turns back as fast as the cam turns (dψ/dφ reaches −1): its "
            "contact runs off to infinity", "return over a larger cam angle, or by a law "
            "with a smaller peak velocity")
