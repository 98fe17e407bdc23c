"""Planetary trains of the common schemes: Willis' formula and the conditions of a design.

Members (the notation of the Russian course, Kudryavtsev): ``a`` the driving central gear,
``b`` the fixed central gear, ``h`` the carrier (the output), ``g`` the planet row meshing
with ``a`` and ``f`` the planet row meshing with ``b`` (one row, ``f = g``, in the simple
scheme).  A mesh is external (``σ = +1``) or internal (``σ = −1``, the central gear is a
ring).  Willis' formula for the train seen from the carrier:

    i_ab^h = (ω_a − ω_h)/(ω_b − ω_h) = σ_a σ_b · z_g z_b / (z_a z_f),

and with ``b`` fixed ``i_ah = ω_a/ω_h = 1 − i_ab^h``.  Any member may be the fixed one (the
simple scheme is the James train: sun, planets, ring, carrier), the formula read for it:

* ``b`` fixed: ``i_ah = 1 − i_ab^h`` (and ``i_ha = 1/i_ah``);
* ``a`` fixed: ``i_bh = 1 − 1/i_ab^h`` (and ``i_hb = 1/i_bh``);
* the carrier ``h`` fixed (an ordinary train): ``i_ab = i_ab^h`` (and ``i_ba = 1/i_ab``).

Conditions of a design with ``k``
planets equally spaced, one module, unshifted gears:

* coaxiality: ``z_a + σ_a z_g = z_b + σ_b z_f`` (both rows have the same centre distance;
  ``a_w = m |z_a + σ_a z_g| / 2``);
* assembly: ``(σ_a z_a z_f − σ_b z_b z_g) / (k · gcd(z_g, z_f))`` is a whole number (the
  phases of both meshes repeat at every planet; ``(z_a + z_b)/k`` in the simple scheme);
* neighbours: the planets' tip circles do not touch, ``2 a_w sin(π/k) > d_a`` of the larger
  planet row, ``d_a = m (z + 2 h_a*)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from mechloop.errors import HintedError


@dataclass(frozen=True)
class Scheme:
    """A planetary scheme: the kinds of its two meshes and whether the planet has two
    rows."""

    name: str
    sigma_a: int  #: +1 if a–g is an external mesh, −1 if a is a ring
    sigma_b: int  #: +1 if f–b is an external mesh, −1 if b is a ring
    double: bool  #: the planet has two rows g and f
    title: str


SCHEMES: dict[str, Scheme] = {s.name: s for s in (
    Scheme("simple", +1, -1, False, "sun a – planet g – ring b, carrier h"),
    Scheme("double_planet", +1, -1, True,
           "sun a – planet row g; planet row f – ring b (two-row, external + internal)"),
    Scheme("two_rings", -1, -1, True,
           "ring a – planet row g; planet row f – ring b (two internal meshes)"),
    Scheme("two_suns", +1, +1, True,
           "sun a – planet row g; planet row f – sun b (two external meshes)"),
)}


def scheme_of(name: str) -> Scheme:
    try:
        return SCHEMES[name]
    except KeyError:
        raise HintedError(f"unknown planetary scheme {name!r}",
                          f"use one of {', '.join(SCHEMES)}") from None


def willis_ratio(scheme: Scheme, z_a: ArrayLike, z_g: ArrayLike, z_f: ArrayLike,
                 z_b: ArrayLike) -> np.ndarray:
    """``i_ab^h = σ_a σ_b z_g z_b/(z_a z_f)``: the ratio of the train seen from the carrier
    (Willis).  Broadcasts over arrays of tooth numbers."""
    z_a, z_g, z_f, z_b = (np.asarray(v, float) for v in (z_a, z_g, z_f, z_b))
    return scheme.sigma_a * scheme.sigma_b * z_g * z_b / (z_a * z_f)


def reduction_ratio(scheme: Scheme, z_a, z_g, z_f, z_b) -> np.ndarray:
    """``i_ah = ω_a/ω_h = 1 − i_ab^h`` with ``b`` fixed.  Broadcasts."""
    return 1.0 - willis_ratio(scheme, z_a, z_g, z_f, z_b)


MEMBERS = ("a", "b", "h")


def check_members(fixed: str, driver: str) -> None:
    """A hinted error unless ``fixed`` and ``driver`` are two different members of
    ``a, b, h``."""
    if fixed not in MEMBERS or driver not in MEMBERS or fixed == driver:
        raise HintedError(f"fixed {fixed!r} and input {driver!r}: take two different "
                          "members of a, b and h", "e.g. fixed: b, input: a")


def member_ratio(willis: ArrayLike, fixed: str = "b", driver: str = "a") -> np.ndarray:
    """``i = ω_driver/ω_output`` of a 2K-H train with the member ``fixed`` held, from
    Willis' ``i_ab^h``; the output is the third of ``a, b, h``.  Broadcasts; ``inf`` where
    the output cannot turn (``i_ab^h = 1`` with a central gear held)."""
    check_members(fixed, driver)
    w = np.asarray(willis, float)
    with np.errstate(divide="ignore"):
        forward = {"b": 1.0 - w, "a": 1.0 - 1.0 / w, "h": w}[fixed]  # a or b in → out
        first = {"b": "a", "a": "b", "h": "a"}[fixed]
        return forward if driver == first else 1.0 / forward


def output_member(fixed: str, driver: str) -> str:
    """The member of ``a, b, h`` that is neither fixed nor the driver."""
    return next(m for m in MEMBERS if m not in (fixed, driver))


def centre_numbers(scheme: Scheme, z_a, z_g, z_f, z_b) -> tuple[np.ndarray, np.ndarray]:
    """``(z_a + σ_a z_g, z_b + σ_b z_f)``: twice the centre distances of the two rows in
    modules (equal when the train is coaxial).  Broadcasts."""
    z_a, z_g, z_f, z_b = (np.asarray(v) for v in (z_a, z_g, z_f, z_b))
    return z_a + scheme.sigma_a * z_g, z_b + scheme.sigma_b * z_f


def assembly_number(scheme: Scheme, z_a, z_g, z_f, z_b, k) -> np.ndarray:
    """``(σ_a z_a z_f − σ_b z_b z_g)/(k · gcd(z_g, z_f))`` as a float (whole when ``k``
    equally spaced planets can be assembled).  Broadcasts over integer arrays."""
    z_a, z_g, z_f, z_b, k = (np.asarray(v, dtype=np.int64) for v in (z_a, z_g, z_f, z_b, k))
    top = scheme.sigma_a * z_a * z_f - scheme.sigma_b * z_b * z_g
    return top / (k * np.gcd(z_g, z_f))


def assembles(scheme: Scheme, z_a, z_g, z_f, z_b, k) -> np.ndarray:
    """Whether ``k`` equally spaced planets can be assembled (exact integer test)."""
    z_a, z_g, z_f, z_b, k = (np.asarray(v, dtype=np.int64) for v in (z_a, z_g, z_f, z_b, k))
    top = scheme.sigma_a * z_a * z_f - scheme.sigma_b * z_b * z_g
    return top % (k * np.gcd(z_g, z_f)) == 0


def neighbour_margin(scheme: Scheme, z_a, z_g, z_f, k, ha: float = 1.0) -> np.ndarray:
    """``2 a_w sin(π/k) − d_a,max`` in modules: positive when neighbouring planets clear
    each other (tip circles of the larger planet row).  Broadcasts."""
    z_a, z_g, z_f, k = (np.asarray(v, float) for v in (z_a, z_g, z_f, k))
    a_w2 = np.abs(z_a + scheme.sigma_a * z_g)   # 2 a_w / m
    return a_w2 * np.sin(np.pi / k) - (np.maximum(z_g, z_f) + 2.0 * ha)


@dataclass(frozen=True)
class PlanetaryTrain:
    """A planetary train of one scheme: tooth numbers ``z_a, z_g, z_f, z_b`` (``z_f = z_g``
    in the simple scheme), ``k`` planets, module ``m_n`` (mm in files), addendum
    coefficient ``ha``.  Input ``a``, output the carrier ``h``, ``b`` fixed."""

    scheme: Scheme
    z_a: int
    z_g: int
    z_f: int
    z_b: int
    k: int
    m_n: float = 1.0
    ha: float = 1.0
    fixed: str = "b"   #: the member held: a, b or h
    driver: str = "a"  #: the input member (the output is the third of a, b, h)

    @property
    def output(self) -> str:
        return output_member(self.fixed, self.driver)

    @property
    def teeth(self) -> dict[str, int]:
        if self.scheme.double:
            return {"a": self.z_a, "g": self.z_g, "f": self.z_f, "b": self.z_b}
        return {"a": self.z_a, "g": self.z_g, "b": self.z_b}

    @property
    def willis(self) -> float:
        """``i_ab^h``."""
        return float(willis_ratio(self.scheme, self.z_a, self.z_g, self.z_f, self.z_b))

    @property
    def ratio(self) -> float:
        """``ω_driver/ω_output`` with ``fixed`` held (``i_ah = 1 − i_ab^h`` by default:
        ``a`` in, ``b`` fixed, the carrier out)."""
        return float(member_ratio(self.willis, self.fixed, self.driver))

    @property
    def a_w(self) -> float:
        """Centre distance of the planets' axes from the central axis (row a–g)."""
        return self.m_n * abs(self.z_a + self.scheme.sigma_a * self.z_g) / 2.0

    @property
    def coaxial(self) -> bool:
        one, two = centre_numbers(self.scheme, self.z_a, self.z_g, self.z_f, self.z_b)
        return bool(one == two)

    @property
    def assembly(self) -> float:
        return float(assembly_number(self.scheme, self.z_a, self.z_g, self.z_f, self.z_b,
                                     self.k))

    @property
    def assembles(self) -> bool:
        return bool(assembles(self.scheme, self.z_a, self.z_g, self.z_f, self.z_b, self.k))

    @property
    def neighbour_margin(self) -> float:
        """Clearance between neighbouring planets' tip circles (unit of ``m_n``)."""
        return self.m_n * float(neighbour_margin(self.scheme, self.z_a, self.z_g, self.z_f,
                                                 self.k, self.ha))

    def speeds(self, omega_in: float = 1.0) -> dict[str, float]:
        """Angular speeds of every member for the input speed ``omega_in`` of the driver
        (``b`` fixed and ``a`` driving by default): ``a``, ``h`` (carrier), ``g`` (the
        planet, absolute) and ``b`` — the fixed one 0."""
        omega = {self.fixed: 0.0, self.driver: omega_in, self.output: omega_in / self.ratio}
        omega_a, omega_h = omega["a"], omega["h"]
        omega_g = omega_h - self.scheme.sigma_a * self.z_a / self.z_g * (omega_a - omega_h)
        return {"a": omega_a, "h": omega_h, "g": omega_g, "b": omega["b"]}

    def pitch_radii(self) -> dict[str, float]:
        """Reference radii ``m z/2`` of every gear."""
        return {key: self.m_n * z / 2.0 for key, z in
                (("a", self.z_a), ("g", self.z_g), ("f", self.z_f), ("b", self.z_b))}


