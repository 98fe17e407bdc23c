"""Link ratios onto an angle that a contour solves (:mod:`mechloop.solve.turns`): a gear
fixed to a rocker or to a crank that a linkage drives, meshing with another gear.

The driven gear's angle is ``k·ψ + Δ`` with ``ψ`` the *continuous* solved angle: checked
against the four-bar's closed form (circle intersection, unwrapped along the motion),
finite differences of that closed form for the rates and accelerations, over several
turns of a drag link (the output crank goes past 2π), across blocks of positions, through
``solve_designs`` and the extra columns of ``solve_designs_at`` (turns from the nearest
position), and for random linkages and ratios.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import mechloop
from mechloop.errors import SolveError
from mechloop.solve.designs import solve_designs, solve_designs_at
from mechloop.solve.kinematics import solve

DEG = math.pi / 180


def geared_four_bar(crank: float, coupler: float, rocker: float, frame: float, *,
                    k: float, delta: float = 90.0, start: float = 10.0,
                    sweep: float = 1080.0, n: int = 180, r1: float = 0.05,
                    variant: int = 1, frame_angle: float = 180.0) -> mechloop.Model:
    """A four-bar O_A→A→B→O_C (vector 3 from B to the pivot O_C, vector 4 from O_C to
    O_A at ``frame_angle``: O_C = (frame, 0) by default) whose link
    3 carries a gear of pitch radius ``r1`` meshing a gear of radius ``−r1/k`` on the
    frame: contour 2 is the mesh (mark to mark, as examples/gear_pair.yaml), the driven
    gear's mark angle ``a7 = k·a3 + delta``."""
    r2 = -r1 / k if k < 0 else r1 / k
    return mechloop.Model.from_dict({
        "units": {"length": "m", "angle": "deg"}, "positions": n,
        "arguments": {1: {"table": {0: start, n: start + sweep}}},
        "vectors": {1: {"r": crank, "a": {"argument": 1}},
                    2: {"r": coupler, "a": "function"},
                    3: {"r": rocker, "a": "function"},
                    4: {"r": frame, "a": frame_angle},
                    5: {"r": r1, "a": {"link": "a3", "delta": 0}},
                    6: {"r": "function", "a": "function"},
                    7: {"r": r2, "a": {"link": "a3", "ratio": k, "delta": delta}},
                    8: {"r": r1 + r2, "a": 180}},
        "contours": [{"vectors": [1, 2, 3, 4], "variant": variant},
                     {"vectors": [5, 6, 7, 8], "start": {"tail": 4}}]})


def closed_form_a3(theta: np.ndarray, crank, coupler, rocker, frame, sign: float,
                   frame_angle: float = 180.0) -> np.ndarray:
    """The angle of vector 3 (B→O_C) by circle intersection, wrapped: B on the circle of
    ``coupler`` about A and of ``rocker`` about O_C, the side of AO_C given by ``sign``."""
    ox, oy = -frame * math.cos(frame_angle * DEG), -frame * math.sin(frame_angle * DEG)
    ax, ay = crank * np.cos(theta), crank * np.sin(theta)
    dx, dy = ox - ax, oy - ay
    dist = np.hypot(dx, dy)
    along = (coupler**2 - rocker**2 + dist**2) / (2 * dist)
    h = np.sqrt(coupler**2 - along**2)
    bx = ax + (along * dx - sign * h * dy) / dist
    by = ay + (along * dy + sign * h * dx) / dist
    return np.arctan2(oy - by, ox - bx)


def _branch(res, crank, coupler, rocker, frame, fa) -> float:
    """The closed form's side that matches the solve at position 0."""
    a0 = res.value("a3")[0]
    theta = res.arguments[1][:1]
    for sign in (1.0, -1.0):
        if abs(math.remainder(closed_form_a3(theta, crank, coupler, rocker, frame,
                                             sign, fa)[0] - a0, 2 * math.pi)) < 1e-9:
            return sign
    raise AssertionError("the solve is on neither branch")


