"""The tooth profile of a gear cut by its basic rack, found from the generating motion.

The gear (centre O at the origin) turns by ``φ`` while the rack (the tool) slides by
``−r φ`` along X, its datum line at ``y = r + x m`` (``r = m z/2``): the rack's pitch line
``y = r`` rolls on the reference circle.  At each ``φ`` the tool touches the gear where the
normal of its boundary passes through the pitch point ``P = (0, r)`` (Willis' theorem of
conjugate profiles):

* on the tool's straight flank: the foot of the perpendicular from ``P`` (it traces the
  involute);
* on the tool's tip round (radius ``ρ* m``, centre ``C``): the point ``C − ρ (P − C)/|P − C|``
  (it traces the trochoidal root fillet);
* the tool's flat tip cuts the root circle.

Those points, taken back into the gear's frame, bound the tooth space.  Where the fillet
cuts into the involute (undercut) the deeper of the two is kept.  The result is the space's
half angle ``η(ρ)`` on radii ``ρ`` from the root to the tip circle, measured from the
space's centre line; the tooth's half angle is ``π/z − η``.  Nothing here uses the involute
formulas of :mod:`.involute`: the tests compare the two.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class ToothProfile:
    """The half-angle of a generated tooth over radius.

    ``rho`` : radii from the root to the tip circle, shape (R,); ``psi`` : the tooth's half
    angle at each (rad; the tooth's thickness there is ``2 ρ ψ``); ``root_half`` : the
    half angle of the tooth space along the root circle (rad); ``flank`` : the generated
    involute points in the gear frame, shape (F, 2), ordered by radius (for measurements);
    ``z`` : the number of teeth; ``fillet`` the generated fillet points (F', 2)."""

    rho: np.ndarray
    psi: np.ndarray
    root_half: float
    flank: np.ndarray
    fillet: np.ndarray
    z: int
    cut_top: float  #: the highest radius the fillet and (undercut) the flank's end reach

    def thickness(self, rho: np.ndarray | float) -> np.ndarray:
        """Arc thickness ``2 ρ ψ(ρ)`` at radii ``rho`` (linear interpolation of ψ)."""
        rho = np.asarray(rho, float)
        return 2.0 * rho * np.interp(rho, self.rho, self.psi)

    def outline(self, *, phase: float = 0.0, arc_points: int = 6) -> np.ndarray:
        """The closed outline of the whole gear, shape (K, 2): tooth ``j`` centred on the
        direction ``phase + 2πj/z`` from the centre."""
        pitch = 2.0 * np.pi / self.z
        r_f, r_a = self.rho[0], self.rho[-1]
        half_space = np.pi / self.z
        # one pitch from the middle of the space below the tooth to the next
        root1 = np.linspace(-half_space, -(half_space - self.root_half), arc_points)
        right = -self.psi            # the flank at angle −ψ, radii rising
        tip = np.linspace(-self.psi[-1], self.psi[-1], arc_points)
        rad = np.concatenate([np.full(arc_points, r_f), self.rho, np.full(arc_points, r_a),
                              self.rho[::-1], np.full(arc_points, r_f)])
        ang = np.concatenate([root1, right, tip, self.psi[::-1], -root1[::-1]])
        teeth = phase + pitch * np.arange(self.z)[:, None] + ang[None, :]
        rads = np.broadcast_to(rad, teeth.shape)
        pts = np.stack([rads * np.cos(teeth), rads * np.sin(teeth)], axis=-1).reshape(-1, 2)
        return np.vstack([pts, pts[:1]])


def _rotate(points: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """Rotate points (..., 2) by ``angle`` (broadcast over the leading axes)."""
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * points[..., 0] - s * points[..., 1],
                     s * points[..., 0] + c * points[..., 1]], axis=-1)


def _space_angle(points_world: np.ndarray, phi: np.ndarray) -> np.ndarray:
    """Points in the gear frame (turned back by ``−φ``) as (ρ, η): η from the space's
    centre line (+Y) towards +X."""
    g = _rotate(points_world, -phi)
    return np.stack([np.hypot(g[:, 0], g[:, 1]), np.arctan2(g[:, 0], g[:, 1])], axis=-1)


def _max_on_grid(branches: list[np.ndarray], grid: np.ndarray) -> np.ndarray:
    """The largest η at each radius of ``grid`` over branches of (ρ, η) points; each
    branch is cut into runs monotonic in ρ and interpolated (NaN outside a run)."""
    best = np.full(grid.shape, -np.inf)
    for pts in branches:
        if len(pts) < 2:
            continue
        step = np.sign(np.diff(pts[:, 0]))
        cuts = np.flatnonzero(step[1:] != step[:-1]) + 1
        for run in np.split(np.arange(len(pts)), cuts + 1):
            if len(run) < 2:
                continue
            seg = pts[run[0]:run[-1] + 1]
            order = np.argsort(seg[:, 0])
            r, e = seg[order, 0], seg[order, 1]
            inside = (grid >= r[0]) & (grid <= r[-1])
            best = np.where(inside, np.maximum(best, np.interp(grid, r, e)), best)
    return best


def generate_tooth(m_n: float, z: int, alpha: float, x: float, *, ha: float = 1.0,
                   c: float = 0.25, rho: float = 0.38, d_a: float | None = None,
                   samples: int = 1500, radii: int = 400) -> ToothProfile:
    """The tooth of an external gear (module ``m_n``, ``z`` teeth, rack pressure angle
    ``alpha`` in rad, shift ``x``) cut by the basic rack with addendum ``(ha + c) m`` and
    tip radius ``rho·m``, up to the tip diameter ``d_a`` (default ``d + 2 m (ha + x)``).

    ``samples`` rack positions per tool segment; ``radii`` radii on which ψ is tabulated
    (clustered towards the root, where the fillet turns fast)."""
    m = float(m_n)
    r = m * z / 2.0
    datum = r + x * m
    h_a0 = (ha + c) * m
    rho0 = rho * m
    r_f = datum - h_a0
    r_a = (d_a / 2.0) if d_a is not None else r + (ha + x) * m
    tan_a, sin_a, cos_a = np.tan(alpha), np.sin(alpha), np.cos(alpha)
    quarter = np.pi * m / 4.0                          # half the tool tooth on its datum line
    h_end = h_a0 - rho0 * (1.0 - sin_a)                # end of the straight flank
    x_c = quarter - (h_a0 - rho0) * tan_a - rho0 / cos_a  # tip round centre (rack frame)
    y_c = datum - h_a0 + rho0
    root_half = max(x_c, 0.0) / r                      # the flat tip's half width, as angle

    # straight flank: the contact depth h below the datum is linear in φ
    #   h(φ) = cos α [(πm/4 − rφ) sin α + x m cos α]
    h_top = -(ha + x + 2.0) * m                        # well above the tip circle
    def phi_of(h: float) -> float:
        return (quarter - (h / cos_a - x * m * cos_a) / sin_a) / r
    phi = np.linspace(phi_of(h_end), phi_of(h_top), samples)
    h = cos_a * ((quarter - r * phi) * sin_a + x * m * cos_a)
    world = np.stack([quarter - h * tan_a - r * phi, datum - h], axis=-1)
    # contact on the P side of N traces the involute; beyond N (an undercut gear) the
    # flank's end traces the involute's mirror branch, which cuts into the tooth
    along = world[:, 0] * cos_a - (world[:, 1] - r) * sin_a  # from P along P -> N
    keep = along <= r * sin_a
    flank_polar = _space_angle(world[keep], phi[keep])
    flank_xy = _rotate(world[keep], -phi[keep])
    mirror_polar = _space_angle(world[~keep], phi[~keep])

    # tip round: centre C(φ) = (x_c − rφ, y_c); the contact point faces away from P
    span = 4.0 * (h_a0 + m) / r
    phi_r = np.linspace(x_c / r - span, x_c / r + span, samples)
    centre = np.stack([x_c - r * phi_r, np.full_like(phi_r, y_c)], axis=-1)
    towards_p = np.stack([-centre[:, 0], r - centre[:, 1]], axis=-1)
    unit = towards_p / np.hypot(towards_p[:, 0], towards_p[:, 1])[:, None]
    point = centre - rho0 * unit
    direction = np.arctan2(-unit[:, 1], -unit[:, 0])   # of (point − C)
    on_arc = (direction >= -np.pi / 2 - 1e-12) & (direction <= -alpha + 1e-12)
    fillet_polar = _space_angle(point[on_arc], phi_r[on_arc])
    fillet_xy = _rotate(point[on_arc], -phi_r[on_arc])

    t = np.linspace(0.0, 1.0, radii)
    grid = r_f + (r_a - r_f) * t ** 2
    grid[0] = r_f
    eta = _max_on_grid([flank_polar, fillet_polar, mirror_polar], grid)
    eta[0] = root_half if not np.isfinite(eta[0]) else max(eta[0], root_half)
    # the root point itself: the fillet starts on the root circle at η = x_c/r
    eta = np.where(np.isfinite(eta), eta, np.nan)
    if np.isnan(eta).any():  # a radius no branch reached (rounding at the ends): fill
        good = ~np.isnan(eta)
        eta = np.interp(grid, grid[good], eta[good])
    psi = np.clip(np.pi / z - eta, 0.0, None)
    order = np.argsort(flank_polar[:, 0])
    cut_top = max(float(fillet_polar[:, 0].max(initial=r_f)),
                  float(mirror_polar[:, 0].max(initial=r_f)))
    return ToothProfile(grid, psi, root_half, flank_xy[order], fillet_xy, int(z), cut_top)
