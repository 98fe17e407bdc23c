"""The gear pair and the planetary ratio of mechloop.gears against a second published worked
example, one with x1 + x2 ≠ 0 and a shifted sun–planet pair.

Source: Leon Kos, "Analysis of Planetary Transmissions", University of Ljubljana (LECAD),
section "Test run" (the listing of the program ``pg``), at
http://lecad.uni-lj.si/~leon/FS/PlanetryTransmissions/node8.html.  Printed there: input the
sun, the ring fixed, the carrier the output; sun 21 teeth, 3 planets, ring 108 teeth,
normal module 1.75 mm, helix angle 0, normal angle 20°, addendum 1.00 and bottom clearance
0.25 of the module; results: planets 43 teeth, transmission ratio 6.14286, centre distance
56.8 mm, addendum modification coefficients sun 0.4380, planet 0.0426, ring 0.0000;
reference diameters 36.7500 / 75.2500 mm, tip diameters sun 41.7008, planet 78.8170 mm,
teeth in a span sun 3, planet 5, base tangent length sun 13.9546, planet 24.3530 mm.

What agrees and why not all of it at once: the program rounds the centre distance to
56.8 mm and prints the shifts to 4 decimals.  The planet's shift is what that centre
distance leaves (0.042648, printed 0.0426): recomputed from a = 56.8 and the sun's 0.4380,
every printed planet value agrees to its last digit.  The sun's printed tip diameter
41.7008 needs the sun's shift unrounded: 0.4380 gives 41.70073 (printed digit 8, ours 7,
0.017 µm short of the rounding edge).  With a = 56.8 a larger sun shift is a smaller planet
shift, so the two printed tips pin the sun's shift between 0.438005 (the sun's tip reaches
41.70075) and 0.438014 (the planet's tip stays above 78.81695); every shift there prints as
0.4380 and reproduces both tips, the planet's shift and the centre distance.  Nothing in
mechloop is loosened for it: the test states the interval and checks both ends.

The ring (an internal gear, z = 108 ≠ 21 + 2·43) is made coaxial by the shifts; mechloop's
planetary conditions are those of unshifted gears, so only the ratio is compared for it.
"""

from __future__ import annotations

import numpy as np
import pytest

from mechloop.gears.pair import gear_pair
from mechloop.gears.planetary import planetary_train

ALPHA = np.radians(20.0)
# printed inputs
M_N, Z_SUN, Z_PLANET, Z_RING, K = 1.75, 21, 43, 108, 3
X_SUN, X_PLANET = 0.4380, 0.0426      # printed to 4 decimals
A_PRINTED = 56.8                      # mm, printed to 1 decimal
# printed results
RATIO = 6.14286
D = (36.7500, 75.2500)
D_A = (41.7008, 78.8170)
K_SPAN = (3, 5)
W_K = (13.9546, 24.3530)


def test_the_sun_planet_pair_from_its_printed_shifts():
    pair = gear_pair(M_N, (Z_SUN, Z_PLANET), ALPHA, x=(X_SUN, X_PLANET))
    assert round(pair.a, 1) == A_PRINTED             # 56.79992 → 56.8
    assert np.array_equal(np.round(pair.d, 4), D)
    assert round(float(pair.d_a[0]), 3) == round(D_A[0], 3)   # 41.701: 3 decimals
    assert round(float(pair.d_a[1]), 3) == round(D_A[1], 3)   # 78.817: 3 decimals


