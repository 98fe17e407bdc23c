"""The Wolfrom train (3K): a sun, a stepped planet, two rings, an idle carrier.

Members: ``a`` the driving sun, ``g`` the planet row meshing with ``a`` and with the fixed
ring ``b``, ``f`` the second planet row (one body with ``g``) meshing with the output ring
``e``; the carrier ``h`` only holds the planets.  The first stage is a simple planetary
train (ring ``b`` fixed) driving the carrier; the second is the two-ring train ``b–g f–e``
seen from that carrier.  Willis' formula for each:

    ω_h = ω_a · z_a/(z_a + z_b),
    (ω_e − ω_h)/(ω_b − ω_h) = i_eb^h = z_b z_f/(z_g z_e)   (two internal meshes),

so with ``ω_b = 0``

    i_ae = ω_a/ω_e = (1 + z_b/z_a) / (1 − z_b z_f/(z_g z_e)).

A negative ratio: the output ring turns against the sun.  Conditions of a design with ``k``
equally spaced planets, one module, unshifted gears:

* coaxiality: ``z_a + z_g = z_b − z_g = z_e − z_f`` (all three meshes at ``a_w``);
* assembly: ``(z_a + z_b)/k`` whole (the sun's teeth at every planet) and
  ``(z_e z_g − z_b z_f)/(k · gcd(z_g, z_f))`` whole (the second ring's, the planets being
  identical stepped gears).  Coaxial, ``z_e z_g − z_b z_f = (z_a + z_g)(z_g − z_f)`` and
  ``z_a + z_b = 2 (z_a + z_g)``: with an odd ``k`` the second follows from the first;
* neighbours: ``2 a_w sin(π/k) > d_a`` of the larger planet row.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from mechloop.errors import HintedError


def wolfrom_ratio(z_a: ArrayLike, z_g: ArrayLike, z_f: ArrayLike, z_b: ArrayLike,
                  z_e: ArrayLike) -> np.ndarray:
    """``i_ae = ω_a/ω_e`` with ring ``b`` fixed (see the module).  Broadcasts; ``inf``
    where ``z_b z_f = z_g z_e`` (the output ring stands still)."""
    z_a, z_g, z_f, z_b, z_e = (np.asarray(v, float) for v in (z_a, z_g, z_f, z_b, z_e))
    # one division of whole numbers, (z_a + z_b) z_g z_e / (z_a (z_g z_e − z_b z_f)):
    # exact whenever the ratio is a whole number
    top = (z_a + z_b) * z_g * z_e
    bottom = z_a * (z_g * z_e - z_b * z_f)
    with np.errstate(divide="ignore"):
        return np.where(bottom == 0.0, np.inf, top / np.where(bottom == 0.0, 1.0, bottom))


@dataclass(frozen=True)
class WolfromTrain:
    """A Wolfrom train: tooth numbers ``z_a, z_g, z_f, z_b, z_e``, ``k`` planets, module
    ``m_n`` (mm in files), addendum coefficient ``ha``.  Input ``a``, ``b`` fixed, output
    ``e``; the carrier ``h`` idles."""

    z_a: int
    z_g: int
    z_f: int
    z_b: int
    z_e: int
    k: int
    m_n: float = 1.0
    ha: float = 1.0

    name = "wolfrom"
    title = "sun a – planet row g – fixed ring b; planet row f – output ring e (Wolfrom)"

    @property
    def teeth(self) -> dict[str, int]:
        return {"a": self.z_a, "g": self.z_g, "f": self.z_f, "b": self.z_b, "e": self.z_e}

    @property
    def carrier_ratio(self) -> float:
        """``i_ah = 1 + z_b/z_a`` of the first stage."""
        return 1.0 + self.z_b / self.z_a

    @property
    def willis_be(self) -> float:
        """``i_eb^h = (ω_e − ω_h)/(ω_b − ω_h) = z_b z_f/(z_g z_e)`` of the second stage,
        seen from the carrier."""
        return self.z_b * self.z_f / (self.z_g * self.z_e)

    @property
    def ratio(self) -> float:
        """``i_ae = ω_a/ω_e`` with ``b`` fixed."""
        return float(wolfrom_ratio(self.z_a, self.z_g, self.z_f, self.z_b, self.z_e))

    @property
    def a_w(self) -> float:
        """Distance of the planets' axes from the central axis (row a–g)."""
        return self.m_n * (self.z_a + self.z_g) / 2.0

    @property
    def coaxial(self) -> bool:
        return self.z_a + self.z_g == self.z_b - self.z_g == self.z_e - self.z_f

    @property
    def assembly(self) -> tuple[float, float]:
        """``((z_a + z_b)/k, (z_e z_g − z_b z_f)/(k gcd(z_g, z_f)))``: both whole when the
        ``k`` planets can be assembled equally spaced."""
        return ((self.z_a + self.z_b) / self.k,
                (self.z_e * self.z_g - self.z_b * self.z_f)
                / (self.k * math.gcd(self.z_g, self.z_f)))

    @property
    def assembles(self) -> bool:
        return ((self.z_a + self.z_b) % self.k == 0 and
                (self.z_e * self.z_g - self.z_b * self.z_f)
                % (self.k * math.gcd(self.z_g, self.z_f)) == 0)

    @property
    def neighbour_margin(self) -> float:
        """Clearance between neighbouring planets' tip circles (unit of ``m_n``)."""
        reach = (self.z_a + self.z_g) * math.sin(math.pi / self.k)
        return self.m_n * (reach - (max(self.z_g, self.z_f) + 2.0 * self.ha))

    def speeds(self, omega_a: float = 1.0) -> dict[str, float]:
        """Angular speeds of every member (``b`` fixed): sun ``a``, carrier ``h``, the
        stepped planet ``g`` (absolute), ``b`` (0) and the output ring ``e``."""
        omega_h = omega_a / self.carrier_ratio
        omega_g = omega_h + self.z_b / self.z_g * (0.0 - omega_h)
        return {"a": omega_a, "h": omega_h, "g": omega_g, "b": 0.0,
                "e": omega_a / self.ratio}

    def pitch_radii(self) -> dict[str, float]:
        """Reference radii ``m z/2`` of every gear."""
        return {key: self.m_n * z / 2.0 for key, z in self.teeth.items()}


def wolfrom_train(teeth: dict[str, int], k: int, m_n: float = 1.0, ha: float = 1.0
                  ) -> WolfromTrain:
    """A :class:`WolfromTrain` from ``teeth = {a, g, f, b, e}``.

    >>> t = wolfrom_train({"a": 15, "g": 24, "f": 21, "b": 63, "e": 60}, 3)
    >>> round(t.ratio, 4), t.coaxial, t.assembles
    (64.0, True, True)
    """
    need = ("a", "g", "f", "b", "e")
    missing = [key for key in need if key not in teeth]
    if missing:
        raise HintedError(f"the wolfrom scheme needs the tooth numbers of "
                          f"{', '.join(need)}; missing {', '.join(missing)}",
                          "write e.g. teeth: {a: 15, g: 24, f: 21, b: 63, e: 60}")
    if k < 1 or math.floor(k) != k:
        raise HintedError(f"{k} planets: write a whole number of planets, 1 or more",
                          "e.g. planets: 3")
    train = WolfromTrain(*(int(teeth[key]) for key in need), int(k), float(m_n), float(ha))
    if train.z_b * train.z_f == train.z_g * train.z_e:
        raise HintedError("with these teeth z_b z_f = z_g z_e: the output ring e would "
                          "stand still whatever the sun does",
                          "change a tooth number of the second stage (f or e)")
    return train
