"""Indicator diagrams (``mechloop.engines``): the work of each ideal cycle against its
closed form, and the gas force over a crank-slider's positions.

The diagram's ``loop_work`` is the sum of the works of its polytropes and isobars written
out; here ``∮ p dV`` is integrated numerically (scipy ``quad`` over each stroke, the
breaks of the pressure given as break points) from :func:`~mechloop.engines.pressure`
alone, and the compressor's against the textbook formula with the clearance
(``W = n/(n−1)·p_s·λ_V·V_h·(π^((n−1)/n) − 1)``, ``λ_V = 1 − c(π^(1/n) − 1)``).
The gas force's work through a crank-slider's kinematics (closed-form slider position,
positions at Gauss–Legendre nodes between the breaks) equals the diagram's area.
"""

from __future__ import annotations

from itertools import pairwise

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from mechloop.engines import (
    CompressorCycle,
    EngineCycle,
    clearance_volume,
    gas_force,
    loop_work,
    pressure,
    stroke_names,
    volumetric_efficiency,
)
from mechloop.engines.diagram import points
from mechloop.errors import HintedError

MPA = 1e6
SWEPT = np.pi * 0.08**2 / 4 * 0.08  # bore 80 mm, stroke 80 mm: 0.402 L

CYCLES = {
    "otto": EngineCycle(4, 9.0, 3.2, 1.0, 1.35, 1.25, 0.09 * MPA, 0.11 * MPA),
    "diesel": EngineCycle(4, 18.0, 1.0, 1.6, 1.37, 1.27, 0.095 * MPA, 0.12 * MPA),
    "mixed": EngineCycle(4, 16.0, 1.7, 1.4, 1.36, 1.26, 0.09 * MPA, 0.115 * MPA),
    "two-stroke": EngineCycle(2, 8.0, 3.0, 1.0, 1.33, 1.25, 0.12 * MPA, exhaust_port=0.22),
    "two-stroke mixed": EngineCycle(2, 17.0, 1.5, 1.5, 1.36, 1.25, 0.14 * MPA,
                                    exhaust_port=0.15),
    "compressor": CompressorCycle(0.1 * MPA, 0.6 * MPA, 0.05, 1.3, 1.25),
}


def _quad_loop(cycle, swept: float) -> float:
    """∮ p dV by quad, stroke by stroke (away from the head: V grows)."""
    vc = clearance_volume(cycle, swept)
    breaks = sorted(v for v, _ in points(cycle, swept).values() if vc < v < vc + swept)
    total = 0.0
    for k in range(len(stroke_names(cycle))):
        value, _ = quad(lambda v, k=k: float(pressure(cycle, v, k, swept)), vc, vc + swept,
                        points=breaks or None, epsabs=0, epsrel=1e-12, limit=200)
        total += value if k % 2 == 0 else -value
    return total


@pytest.mark.parametrize("name", list(CYCLES))
def test_the_loop_work_is_the_sum_of_the_polytropic_works(name):
    cycle = CYCLES[name]
    assert _quad_loop(cycle, SWEPT) == pytest.approx(loop_work(cycle, SWEPT), rel=1e-10)


def test_the_otto_cycle_work_by_its_textbook_formula():
    # the ideal Otto cycle with n1 = n2 = n and no pumping loop (p_r = p_a):
    # W = p_a V_a / (n - 1) · (λ - 1)(ε^(n-1) - 1) (e.g. Kolchin & Demidov, eq. of the
    # calculated cycle with ρ = 1)
    n, eps, lam, pa = 1.3, 9.0, 3.0, 0.1 * MPA
    cycle = EngineCycle(4, eps, lam, 1.0, n, n, pa, pa)
    va = SWEPT * eps / (eps - 1)
    expected = pa * va / (n - 1) * (lam - 1) * (eps ** (n - 1) - 1)
    assert loop_work(cycle, SWEPT) == pytest.approx(expected, rel=1e-12)


def test_the_compressor_work_with_its_clearance():
    # one exponent for compression and re-expansion: W = n/(n-1) p_s λ_V V_h (π^((n-1)/n) - 1)
    n, c, ps, pd = 1.3, 0.06, 0.1 * MPA, 0.7 * MPA
    cycle = CompressorCycle(ps, pd, c, n, n)
    lam_v = 1 - c * ((pd / ps) ** (1 / n) - 1)
    assert volumetric_efficiency(cycle) == pytest.approx(lam_v, rel=1e-14)
    expected = n / (n - 1) * ps * lam_v * SWEPT * ((pd / ps) ** ((n - 1) / n) - 1)
    assert -_quad_loop(cycle, SWEPT) == pytest.approx(expected, rel=1e-10)
    # the suction valve is open (p = p_s) over λ_V of the suction stroke
    vc = c * SWEPT
    v4 = brentq(lambda v: float(pressure(cycle, v, 0, SWEPT)) - ps * (1 + 1e-12), vc,
                vc + SWEPT, xtol=1e-16)
    assert (vc + SWEPT - v4) / SWEPT == pytest.approx(lam_v, rel=1e-9)


