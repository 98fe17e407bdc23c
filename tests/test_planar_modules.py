"""The planar elementary modules Pl1–Pl4 (DESIGN §2, seed 000 sec. 1.5) over random geometry.

Every property is checked against something the module does not compute itself:

* closure — the returned unknowns put back into ``Σ r_i (cos α_i, sin α_i)`` give zero to
  ``1e-12 × Σ|r_i|`` wherever ``ok``;
* existence — ``ok`` is false exactly when no real solution exists, with the condition
  written independently here (triangle inequality, distance from a point to a line,
  parallel directions) and the inputs kept away from the boundary;
* variant conventions — Pl3 variant 1 has ``cos(α2 − α1) < 0``; Pl4 variant 1 has vector 1
  counter-clockwise of ``p = r1 + r2`` (``cross(p, r1) > 0``);
* broadcasting — ``(D, P)`` inputs give the same numbers as row-by-row ``(P,)`` calls;
* :func:`track_variant` — follows a smooth branch whatever the labels of the two solutions.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from mechloop.modules.planar import (
    solve_pl1,
    solve_pl2,
    solve_pl3,
    solve_pl4,
    track_variant,
)

FAST = settings(max_examples=300, deadline=None)

lengths = st.floats(0.05, 2.0)
angles = st.floats(-10.0, 10.0)  # any real angle, beyond ±π on purpose
variants = st.sampled_from([1, 2])
#: Length of the known sum: zero, or a normal number (no subnormal round-off games).
sums = st.one_of(st.just(0.0), st.floats(1e-6, 3.0))
#: Relative distance from an existence boundary below which a case is not drawn.
MARGIN = 1e-6


def e(a):
    return np.cos(a), np.sin(a)


def closure(terms):
    """|Σ r_i e_i| and Σ |r_i| for terms ``(r, a)`` (a known sum given as ``(|S|, dir)``)."""
    x = math.fsum(r * math.cos(a) for r, a in terms)
    y = math.fsum(r * math.sin(a) for r, a in terms)
    return math.hypot(x, y), math.fsum(abs(r) for r, _ in terms)


def known_sum(p, ap):
    """The known sum ``(x, y)`` for a required ``r1 + r2 = p (cos ap, sin ap)``."""
    return -p * math.cos(ap), -p * math.sin(ap)


# ---------------------------------------------------------------------------- Pl1


@FAST
@given(x=st.floats(-3, 3), y=st.floats(-3, 3))
def test_pl1_closes_the_loop(x, y):
    assume(math.hypot(x, y) > 1e-9)
    r1, a1, ok = solve_pl1(x, y)
    assert ok
    assert r1 >= 0
    res, scale = closure([(float(r1), float(a1)), (math.hypot(x, y), math.atan2(y, x))])
    assert res <= 1e-12 * scale


def test_pl1_zero_sum_is_a_break():
    r1, a1, ok = solve_pl1(np.array([0.0, 1.0]), np.array([0.0, 0.0]))
    assert ok.tolist() == [False, True]
    assert np.isnan(r1[0]) and np.isnan(a1[0])
    assert r1[1] == 1.0 and math.cos(a1[1]) == -1.0


# ---------------------------------------------------------------------------- Pl2


@FAST
@given(p=sums, ap=angles, a1=angles, a2=angles)
def test_pl2_closes_the_loop_when_directions_cross(p, ap, a1, a2):
    assume(abs(math.sin(a1 - a2)) > 1e-3)
    x, y = known_sum(p, ap)
    r1, r2, ok = solve_pl2(x, y, a1, a2)
    assert ok
    res, scale = closure([(float(r1), a1), (float(r2), a2), (p, ap + math.pi)])
    assert res <= 1e-12 * scale


@FAST
@given(p=st.floats(0.01, 3.0), ap=angles, a1=angles, turn=st.sampled_from([0.0, math.pi]))
def test_pl2_parallel_directions_are_a_break(p, ap, a1, turn):
    x, y = known_sum(p, ap)
    r1, r2, ok = solve_pl2(x, y, a1, a1 + turn)
    assert not ok
    assert np.isnan(r1) and np.isnan(r2)


# ---------------------------------------------------------------------------- Pl3


def pl3_distance(x, y, a1):
    """Distance from the origin to the line that vector 2 must reach: the known sum plus
    any multiple of vector 1's direction, ``|cross(e1, S)|``."""
    return abs(math.cos(a1) * y - math.sin(a1) * x)