def _check(model, dims, k, delta_deg, *, atol=1e-11, fa=180.0):
    res = solve(model)
    assert not res.broken.any()
    theta = res.arguments[1]
    sign = _branch(res, *dims, fa)
    psi = np.unwrap(closed_form_a3(theta, *dims, sign, fa))  # the continuous closed form
    a3 = res.value("a3")
    turns = (a3 - psi) / (2 * math.pi)
    np.testing.assert_allclose(turns, np.round(turns[0]), atol=1e-11)
    assert 0 <= a3[0] < 2 * math.pi  # it starts in [0, 2π), like every solved angle
    a7 = res.value("a7")
    np.testing.assert_allclose(a7, k * a3 + delta_deg * DEG, rtol=0, atol=atol)
    assert np.abs(np.diff(a7)).max() < abs(k) * np.abs(np.diff(a3)).max() + 1e-9
    # rates: the analogs by the crank angle against central differences of the closed
    # form; the driven gear's k times the carrier's
    h = 1e-6
    analogs = solve(model, analogs_of=1)
    f = lambda t: closed_form_a3(t, *dims, sign, fa)  # noqa: E731
    d1 = np.array([math.remainder(x, 2 * math.pi) for x in f(theta + h) - f(theta - h)])
    np.testing.assert_allclose(analogs.rate("a3"), d1 / (2 * h), rtol=0, atol=1e-7)
    np.testing.assert_allclose(analogs.rate("a7"), k * analogs.rate("a3"), rtol=1e-14,
                               atol=0)
    h2 = 1e-4
    d2 = np.array([math.remainder(x, 2 * math.pi) for x in f(theta + h2) - f(theta)]) \
        - np.array([math.remainder(x, 2 * math.pi) for x in f(theta) - f(theta - h2)])
    np.testing.assert_allclose(analogs.accel("a3"), d2 / h2**2, rtol=0, atol=2e-5)
    np.testing.assert_allclose(analogs.accel("a7"), k * analogs.accel("a3"), rtol=1e-14,
                               atol=0)
    # the pitch circles roll: r1·ψ' = −r2·φ' (external mesh, k < 0)
    r1, r2 = 0.05, 0.05 / abs(k)
    if k < 0:
        np.testing.assert_allclose(r1 * analogs.rate("a3"), -r2 * analogs.rate("a7"),
                                   rtol=1e-13, atol=1e-15)
    return res


def test_a_gear_on_a_rocker_follows_the_four_bar() -> None:
    """A crank-rocker (0.1, 0.3, 0.25, 0.3 m, the frame along +Y) whose rocker carries a
    pinion z1 meshing a wheel with k = −z1/z2 = −0.4: the wheel's angle is
    −0.4·(rocker angle) + 90° at every position of three crank turns; the rocker's angle
    crosses ±180° (the raw atan2 jumps by 2π there, which the ratio would turn into jumps
    of 0.8π)."""
    dims = (0.1, 0.3, 0.25, 0.3)
    model = geared_four_bar(*dims, k=-0.4, frame_angle=90)
    res = _check(model, dims, -0.4, 90.0, fa=90)
    raw = np.arctan2(np.sin(res.value("a3")), np.cos(res.value("a3")))
    assert np.abs(np.diff(raw)).max() > math.pi  # the wrapped angle does jump
    assert np.ptp(res.value("a3")) < math.pi  # a rocker: it swings, it does not turn


def test_a_gear_on_a_driven_crank_over_several_turns() -> None:
    """A drag link (frame 0.1 m the shortest: both cranks turn) driven over three turns:
    the output crank's angle runs past 6π, and the gear it carries turns −0.4 times as
    far — its angle is −0.4·(the continuous output angle) + 90°, not of the wrapped one."""
    dims = (0.3, 0.35, 0.4, 0.1)
    model = geared_four_bar(*dims, k=-0.4)
    res = _check(model, dims, -0.4, 90.0)
    a3 = res.value("a3")
    assert np.ptp(a3) > 5.9 * math.pi  # three whole turns
    assert np.ptp(res.value("a7")) == pytest.approx(0.4 * np.ptp(a3), rel=1e-12)


def test_turns_continue_across_blocks_and_through_designs() -> None:
    """Blocks of 16 positions give the one-block values (the turns carried across the
    overlap position); ``solve_designs`` gives ``solve``'s; the extra columns of
    ``solve_designs_at`` between the positions take their turns from the nearest
    position and equal a solve at twice the positions; chosen positions are refused."""
    dims = (0.3, 0.35, 0.4, 0.1)
    model = geared_four_bar(*dims, k=-0.4, n=90)
    one = solve(model)
    small = solve(model, block=16)
    for name in ("a3", "a7", "r6", "a6"):
        np.testing.assert_allclose(small.value(name), one.value(name), rtol=0, atol=1e-13)
        np.testing.assert_allclose(small.rate(name), one.rate(name), rtol=0, atol=1e-13)
    many = solve_designs(model, {})
    for name in ("a3", "a7", "a6"):
        np.testing.assert_array_equal(np.asarray(many.values[name])[0], one.value(name))
    x = one.arguments[1]
    mid = ((x[:-1] + x[1:]) / 2)[None, :]
    _, at = solve_designs_at(model, {}, mid)
    fine = solve(geared_four_bar(*dims, k=-0.4, n=180))
    assert not at.broken.any()
    for name in ("a3", "a7", "a6", "r6"):
        np.testing.assert_allclose(np.asarray(at.values[name])[0], fine.value(name)[1::2],
                                   rtol=0, atol=1e-12)
    with pytest.raises(SolveError, match="whole turns"):
        solve_designs(model, {}, positions=[0, 5])


