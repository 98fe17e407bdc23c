"""The exact existence check between positions for coupled blocks, and the continuation's
first step.

* A class-III triad (:func:`test_coupled_blocks.triad`) whose dyad 3 is just too short
  for a window of about 1.2° of the crank (a fold pair: the assembly followed merges
  with its mirror and reappears): from samples every 5° on the branch (a 0.5° solve,
  every tenth position) the check finds the break between two positions that assemble,
  its ends agreeing with the SciPy assembly oracle (:mod:`oracles.assemblies`) followed
  in fine steps from either side; designs 1e-4 and 1e-2 short of the window are
  accepted, as a solve on 25,000 positions confirms; synthesis refuses the broken one.
* The first step after the assembly at position 0 is checked against the tangent
  predictor: two four-bars in one block (determinant = product of theirs, so flipping
  both keeps its sign) with one large crank step where Newton's method from position 0
  lands on the doubly flipped assembly — a jump of the same sign, reported as one.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
from oracles.assemblies import Equations
from test_coupled_blocks import BASE, triad

import mechloop
from mechloop.model.check import require_valid
from mechloop.modules.coupled import JUMP, OK, Plan, continue_block
from mechloop.solve.designs import solve_designs
from mechloop.solve.existence import THRESHOLD, assembles_throughout
from mechloop.synthesis.problem import SynthesisProblem

START, STOP = 61.0, 86.0  # deg: the crank's range, the window lies near 71.8..72.9


def window_model(n: int, r6: float, synthesis: bool = False) -> mechloop.Model:
    """The triad of :data:`BASE` with dyad 3 of length ``r6``, the crank from 61° to
    86° in ``n`` steps."""
    model = triad(**BASE, sweep=360, n=n)
    vectors = dict(model.vectors)
    vectors[6] = vectors[6].model_copy(update={"r": r6})
    update = {"vectors": vectors, "arguments": {1: model.arguments[1].model_copy(
        update={"table": {0: START, n: STOP}})}}
    if synthesis:
        data = model.model_copy(update=update).model_dump(mode="json", exclude_none=True)
        data["synthesis"] = {"vary": {"r6": [1.0, 1.2]},
                             "path": {"point": {"head": 6},
                                      "targets": [[0.5, 1.0], [0.5, 1.1]]},
                             "objective": "ssq"}
        return mechloop.Model.from_dict(data)
    return model.model_copy(update=update)


def coarse_samples(r6: float) -> SimpleNamespace:
    """The branch at every 5°: a solve every 0.5°, every tenth position (that solve
    breaks inside the window and restarts after it from the last assembly)."""
    fine = mechloop.solve(window_model(50, r6))
    return SimpleNamespace(values={k: np.asarray(v)[None, ::10] for k, v in
                                   fine.values.items()}, broken=fine.broken[None, ::10])


def oracle_edge(eq: Equations, u: np.ndarray, x0: float, toward: float) -> float:
    """Where the oracle loses the assembly ``u`` at input ``x0`` (rad, argument 1 as at
    position 0 plus a shift) followed towards ``toward``: steps halved down to 1e-9 rad
    wherever no root lies near (within 0.05 rad) or the Jacobian's sign changes."""
    sign = eq.jacobian_sign(u, 0)
    base = math.radians(START)
    at, step = x0, (toward - x0) / 8
    while abs(step) > 1e-9:
        nxt = eq.solve_from(u, 0, at + step - base)
        ok = (nxt is not None and eq.distance(nxt, u) < 0.05
              and np.sign(np.linalg.det(eq.jacobian(nxt, 0, at + step - base))) == sign)
        if ok:
            u, at = nxt, at + step
        else:
            step /= 2
    return at


def test_a_triad_break_between_two_samples_is_found_where_the_oracle_loses_it():
    """The assembly is lost for about 1.2° of the crank (71.76° to 72.92°, the oracle's
    ends) between the samples at 71° and 76°; the check finds both ends to 1e-6 rad."""
    r6 = 1.11916
    samples = coarse_samples(r6)
    assert not samples.broken.any()  # every sample assembles on the branch
    model = window_model(5, r6)
    eq = Equations(model)
    x = np.radians(np.linspace(START, STOP, 6))
    for k in range(6):  # the samples are the oracle's roots on one sign
        u = np.array([samples.values[n][0, k] for n in eq.names])
        assert np.abs(eq.residual(u, 0, x[k] - x[0])).max() < 1e-12
    found = assembles_throughout(model, samples=samples, intervals=True)
    assert not found.feasible[0] and found.margin[0] <= THRESHOLD
    assert len(found.breaks) == 1
    brk = found.breaks[0]
    assert (brk.design, brk.contour, brk.after, brk.exact) == (0, 1, 2, False)
    # the oracle, following the branch from 71° up and from 76° down in fine steps
    u71 = np.array([samples.values[n][0, 2] for n in eq.names])
    u76 = np.array([samples.values[n][0, 3] for n in eq.names])
    first = oracle_edge(eq, u71, x[2], x[3])
    last = oracle_edge(eq, u76, x[3], x[2])
    assert x[2] < first < last < x[3]
    assert round(math.degrees(last - first), 1) == 1.2
    assert abs(brk.start - first) < 1e-6 and abs(brk.stop - last) < 1e-6


