"""The spatial vector and the elementary spatial modules (seed 000 sec. 1.1, table 2.1).

Each module is checked against things it does not compute itself:

* a known closed configuration — random vectors ``i, j, k`` define the known sum
  ``S = −(v_i + v_j + v_k)``; the module, given the known parameters, must return that
  configuration on one of its branches;
* closure — every branch marked ``ok`` put back into the raw 3-D sum (1.1) closes it to
  ``1e-9`` (no spurious root);
* the branch count — the leading axis is the table's count, and a slow oracle (SciPy
  ``root`` on the raw closure from many starts, per position) finds no solution that
  the module misses;
* planar contours written as spatial (every ``β = 0``) give the planar modules' numbers.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import root

from mechloop.modules.planar import solve_pl1, solve_pl2, solve_pl3, solve_pl4
from mechloop.spatial import (
    accelerations,
    components,
    in_convention,
    parameters,
    pr20_family,
    rates,
    solve_pr1,
    solve_pr2,
    solve_pr3,
    solve_pr4,
    solve_pr5,
    solve_pr6,
    solve_pr7,
    solve_pr8,
    solve_pr9,
    solve_pr10,
    solve_pr11,
    solve_pr12,
    solve_pr13,
    solve_pr14,
    solve_pr15,
    solve_pr16,
    solve_pr17,
    solve_pr18,
    solve_pr19,
)
from mechloop.spatial.roots import wrap

FAST = settings(max_examples=40, deadline=None)
seeds = st.integers(0, 2**32 - 1)
P = 64
#: Distance (in sin/cos of an elevation) kept from the degenerate directions.
MARGIN = 0.15

# module: (function, unknowns, knowns, branches, takes convention) with a parameter named
# by (vector 0/1/2, "r" | "a" | "b").
MODULES = {
    "Pr1": (solve_pr1, [(0, "r"), (0, "a"), (0, "b")], [], 1, True),
    "Pr2": (solve_pr2, [(0, "r"), (0, "a"), (1, "r")], [(0, "b"), (1, "a"), (1, "b")], 1, False),
    "Pr3": (solve_pr3, [(0, "r"), (0, "a"), (1, "a")], [(0, "b"), (1, "r"), (1, "b")], 2, False),
    "Pr4": (solve_pr4, [(0, "r"), (0, "a"), (1, "b")], [(0, "b"), (1, "r"), (1, "a")], 2, False),
    "Pr5": (solve_pr5, [(0, "r"), (0, "b"), (1, "r")], [(0, "a"), (1, "a"), (1, "b")], 2, False),
    "Pr6": (solve_pr6, [(0, "r"), (0, "b"), (1, "a")], [(0, "a"), (1, "r"), (1, "b")], 4, False),
    "Pr7": (solve_pr7, [(0, "r"), (0, "b"), (1, "b")], [(0, "a"), (1, "r"), (1, "a")], 2, False),
    "Pr8": (solve_pr8, [(0, "a"), (0, "b"), (1, "r")], [(0, "r"), (1, "a"), (1, "b")], 2, True),
    "Pr9": (solve_pr9, [(0, "a"), (0, "b"), (1, "a")], [(0, "r"), (1, "r"), (1, "b")], 2, True),
    "Pr10": (solve_pr10, [(0, "a"), (0, "b"), (1, "b")], [(0, "r"), (1, "r"), (1, "a")], 2,
             True),
    "Pr11": (solve_pr11, [(0, "r"), (1, "r"), (2, "r")],
             [(0, "a"), (0, "b"), (1, "a"), (1, "b"), (2, "a"), (2, "b")], 1, False),
    "Pr12": (solve_pr12, [(0, "r"), (1, "r"), (2, "a")],
             [(0, "a"), (0, "b"), (1, "a"), (1, "b"), (2, "r"), (2, "b")], 2, False),
    "Pr13": (solve_pr13, [(0, "r"), (1, "r"), (2, "b")],
             [(0, "a"), (0, "b"), (1, "a"), (1, "b"), (2, "r"), (2, "a")], 2, False),
    "Pr14": (solve_pr14, [(0, "r"), (1, "a"), (2, "a")],
             [(0, "a"), (0, "b"), (1, "r"), (1, "b"), (2, "r"), (2, "b")], 4, False),
    "Pr15": (solve_pr15, [(0, "r"), (1, "a"), (2, "b")],
             [(0, "a"), (0, "b"), (1, "r"), (1, "b"), (2, "r"), (2, "a")], 4, False),
    "Pr16": (solve_pr16, [(0, "a"), (1, "a"), (2, "a")],
             [(0, "r"), (0, "b"), (1, "r"), (1, "b"), (2, "r"), (2, "b")], 8, False),
    "Pr17": (solve_pr17, [(0, "a"), (1, "a"), (2, "b")],
             [(0, "r"), (0, "b"), (1, "r"), (1, "b"), (2, "r"), (2, "a")], 8, False),
    "Pr18": (solve_pr18, [(0, "b"), (1, "b"), (2, "r")],
             [(0, "r"), (0, "a"), (1, "r"), (1, "a"), (2, "a"), (2, "b")], 2, False),
    "Pr19": (solve_pr19, [(0, "b"), (1, "b"), (2, "a")],
             [(0, "r"), (0, "a"), (1, "r"), (1, "a"), (2, "r"), (2, "b")], 4, False),
}


def _config(rng: np.random.Generator, name: str, convention: int, n: int = P) -> dict:
    """Random closed configuration: parameters of vectors 0, 1, 2 (``(n,)`` each)."""
    _, unknowns, knowns, _, _ = MODULES[name]
    used = {v for v, _ in unknowns + knowns}
    par = {}
    for v in range(3):
        par[v, "r"] = rng.uniform(0.5, 2.0, n) if v in used else np.zeros(n)
        par[v, "a"] = rng.uniform(-np.pi, np.pi, n)
        par[v, "b"] = rng.uniform(-np.pi, np.pi, n)
    for v in range(3):
        # keep away from the degenerate directions where an unknown β is undefined
        # (vertical vector) or, with its elevation known, the cone flattens (horizontal)
        if (v, "b") in unknowns:
            a = par[v, "a"]
            while True:
                bad = np.abs(np.cos(a)) < MARGIN
                if (v, "a") in knowns:
                    bad |= np.abs(np.sin(a)) < MARGIN
                if not bad.any():
                    break
                a = np.where(bad, rng.uniform(-np.pi, np.pi, n), a)
            par[v, "a"] = a
    for v in range(3):  # both angles of one vector unknown: the truth in the convention
        if (v, "a") in unknowns and (v, "b") in unknowns:
            par[v, "a"], par[v, "b"] = in_convention(par[v, "a"], par[v, "b"],
                                                     convention=convention)
    return par


def _closure_sum(par: dict) -> np.ndarray:
    """Σ of the three vectors, shape ``(3, ...)``."""
    return sum(np.stack(components(par[v, "r"], par[v, "a"], par[v, "b"])) for v in range(3))


def _call(name: str, par: dict, s: np.ndarray, convention: int):
    fn, _, knowns, _, conv = MODULES[name]
    kwargs = {"convention": convention} if conv else {}
    out = fn(s[0], s[1], s[2], *(par[k] for k in knowns), **kwargs)
    return out[:3], out[3]


def _distance(key: tuple, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    return np.abs(x - y) if key[1] == "r" else np.abs(wrap(x - y))


@pytest.mark.parametrize("name", sorted(MODULES))
@pytest.mark.parametrize("convention", [1, 2])
@FAST
@given(seed=seeds)
def test_module_finds_the_configuration_and_every_branch_closes(name, convention, seed):
    rng = np.random.default_rng(seed)
    _, unknowns, _, branches, _ = MODULES[name]
    par = _config(rng, name, convention)
    s = -_closure_sum(par)
    values, ok = _call(name, par, s, convention)
    assert ok.shape == (branches, P)
    assert all(v.shape == (branches, P) for v in values)
    # every branch marked ok closes the raw 3-D loop; every other one is NaN
    for b in range(branches):
        trial = dict(par)
        for key, val in zip(unknowns, values, strict=True):
            trial[key] = val[b]
        res = np.linalg.norm(_closure_sum(trial) + s, axis=0)
        assert np.all(res[ok[b]] <= 1e-9), (name, b, res[ok[b]].max())
        assert all(np.isnan(v[b][~ok[b]]).all() for v in values)
    # real roots of these equations come in pairs (a lost or invented root breaks that)
    if branches > 1:
        assert np.all(ok.sum(axis=0) % 2 == 0), (name, ok.sum(axis=0))
    # the configuration the sum was built from is on one of the branches
    dist = np.zeros((branches, P))
    for key, val in zip(unknowns, values, strict=True):
        dist = np.fmax(dist, np.where(ok, _distance(key, val, par[key][None]), np.inf))
    assert np.all(dist.min(axis=0) <= 1e-6), (name, dist.min(axis=0).max())


def _canonical(name: str, x: np.ndarray, convention: int) -> np.ndarray:
    """A solution ``x`` (the three unknowns) in the module's representation."""
    _, unknowns, _, _, _ = MODULES[name]
    x = x.copy()
    keys = list(unknowns)
    for v in range(3):
        if (v, "r") in keys and (v, "a") in keys:  # r ≥ 0 with α a full turn
            ir, ia = keys.index((v, "r")), keys.index((v, "a"))
            if x[ir] < 0:
                x[ir], x[ia] = -x[ir], x[ia] + np.pi
        if (v, "a") in keys and (v, "b") in keys:
            ia, ib = keys.index((v, "a")), keys.index((v, "b"))
            a, b = in_convention(x[ia], x[ib], convention=convention)
            x[ia], x[ib] = float(a), float(b)
    for i, key in enumerate(keys):
        if key[1] != "r":
            x[i] = float(wrap(x[i]))
    return x