@settings(max_examples=25, deadline=None)
@given(crank=st.floats(0.05, 0.2), coupler=st.floats(0.2, 0.5), rocker=st.floats(0.2, 0.5),
       frame=st.floats(0.2, 0.5), k=st.sampled_from([-0.4, -2.5, 0.5, -1 / 3, 3.0]),
       delta=st.floats(-180, 180), start=st.floats(-180, 180),
       variant=st.sampled_from([1, 2]))
def test_random_geared_crank_rockers(crank, coupler, rocker, frame, k, delta, start,
                                     variant) -> None:
    """Random Grashof crank-rockers (the crank the shortest, s + l < p + q with a margin
    away from the change point), either assembly, a random ratio and phase, two crank
    turns: the geared angle is k times the continuous closed-form rocker angle."""
    links = sorted([crank, coupler, rocker, frame])
    assume(links[0] == crank and links[0] + links[3] < links[1] + links[2] - 0.03)
    dims = (crank, coupler, rocker, frame)
    model = geared_four_bar(*dims, k=k, delta=delta, start=start, sweep=720, n=120,
                            variant=variant)
    _check(model, dims, k, delta, atol=1e-10)


def test_between_positions_takes_the_turns_from_the_samples() -> None:
    """The existence check's solve between positions (no regular positions there) takes
    a ratio-scaled angle's turns from the sampled solve interpolated at the fractional
    position: at the midpoints it equals a solve at twice the positions."""
    from mechloop.solve.between import _solve_at, _turns_at
    from mechloop.solve.existence import ExistenceCheck

    dims = (0.3, 0.35, 0.4, 0.1)
    model = geared_four_bar(*dims, k=-0.4, n=90)
    one = solve(model)
    t = np.arange(90.0)[None, :] + 0.5
    inputs = np.interp(t, np.arange(91), one.arguments[1])
    turns = {"a3": one.value("a3")[None, :]}
    values, broken = _solve_at(ExistenceCheck(model), {}, inputs,
                               turn_ref=_turns_at(turns, t))
    fine = solve(geared_four_bar(*dims, k=-0.4, n=180))
    assert not broken.any()
    for name in ("a3", "a7", "r6"):  # a3 continuous, so a7 = k·a3 + Δ is right
        np.testing.assert_allclose(values[name][0], fine.value(name)[1::2], rtol=0,
                                   atol=1e-12)
    # an angle no ratio scales stays as atan2 gives it here (whole turns do not matter)
    step = values["a6"][0] - fine.value("a6")[1::2]
    np.testing.assert_allclose(np.remainder(step + 1, 2 * np.pi) - 1, 0.0, atol=1e-12)
    # without the samples the turns are unknown: NaN, never a wrong whole turn
    bare, _ = _solve_at(ExistenceCheck(model), {}, inputs)
    assert np.isnan(bare["a7"]).all()


def test_an_envelope_through_a_ratio_scaled_solved_angle_is_refused() -> None:
    """The envelope's points are solved each at its own position, without the turns a
    ratio onto a solved angle needs: refused (not built), never a wrong whole turn."""
    from pathlib import Path

    from mechloop.solve.intermediate import solve_intermediate

    path = Path(__file__).resolve().parents[1] / "examples" / "cam_roller_follower.yaml"
    data = mechloop.load_model(path).model_dump(mode="python", exclude_none=True)
    data["vectors"][6] = {"r": 5.0, "a": {"link": "a4", "ratio": 2.0}}
    data["vectors"][7] = {"r": "function", "a": "function"}
    data["contours"].append({"vectors": [6, 7]})
    with pytest.raises(SolveError, match="whole turns"):
        solve_intermediate(mechloop.Model.from_dict(data))