@FAST
@given(p=sums, ap=angles, a1=angles, r2=lengths, variant=variants)
def test_pl3_exists_exactly_when_vector_2_reaches_the_line(p, ap, a1, r2, variant):
    x, y = known_sum(p, ap)
    d = pl3_distance(x, y, a1)
    assume(abs(d - r2) > MARGIN * (r2 + p))
    r1, a2, ok = solve_pl3(x, y, a1, r2, variant=variant)
    assert bool(ok) == (d < r2)
    if not ok:
        assert np.isnan(r1) and np.isnan(a2)
        return
    res, scale = closure([(float(r1), a1), (r2, float(a2)), (p, ap + math.pi)])
    assert res <= 1e-12 * scale
    # variant 1: |α2 − α1| > π/2, variant 2: |α2 − α1| < π/2
    cos_phi = math.cos(float(a2) - a1)
    assert (cos_phi < 0) if variant == 1 else (cos_phi > 0)


@FAST
@given(p=sums, ap=angles, a1=angles, r2=lengths)
def test_pl3_variants_are_mirror_images_about_vector_1(p, ap, a1, r2):
    x, y = known_sum(p, ap)
    assume(pl3_distance(x, y, a1) < r2 * (1 - MARGIN))
    r1a, a2a, _ = solve_pl3(x, y, a1, r2, variant=1)
    r1b, a2b, _ = solve_pl3(x, y, a1, r2, variant=2)
    # the two ends of vector 2 on the line are symmetric about the foot of the
    # perpendicular: same sin(α2 − α1), opposite cos(α2 − α1)
    assert math.sin(a2a - a1) == pytest.approx(math.sin(a2b - a1), abs=1e-12)
    assert math.cos(a2a - a1) == pytest.approx(-math.cos(a2b - a1), abs=1e-12)
    gap = math.sqrt(r2 * r2 - pl3_distance(x, y, a1) ** 2)
    assert r1a - r1b == pytest.approx(2 * gap, abs=1e-12 * (r2 + p))


def test_pl3_exact_tangency_is_not_a_break():
    # vector 2 (length 0.5) just touches the line: the known sum is 0.5 off it
    a1 = 0.7
    x, y = -0.5 * math.sin(a1) + 0.3 * math.cos(a1), 0.5 * math.cos(a1) + 0.3 * math.sin(a1)
    for variant in (1, 2):
        r1, a2, ok = solve_pl3(x, y, a1, 0.5, variant=variant)
        assert ok
        assert float(r1) == pytest.approx(-0.3, abs=1e-7)
        assert math.sin(float(a2) - a1) == pytest.approx(-1.0, abs=1e-12)


# ---------------------------------------------------------------------------- Pl4


def cross(ax, ay, bx, by):
    return ax * by - ay * bx


@FAST
@given(p=st.one_of(st.just(0.0), st.floats(1e-6, 4.0)), ap=angles, r1=lengths, r2=lengths,
       variant=variants)
def test_pl4_exists_exactly_when_the_triangle_does(p, ap, r1, r2, variant):
    lo, hi = abs(r1 - r2), r1 + r2
    assume(min(abs(p - lo), abs(p - hi)) > MARGIN * hi)
    x, y = known_sum(p, ap)
    a1, a2, ok = solve_pl4(x, y, r1, r2, variant=variant)
    assert bool(ok) == (lo < p < hi)
    if not ok:
        assert np.isnan(a1) and np.isnan(a2)
        return
    res, scale = closure([(r1, float(a1)), (r2, float(a2)), (p, ap + math.pi)])
    assert res <= 1e-12 * scale
    # variant 1 turns vector 1 counter-clockwise from p, variant 2 clockwise
    side = cross(p * math.cos(ap), p * math.sin(ap), r1 * math.cos(a1), r1 * math.sin(a1))
    assert (side > 0) if variant == 1 else (side < 0)


@FAST
@given(u=st.floats(1e-3, 1 - 1e-3), ap=angles, r1=lengths, r2=lengths)
def test_pl4_triangle_angles_follow_the_law_of_cosines(u, ap, r1, r2):
    p = abs(r1 - r2) + u * (r1 + r2 - abs(r1 - r2))  # strictly inside the triangle range
    x, y = known_sum(p, ap)
    a1, a2, _ = solve_pl4(x, y, r1, r2, variant=1)
    b1, b2, _ = solve_pl4(x, y, r1, r2, variant=2)
    # B (between r1 and p, opposite r2) and A (between r2 and p, opposite r1)
    big_b = math.acos((r1 * r1 + p * p - r2 * r2) / (2 * r1 * p))
    big_a = math.acos((r2 * r2 + p * p - r1 * r1) / (2 * r2 * p))
    assert abs(math.remainder(a1 - (ap + big_b), 2 * math.pi)) < 1e-7
    assert abs(math.remainder(a2 - (ap - big_a), 2 * math.pi)) < 1e-7
    assert abs(math.remainder(b1 - (ap - big_b), 2 * math.pi)) < 1e-7
    assert abs(math.remainder(b2 - (ap + big_a), 2 * math.pi)) < 1e-7