def planetary_train(scheme: str | Scheme, teeth: dict[str, int], k: int, m_n: float = 1.0,
                    ha: float = 1.0, *, fixed: str = "b", driver: str = "a"
                    ) -> PlanetaryTrain:
    """A :class:`PlanetaryTrain` from a scheme name and ``teeth = {a, g, b}`` (simple) or
    ``{a, g, f, b}`` (two-row schemes).

    >>> t = planetary_train("simple", {"a": 20, "g": 30, "b": 80}, 4)
    >>> t.ratio, t.coaxial, t.assembles, t.assembly
    (5.0, True, True, 25.0)
    >>> planetary_train("simple", {"a": 20, "g": 30, "b": 80}, 4, fixed="a", driver="h").ratio
    0.8
    """
    s = scheme if isinstance(scheme, Scheme) else scheme_of(scheme)
    need = ("a", "g", "f", "b") if s.double else ("a", "g", "b")
    missing = [key for key in need if key not in teeth]
    if missing:
        raise HintedError(f"the {s.name} scheme needs the tooth numbers of "
                          f"{', '.join(need)}; missing {', '.join(missing)}",
                          "write e.g. teeth: {a: 20, g: 30, b: 80}" if not s.double else
                          "write e.g. teeth: {a: 20, g: 40, f: 20, b: 80}")
    z_f = teeth["f"] if s.double else teeth["g"]
    if k < 1 or math.floor(k) != k:
        raise HintedError(f"{k} planets: write a whole number of planets, 1 or more",
                          "e.g. planets: 3")
    check_members(fixed, driver)
    train = PlanetaryTrain(s, int(teeth["a"]), int(teeth["g"]), int(z_f), int(teeth["b"]),
                           int(k), float(m_n), float(ha), fixed, driver)
    if train.willis == 1.0 and fixed != "h":
        raise HintedError(f"with these teeth i_ab^h = 1: a and b turn alike about the "
                          f"carrier, so with {fixed} fixed nothing can turn",
                          "change a tooth number of one row (or hold the carrier h)")
    return train