def test_the_pair_from_the_printed_centre_distance_agrees_to_every_printed_digit():
    pair = gear_pair(M_N, (Z_SUN, Z_PLANET), ALPHA, a=A_PRINTED, x1=X_SUN)
    assert round(pair.x[1], 4) == X_PLANET            # 0.042648 prints as 0.0426
    assert round(float(pair.d_a[1]), 4) == D_A[1]     # 78.8170, every digit
    assert np.array_equal(np.round(pair.d, 4), D)
    # the sun: 0.4380 exactly gives 41.70073 (one unit of the last printed digit off)…
    assert round(float(pair.d_a[0]), 4) == 41.7007
    # …while the sun shifts from 0.438005 to 0.438014 (all printed 0.4380) give both tips
    for x_sun in (0.438006, 0.438013):
        sun = gear_pair(M_N, (Z_SUN, Z_PLANET), ALPHA, a=A_PRINTED, x1=x_sun)
        assert round(sun.x[0], 4) == X_SUN
        assert round(float(sun.d_a[0]), 4) == D_A[0]
        assert round(float(sun.d_a[1]), 4) == D_A[1]  # the planet's stays 78.8170
    # and outside that interval one of them is not reproduced
    for x_sun in (0.438004, 0.438016):
        sun = gear_pair(M_N, (Z_SUN, Z_PLANET), ALPHA, a=A_PRINTED, x1=x_sun)
        assert tuple(np.round(sun.d_a, 4)) != D_A


def test_the_printed_span_measurements():
    pair = gear_pair(M_N, (Z_SUN, Z_PLANET), ALPHA, a=A_PRINTED, x1=X_SUN)
    assert tuple(pair.k_span) == K_SPAN
    assert tuple(np.round(pair.W_k, 4)) == W_K        # both to every printed digit
    # the planet's printed W_k, like its tip, is that of the shift a = 56.8 leaves: the
    # printed 0.0426 itself gives 24.35295, which rounds to 24.3529
    printed = gear_pair(M_N, (Z_SUN, Z_PLANET), ALPHA, x=(X_SUN, X_PLANET))
    assert round(float(printed.W_k[1]), 4) == 24.3529


def test_the_span_is_the_caliper_width_over_the_generated_teeth():
    """W_k measured on the teeth the basic rack generates (mechloop.gears.generation, not
    the W_k formula): turn the k teeth symmetric about the x axis; the caliper's jaw, a
    blade entering the space beyond the top tooth, touches that tooth's outer involute
    flank (above the form circle, where the fillet begins) at its highest point."""
    from mechloop.gears.generation import generate_tooth

    pair = gear_pair(M_N, (Z_SUN, Z_PLANET), ALPHA, a=A_PRINTED, x1=X_SUN)
    for i in range(2):
        z, k = pair.z[i], int(pair.k_span[i])
        tooth = generate_tooth(M_N, z, ALPHA, pair.x[i], d_a=float(pair.d_a[i]),
                               radii=4000)
        top = (k - 1) / 2 * 2 * np.pi / z            # the top tooth's centre line
        flank = tooth.rho >= pair.d_Ff[i] / 2
        heights = tooth.rho[flank] * np.sin(top + tooth.psi[flank])
        j = int(np.argmax(heights))
        assert 0 < j < heights.size - 1               # touches the flank, not its ends
        assert 2 * heights[j] == pytest.approx(float(pair.W_k[i]), abs=5e-6)
        # and W_k = (k − 1) p_b + s_b along the base circle
        assert float(pair.W_k[i]) == pytest.approx((k - 1) * pair.p_b + float(pair.s_b[i]),
                                                    rel=1e-13)


def test_the_tips_are_shortened_to_keep_the_bottom_clearance():
    # the printed tip diameters are those of tips shortened by Δy·m (GOST 16532-70 / DIN
    # 3960 practice), not d + 2 m (h_a* + x): the unshortened sun tip would be 41.783 mm
    pair = gear_pair(M_N, (Z_SUN, Z_PLANET), ALPHA, a=A_PRINTED, x1=X_SUN)
    assert round(pair.dy, 4) == 0.0235
    assert pair.d[0] + 2 * M_N * (1 + X_SUN) == pytest.approx(41.783, abs=5e-4)
    assert np.allclose(pair.tip_clearances, 0.25 * M_N, rtol=0, atol=1e-12)


def test_the_printed_transmission_ratio():
    train = planetary_train("simple", {"a": Z_SUN, "g": Z_PLANET, "b": Z_RING}, K, M_N)
    assert round(train.ratio, 5) == RATIO             # 1 + 108/21 = 6.142857…
    # the program makes the ring coaxial by the shifts: unshifted, it is not
    assert not train.coaxial and Z_SUN + 2 * Z_PLANET == Z_RING - 1
    assert train.assembles                            # (21 + 108)/3 = 43