@pytest.mark.parametrize("r1, r2, p", [(0.3, 0.5, 0.8), (0.3, 0.5, 0.2), (0.5, 0.3, 0.2),
                                       (1.7, 0.05, 1.75), (1.7, 0.05, 1.65)])
@pytest.mark.parametrize("ap", [0.0, 1.234, -2.9, 3.0])
def test_pl4_exact_toggle_is_not_a_break(r1, r2, p, ap):
    """A triangle collapsed to a line, computed with round-off, still closes."""
    x, y = known_sum(p, ap)
    for variant in (1, 2):
        a1, a2, ok = solve_pl4(x, y, r1, r2, variant=variant)
        assert ok
        res, scale = closure([(r1, float(a1)), (r2, float(a2)), (p, ap + math.pi)])
        assert res <= 1e-7 * scale  # the angle error is O(sqrt(eps)) at a toggle


def test_pl4_zero_sum_is_a_break():
    a1, a2, ok = solve_pl4(0.0, 0.0, 0.5, 0.5)
    assert not ok and np.isnan(a1) and np.isnan(a2)


# -------------------------------------------------------------------- broadcasting

D, P = 4, 9


def rows_equal(batch, rows):
    for got, want in zip(batch, zip(*rows, strict=True), strict=True):
        np.testing.assert_array_equal(got, np.stack(want))


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_modules_broadcast_designs_like_row_by_row_calls(seed):
    rng = np.random.default_rng(seed)
    x, y = rng.uniform(-2, 2, (2, D, P))
    a1, a2 = rng.uniform(-4, 4, (2, D, P))
    r1, r2 = rng.uniform(0.05, 2, (2, D, P))
    var = rng.integers(1, 3, (D, P))
    cases = [
        (solve_pl1, (x, y), {}),
        (solve_pl2, (x, y, a1, a2), {}),
        (solve_pl3, (x, y, a1, r2), {"variant": var}),
        (solve_pl4, (x, y, r1, r2), {"variant": var}),
    ]
    for fn, args, kw in cases:
        batch = fn(*args, **kw)
        assert all(np.shape(out) == (D, P) for out in batch)
        rows = [fn(*(a[d] for a in args), **{k: v[d] for k, v in kw.items()})
                for d in range(D)]
        rows_equal(batch, rows)
        # (P,) and (1, P) agree
        one = fn(*(a[:1] for a in args), **{k: v[:1] for k, v in kw.items()})
        rows_equal(one, [rows[0]])
    # per-position inputs (P,) broadcast against per-design (D, P) sums
    batch = solve_pl4(x, y, r1[0], r2[0], variant=2)
    rows = [solve_pl4(x[d], y[d], r1[0], r2[0], variant=2) for d in range(D)]
    rows_equal(batch, rows)
    batch = solve_pl3(x, y, a1[0], 0.7, variant=var[0])
    rows = [solve_pl3(x[d], y[d], a1[0], 0.7, variant=var[0]) for d in range(D)]
    rows_equal(batch, rows)


def test_variant_must_be_1_or_2():
    with pytest.raises(ValueError, match="variant"):
        solve_pl4(1.0, 0.0, 0.6, 0.6, variant=3)
    with pytest.raises(ValueError, match="variant"):
        solve_pl3(1.0, 0.0, 0.0, 0.6, variant=np.array([1, 0]))


# ------------------------------------------------------------------- track_variant


def pl4_points(x, y, r1, r2, variant):
    a1, a2, ok = solve_pl4(x, y, r1, r2, variant=variant)
    return (r1 * np.cos(a1), r1 * np.sin(a1), r2 * np.cos(a2), r2 * np.sin(a2)), ok


def crank_rocker_dyad(n=72, a=0.1, b=0.35, c=0.3, g=0.4):
    """Known sum of a Grashof crank-rocker's dyad over a crank turn: no toggle, no break."""
    theta = np.linspace(0, 2 * np.pi, n + 1)
    return a * np.cos(theta) - g, a * np.sin(theta), b, c


def folded_isosceles(n=41, c=0.5, s_max=0.3):
    """An isosceles dyad (r1 = r2 = c) whose base p = (−s, 0) shrinks through zero: the
    triangle flips through a straight line between two positions (s is never 0)."""
    s = np.linspace(s_max, -0.9 * s_max, n + 1)
    return s, np.zeros_like(s), c, c