def test_triads_just_short_of_the_window_assemble_throughout():
    """1e-4 and 1e-2 (relative) shorter than the window's opening value (about 1.11915):
    accepted by the check, and a solve on 25,000 positions (1e-3°) breaks nowhere."""
    for r6 in (1.119, 1.108):
        found = assembles_throughout(window_model(5, r6), samples=coarse_samples(r6),
                                     intervals=True)
        assert found.feasible[0] and found.margin[0] > THRESHOLD and not found.breaks
    # a solve on 25,000 positions: the two assemble, the window is real for the third
    dense = solve_designs(window_model(25_000, 1.0), {"r6": [1.119, 1.108, 1.11916]},
                          derivatives=False)
    np.testing.assert_array_equal(dense.broken.any(axis=1), [False, False, True])


def test_synthesis_refuses_a_triad_that_breaks_between_two_samples():
    problem = SynthesisProblem(window_model(5, 1.11916, synthesis=True))
    designs = np.array([[1.11916], [1.119]])
    each = [coarse_samples(r) for r in (1.11916, 1.119)]
    samples = SimpleNamespace(
        values={k: np.concatenate([np.broadcast_to(s.values[k], (1, 6)) for s in each])
                for k in each[0].values},
        broken=np.zeros((2, 6), dtype=bool))
    np.testing.assert_array_equal(problem.exists(designs, samples), [False, True])


# ------------------------------------------------------------------ the first step

def two_four_bars(thetas, c, a, b, d, c2, phase):
    """Two four-bars (crank ``c`` / ``c2`` at θ / θ + phase, coupler ``a``, rocker
    ``b``, frame ``d``) as one block of 4 unknowns, the known stack per column θ."""
    cols = [0.0, 1.0, c, a, b, d, math.pi, c2]
    th = np.asarray(thetas, dtype=float)
    known = np.empty((len(cols) + 2, 1, th.size))
    for i, v in enumerate(cols):
        known[i] = v
    known[len(cols)], known[len(cols) + 1] = th, th + phase
    t1, t2 = len(cols), len(cols) + 1
    terms = np.array([(0, -1, 1, 2, -1, 1, t1), (0, -1, 1, 3, 0, 1, 0),
                      (0, -1, 1, 4, 1, 1, 0), (0, -1, 1, 5, -1, 1, 6),
                      (1, -1, 1, 7, -1, 1, t2), (1, -1, 1, 3, 2, 1, 0),
                      (1, -1, 1, 4, 3, 1, 0), (1, -1, 1, 5, -1, 1, 6)], dtype=np.int64).T
    plan = Plan(unknowns=("a2", "a3", "a6", "a7"), eq=terms[0], r_unknown=terms[1],
                r_scale=terms[2], r_col=terms[3], a_unknown=terms[4], a_scale=terms[5],
                a_col=terms[6], angle=np.ones(4, dtype=bool))
    return plan, known


def test_a_same_sign_jump_on_the_first_step_is_a_jump():
    geometry = (1.9149143401085398, 1.9289377453807446, 2.008877202988642,
                0.5612970908164001, 1.3213436242115533, 4.635246488110723)
    step = 2.6781142986892426  # rad: one crank step from position 0
    plan, known = two_four_bars([0.0, step], *geometry)
    U, status, det, _ = continue_block(plan, known, want=1, guess={}, singular_sin=1e-6)
    # the branch, followed in 400 steps from the same assembly, does not break
    plan, fine = two_four_bars(np.linspace(0.0, step, 401), *geometry)
    Uf, status_f, det_f, _ = continue_block(plan, fine, want=1, guess={}, singular_sin=1e-6)
    assert (status_f == OK).all() and np.allclose(Uf[0, 0], U[0, 0])
    assert (np.sign(det_f) == np.sign(det[0, 0])).all()
    # Newton's method from position 0 lands elsewhere (2.69 rad from the branch, on the
    # doubly flipped assembly: the same determinant sign — returned as a good position
    # before the first step had the tangent check), which is reported as a jump
    assert status[0, 1] == JUMP
    # a fine enough first step stays on the branch and is accepted
    plan, near = two_four_bars([0.0, step / 400], *geometry)
    U2, status2, _, _ = continue_block(plan, near, want=1, guess={}, singular_sin=1e-6)
    assert (status2 == OK).all()
    np.testing.assert_allclose(U2[0, 1], Uf[0, 1], atol=1e-12)