def test_cycle_parameters_are_checked():
    with pytest.raises(HintedError, match="2 or 4 strokes"):
        EngineCycle(3, 9, 3, 1, 1.35, 1.25, 1e5, 1e5)
    with pytest.raises(HintedError, match="exhaust pressure"):
        EngineCycle(4, 9, 3, 1, 1.35, 1.25, 1e5)
    with pytest.raises(HintedError, match="pre-expansion"):
        EngineCycle(2, 9, 1, 8, 1.35, 1.25, 1e5, exhaust_port=0.3)
    with pytest.raises(HintedError, match="delivers nothing"):
        CompressorCycle(1e5, 2e6, 0.2, 1.3, 1.2)


def _slider(phi, r=0.04, rod=0.14, offset=0.0):
    """Closed-form crank-slider: the piston's distance from the crank axis along the
    cylinder and its derivative over the crank angle."""
    s = offset - r * np.sin(phi)  # the rod's lateral leg
    root = np.sqrt(rod**2 - s**2)
    return r * np.cos(phi) + root, -r * np.sin(phi) + s * r * np.cos(phi) / root


def _gauss_positions(breaks, nodes=24):
    """Gauss–Legendre nodes and weights between consecutive break angles, with the breaks
    themselves as positions of weight 0 (the positions cover the whole cycle)."""
    t, w = np.polynomial.legendre.leggauss(nodes)
    phi, weight = [np.asarray(breaks)], [np.zeros(len(breaks))]
    for a, b in pairwise(breaks):
        phi.append((a + b) / 2 + (b - a) / 2 * t)
        weight.append((b - a) / 2 * w)
    phi, weight = np.concatenate(phi), np.concatenate(weight)
    order = np.argsort(phi)
    return phi[order], weight[order]


@pytest.mark.parametrize("name", ["mixed", "two-stroke mixed", "compressor"])
@pytest.mark.parametrize("offset", [0.0, 0.012])
def test_the_gas_force_work_over_a_cycle_is_the_diagram_area(name, offset):
    # the work of F = (p - p0) A on the piston, ∫ F·(-dx/dφ) dφ over the cycle, by
    # Gauss-Legendre quadrature between the breaks of the integrand: the dead centres
    # (found here from the closed-form slider, offset or not) and the angles where the
    # volume passes the diagram's corners
    cycle = CYCLES[name]
    r, rod, bore, p0 = 0.04, 0.14, 0.08, 0.1 * MPA
    turns = 2 if isinstance(cycle, EngineCycle) and cycle.strokes == 4 else 1
    x = lambda phi: _slider(phi, r, rod, offset)[0]  # noqa: E731
    dx = lambda phi: _slider(phi, r, rod, offset)[1]  # noqa: E731
    tdc = brentq(dx, -1.0, 1.0)
    bdc = brentq(dx, np.pi - 1.0, np.pi + 1.0)
    area = np.pi * bore**2 / 4
    swept = area * (x(tdc) - x(bdc))
    vc = clearance_volume(cycle, swept)
    corners = [v for v, _ in points(cycle, swept).values() if vc * (1 + 1e-9) < v
               < (vc + swept) * (1 - 1e-9)]
    breaks = []
    for k in range(turns):
        for lo, hi in ((tdc, bdc), (bdc, tdc + 2 * np.pi)):
            lo, hi = lo + 2 * np.pi * k, hi + 2 * np.pi * k
            breaks += [lo, hi]
            for v in corners:
                breaks.append(brentq(lambda p, v=v: vc + area * (x(tdc) - x(p)) - v, lo, hi))
    phi, weight = _gauss_positions(np.unique(breaks))
    gas = gas_force(cycle, phi, x(phi), dx(phi), bore=bore, crankcase=p0)
    assert gas.swept == pytest.approx(swept, rel=1e-12)
    work = float(np.sum(weight * gas.force * -dx(phi)))
    assert work == pytest.approx(loop_work(cycle, swept), rel=1e-9)


def test_the_strokes_of_a_four_stroke_follow_the_firing_angle():
    cycle = CYCLES["otto"]
    phi = np.radians(np.arange(0, 721, 10.0))
    x, dx = _slider(phi)
    gas = gas_force(cycle, phi, x, dx, bore=0.08, crankcase=1e5, firing=np.radians(360))
    deg = np.degrees(phi)
    expected = np.select([deg < 180, deg < 360, deg < 540, deg < 720], [2, 3, 0, 1], 2)
    assert np.array_equal(gas.stroke, expected)
    # at the firing dead centre the pressure is p_z = λ p_a ε^n1
    assert gas.pressure[36] == pytest.approx(3.2 * 0.09 * MPA * 9**1.35, rel=1e-12)
    # shifted by a full cycle or given anywhere within a quarter turn: the same strokes
    for firing in (360 + 720, 360 + 80, 360 - 80):
        again = gas_force(cycle, phi, x, dx, bore=0.08, crankcase=1e5,
                          firing=np.radians(firing))
        assert np.array_equal(again.stroke, expected)


def test_the_doctests():
    import doctest

    from mechloop.engines import diagram

    assert doctest.testmod(diagram, raise_on_error=True).attempted > 0