@pytest.mark.parametrize("name", sorted(set(MODULES) - {"Pr1", "Pr2", "Pr11"}))
@settings(max_examples=3, deadline=None)
@given(seed=seeds)
def test_no_solution_is_missed(name, seed):
    """Slow oracle: SciPy's root on the raw closure from 30 starts per position finds no
    solution outside the module's branches (so the count of real roots is complete)."""
    rng = np.random.default_rng(seed)
    _, unknowns, _, _, _ = MODULES[name]
    par = _config(rng, name, 1, n=2)
    s = -_closure_sum(par)
    values, ok = _call(name, par, s, 1)
    for p in range(2):
        base = {k: v[p] for k, v in par.items()}

        def residual(x, base=base, p=p):
            trial = dict(base)
            for key, val in zip(unknowns, x, strict=True):
                trial[key] = val
            return _closure_sum(trial) + s[:, p]

        found = np.stack([values[i][:, p] for i in range(3)], axis=1)[ok[:, p]]
        for _ in range(30):
            x0 = [rng.uniform(-3, 3) if k[1] == "r" else rng.uniform(-np.pi, np.pi)
                  for k in unknowns]
            sol = root(residual, x0, tol=1e-13)
            if not sol.success or np.linalg.norm(residual(sol.x)) > 1e-10:
                continue
            x = _canonical(name, sol.x, 1)
            gap = [max(_distance(k, found[b, i], x[i]) for i, k in enumerate(unknowns))
                   for b in range(len(found))]
            assert min(gap, default=np.inf) <= 1e-6, (name, x, found)


