"""Sizes beyond KDAM's free version (200 positions, 20 arguments, 50 contours, 501 vectors,
20 vectors per contour): mechloop must solve them, and solve them right."""

from __future__ import annotations

import math

import numpy as np

import mechloop

CRANK, COUPLER, ROCKER, GROUND = 1.0, 3.5, 2.5, 3.0
TWIST = 10.0  # deg: each four-bar's crank is the previous rocker turned by this much


def chain_of_four_bars(n_contours: int, n_positions: int) -> mechloop.Model:
    """Four-bars in series: the rocker angle of one (plus 10°) drives the crank of the next."""
    vectors: dict[int, dict] = {1: {"r": CRANK, "a": {"argument": 1}}}
    contours = []
    number, crank, rocker = 1, 1, None
    for k in range(n_contours):
        if k:
            number += 1
            crank = number
            vectors[crank] = {"r": CRANK, "a": {"link": f"a{rocker}", "delta": TWIST}}
        coupler, rocker, ground = number + 1, number + 2, number + 3
        vectors[coupler] = {"r": COUPLER, "a": "function"}
        vectors[rocker] = {"r": ROCKER, "a": "function"}
        vectors[ground] = {"r": GROUND, "a": 180}
        number = ground
        contours.append({"vectors": [crank, coupler, rocker, ground]})
    return mechloop.Model.from_dict({
        "positions": n_positions - 1,
        "time": {"rpm": 60},
        "arguments": {1: {"law": "constant_speed", "start": [0, 0],
                          "end": [n_positions - 1, 360]}},
        "vectors": vectors,
        "contours": contours,
    })


def rocker_by_circles(theta: float) -> float:
    """Rocker direction B->C of the four-bar O=(0,0), C=(3,0) for crank angle theta (rad):
    B is where the circles about A (radius 3.5) and C (radius 2.5) cross, on the left of
    A->C (variant 1)."""
    ax, ay = CRANK * math.cos(theta), CRANK * math.sin(theta)
    cx, cy = GROUND, 0.0
    d = math.hypot(cx - ax, cy - ay)
    along = (COUPLER**2 - ROCKER**2 + d * d) / (2 * d)
    h = math.sqrt(COUPLER**2 - along**2)
    ux, uy = (cx - ax) / d, (cy - ay) / d
    bx, by = ax + along * ux - h * uy, ay + along * uy + h * ux
    return math.atan2(cy - by, cx - bx)


def test_five_hundred_chained_contours_match_a_plain_loop():
    n_contours, n_positions = 500, 40
    model = chain_of_four_bars(n_contours, n_positions)
    assert len(model.vectors) == 4 * n_contours
    res = mechloop.solve(model)
    assert not res.broken.any()
    last_rocker = 4 * n_contours - 1  # crank, coupler, rocker, ground in every contour
    for k in range(0, n_positions, 7):
        theta = 2 * math.pi * k / (n_positions - 1)
        for _ in range(n_contours):
            rocker = rocker_by_circles(theta)
            theta = rocker + math.radians(TWIST)
        got = res.value(f"a{last_rocker}")[k]
        assert math.isclose(math.remainder(got - rocker, 2 * math.pi), 0.0, abs_tol=1e-9)


def test_a_hundred_thousand_positions():
    res = mechloop.solve(chain_of_four_bars(1, 100_001))
    theta = np.linspace(0, 2 * np.pi, 100_001)[::9973]
    expected = np.array([rocker_by_circles(t) for t in theta])
    got = res.value("a3")[::9973]
    np.testing.assert_allclose(np.remainder(got - expected + np.pi, 2 * np.pi) - np.pi, 0,
                               atol=1e-10)


def test_twenty_arguments_and_twenty_vectors_in_one_contour():
    """A 20-vector contour whose 18 known vectors are each driven by its own argument
    (lengths and angles alike), plus two more arguments driving a second contour."""
    n = 50
    vectors: dict[int, dict] = {}
    arguments: dict[int, dict] = {}
    rng = np.random.default_rng(7)
    for i in range(1, 19):
        if i % 2:
            arguments[i] = {"law": "harmonic", "start": [0, float(rng.uniform(0.1, 0.3))],
                            "end": [n, float(rng.uniform(0.1, 0.3))]}
            vectors[i] = {"r": {"argument": i}, "a": float(rng.uniform(0, 360))}
        else:
            arguments[i] = {"law": "cycloidal", "start": [0, float(rng.uniform(0, 360))],
                            "end": [n, float(rng.uniform(0, 360))]}
            vectors[i] = {"r": float(rng.uniform(0.1, 0.3)), "a": {"argument": i}}
    vectors[19] = {"r": "function", "a": "function"}  # Pl1 closes the 19 others
    vectors[20] = {"r": 0.0, "a": 0}
    arguments[19] = {"table": {0: 0.5, n: 0.7}}
    arguments[20] = {"table": {0: 0, n: 90}}
    vectors[21] = {"r": {"argument": 19}, "a": {"argument": 20}}
    vectors[22] = {"r": "function", "a": "function"}
    model = mechloop.Model.from_dict({
        "positions": n, "time": {"rpm": 10}, "arguments": arguments, "vectors": vectors,
        "contours": [{"vectors": list(range(1, 21))}, {"vectors": [21, 22]}]})
    res = mechloop.solve(model)
    x = sum(res.value(f"r{i}") * np.cos(res.value(f"a{i}")) for i in range(1, 20))
    y = sum(res.value(f"r{i}") * np.sin(res.value(f"a{i}")) for i in range(1, 20))
    np.testing.assert_allclose(x, 0, atol=1e-12)
    np.testing.assert_allclose(y, 0, atol=1e-12)
    np.testing.assert_allclose(res.value("r22"), res.value("r21"), rtol=1e-12)
