"""The velocity plan (Kutzbach diagram) of a planetary train: the linear speed of the
points of every member along one radius through the planet's axis.

The speed of a member turning at ``ω`` about the central axis is ``v = ω y`` at the
distance ``y`` from it — a straight line through the origin; the planet turns about its
own axis at ``a_w`` and runs with the carrier, so its line is ``v = ω_h a_w + ω_g (y − a_w)``.
Rolling without slip makes the planet's line meet each central gear's line at that gear's
pitch radius (``v = ω_a r_a`` at ``r_a``, ``v = ω_b r_b`` at ``r_b``, 0 for a fixed ``b``):
the plan checks Willis' formula by geometry, whichever member is held.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.figure import Figure

from mechloop.gears.planetary import PlanetaryTrain
from mechloop.gears.wolfrom import WolfromTrain
from mechloop.views.figure import new_figure


@dataclass(frozen=True)
class VelocityPlan:
    """The lines of the plan: ``omega`` (rad/s) of ``a, h, g, b``; radii (mm) of the
    central gears' pitch circles ``r_a, r_b``, of the planet's axis ``a_w`` and the planet's
    extent ``(y_low, y_high)``."""

    omega: dict[str, float]
    r_a: float
    r_b: float
    a_w: float
    planet: tuple[float, float]

    def planet_speed(self, y: np.ndarray | float) -> np.ndarray:
        """Linear speed (mm/s) of the planet's points at the radii ``y`` (mm)."""
        y = np.asarray(y, float)
        return self.omega["h"] * self.a_w + self.omega["g"] * (y - self.a_w)


def velocity_plan(train: PlanetaryTrain, speed_rpm: float = 1000.0) -> VelocityPlan:
    """The plan of ``train`` with its driver (``a`` by default) turning at ``speed_rpm``."""
    omega = train.speeds(speed_rpm * np.pi / 30.0)
    radii = train.pitch_radii()
    a_w = train.a_w
    r_g, r_f = radii["g"], radii["f"]
    # the planet meets a and b on the inner side (an external mesh) or the outer (a ring)
    ys = (a_w - train.scheme.sigma_a * r_g, a_w - train.scheme.sigma_b * r_f, a_w - r_g,
          a_w + r_g, a_w - r_f, a_w + r_f)
    return VelocityPlan(omega, radii["a"], radii["b"], a_w, (min(ys), max(ys)))


def plot_velocity_plan(train: PlanetaryTrain, speed_rpm: float = 1000.0) -> Figure:
    """The Kutzbach diagram: radius (mm) up, linear speed (m/s) across."""
    plan = velocity_plan(train, speed_rpm)
    fig = new_figure(7.0, 6.0)
    ax = fig.subplots()
    held = train.fixed
    for key, colour, label, top in (("a", "tab:blue", "a", plan.r_a),
                                    ("h", "tab:green", "carrier h", plan.a_w),
                                    ("b", "k", "b", plan.r_b)):
        label += {held: " (fixed)", train.driver: " (input)",
                  train.output: " (output)"}[key]
        w = plan.omega[key]
        ys = np.array([0.0, top])
        ax.plot(w * ys / 1000.0, ys, color=colour,
                label=f"{label}: ω = {w:.4g} rad/s")
    yp = np.linspace(*plan.planet, 50)
    ax.plot(plan.planet_speed(yp) / 1000.0, yp, color="tab:red", lw=2,
            label=f"planet g: ω = {plan.omega['g']:.4g} rad/s")
    for y, name in ((plan.r_a, "r_a"), (plan.r_b, "r_b"), (plan.a_w, "a_w")):
        ax.axhline(y, color="0.6", lw=0.5, ls=":")
        ax.annotate(name, (0, y), textcoords="offset points", xytext=(3, 2), fontsize=8)
    ax.plot([plan.omega["a"] * plan.r_a / 1000.0, plan.omega["b"] * plan.r_b / 1000.0,
             plan.omega["h"] * plan.a_w / 1000.0],
            [plan.r_a, plan.r_b, plan.a_w], "o", color="k", ms=4)
    ax.axvline(0, color="k", lw=0.5)
    ax.set_xlabel("linear speed v, m/s")
    ax.set_ylabel("distance from the central axis, mm")
    ax.set_title(f"{train.scheme.name}: z = "
                 + "/".join(f"{k}{v}" for k, v in train.teeth.items())
                 + f", i_{train.driver}{train.output} = {train.ratio:.6g}, "
                 f"n_{train.driver} = {speed_rpm:g} rpm", fontsize=9)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    return fig


def wolfrom_plan(train: WolfromTrain, speed_rpm: float = 1000.0) -> VelocityPlan:
    """The plan of a Wolfrom train with the sun ``a`` at ``speed_rpm``: the stepped
    planet is one body, one straight line meeting ``a`` at ``r_a``, the fixed ring ``b`` at
    ``r_b`` (v = 0) and the output ring ``e`` at ``r_e``.  ``r_b`` of the plan is the fixed
    ring's; the output ring's radius is ``pitch_radii()["e"]``."""
    omega = train.speeds(speed_rpm * np.pi / 30.0)
    radii = train.pitch_radii()
    a_w = train.a_w
    low = a_w - max(radii["g"], radii["f"])
    high = a_w + max(radii["g"], radii["f"])
    return VelocityPlan(omega, radii["a"], radii["b"], a_w, (low, high))


def plot_wolfrom_plan(train: WolfromTrain, speed_rpm: float = 1000.0) -> Figure:
    """The Kutzbach diagram of a Wolfrom train: radius (mm) up, linear speed (m/s)
    across."""
    plan = wolfrom_plan(train, speed_rpm)
    r_e = train.pitch_radii()["e"]
    fig = new_figure(7.0, 6.0)
    ax = fig.subplots()
    for key, colour, label, top in (("a", "tab:blue", "sun a", plan.r_a),
                                    ("h", "tab:green", "carrier h", plan.a_w),
                                    ("b", "k", "ring b (fixed)", plan.r_b),
                                    ("e", "tab:purple", "ring e (output)", r_e)):
        w = plan.omega[key]
        ys = np.array([0.0, top])
        ax.plot(w * ys / 1000.0, ys, color=colour, label=f"{label}: ω = {w:.4g} rad/s")
    yp = np.linspace(*plan.planet, 50)
    ax.plot(plan.planet_speed(yp) / 1000.0, yp, color="tab:red", lw=2,
            label=f"stepped planet g/f: ω = {plan.omega['g']:.4g} rad/s")
    for y, name in ((plan.r_a, "r_a"), (plan.r_b, "r_b"), (r_e, "r_e"), (plan.a_w, "a_w")):
        ax.axhline(y, color="0.6", lw=0.5, ls=":")
        ax.annotate(name, (0, y), textcoords="offset points", xytext=(3, 2), fontsize=8)
    ax.plot([plan.omega["a"] * plan.r_a / 1000.0, 0.0, plan.omega["e"] * r_e / 1000.0,
             plan.omega["h"] * plan.a_w / 1000.0], [plan.r_a, plan.r_b, r_e, plan.a_w], "o",
            color="k", ms=4)
    ax.axvline(0, color="k", lw=0.5)
    ax.set_xlabel("linear speed v, m/s")
    ax.set_ylabel("distance from the central axis, mm")
    ax.set_title("wolfrom: z = " + "/".join(f"{k}{v}" for k, v in train.teeth.items())
                 + f", i_ae = {train.ratio:.6g}, n_a = {speed_rpm:g} rpm", fontsize=9)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    return fig