def test_track_variant_keeps_labels_without_a_toggle():
    x, y, r1, r2 = crank_rocker_dyad()
    b1, ok1 = pl4_points(x, y, r1, r2, 1)
    b2, ok2 = pl4_points(x, y, r1, r2, 2)
    assert ok1.all() and ok2.all()
    assert (track_variant(b1, b2, ok1 & ok2, start=1) == 1).all()
    assert (track_variant(b1, b2, ok1 & ok2, start=2) == 2).all()


def test_track_variant_swaps_labels_when_the_triangle_flips():
    s, y, r1, r2 = folded_isosceles()
    b1, ok1 = pl4_points(s, y, r1, r2, 1)
    b2, ok2 = pl4_points(s, y, r1, r2, 2)
    labels = track_variant(b1, b2, ok1 & ok2, start=1)
    # Independent: on the smooth branch vector 1 = c (cos β, sin β), vector 2 its mirror
    # image c (cos β, −sin β), so 2c cos β = −s.  The branch that starts in variant 1
    # (cross(p, r1) = −s c sin β > 0, i.e. sin β < 0 while s > 0) keeps sin β < 0, which
    # is variant 2 once s < 0.
    np.testing.assert_array_equal(labels, np.where(s > 0, 1, 2))
    chosen = [np.where(labels == 1, u, v) for u, v in zip(b1, b2, strict=True)]
    beta = -np.arccos(-s / (2 * r1))
    np.testing.assert_allclose(chosen[0], r1 * np.cos(beta), atol=1e-12)
    np.testing.assert_allclose(chosen[1], r1 * np.sin(beta), atol=1e-12)


@settings(max_examples=60, deadline=None)
@given(swaps=arrays(np.bool_, 73), a=st.floats(0.05, 0.15), b=st.floats(0.3, 0.5),
       c=st.floats(0.3, 0.5), g=st.floats(0.35, 0.5))
def test_track_variant_recovers_a_branch_from_shuffled_labels(swaps, a, b, c, g):
    """Whatever labels the two solutions carry at each position, tracking returns the
    smooth branch (here a crank-rocker's variant 1, shuffled at random)."""
    # Grashof crank-rocker with a comfortable transmission angle: branches well apart
    assume(a + max(b, c, g) < min(b, c, g) + sorted([b, c, g])[1] - 0.05)
    x, y, r1, r2 = crank_rocker_dyad(72, a, b, c, g)
    smooth, ok = pl4_points(x, y, r1, r2, 1)
    other, _ = pl4_points(x, y, r1, r2, 2)
    assert ok.all()
    lab1 = tuple(np.where(swaps, o, s) for s, o in zip(smooth, other, strict=True))
    lab2 = tuple(np.where(swaps, s, o) for s, o in zip(smooth, other, strict=True))
    labels = track_variant(lab1, lab2, ok, start=2 if swaps[0] else 1)
    np.testing.assert_array_equal(labels, np.where(swaps, 2, 1))


def test_track_variant_label_persists_across_a_break():
    x, y, r1, r2 = crank_rocker_dyad()
    b1, _ = pl4_points(x, y, r1, r2, 1)
    b2, _ = pl4_points(x, y, r1, r2, 2)
    ok = np.ones(x.shape, dtype=bool)
    ok[20:30] = False
    b1 = tuple(np.where(ok, u, np.nan) for u in b1)
    b2 = tuple(np.where(ok, u, np.nan) for u in b2)
    assert (track_variant(b1, b2, ok, start=1) == 1).all()
    assert (track_variant(b1, b2, ok, start=2) == 2).all()


def test_track_variant_broadcasts_over_designs():
    cases = [crank_rocker_dyad(40), folded_isosceles(40), crank_rocker_dyad(40, a=0.12)]
    pts1, pts2, oks, rows = [], [], [], []
    for x, y, r1, r2 in cases:
        b1, ok1 = pl4_points(x, y, r1, r2, 1)
        b2, ok2 = pl4_points(x, y, r1, r2, 2)
        pts1.append(b1)
        pts2.append(b2)
        oks.append(ok1 & ok2)
        rows.append(track_variant(b1, b2, ok1 & ok2))
    stack = [tuple(np.stack(c) for c in zip(*pts, strict=True)) for pts in (pts1, pts2)]
    batch = track_variant(stack[0], stack[1], np.stack(oks))
    assert batch.shape == (3, 41)
    np.testing.assert_array_equal(batch, np.stack(rows))
    assert (batch[1] == 2).any()  # the flipping case really swaps
