"""Coupled blocks in models with spatial contours, and the swashplate example (issue 17).

Checked against independent references: the raw 3-D closure of random coupled spatial
blocks (hypothesis) and the assembly they were built from, finite differences for the
exact rates of the block Jacobian, the planar coupled solver (a class-III triad and a
non-elementary slider written as spatial and as mixed spatial + planar), the planar
solver's breaks, the swashplate's closed form over the whole turn, and located errors.
"""

from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.optimize import least_squares
from test_coupled_blocks import BASE, GOOD, triad
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.errors import ModelError
from mechloop.model.load import model_from_data

ROOT = Path(__file__).resolve().parents[1]
SWASHPLATE = ROOT / "examples" / "spatial" / "swashplate.yaml"


def _solve(data: dict, **kwargs):
    return mechloop.solve(model_from_data(copy.deepcopy(data)), **kwargs)


def _unit(a, b) -> np.ndarray:
    """The unit vector of elevation ``a`` and rotation ``b`` (rad), ``(3, ...)``."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return np.stack([np.cos(a) * np.cos(b), np.sin(a) + 0 * b, np.cos(a) * np.sin(b)])


def _rab(v: np.ndarray) -> tuple[float, float, float]:
    """Length, elevation and rotation (deg) of a Cartesian vector."""
    r = float(np.linalg.norm(v))
    return r, math.degrees(math.asin(v[1] / r)), math.degrees(math.atan2(v[2], v[0]))


# ------------------------------------------------------------------ the swashplate
def test_swashplate_stroke_is_its_closed_form_over_the_whole_turn():
    model = mechloop.load_model(SWASHPLATE)
    res = mechloop.solve(model)
    assert [c.module for c in res.structure.contours] == ["Pr11"] and not res.breaks
    radius, swash = 0.040, math.radians(15)
    phi = res.arguments[1]  # rad
    assert phi[0] == 0 and phi[-1] == pytest.approx(2 * math.pi)  # the whole turn
    omega = 2 * math.pi * model.time.rpm / 60
    s = radius * math.tan(swash)
    np.testing.assert_allclose(res.values["r2"], s * (1 - np.cos(phi)), rtol=0, atol=1e-15)
    np.testing.assert_allclose(res.rates["r2"], s * omega * np.sin(phi), rtol=0,
                               atol=1e-12 * s * omega)
    np.testing.assert_allclose(res.accels["r2"], s * omega**2 * np.cos(phi), rtol=0,
                               atol=1e-12 * s * omega**2)
    # the foot stays on the plate: its height is -tan(15°) times its X past T
    x = radius * np.cos(phi)
    np.testing.assert_allclose(res.values["r2"], -math.tan(swash) * (x - radius), atol=1e-15)


# ------------------------------------------------------ random coupled spatial blocks
def _coupled_pair(seed: int, sweep: float = 30.0, positions: int = 30) -> tuple[dict, dict]:
    """Two spatial contours that need each other's functions, built around a random
    assembly at position 0 (returned as the unknowns' values, SI): contour 1 solves a2,
    b2, r3 with b3 linked to b5; contour 2 solves b5, b6, r7 with a6 linked to a2."""
    rng = np.random.default_rng(seed)
    r = rng.uniform(0.5, 2.0, 8)
    ang = np.degrees(rng.uniform(-1.2, 1.2, 16))
    true = {"a2": ang[0], "b2": ang[1], "r3": r[2], "b5": ang[2], "b6": ang[3], "r7": r[6]}
    d3, d6 = ang[4], ang[5]
    v = {1: r[0] * _unit(math.radians(ang[6]), math.radians(ang[7])),
         2: r[1] * _unit(math.radians(true["a2"]), math.radians(true["b2"])),
         3: true["r3"] * _unit(math.radians(ang[8]), math.radians(true["b5"] + d3)),
         5: r[4] * _unit(math.radians(ang[9]), math.radians(true["b5"])),
         6: r[5] * _unit(math.radians(true["a2"] + d6), math.radians(true["b6"])),
         7: true["r7"] * _unit(math.radians(ang[10]), math.radians(ang[11]))}
    frame1, frame2 = _rab(v[1] + v[2] + v[3]), _rab(v[5] + v[6] - v[7])
    vectors = {
        1: {"r": r[0], "a": ang[6], "b": {"argument": 1, "offset": ang[7]}},
        2: {"r": r[1], "a": "function", "b": "function"},
        3: {"r": "function", "a": ang[8], "b": {"link": "b5", "delta": d3}},
        4: {"r": frame1[0], "a": frame1[1], "b": frame1[2]},
        5: {"r": r[4], "a": ang[9], "b": "function"},
        6: {"r": r[5], "a": {"link": "a2", "delta": d6}, "b": "function"},
        7: {"r": "function", "a": ang[10], "b": ang[11]},
        8: {"r": frame2[0], "a": frame2[1], "b": frame2[2]},
    }
    data = {"units": {"length": "m", "angle": "deg"}, "positions": positions,
            "arguments": {1: {"table": {0: 0, positions: sweep}}},
            "vectors": {k: {kk: float(x) if isinstance(x, np.floating) else x
                            for kk, x in vec.items()} for k, vec in vectors.items()},
            "contours": [
                {"vectors": [1, 2, 3, -4], "spatial": True,
                 "guess": {k: float(true[k]) for k in ("a2", "b2", "r3")}},
                {"vectors": [5, 6, -7, -8], "spatial": True,
                 "guess": {k: float(true[k]) for k in ("b5", "b6", "r7")}}]}
    for vec in data["vectors"].values():
        for k, x in vec.items():
            if isinstance(x, dict):
                vec[k] = {kk: float(y) if isinstance(y, (np.floating, float)) else y
                          for kk, y in x.items()}
    return data, true


def _closure(res, contour: list[int]) -> np.ndarray:
    """The 3-D closure of a contour from the solved parameters, ``(3, P)``."""
    total = 0.0
    for n in contour:
        k = abs(n)
        total = total + math.copysign(1, n) * res.values[f"r{k}"] * _unit(
            res.values[f"a{k}"], res.values[f"b{k}"])
    return total


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 2**31 - 1))
def test_random_coupled_spatial_block_closes_and_starts_at_its_assembly(seed):
    data, true = _coupled_pair(seed)
    res = _solve(data)
    (block,) = res.structure.blocks
    assert block.coupled and block.contours == (1, 2)
    assert [c.module for c in res.structure.contours] == ["coupled", "coupled"]
    # position 0 is the assembly the block was built from (the guess is exact there)
    for name, value in true.items():
        got = res.values[name][0]
        if name[0] == "r":
            assert got == pytest.approx(value, abs=1e-9)
        else:
            assert math.remainder(got - math.radians(value), 2 * math.pi) == pytest.approx(
                0, abs=1e-9)
    ok = ~res.broken
    assert ok[0]
    for contour in ([1, 2, 3, -4], [5, 6, -7, -8]):
        assert np.abs(_closure(res, contour)[:, ok]).max() < 1e-9
    # the links hold inside the block, and the path is continuous where it is solved
    np.testing.assert_allclose(res.values["b3"][ok], res.values["b5"][ok]
                               + math.radians(data["vectors"][3]["b"]["delta"]), atol=1e-12)
    np.testing.assert_allclose(res.values["a6"][ok], res.values["a2"][ok]
                               + math.radians(data["vectors"][6]["a"]["delta"]), atol=1e-12)
    # the assembly of position 0 followed up to the first break: four times finer input
    # steps give the same solutions (a jump to another assembly between two positions
    # would not be taken by both; a fixed bound on a step would not do: near a pole of
    # its β a link turns fast).  After a break the block is found again by a search,
    # which may enter another assembly: that part is not compared.
    fine = _solve(_coupled_pair(seed, positions=4 * data["positions"])[0])
    both = ok & ~fine.broken[::4]
    run = int(np.argmin(both)) if not both.all() else both.size
    assert run >= 1
    for name in true:
        np.testing.assert_allclose(res.values[name][:run], fine.values[name][::4][:run],
                                   rtol=0, atol=1e-9)
    # a broken position is reported, never silently; where the block breaks right after a
    # good position, least squares on the raw closure from that solution finds no assembly
    # either (a limit position: the block cannot follow the input)
    assert sum(len(b.positions) for b in res.breaks) == res.broken.sum()
    first = np.flatnonzero(res.broken[1:] & ok[:-1])
    for k in first[:1] + 1:
        start = np.array([res.values[n][k - 1] for n in UNKNOWNS])
        fit = least_squares(_raw, start, args=(data, res.arguments[1][k]), xtol=1e-15,
                            ftol=1e-15, gtol=1e-15)
        assert np.abs(fit.fun).max() > 1e-8


UNKNOWNS = ("a2", "b2", "r3", "b5", "b6", "r7")


def _raw(x: np.ndarray, data: dict, phi: float) -> np.ndarray:
    """The raw 3-D closure of both contours of :func:`_coupled_pair` at unknowns ``x``
    (SI) and argument ``phi`` (rad), written from the model data alone."""
    vec = data["vectors"]
    a2, b2, r3, b5, b6, r7 = x
    rad = math.radians

    def const(n: int) -> np.ndarray:
        return vec[n]["r"] * _unit(rad(vec[n]["a"]), rad(vec[n]["b"]))

    v1 = vec[1]["r"] * _unit(rad(vec[1]["a"]), rad(vec[1]["b"]["offset"]) + phi)
    v2 = vec[2]["r"] * _unit(a2, b2)
    v3 = r3 * _unit(rad(vec[3]["a"]), b5 + rad(vec[3]["b"]["delta"]))
    v5 = vec[5]["r"] * _unit(rad(vec[5]["a"]), b5)
    v6 = vec[6]["r"] * _unit(a2 + rad(vec[6]["a"]["delta"]), b6)
    v7 = r7 * _unit(rad(vec[7]["a"]), rad(vec[7]["b"]))
    return np.concatenate([v1 + v2 + v3 - const(4), v5 + v6 - v7 - const(8)])


def test_coupled_spatial_rates_match_finite_differences():
    data, _ = _coupled_pair(0, sweep=20, positions=10)
    res = _solve(data)
    assert not res.broken.any()
    h = 1e-3  # deg: central differences in argument 1's offset (analogs per rad)
    runs = []
    for step in (-h, 0.0, h):
        moved = copy.deepcopy(data)
        moved["vectors"][1]["b"]["offset"] += step
        runs.append(_solve(moved))
    h = math.radians(h)
    for name in ("a2", "b2", "r3", "b5", "b6", "r7", "b3", "a6"):
        lo, mid, hi = (r.values[name] for r in runs)
        d1, d2 = (hi - lo) / (2 * h), (hi - 2 * mid + lo) / h**2
        scale1, scale2 = np.abs(res.rates[name]).max(), np.abs(res.accels[name]).max()
        assert np.abs(res.rates[name] - d1).max() <= 1e-6 * max(scale1, 1e-3), name
        assert np.abs(res.accels[name] - d2).max() <= 1e-4 * max(scale2, 1e-3), name


# ------------------------------------------- planar coupled models written as spatial
def _triad_data(**kwargs) -> dict:
    return triad(**BASE, **kwargs).model_dump(exclude_none=True)


def _spatial_triad(data: dict, contours: tuple[int, ...]) -> dict:
    """The triad with ``contours`` (0-based) spatial, the frame vector's β the third
    unknown of each (guessed 0: the plane of the drawing)."""
    out = copy.deepcopy(data)
    frames = {0: 4, 1: 9}
    for ci in contours:
        out["contours"][ci]["spatial"] = True
        out["vectors"][frames[ci]]["b"] = "function"
        out["contours"][ci]["guess"][f"b{frames[ci]}"] = 0
    return out


#: The planar coupled results a coupled block written as spatial gives (relative to each
#: column's largest value).
COUPLED_RTOL = 1e-10


def _assert_same(spatial, planar, names, rtol: float = COUPLED_RTOL) -> None:
    for name in names:
        for what in ("values", "rates", "accels"):
            got, want = getattr(spatial, what)[name], getattr(planar, what)[name]
            assert np.array_equal(np.isnan(got), np.isnan(want)), (name, what)
            scale = np.nanmax(np.abs(want))
            assert np.nanmax(np.abs(got - want)) <= rtol * scale, (name, what)


@pytest.mark.parametrize("contours, plane", [((0, 1), None), ((0,), None),
                                             ((0,), [0, 0.6, 0.8])],
                         ids=["spatial", "mixed", "mixed-tilted-plane"])
def test_planar_triad_written_as_spatial_gives_the_planar_coupled_results(contours, plane):
    data = _triad_data(sweep=-120, n=24)
    planar = _solve(data)
    written = _spatial_triad(data, contours)
    if plane is not None:  # the planar contour in a tilted plane: solved in its own axes
        written["contours"][1]["plane"] = {"normal": plane}
    spatial = _solve(written)
    assert spatial.structure.blocks[0].coupled and not planar.broken.any()
    _assert_same(spatial, planar, ["a1", "a3", "a6", "a7", "a2", "a8"], COUPLED_RTOL)
    assert np.abs(spatial.values["b4"]).max() < 1e-12
    assert np.abs(spatial.rates["b4"]).max() < 1e-12


def test_breaks_of_a_coupled_spatial_block_are_the_planar_ones():
    data = _triad_data(sweep=360, n=36)
    planar = _solve(data)
    spatial = _solve(_spatial_triad(data, (0, 1)))
    assert planar.breaks, "the full turn passes the triad's limit positions"
    assert [(b.contour, b.module, b.reason, tuple(b.positions), b.contours)
            for b in spatial.breaks] == [(b.contour, b.module, b.reason, tuple(b.positions),
                                          b.contours) for b in planar.breaks]
    np.testing.assert_array_equal(spatial.broken, planar.broken)
    _assert_same(spatial, planar, ["a1", "a3", "a6", "a7"])


def test_a_spatial_contour_linking_to_its_own_function_is_solved_like_the_planar_one():
    data = copy.deepcopy(GOOD)
    data["vectors"] = {**data["vectors"], 4: {"r": 0.01, "a": {"link": "a2", "delta": 90}}}
    planar = _solve(data)
    spatial = copy.deepcopy(data)
    spatial["contours"][0]["spatial"] = True
    spatial["vectors"][3]["b"] = "function"  # the slider line, horizontal: β = 0
    spatial["contours"][0]["guess"] = {"b3": 0, "a2": math.degrees(planar.values["a2"][0]),
                                       "r3": planar.values["r3"][0]}
    spatial = _solve(spatial)
    (block,) = spatial.structure.blocks
    assert block.coupled and block.contours == (1,)
    _assert_same(spatial, planar, ["a2", "r3", "a4"])


# -------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("change, where, words, fix", [
    ({"variant": 3}, "contours[0].variant", "solved in a coupled block, whose variant is 1",
     "set 'variant' to 1, 2 or 'auto'"),
    ({"guess": {"a9": 10}}, "contours[0].guess.a9", "a9 is not an unknown of the coupled "
     "block of contours 1, 2", "guess some of a2, b2, r3, b5, b6, r7"),
])
def test_bad_coupled_block_input_is_located_with_a_fix(tmp_path, change, where, words, fix):
    data, _ = _coupled_pair(3)
    data["contours"][0].update(change)
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data), encoding="utf-8")
    with pytest.raises(ModelError) as info:
        mechloop.load_model(path)
    found = [p for p in info.value.problems if words in p.message]
    assert found, str(info.value)
    assert found[0].where() == where and fix in found[0].hint
    assert found[0].line is not None
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2 and words.split()[0] in result.output


def test_a_guess_on_a_contour_solved_alone_is_still_refused():
    data = yaml.safe_load(SWASHPLATE.read_text(encoding="utf-8"))
    data["contours"][0]["guess"] = {"r2": 1}
    with pytest.raises(ModelError) as info:
        model_from_data(data)
    assert "a guess applies only to a coupled block" in str(info.value)


def test_designs_of_a_coupled_spatial_block_in_one_pass_are_the_designs_one_by_one():
    """``solve_designs`` over a coupled spatial block: each row (a constant and a link
    delta varied) is the solve of that design's model."""
    from mechloop.solve.designs import solve_designs

    data, _ = _coupled_pair(0, sweep=20, positions=10)
    model = model_from_data(copy.deepcopy(data))
    delta = data["vectors"][6]["a"]["delta"]
    over = {"r1": data["vectors"][1]["r"] + np.array([0.0, 0.01, -0.02]),
            "a6": np.radians(delta + np.array([0.0, 0.5, -0.5]))}
    many = solve_designs(model, over)
    assert many.broken.shape == (3, model.positions + 1) and not many.broken.any()
    for row in range(3):
        one = copy.deepcopy(data)
        one["vectors"][1]["r"] = float(over["r1"][row])
        one["vectors"][6]["a"]["delta"] = float(np.degrees(over["a6"][row]))
        want = _solve(one)
        for name in UNKNOWNS:
            for what in ("values", "rates", "accels"):
                np.testing.assert_allclose(getattr(many, what)[name][row],
                                           getattr(want, what)[name], rtol=1e-12,
                                           atol=1e-12, err_msg=f"{name} {what} {row}")


def test_a_coupled_spatial_model_through_the_cli(tmp_path):
    data, _ = _coupled_pair(0, sweep=20, positions=10)
    path = tmp_path / "pair.yaml"
    path.write_text(yaml.safe_dump(data), encoding="utf-8")
    runner = CliRunner()
    assert runner.invoke(app, ["check", str(path)]).exit_code == 0
    info = runner.invoke(app, ["info", str(path)])
    assert info.exit_code == 0
    assert "coupled block 1: contours 1, 2 solved together for α2, β2, r3, β5, β6, r7" in (
        " ".join(info.output.split()))
    out = tmp_path / "pair.csv"
    assert runner.invoke(app, ["solve", str(path), "-o", str(out)]).exit_code == 0
    written = pd.read_csv(out)
    frame = _solve(data).to_frame()
    np.testing.assert_allclose(written["r3 [m]"], frame["r3 [m]"], rtol=1e-15)


@pytest.mark.parametrize("variant, sign", [(1, -1), (2, 1)])
def test_without_a_guess_the_variant_is_the_sign_of_the_block_determinant(variant, sign):
    """No guess: the first assembly from the fixed starts whose block Jacobian (rows: the
    contours' x, y, z; columns: the unknowns in contour order) has the variant's sign —
    checked on the raw closure's Jacobian by central differences."""
    data, _ = _coupled_pair(0, sweep=20, positions=10)
    for contour in data["contours"]:
        del contour["guess"]
        contour["variant"] = variant
    res = _solve(data)
    assert not res.broken[0]
    x = np.array([res.values[n][0] for n in UNKNOWNS])
    h = 1e-6
    jac = np.stack([(_raw(x + h * e, data, 0.0) - _raw(x - h * e, data, 0.0)) / (2 * h)
                    for e in np.eye(6)], axis=1)
    assert np.abs(_raw(x, data, 0.0)).max() < 1e-9
    assert np.sign(np.linalg.det(jac)) == sign