@pytest.mark.parametrize("convention", [1, 2])
@FAST
@given(seed=seeds)
def test_vector_round_trip(convention, seed):
    rng = np.random.default_rng(seed)
    x, y, z = rng.normal(size=(3, P))
    r, a, b, ok = parameters(x, y, z, convention=convention)
    assert ok.all() and np.all(r >= 0)
    if convention == 1:
        assert np.all((a > -np.pi) & (a <= np.pi) & (b > -np.pi / 2) & (b <= np.pi / 2))
    else:
        assert np.all((a >= -np.pi / 2) & (a <= np.pi / 2) & (b > -np.pi) & (b <= np.pi))
    np.testing.assert_allclose(np.stack(components(r, a, b)), [x, y, z], atol=1e-14)
    # parameters in range come back unchanged
    r2, a2, b2, _ = parameters(*components(r, a, b), convention=convention)
    np.testing.assert_allclose([r2, a2, b2], [r, a, b], atol=1e-12)


def test_zero_vector_is_a_reported_break():
    r, a, b, ok = parameters([0.0, 1.0], [0.0, 0.0], [0.0, 0.0])
    assert ok.tolist() == [False, True]
    assert np.isnan([r[0], a[0], b[0]]).all()


@FAST
@given(seed=seeds)
def test_planar_contour_as_spatial_matches_pl1_to_pl4(seed):
    rng = np.random.default_rng(seed)
    x, y = rng.uniform(-2, 2, (2, P))
    zero = np.zeros(P)
    # Pl1 ↔ Pr1 (convention 1 keeps α a full turn, β = 0)
    r, a, ok = solve_pl1(x, y)
    rs, as_, bs, oks = solve_pr1(x, y, zero)
    np.testing.assert_array_equal(oks[0], ok)
    np.testing.assert_allclose(rs[0], r, rtol=1e-12)
    np.testing.assert_allclose(wrap(as_[0] - a), 0.0, atol=1e-12)
    np.testing.assert_allclose(bs[0], 0.0, atol=1e-12)
    # Pl2 ↔ Pr13 on its β_k = 0 branch (vector k a known of the planar contour)
    a1, a2, ak = rng.uniform(-np.pi, np.pi, (3, P))
    rk = rng.uniform(0.5, 2.0, P)
    r1, r2, ok2 = solve_pl2(x, y, a1, a2)
    sx, sy = x - rk * np.cos(ak), y - rk * np.sin(ak)
    ri, rj, bk, ok13 = solve_pr13(sx, sy, zero, a1, zero, a2, zero, rk, ak)
    on_plane = ok13 & (np.abs(wrap(bk)) < 1e-9)
    assert np.all(on_plane.sum(axis=0) == ok2)
    pick = on_plane.argmax(axis=0)
    cols = np.arange(P)
    np.testing.assert_allclose(ri[pick, cols][ok2], r1[ok2], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(rj[pick, cols][ok2], r2[ok2], rtol=1e-12, atol=1e-12)
    # Pl3 ↔ Pr6 on its β_i = 0 branches: both variants, as a set
    q2 = rng.uniform(0.5, 2.0, P)
    for variant in (1, 2):
        p1, p2, ok3 = solve_pl3(x, y, a1, q2, variant=variant)
        ri, bi, aj, ok6 = solve_pr6(x, y, zero, a1, q2, zero)
        flat = ok6 & (np.abs(wrap(bi)) < 1e-9)
        assert np.all(flat.any(axis=0) == ok3)
        gap = np.fmax(np.abs(ri - p1) / (1 + np.abs(p1)), np.abs(wrap(aj - p2)))
        gap = np.where(flat, gap, np.inf).min(axis=0)
        assert np.all(gap[ok3] <= 1e-12), gap[ok3].max()
    # Pl4 ↔ Pr9 (convention 1): both variants, as a set, with β_i = 0
    q1, q2 = rng.uniform(0.5, 2.0, (2, P))
    for variant in (1, 2):
        al1, al2, ok4 = solve_pl4(x, y, q1, q2, variant=variant)
        ai, bi, aj, ok9 = solve_pr9(x, y, zero, q1, q2, zero)
        assert np.all(ok9.any(axis=0) == ok4)
        gap = np.fmax(np.abs(wrap(ai - al1)), np.abs(wrap(aj - al2)))
        gap = np.where(ok9, gap, np.inf).min(axis=0)
        assert np.all(gap[ok4] <= 1e-12)
        assert np.all(np.abs(bi[ok9]) <= 1e-12)


def test_impossible_geometry_is_a_break_on_every_branch():
    far = np.full(5, 100.0)
    one = np.ones(5)
    zero = np.zeros(5)
    for values_ok in (
        solve_pr9(far, far, far, one, one, zero),
        solve_pr10(far, far, far, one, one, zero),
        solve_pr8(far, zero, zero, one, np.full(5, np.pi / 2), zero),
        solve_pr3(far, zero, far, zero, one, np.full(5, 0.3)),
        solve_pr19(zero, far, zero, one, zero, one, zero, one, zero),
    ):
        *values, ok = values_ok
        assert not ok.any()
        assert all(np.isnan(v).all() for v in values)


@pytest.mark.parametrize("name", ["Pr3", "Pr6", "Pr11", "Pr16", "Pr19"])
def test_designs_by_positions_equals_row_by_row(name):
    rng = np.random.default_rng(3)
    pars = [_config(rng, name, 1, n=P) for _ in range(2)]
    stacked = {k: np.stack([p[k] for p in pars]) for k in pars[0]}
    values, ok = _call(name, stacked, -_closure_sum(stacked), 1)
    for d, par in enumerate(pars):
        row_values, row_ok = _call(name, par, -_closure_sum(par), 1)
        np.testing.assert_array_equal(ok[:, d], row_ok)
        for v, rv in zip(values, row_values, strict=True):
            np.testing.assert_array_equal(v[:, d], rv)


def test_pr20_family_exists_exactly_when_y_row_and_polygon_close():
    rng = np.random.default_rng(7)
    r = rng.uniform(0.5, 2.0, (3, P))
    a = rng.uniform(-1.2, 1.2, (3, P))
    b = rng.uniform(-np.pi, np.pi, (3, P))
    s = -sum(np.stack(components(r[v], a[v], b[v])) for v in range(3))
    assert pr20_family(*s, r[0], a[0], r[1], a[1], r[2], a[2]).all()
    # moved off the Y row: no solution
    assert not pr20_family(s[0], s[1] + 0.1, s[2], r[0], a[0], r[1], a[1], r[2], a[2]).any()
    # horizontal sum beyond reach of the three projections: no solution
    big = 10.0 * np.ones(P)
    assert not pr20_family(big, s[1], s[2], r[0], a[0], r[1], a[1], r[2], a[2]).any()


@pytest.mark.parametrize("name", ["Pr2", "Pr6", "Pr9", "Pr11", "Pr15", "Pr17", "Pr19"])
@settings(max_examples=10, deadline=None)
@given(seed=seeds)
def test_rates_and_accelerations_match_finite_differences(name, seed):
    """Known parameters move as ``p0 + p1 t + p2 t²`` (a fourth, fully known vector makes
    ``S``); the module solved at ``t = −h, 0, h`` on the branch nearest the truth gives
    central differences that :func:`rates` / :func:`accelerations` must match."""
    rng = np.random.default_rng(seed)
    _, unknowns, knowns, _, _ = MODULES[name]
    n = 32
    par = _config(rng, name, 1, n=n)
    extra = {"r": rng.uniform(0.5, 2, n), "a": rng.uniform(-3, 3, n), "b": rng.uniform(-3, 3, n)}
    s0 = -_closure_sum(par)
    # the fourth vector absorbs the closure at t = 0: S = v_3 + (S0 − v_3(0)) is fixed
    # apart from v_3's motion
    v3 = np.stack(components(extra["r"], extra["a"], extra["b"]))
    rest = s0 - v3
    moving = [*knowns, (3, "r"), (3, "a"), (3, "b")]
    d1 = {k: rng.uniform(-1, 1, n) for k in moving}
    d2 = {k: rng.uniform(-1, 1, n) for k in moving}

    def at(t):
        q = {k: v.copy() for k, v in par.items()}
        q.update({(3, p): extra[p].copy() for p in "rab"})
        for k in moving:
            q[k] = q[k] + d1[k] * t + d2[k] * t * t
        s = rest + np.stack(components(q[3, "r"], q[3, "a"], q[3, "b"]))
        values, ok = _call(name, q, s, 1)
        return q, values, ok

    def pick(values, ok):
        dist = np.zeros(ok.shape)
        for key, val in zip(unknowns, values, strict=True):
            dist = np.fmax(dist, np.where(ok, _distance(key, val, par[key][None]), np.inf))
        b = dist.argmin(axis=0)
        return np.stack([v[b, np.arange(n)] for v in values])

    h1, h = 1e-6, 1e-5  # steps for the first and the second difference
    x = {t: pick(*at(t)[1:]) for t in (-h, -h1, 0.0, h1, h)}
    fd1 = (x[h1] - x[-h1]) / (2 * h1)
    fd2 = (x[h] - 2 * x[0.0] + x[-h]) / h**2
    for i, key in enumerate(unknowns):
        if key[1] != "r":
            fd1[i] = wrap(x[h1][i] - x[-h1][i]) / (2 * h1)
            fd2[i] = (wrap(x[h][i] - x[0.0][i]) - wrap(x[0.0][i] - x[-h][i])) / h**2
    q0 = {k: v.copy() for k, v in par.items()}
    q0.update({(3, p): extra[p] for p in "rab"})
    stack = {p: np.stack([q0[v, p] for v in range(4)]) for p in "rab"}
    for i, key in enumerate(unknowns):
        stack[key[1]][key[0]] = x[0.0][i]
    rate = {p: np.stack([d1.get((v, p), np.zeros(n)) for v in range(4)]) for p in "rab"}
    acc = {p: np.stack([2 * d2.get((v, p), np.zeros(n)) for v in range(4)]) for p in "rab"}
    *v1, ok1 = rates(stack["r"], stack["a"], stack["b"], rate["r"], rate["a"], rate["b"],
                     unknowns)
    assert ok1.all()
    for i, key in enumerate(unknowns):
        rate[key[1]][key[0]] = v1[i]
    *v2, ok2 = accelerations(stack["r"], stack["a"], stack["b"], rate["r"], rate["a"],
                             rate["b"], acc["r"], acc["a"], acc["b"], unknowns)
    assert ok2.all()
    # near a dead point (huge rates) finite differences lose their accuracy: compare
    # away from it, at most positions
    calm = (np.abs(np.stack(v1)) < 30.0).all(axis=0) & (np.abs(np.stack(v2)) < 300.0).all(axis=0)
    assert calm.sum() >= n // 4
    np.testing.assert_allclose(np.stack(v1)[:, calm], fd1[:, calm], rtol=1e-5, atol=1e-5)
    np.testing.assert_allclose(np.stack(v2)[:, calm], fd2[:, calm], rtol=1e-3, atol=1e-3)


@pytest.mark.parametrize("name", sorted(MODULES))
@pytest.mark.parametrize("fill", [0.0, np.nan])
def test_broken_or_degenerate_input_is_a_break_without_warning(name, fill):
    """An input broken upstream (NaN) or fully degenerate (all zero) gives ``ok`` false
    and NaN on every branch; RuntimeWarnings are errors in this suite."""
    fn, _, knowns, branches, _ = MODULES[name]
    *values, ok = fn(*[np.full(4, fill)] * (3 + len(knowns)))
    assert ok.shape == (branches, 4) and not ok.any()
    assert all(np.isnan(v).all() for v in values)


def test_the_solvers_table_of_modules_is_table_2_1_as_written_here():
    """The solver picks a module by the table in mechloop.spatial.contour; it must be the
    one these tests state independently (seed 000 table 2.1: unknowns, knowns, branches)."""
    from mechloop.spatial.contour import MODULES as SOLVERS

    assert SOLVERS == MODULES