# ------------------------------------------------------------------ variant auto

def test_variant_auto_on_a_block_follows_the_assembly_as_a_fixed_variant_does():
    """``variant: auto`` on a contour of a block: the first assembly as without it (here
    the guess's), followed by continuity — over a turn where the determinant keeps its
    sign, exactly the numbers and breaks of the fixed variant; the check between
    positions gives the same verdict."""
    fixed = window_model(50, 1.108)
    contours = list(fixed.contours)
    contours[0] = contours[0].model_copy(update={"variant": "auto"})
    auto = fixed.model_copy(update={"contours": contours})
    assert require_valid(auto).blocks[0].variant == "auto"
    a, b = mechloop.solve(fixed), mechloop.solve(auto)
    assert not a.broken.any() and not b.broken.any()
    for name in ("a1", "a3", "a6", "a7"):
        np.testing.assert_array_equal(a.values[name], b.values[name])
        np.testing.assert_array_equal(a.rates[name], b.rates[name])
    assert assembles_throughout(fixed).feasible[0] and assembles_throughout(auto).feasible[0]


# ------------------------------------------------------------------ mechloop solve

def test_solve_warns_of_a_triad_break_between_two_positions(tmp_path):
    """Positions at 71.25°, 73.25°, 75.25° and 77.25°: every one assembles on the branch
    (the continuation steps over the window), and the solve names the break between
    positions 0 and 1 with the oracle's ends (71.7609° to 72.9215°, the first test);
    the command line prints it."""
    import json

    from typer.testing import CliRunner

    from mechloop.cli import app

    model = window_model(3, 1.11916)
    model = model.model_copy(update={"arguments": {1: model.arguments[1].model_copy(
        update={"table": {0: 71.25, 3: 77.25}})}})
    res = mechloop.solve(model)
    assert not res.broken.any()
    (brk,) = res.breaks_between
    assert (brk.contour, brk.module, brk.after) == (1, "coupled", 0)
    np.testing.assert_allclose(np.degrees([brk.start, brk.stop]), [71.7609, 72.9215],
                               atol=1e-4)
    path = tmp_path / "triad.json"
    path.write_text(json.dumps(model.model_dump(mode="json", exclude_none=True)))
    result = CliRunner().invoke(app, ["solve", str(path)])
    assert result.exit_code == 0, result.output
    assert "between positions 0 and 1" in " ".join(result.output.split())


def test_variant_auto_follows_a_block_through_a_change_of_its_determinant_sign():
    """A triangle (known side ``d(t)``, unknown angles of sides 1 and 1.5) flattened at
    ``t = 0.5`` (``d = 2.5``) and reopened: the continuous motion turns side 1 on through
    180° (its angle linear in ``t`` near there, the determinant changing sign). With
    ``track`` (``variant: auto``) the block follows it and the sign; without, the step
    across is a jump and the assembly restarts on the old sign (the mirror image)."""
    r2, r3, k = 1.0, 1.5, 0.8
    t = np.linspace(0.0, 1.0, 20)
    d = (r2 + r3) * (1 - k * (t - 0.5) ** 2)
    known = np.empty((5, 1, t.size))
    for i, v in enumerate([0.0, 1.0, r2, r3]):
        known[i] = v
    known[4] = d
    terms = np.array([(0, -1, 1, 4, -1, 1, 0), (0, -1, 1, 2, 0, 1, 0),
                      (0, -1, 1, 3, 1, 1, 0)], dtype=np.int64).T
    plan = Plan(unknowns=("a2", "a3"), eq=terms[0], r_unknown=terms[1], r_scale=terms[2],
                r_col=terms[3], a_unknown=terms[4], a_scale=terms[5], a_col=terms[6],
                angle=np.ones(2, dtype=bool))
    U, status, det, _ = continue_block(plan, known, want=-1, guess={}, singular_sin=1e-6,
                                       track=True)
    assert (status == OK).all()
    np.testing.assert_array_equal(np.sign(det[0]), np.where(t < 0.5, -1.0, 1.0))
    # the closed form: side 1 makes the triangle's angle γ at the origin with −d, on one
    # side before the flat position and on the other after it: −π ± γ,
    # γ = arccos((d² + r2² − r3²) / (2 d r2))
    gamma = np.arccos(np.clip((d ** 2 + r2 ** 2 - r3 ** 2) / (2 * d * r2), -1, 1))
    expected = -np.pi + np.where(t < 0.5, gamma, -gamma)
    np.testing.assert_allclose(U[0, :, 0], expected, atol=1e-9)
    U, status, det, _ = continue_block(plan, known, want=-1, guess={}, singular_sin=1e-6)
    assert status[0, 10] == JUMP and (np.delete(status[0], 10) == OK).all()
    assert (np.sign(np.delete(det[0], 10)) == -1).all()
