"""The walk that places contours from their starts (:mod:`mechloop.dynamics.placing`),
shared by the planar ``Placement`` and the spatial ``Placement3``.

Checked by hand on small contours of complex vectors: tails as the sums of the vectors
before them from each start (origin, fixed coordinates, another contour's tail or head,
a start given per contour), subtracted vectors of a spatial contour, and the located
errors of starts that cannot be placed.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from mechloop.dynamics.placing import ContourPlacement
from mechloop.dynamics.points import Motion
from mechloop.errors import ModelError
from mechloop.model.dynamic import HeadPoint, TailPoint


class _Points(ContourPlacement[Motion]):
    """Complex points at two positions; vectors moving with velocity 1j·z."""

    def _at_rest(self, position):
        zero = np.zeros(2, dtype=complex)
        return Motion(zero if position is None else position, zero, zero)

    def _fixed(self, x, y):
        return np.full(2, complex(x, y))


def _place(contours, vectors, starts=None):
    """Contours given as ``(vectors, start, spatial)``; ``vectors`` {n: complex z}."""
    model = SimpleNamespace(
        contours=[SimpleNamespace(vectors=v, start=s, spatial=sp) for v, s, sp in contours],
        units=SimpleNamespace(length="mm"))
    results = SimpleNamespace(model=model, broken=np.zeros(2, dtype=bool))
    motions = {n: Motion(np.full(2, z), np.full(2, 1j * z), np.zeros(2, dtype=complex))
               for n, z in vectors.items()}
    return _Points(results, motions, starts)


VECTORS = {1: 1 + 0j, 2: 1j, 3: -1 - 1j, 4: 2 + 0j, 5: -2 + 0j, 6: 3j}


def test_tails_are_the_sums_of_the_vectors_before_them_from_each_start():
    # contour 2 starts at the head of vector 2 (1 + 1j), contour 3 at [1000, 0] mm;
    # contour 2 is listed after the one that needs it
    place = _place([([6], HeadPoint(head=4), False), ([1, 2, 3], "origin", False),
                    ([4, 5], HeadPoint(head=2), False)], VECTORS)
    assert place.tail(1).z[0] == 0 and place.tail(2).z[0] == 1 and place.tail(3).z[0] == 1 + 1j
    assert place.head(3).z[0] == 0
    assert place.tail(4).z[0] == 1 + 1j and place.tail(5).z[0] == 3 + 1j
    assert place.tail(6).z[0] == 3 + 1j and place.head(6).z[0] == 3 + 4j
    assert place.tail(6).v[0] == 1j * 1 + 1j * 1j + 1j * 2  # the velocities add alike
    fixed = _place([([4, 5], [1000, 0], False)], VECTORS)
    assert fixed.tail(4).z[0] == pytest.approx(1.0) and fixed.tail(5).z[0] == pytest.approx(3)


def test_a_start_given_per_contour_overrides_the_model():
    place = _place([([4, 5], "origin", False)], VECTORS,
                   starts={0: np.array([5j, 6j])})
    assert list(place.tail(5).z) == [2 + 5j, 2 + 6j]


def test_a_subtracted_vector_of_a_spatial_contour_has_its_head_at_the_walk():
    # walk 4 from the origin to 2; −5 (5 is −2) has its head there and its tail at 4
    place = _place([([4, -5], "origin", True)], VECTORS)
    assert place.tail(4).z[0] == 0
    assert place.head(5).z[0] == 2 and place.tail(5).z[0] == 4
    planar = _place([([4, -5], "origin", False)], VECTORS)  # no sign in a planar contour
    assert planar.tail(5).z[0] == 2 and planar.head(5).z[0] == 0


@pytest.mark.parametrize(("contours", "message"), [
    ([([1, 2, 3], TailPoint(tail=4), False), ([4, 5], HeadPoint(head=1), False)],
     "in a cycle"),
    ([([1, 2, 3], TailPoint(tail=9), False)], "vector 9 does not exist"),
    ([([1, 2, 3], HeadPoint(head=2), False)], "vector 2 is in this contour"),
])
def test_starts_that_cannot_be_placed_are_located(contours, message):
    with pytest.raises(ModelError) as info:
        _place(contours, VECTORS)
    (problem,) = info.value.problems
    assert problem.path[0] == "contours" and problem.path[2] == "start"
    assert message in problem.message
