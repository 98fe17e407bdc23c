"""Which bodies hold the vector ends, and the contour points two bodies share
(:mod:`mechloop.dynamics.holds`, used by the planar mechanism and the spatial structure).

Checked by hand on small models: every junction of the contours listed with the bodies
that hold it, a subtracted vector's junctions at its head and tail swapped, and a point
held by three bodies reported at its contour entry.
"""

from __future__ import annotations

from types import SimpleNamespace

from mechloop.dynamics.holds import shared_junctions, vector_holds


def _model(contours, bodies, vectors=(1, 2, 3)):
    return SimpleNamespace(
        contours=[SimpleNamespace(vectors=list(c)) for c in contours],
        bodies={n: SimpleNamespace(vectors=list(v), ends=dict(e))
                for n, (v, e) in bodies.items()},
        vectors={v: None for v in vectors})


def test_bodies_hold_the_ends_of_their_vectors_and_the_ground_the_constant_ones():
    model = _model([[1, 2, 3]], {1: ([1], {}), 2: ([2], {2: "head"})})
    constant = {"r1", "a3", "r3", "b3"}
    holds = vector_holds(model, constant)
    assert holds == {(1, "tail"): {1}, (1, "head"): {1}, (2, "head"): {2},
                     (3, "tail"): {0}, (3, "head"): {0}}
    assert vector_holds(model, constant - {"b3"}, letters="rab") == {
        (1, "tail"): {1}, (1, "head"): {1}, (2, "head"): {2}}


def test_junctions_held_by_two_bodies_are_listed_with_the_vector_starting_there():
    model = _model([[1, 2, 3]], {1: ([1], {}), 2: ([2], {2: "head"})})
    holds = vector_holds(model, {"r1", "a3", "r3"})
    problems: list = []
    # 3→1: ground (3's head) and body 1 (1's tail); 1→2: body 1 alone; 2→3: body 2
    # (2's head) and the ground (3's tail)
    assert list(shared_junctions(model, holds, problems)) == [(1, (0, 1)), (3, (0, 2))]
    assert problems == []


def test_a_subtracted_vector_meets_the_next_at_its_tail():
    # contour 1, −2: from 1's head the walk runs along 2 backwards, from 2's head to its
    # tail, and back to 1's tail; sliding vectors held at their tails: only 2's tail
    # (body 2) meets 1's tail (body 1)
    model = _model([[1, -2]], {1: ([1], {1: "tail"}), 2: ([2], {2: "tail"})}, (1, 2))
    holds = vector_holds(model, set())
    problems: list = []
    assert list(shared_junctions(model, holds, problems)) == [(1, (1, 2))]
    # both lengths constant: 1's head (body 1) meets 2's head (body 2), the entry −2
    holds = vector_holds(model, {"r1", "r2"})
    assert list(shared_junctions(model, holds, problems)) == [(1, (1, 2)), (-2, (1, 2))]
    assert problems == []


def test_a_point_held_by_three_bodies_is_a_located_problem():
    # bodies 1 and 5 both carry vector 1: each end of it is held by two bodies already
    model = _model([[3, 1, 2]], {1: ([1], {}), 2: ([2], {}), 4: ([3], {}), 5: ([1], {})})
    holds = vector_holds(model, {"r1", "r2", "r3"})
    problems: list = []
    assert list(shared_junctions(model, holds, problems)) == [(3, (2, 4))]
    assert [p.path for p in problems] == [("contours", 0, "vectors", 1),
                                          ("contours", 0, "vectors", 2)]
    assert "bodies 1, 4, 5 all hold the point where vector 3 ends and vector 1 starts" \
        in problems[0].message
    assert "bodies 1, 2, 5" in problems[1].message
    assert all("joints:" in p.hint for p in problems)
