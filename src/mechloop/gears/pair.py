"""The geometry of an external involute spur gear pair (ISO 21771 names).

Inputs: module ``m_n``, numbers of teeth ``z = (z_1, z_2)``, normal pressure angle
``alpha_n`` (rad), profile shift coefficients ``x`` or the centre distance ``a``, the basic
rack's addendum, clearance and tool tip radius coefficients ``h_a*, c*, ρ*`` (ISO 53
profile A: 1, 0.25, 0.38).  The tip circles are reduced by ``Δy·m`` (``Δy = x_1 + x_2 − y``,
``y = (a − a_0)/m``) so the tip clearance stays ``c* m`` (GOST 16532-70, DIN 3960).
Per-gear values are arrays of shape (2,): index 0 the pinion (gear 1), 1 the wheel.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from mechloop.errors import HintedError
from mechloop.gears.centre_distance import (
    centre_distance_from_shifts,
    shift_sum_from_centre_distance,
)
from mechloop.gears.checks import (
    Check,
    form_diameter,
    lowest_contact_diameters,
    minimum_shift,
)
from mechloop.gears.involute import chordal_thickness, inv, thickness_on_circle
from mechloop.gears.span import base_tangent_length, span_teeth


@dataclass(frozen=True)
class GearPair:
    """An external spur gear pair without backlash; lengths in the unit of ``m_n``,
    angles in rad.  Build it with :func:`gear_pair`."""

    m_n: float
    z: tuple[int, int]
    alpha_n: float
    x: tuple[float, float]
    ha: float = 1.0
    c: float = 0.25
    rho: float = 0.38
    s_a_min: float = 0.25  #: least tip thickness, in modules (pointed-tooth check)
    a: float = field(init=False)
    alpha_w: float = field(init=False)

    def __post_init__(self) -> None:
        a, alpha_w = centre_distance_from_shifts(self.m_n, *self.z, *self.x, self.alpha_n)
        object.__setattr__(self, "a", float(a))
        object.__setattr__(self, "alpha_w", float(alpha_w))

    # ------------------------------------------------------------------ per gear, (2,)
    @property
    def zs(self) -> np.ndarray:
        return np.asarray(self.z, float)

    @property
    def xs(self) -> np.ndarray:
        return np.asarray(self.x, float)

    @property
    def d(self) -> np.ndarray:
        """Reference diameters ``m z``."""
        return self.m_n * self.zs

    @property
    def d_b(self) -> np.ndarray:
        """Base diameters ``d cos α``."""
        return self.d * np.cos(self.alpha_n)

    @property
    def d_w(self) -> np.ndarray:
        """Working pitch diameters ``2 a z_i/(z_1 + z_2)``."""
        return 2.0 * self.a * self.zs / self.zs.sum()

    @property
    def d_a(self) -> np.ndarray:
        """Tip diameters ``d + 2 m (h_a* + x − Δy)``."""
        return self.d + 2.0 * self.m_n * (self.ha + self.xs - self.dy)

    @property
    def d_f(self) -> np.ndarray:
        """Root diameters ``d − 2 m (h_a* + c* − x)``."""
        return self.d - 2.0 * self.m_n * (self.ha + self.c - self.xs)

    @property
    def h_a(self) -> np.ndarray:
        """Addenda ``(d_a − d)/2``."""
        return (self.d_a - self.d) / 2.0

    @property
    def h_f(self) -> np.ndarray:
        """Dedenda ``(d − d_f)/2``."""
        return (self.d - self.d_f) / 2.0

    @property
    def h(self) -> np.ndarray:
        """Tooth depths ``(d_a − d_f)/2``."""
        return (self.d_a - self.d_f) / 2.0

    @property
    def s(self) -> np.ndarray:
        """Tooth thickness on the reference circle ``m (π/2 + 2 x tan α)``."""
        return self.m_n * (np.pi / 2.0 + 2.0 * self.xs * np.tan(self.alpha_n))

    @property
    def e(self) -> np.ndarray:
        """Space width on the reference circle ``p − s``."""
        return self.p - self.s

    def s_y(self, d_y) -> np.ndarray:
        """Tooth thickness (arc) on the circles ``d_y`` (shape (2,) or broadcasting with
        it: ``d_y[..., i]`` is a circle of gear ``i``)."""
        return thickness_on_circle(self.s, self.d, self.alpha_n, d_y)

    @property
    def s_a(self) -> np.ndarray:
        """Tooth thickness on the tip circle."""
        return self.s_y(self.d_a)

    @property
    def s_w(self) -> np.ndarray:
        """Tooth thickness on the working pitch circle."""
        return self.s_y(self.d_w)

    @property
    def s_b(self) -> np.ndarray:
        """Tooth thickness on the base circle."""
        return self.s_y(self.d_b)

    @property
    def chordal(self) -> tuple[np.ndarray, np.ndarray]:
        """Chordal thickness on the reference circle and its height from the tip."""
        return chordal_thickness(self.s, self.d, self.d_a)

    @property
    def k_span(self) -> np.ndarray:
        """Teeth in the span of the base tangent length (see :mod:`.span`)."""
        return span_teeth(self.zs, self.xs, self.alpha_n)

    @property
    def W_k(self) -> np.ndarray:
        """Base tangent length over ``k_span`` teeth (span measurement)."""
        return base_tangent_length(self.m_n, self.zs, self.xs, self.alpha_n, self.k_span)

    @property
    def x_min(self) -> np.ndarray:
        """Smallest shift without undercut (see :func:`.checks.minimum_shift`)."""
        return minimum_shift(self.zs, self.ha, self.c, self.rho, self.alpha_n)

    @cached_property
    def _form(self) -> tuple[np.ndarray, np.ndarray]:
        return form_diameter(self.m_n, self.zs, self.xs, self.ha, self.c, self.rho,
                             self.alpha_n)

    @property
    def d_Ff(self) -> np.ndarray:
        """Form diameters: where the generated involute starts above the fillet."""
        return self._form[0]

    @property
    def undercut(self) -> np.ndarray:
        return self._form[1]

    @cached_property
    def _lowest(self) -> tuple[np.ndarray, np.ndarray]:
        return lowest_contact_diameters(self.a, self.alpha_w, self.d_b, self.d_a)

    @property
    def d_Nf(self) -> np.ndarray:
        """Diameters of the lowest contact point on each flank (active profile start)."""
        return self._lowest[0]

    # ------------------------------------------------------------------ the pair
    @property
    def u(self) -> float:
        """Gear ratio ``z_2/z_1``."""
        return self.z[1] / self.z[0]

    @property
    def p(self) -> float:
        """Pitch ``π m``."""
        return float(np.pi * self.m_n)

    @property
    def p_b(self) -> float:
        """Base pitch ``π m cos α``."""
        return float(np.pi * self.m_n * np.cos(self.alpha_n))

    @property
    def a0(self) -> float:
        """Reference centre distance ``m (z_1 + z_2)/2``."""
        return float(self.m_n * self.zs.sum() / 2.0)

    @property
    def y(self) -> float:
        """Centre distance modification coefficient ``(a − a_0)/m``."""
        return (self.a - self.a0) / self.m_n

    @property
    def dy(self) -> float:
        """Tip shortening coefficient ``x_1 + x_2 − y`` (≥ 0)."""
        return float(self.xs.sum() - self.y)

    @property
    def tip_clearances(self) -> np.ndarray:
        """Tip clearances ``a − (d_a1 + d_f2)/2`` and ``a − (d_a2 + d_f1)/2``."""
        return self.a - (self.d_a + self.d_f[::-1]) / 2.0

    @property
    def line_of_action(self) -> float:
        """Length ``N_1 N_2 = a sin α_w`` of the line of action between the base circles."""
        return float(self.a * np.sin(self.alpha_w))

    @property
    def active_line(self) -> tuple[float, float]:
        """``(g_A, g_E)``: the ends of the path of contact measured from N_1 (gear 1's
        base circle tangent point): where the wheel's and the pinion's tip circles cross
        the line of action."""
        reach = np.sqrt(np.maximum((self.d_a / 2) ** 2 - (self.d_b / 2) ** 2, 0.0))
        return float(self.line_of_action - reach[1]), float(reach[0])

    @property
    def g_alpha(self) -> float:
        """Length of the path of contact."""
        g_a, g_e = self.active_line
        return g_e - g_a

    @property
    def eps_alpha(self) -> float:
        """Transverse contact ratio ``g_α / p_b``."""
        return self.g_alpha / self.p_b

    # ------------------------------------------------------------------ checks
    def checks(self) -> list[Check]:
        """The involute flank (the tip circle above the form circle), undercut, pointed tooth
        and interference of both gears, and the contact ratio."""
        out: list[Check] = []
        x_min, s_a = self.x_min, self.s_a
        beyond = self._lowest[1]
        for i in range(2):
            name = ("pinion", "wheel")[i]
            ok = bool(self.d_a[i] > self.d_Ff[i])
            out.append(Check("involute flank", i + 1, float(self.d_a[i]),
                             float(self.d_Ff[i]), ok,
                             f"{name}: the tip diameter d_a = {self.d_a[i]:.5g} "
                             + (">" if ok else "≤") + f" the form diameter d_Ff = "
                             f"{self.d_Ff[i]:.5g}"
                             + ("" if ok else " — the tooth has no involute flank (the tool "
                                "cuts only the fillet: the shift is too large)")))
            ok = self.xs[i] >= x_min[i] - 1e-12
            out.append(Check("undercut", i + 1, float(self.xs[i]), float(x_min[i]), bool(ok),
                             f"{name}: x = {self.xs[i]:.4g} "
                             + ("≥" if ok else "<") + f" x_min = {x_min[i]:.4g}"
                             + ("" if ok else " — the tooth is undercut")))
            limit = self.s_a_min * self.m_n
            ok = s_a[i] >= limit
            out.append(Check("pointed tooth", i + 1, float(s_a[i]), float(limit), bool(ok),
                             f"{name}: s_a = {s_a[i]:.4g} " + ("≥" if ok else "<")
                             + f" {self.s_a_min:g}·m = {limit:.4g}"
                             + ("" if ok else " — the tooth is (nearly) pointed")))
            reach = self.d_Nf[i]
            ok = bool(not beyond[i] and reach >= self.d_Ff[i] - 1e-9 * self.m_n)
            mate = ("wheel", "pinion")[i]
            if ok:
                why = ""
            elif self.undercut[i]:
                why = (" — interference: the tip meets the undercut, not the involute (no "
                       "conjugate contact there; the real path of contact is shorter)")
            else:
                why = " — interference: the tip digs into the fillet (the teeth overlap)"
            out.append(Check("interference", i + 1, float(reach), float(self.d_Ff[i]), ok,
                             f"{name}: the {mate}'s tip meets the flank down to "
                             f"d_Nf = {reach:.5g}"
                             + (" beyond the base circle's tangent point N"
                                if beyond[i] else
                                (" ≥" if ok else " <") + f" the form diameter d_Ff = "
                                f"{self.d_Ff[i]:.5g}") + why))
        g_a, g_e = self.active_line
        beyond_n = g_a < 0 or g_e > self.line_of_action
        ok = self.eps_alpha >= 1.0 and not beyond_n
        out.append(Check("contact ratio", None, self.eps_alpha, 1.0, bool(ok),
                         f"ε_α = {self.eps_alpha:.4g} " + ("≥" if self.eps_alpha >= 1 else "<")
                         + " 1" + (" — the mesh is not continuous" if self.eps_alpha < 1
                                   else "")
                         + (" — the path of contact runs beyond N1N2, so the involutes "
                            "do not reach it (interference)" if beyond_n else "")))
        return out


def gear_pair(m_n: float, z: tuple[int, int], alpha_n: float, *,
              x: tuple[float, float] | None = None, a: float | None = None,
              x1: float | None = None, ha: float = 1.0, c: float = 0.25,
              rho: float = 0.38, s_a_min: float = 0.25) -> GearPair:
    """An external spur gear pair from its shifts ``x = (x_1, x_2)``, or from its centre
    distance ``a`` and the pinion's shift ``x1`` (the wheel takes the rest of the sum that
    ``a`` fixes).  ``alpha_n`` in rad; lengths in one unit (mm in files).

    >>> p = gear_pair(3, (12, 24), np.radians(20), x=(0.6, 0.36))
    >>> round(p.a, 3), round(float(np.degrees(p.alpha_w)), 4)
    (56.5, 26.0886)
    """
    if m_n <= 0 or not np.isfinite(m_n):
        raise HintedError(f"module {m_n}: not a positive number", "write e.g. module: 2")
    if min(z) < 1:
        raise HintedError(f"teeth {z}: a gear has at least one tooth", "write e.g. [20, 40]")
    if x is None:
        if a is None or x1 is None:
            raise HintedError("give the shifts x = (x1, x2), or the centre distance a with "
                              "the pinion's shift x1", "e.g. shifts: [0.3, 0.2]")
        x_sum, _ = shift_sum_from_centre_distance(m_n, *z, a, alpha_n)
        x = (float(x1), float(x_sum) - float(x1))
    pair = GearPair(float(m_n), (int(z[0]), int(z[1])), float(alpha_n),
                    (float(x[0]), float(x[1])), ha, c, rho, s_a_min)
    inside = pair.d_a <= pair.d_b
    if inside.any():
        raise HintedError(f"the {'pinion' if inside[0] else 'wheel'}'s tip circle falls "
                          f"inside its base circle (tips shortened by Δy·m = "
                          f"{pair.dy * pair.m_n:.4g}): no involute is left to mesh",
                          "take a smaller centre distance or smaller shifts")
    return pair


__all__ = ["GearPair", "gear_pair", "inv"]
