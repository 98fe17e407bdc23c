"""The compiled Pl4 kernel gives what the NumPy module and the position solve give."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import mechloop
from mechloop.modules.kernels import pl4_contour
from mechloop.modules.planar import EXISTENCE_RTOL, pl4_unit
from mechloop.solve import kinematics
from mechloop.solve.designs import solve_designs
from mechloop.solve.kinematics import SINGULAR_SIN

finite = st.floats(-10, 10, allow_nan=False)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(finite, finite, finite, finite), min_size=1, max_size=30),
       st.sampled_from([1, 2]))
def test_kernel_equals_the_numpy_module_and_its_jacobian_test(rows, variant):
    x, y, r1, r2 = (np.array(col)[None, :] for col in zip(*rows, strict=True))
    # toggle positions and zero lengths too: r2 chosen to close the triangle exactly
    r2 = np.concatenate([r2, np.hypot(x, y) - r1])
    x, y, r1 = np.concatenate([x, x]), np.concatenate([y, y]), np.concatenate([r1, r1])
    got = pl4_contour(x, y, r1, r2, variant=variant, rtol=EXISTENCE_RTOL,
                      singular_sin=SINGULAR_SIN)
    c1, s1, c2, s2, ok = pl4_unit(x, y, r1, r2, variant=variant)
    np.testing.assert_array_equal(got[4], ok)
    for a, b in zip(got[:4], (c1, s1, c2, s2), strict=True):
        np.testing.assert_array_equal(a, b)  # bit for bit (NaN where no solution)
    # the position solve's test: columns r n of the two unknown angles
    c1x, c1y, c2x, c2y = -r1 * s1, r1 * c1, -r2 * s2, r2 * c2
    det = c1x * c2y - c1y * c2x
    norm = np.sqrt((c1x**2 + c1y**2) * (c2x**2 + c2y**2))
    with np.errstate(invalid="ignore"):
        dead = ok & ~(np.abs(det) > SINGULAR_SIN * norm)
    np.testing.assert_array_equal(got[5], dead)
    good = ok & ~dead
    np.testing.assert_array_equal(got[6], np.where(good, np.sign(det), 0).astype(np.int8))


@settings(max_examples=15, deadline=None)
@given(st.integers(0, 2**32 - 1))
def test_a_population_solved_with_the_kernel_equals_numpy(seed):
    model = mechloop.load_model("examples/eighteen_points_timing_synthesis.yaml")
    rng = np.random.default_rng(seed)
    n = 300
    over = {"r1": rng.uniform(0, 0.05, n), "r2": rng.uniform(0, 0.05, n),
            "r3": rng.uniform(0, 0.05, n), "r4": rng.uniform(0, 0.05, n),
            "a4": rng.uniform(0, 2 * np.pi, n), "r6": rng.uniform(-0.05, 0.05, n)}
    positions = np.arange(0, 360, 20)
    fast = solve_designs(model, over, derivatives=False, positions=positions)
    assert fast.broken.size >= kinematics.KERNEL_ELEMENTS
    saved = kinematics.KERNEL_ELEMENTS
    kinematics.KERNEL_ELEMENTS = 10**15
    try:
        plain = solve_designs(model, over, derivatives=False, positions=positions)
    finally:
        kinematics.KERNEL_ELEMENTS = saved
    np.testing.assert_array_equal(fast.broken, plain.broken)
    np.testing.assert_array_equal(fast.keeps_variant, plain.keeps_variant)
    for name in ("a2", "a3", "r8", "a8"):
        np.testing.assert_array_equal(fast.values[name], plain.values[name])
