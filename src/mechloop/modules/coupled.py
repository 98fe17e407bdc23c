"""A coupled block: ``k`` contours whose ``2k`` closure equations are solved together.

When contours need each other's functions, or a contour links to one of its own functions
(a non-elementary module: a class-III group such as a triad), no closed form gives the
unknowns.  The block's raw closure equations

    ``Σ_{i ∈ contour j} r_i cos α_i = 0``, ``Σ_{i ∈ contour j} r_i sin α_i = 0``
    (j = 1..k)

are solved for its ``2k`` unknowns (the functions, :class:`~mechloop.model.structure.
BlockInfo`) by Newton's method, one position after the other (continuation): each
position starts from a predictor — the previous solution, or the line through the last two
— so the solution stays on the assembly branch chosen at position 0.  A parameter linked
to an unknown ``u`` enters as ``scale·u + delta`` (``scale`` is 1 for a plain link).

**Position 0** (or the first position that assembles) starts from the assembly the user
chose: the contour's ``guess`` (approximate unknowns; the converged solution nearest to it
is kept), or without one, Newton from a fixed set of starts (angles spread over the turn,
lengths over twice the sum of the block's known lengths), keeping the first that converges
with the Jacobian determinant of the block's ``variant``: negative for variant 1, positive
for variant 2 — the convention of the elementary modules Pl3 and Pl4, so a contour solved
here has the same assembly as in closed form.  A block with several assemblies of one sign
(a triad has up to six) should be given a ``guess``.

**Breaks** (status per element, :data:`REASONS`): Newton does not converge (no assembly
near the previous one: past a limit position), the Jacobian is singular (a dead point:
``|det J| / Π ‖column‖`` below :data:`~mechloop.solve.kinematics.SINGULAR_SIN`, the
relative test the elementary modules use — for 2×2 it is the sine between the columns),
or the solution jumped to another assembly branch (the determinant changed sign, or,
with a predictor from the last two positions, the solution lies farther from it than
twice the last step and more than :data:`JUMP_ANGLE` for an angle or :data:`JUMP_LENGTH`
of the block's size for a length).  The first step after position 0 and after a break,
which has no line through two good positions, is checked the same way against the
first-order predictor ``u + δ`` (``δ = −J⁻¹F`` at the new position from the last
solution: the velocity times the input's step), with twice ``|δ|`` as the step.  After a
break, later positions restart from the last good solution.

The continuation is sequential along positions and runs compiled (numba): a block is
described by integer and float arrays (:class:`Terms`: where each vector's ``r`` and ``α``
come from — a known column, or an unknown with a scale column and an offset column), and
one kernel call solves every design × position of a block with no Python loop.  The same
kernel solves the coupled blocks of models with spatial contours
(:mod:`mechloop.spatial.block`), whose terms add three equations ``±r (cos α cos β,
sin α, cos α sin β)`` per spatial contour.

**Rates** are exact from the block Jacobian: the same linear systems as DESIGN §3 with the
``2k × 2k`` Jacobian (:func:`block_rates`).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Protocol

import numpy as np
from numba import njit
from numpy.typing import NDArray

Array = NDArray[np.float64]

#: Newton iterations per position before it counts as not converged.
MAX_ITERATIONS = 60
#: Newton has converged when its step is below this (rad; for lengths, times the block's
#: size); one more step then polishes the solution to rounding.
STEP_TOL = 1e-11
#: The closure residual (relative to the block's size) a converged solution must meet.
RESIDUAL_TOL = 1e-9
#: A continuing step whose solution lies farther than this from the predictor (rad), and
#: farther than twice the last step, has jumped to another assembly.
JUMP_ANGLE = math.pi / 4
#: The same for a length, as a fraction of the block's size (sum of its known lengths).
JUMP_LENGTH = 0.25
#: Starts tried at the first position when no assembly is known yet.
STARTS = 64

OK, NO_CONVERGENCE, DEAD, JUMP = 0, 1, 2, 3
REASONS = {
    NO_CONVERGENCE: "Newton's method finds no assembly of the coupled block near the "
                    "previous one (past a limit position, or the block cannot close)",
    DEAD: "dead point: the coupled block's Jacobian is singular, velocities are unbounded",
    JUMP: "the coupled block jumped to another assembly branch (its Jacobian determinant "
          "changed sign or the solution moved too far in one step): positions are too "
          "coarse here, or the motion passes a singular position",
}


@dataclass(frozen=True)
class Plan:
    """Where every vector parameter of the block comes from, as arrays over terms ``t``
    (one term per vector): ``eq[t]`` the contour (0..k−1) whose equations it enters;
    ``r_unknown[t]`` the unknown its length is (scaled), or −1 for a known length;
    ``r_scale[t]``, ``r_col[t]`` columns of the known stack holding the scale and the
    value (known) or offset (linked to an unknown); the same for the angle.  ``angle``
    marks the unknowns that are angles."""

    unknowns: tuple[str, ...]
    eq: NDArray[np.int64]
    r_unknown: NDArray[np.int64]
    r_scale: NDArray[np.int64]
    r_col: NDArray[np.int64]
    a_unknown: NDArray[np.int64]
    a_scale: NDArray[np.int64]
    a_col: NDArray[np.int64]
    angle: NDArray[np.bool_]

    @functools.cached_property
    def terms(self) -> Terms:
        """The terms as the compiled solver reads them (:class:`Terms`): every term
        planar (2 equations from ``2·eq``, sign +1, no β)."""
        count = self.eq.shape[0]
        return Terms(row=2 * self.eq.astype(np.int64), dim=np.full(count, 2, dtype=np.int64),
                     sign=np.ones(count),
                     unknown=np.stack([self.r_unknown, self.a_unknown,
                                       np.full(count, -1)]).astype(np.int64),
                     scale=np.stack([self.r_scale, self.a_scale,
                                     self.r_scale]).astype(np.int64),
                     col=np.stack([self.r_col, self.a_col, self.r_col]).astype(np.int64))


@dataclass(frozen=True)
class Terms:
    """A block's terms (one per vector) as the compiled solver reads them, for planar
    and spatial contours alike: ``row[t]`` the first equation of the term's contour,
    ``dim[t]`` its number of equations (2 planar, 3 spatial), ``sign[t]`` ±1 (−1: a
    subtracted vector); per letter ``k`` (0 r, 1 α, 2 β): ``unknown[k, t]`` the unknown
    it is linked to (−1: known), ``scale[k, t]`` and ``col[k, t]`` the known stack's
    columns of the link's scale and of the value (known) or offset (linked).  Integer
    arrays ``(T,)`` and ``(3, T)``; ``sign`` float ``(T,)``."""

    row: NDArray[np.int64]
    dim: NDArray[np.int64]
    sign: NDArray[np.float64]
    unknown: NDArray[np.int64]
    scale: NDArray[np.int64]
    col: NDArray[np.int64]


@njit(cache=True, nogil=True)
def _value(K, r, c, u, unknown, scale, col, k, t):  # pragma: no cover - compiled
    """Letter ``k`` (0 r, 1 α, 2 β) of term ``t`` at row ``r``, column ``c``: the known
    column, or ``scale·u + offset`` for a parameter linked to an unknown."""
    if unknown[k, t] >= 0:
        return K[scale[k, t], r, c] * u[unknown[k, t]] + K[col[k, t], r, c]
    return K[col[k, t], r, c]


@njit(cache=True, nogil=True)
def _evaluate(K, r, c, u, row, dim, sign, unknown, scale, col, F, J):  # pragma: no cover
    """Closure residual ``F`` and Jacobian ``J`` of the block at ``u`` (see
    :meth:`Plan.terms`): a term of ``dim`` 2 adds ``±r (cos α, sin α)`` to its contour's
    two equations from ``row``, one of ``dim`` 3 (a spatial contour's) adds ``±r (cos α
    cos β, sin α, cos α sin β)`` to its three."""
    m = u.shape[0]
    for i in range(m):
        F[i] = 0.0
        for j in range(m):
            J[i, j] = 0.0
    for t in range(row.shape[0]):
        length = sign[t] * _value(K, r, c, u, unknown, scale, col, 0, t)
        a = _value(K, r, c, u, unknown, scale, col, 1, t)
        ca, sa = math.cos(a), math.sin(a)
        e = row[t]
        if dim[t] == 2:  # written out: the planar solver's hot path
            F[e] += length * ca
            F[e + 1] += length * sa
            if unknown[0, t] >= 0:
                k = sign[t] * K[scale[0, t], r, c]
                J[e, unknown[0, t]] += k * ca
                J[e + 1, unknown[0, t]] += k * sa
            if unknown[1, t] >= 0:
                k = K[scale[1, t], r, c] * length
                J[e, unknown[1, t]] += k * -sa
                J[e + 1, unknown[1, t]] += k * ca
            continue
        b = _value(K, r, c, u, unknown, scale, col, 2, t)
        cb, sb = math.cos(b), math.sin(b)
        d = (ca * cb, sa, ca * sb)
        da = (-sa * cb, ca, -sa * sb)
        db = (-ca * sb, 0.0, ca * cb)
        for q in range(3):
            F[e + q] += length * d[q]
            if unknown[0, t] >= 0:
                J[e + q, unknown[0, t]] += sign[t] * K[scale[0, t], r, c] * d[q]
            if unknown[1, t] >= 0:
                J[e + q, unknown[1, t]] += K[scale[1, t], r, c] * length * da[q]
            if unknown[2, t] >= 0:
                J[e + q, unknown[2, t]] += K[scale[2, t], r, c] * length * db[q]


@njit(cache=True, nogil=True)
def _step(J, F, dx):  # pragma: no cover - compiled
    """Solve ``J dx = −F`` (Gaussian elimination with partial pivoting, ``J`` and ``F``
    overwritten); returns ``(det J, |det J| / Π ‖column‖)``."""
    m = F.shape[0]
    hadamard = 1.0
    for j in range(m):
        norm = 0.0
        for i in range(m):
            norm += J[i, j] * J[i, j]
        hadamard *= math.sqrt(norm)
    det = 1.0
    for k in range(m):
        p = k
        for i in range(k + 1, m):
            if abs(J[i, k]) > abs(J[p, k]):
                p = i
        if J[p, k] == 0.0:
            return 0.0, 0.0
        if p != k:
            det = -det
            for j in range(m):
                J[k, j], J[p, j] = J[p, j], J[k, j]
            F[k], F[p] = F[p], F[k]
        det *= J[k, k]
        for i in range(k + 1, m):
            f = J[i, k] / J[k, k]
            for j in range(k, m):
                J[i, j] -= f * J[k, j]
            F[i] -= f * F[k]
    for i in range(m - 1, -1, -1):
        acc = -F[i]
        for j in range(i + 1, m):
            acc -= J[i, j] * dx[j]
        dx[i] = acc / J[i, i]
    ratio = abs(det) / hadamard if hadamard > 0 else 0.0
    return det, ratio


@njit(cache=True, nogil=True)
def _newton(K, row, col, u, eq0, dim, sgn, unk, scl, src, angle, size,
            F, J, dx):  # pragma: no cover - compiled
    """Newton's method from ``u`` (updated in place) on the block whose terms are
    ``eq0 .. src`` (the fields of :class:`Terms`).  Returns ``(converged, det, ratio)``
    at the solution."""
    m = u.shape[0]
    polished = False
    for _ in range(MAX_ITERATIONS):
        _evaluate(K, row, col, u, eq0, dim, sgn, unk, scl, src, F, J)
        if polished:
            res = 0.0
            for i in range(m):
                res = max(res, abs(F[i]))
            det, ratio = _step(J, F, dx)
            return res <= RESIDUAL_TOL * size and math.isfinite(det), det, ratio
        det, ratio = _step(J, F, dx)
        if det == 0.0 or not math.isfinite(det):
            return False, 0.0, 0.0
        big = 0.0
        for i in range(m):
            big = max(big, abs(dx[i]) if angle[i] else abs(dx[i]) / size)
        if not math.isfinite(big):
            return False, 0.0, 0.0
        factor = 1.0 if big <= 1.0 else 1.0 / big  # at most 1 rad (or one size) a step
        for i in range(m):
            u[i] += factor * dx[i]
        if big <= STEP_TOL:
            polished = True  # one more step, then the residual test
    return False, 0.0, 0.0


@njit(cache=True, nogil=True)
def _size(K, row, col, unk, src):  # pragma: no cover - compiled
    """The block's length scale: the sum of its known lengths (1 if none)."""
    total = 0.0
    for t in range(unk.shape[1]):
        if unk[0, t] < 0:
            total += abs(K[src[0, t], row, col])
    return total if total > 0 and math.isfinite(total) else 1.0


@njit(cache=True, nogil=True)
def _assemble(K, row, col, u, eq0, dim, sgn, unk, scl, src, angle, size, starts, want,
              guessed, guess, singular_sin, F, J, dx):  # pragma: no cover - compiled
    """An assembly at one position from the fixed starts: the converged regular solution
    nearest to the guess (if any unknown is guessed), else the first with the wanted
    determinant sign (0: any).  Returns ``(status, det)``; ``u`` holds the solution."""
    m = u.shape[0]
    best = np.empty(m)
    best_det = 0.0
    best_dist = np.inf
    any_guess = False
    for i in range(m):
        any_guess = any_guess or guessed[i]
    dead_seen = False
    trial = np.empty(m)
    for s in range(starts.shape[0]):
        for i in range(m):
            if guessed[i]:
                trial[i] = guess[i]
            elif angle[i]:
                trial[i] = -math.pi + 2.0 * math.pi * starts[s, i]
            else:
                trial[i] = 2.0 * size * starts[s, i]
        ok, det, ratio = _newton(K, row, col, trial, eq0, dim, sgn, unk, scl, src, angle,
                                 size, F, J, dx)
        if not ok:
            continue
        if not ratio > singular_sin:
            dead_seen = True
            continue
        if any_guess:
            dist = 0.0
            for i in range(m):
                if guessed[i]:
                    d = trial[i] - guess[i]
                    if angle[i]:
                        d = (d + math.pi) % (2.0 * math.pi) - math.pi
                    else:
                        d /= size
                    dist += d * d
            if dist < best_dist:
                best_dist = dist
                best_det = det
                best[:] = trial
        elif want == 0 or (det > 0) == (want > 0):
            u[:] = trial
            return OK, det
    if any_guess and best_dist < np.inf:
        u[:] = best
        return OK, best_det
    return DEAD if dead_seen else NO_CONVERGENCE, 0.0


@njit(cache=True, nogil=True)
def _continue(K, eq0, dim, sgn, unk, scl, src, angle, first, n_regular, extra_start,
              starts, want, guessed, guess, singular_sin,
              last, prev, run, sign, found, U, status, det_out,
              from_start, start_u, start_sign, track):  # pragma: no cover
    """Every row (design) of the block whose terms are ``eq0 .. src`` (the fields of
    :class:`Terms`) along the columns (positions) ``first..n_regular−1`` by
    continuation, then the extra columns each from its nearest regular column
    ``extra_start`` — or, with ``from_start``, each from its own start ``start_u[row, j]``
    on the branch of determinant sign ``start_sign[row, j]`` (a NaN start: not solved).
    ``last``, ``prev`` (the last two good solutions), ``run`` (good columns in a row just
    before), ``sign`` (the determinant's sign on the branch) and ``found`` (an assembly
    known) carry the state in and out.  With ``track`` (a block of ``variant: auto``)
    the determinant's sign may change from one column to the next where the solution
    passes the predictor check (a continuous path through a singular position): the
    branch's sign then follows it.  A start sign 0 accepts either sign.

    A step with fewer than two good columns just before (the first after the assembly,
    or after a break) is checked by the first-order predictor ``last + δ``: ``δ =
    −J⁻¹ F``, ``F`` and ``J`` the residual and Jacobian of the last solution at the new
    column (the velocity times the input's step, to first order; the Jacobian where
    the last solution holds instead was tried and passes more jumps near a limit
    position, where it is nearly singular): the solution must lie within
    :data:`JUMP_ANGLE` (or :data:`JUMP_LENGTH` of the size) or twice ``|δ|`` of it, as a
    later step is checked against the line through its last two."""
    n_rows = K.shape[1]
    n_cols = K.shape[2]
    m = angle.shape[0]
    F = np.empty(m)
    J = np.empty((m, m))
    dx = np.empty(m)
    u = np.empty(m)
    tangent = np.empty(m)
    for row in range(n_rows):
        for col in range(first, n_regular):
            size = _size(K, row, col, unk, src)
            if not found[row]:
                code, det = _assemble(K, row, col, u, eq0, dim, sgn, unk, scl, src, angle,
                                      size, starts, want, guessed, guess, singular_sin,
                                      F, J, dx)
                status[row, col] = code
                det_out[row, col] = det
                for i in range(m):
                    U[row, col, i] = u[i] if code == OK else math.nan
                if code == OK:
                    found[row] = True
                    sign[row] = 1 if det > 0 else -1
                    last[row, :] = u
                    run[row] = 1
                continue
            for i in range(m):
                if run[row] >= 2:
                    u[i] = 2.0 * last[row, i] - prev[row, i]
                else:
                    u[i] = last[row, i]
            predicted = False
            if run[row] < 2:  # no line through two good columns: the tangent predictor
                _evaluate(K, row, col, u, eq0, dim, sgn, unk, scl, src, F, J)
                d0, _ = _step(J, F, dx)
                predicted = d0 != 0.0 and math.isfinite(d0)
                for i in range(m):
                    tangent[i] = dx[i]
                    predicted = predicted and math.isfinite(dx[i])
            ok, det, ratio = _newton(K, row, col, u, eq0, dim, sgn, unk, scl, src, angle,
                                     size, F, J, dx)
            code = OK
            flip = False
            if not ok:
                code = NO_CONVERGENCE
            elif not ratio > singular_sin:
                code = DEAD
            else:
                if (det > 0) != (sign[row] > 0):
                    if track:  # variant auto: the sign may change on a continuous path
                        flip = True
                    else:
                        code = JUMP
                if code == OK and run[row] >= 2:
                    for i in range(m):
                        d = abs(u[i] - (2.0 * last[row, i] - prev[row, i]))
                        step = 2.0 * abs(last[row, i] - prev[row, i])
                        limit = max(JUMP_ANGLE if angle[i] else JUMP_LENGTH * size, step)
                        if d > limit:
                            code = JUMP
                elif code == OK and predicted:
                    for i in range(m):
                        d = abs(u[i] - (last[row, i] + tangent[i]))
                        limit = max(JUMP_ANGLE if angle[i] else JUMP_LENGTH * size,
                                    2.0 * abs(tangent[i]))
                        if d > limit:
                            code = JUMP
                elif code == OK and flip:
                    code = JUMP  # no predictor to tell a continuous path from a jump
            if code == OK and flip:
                sign[row] = 1 if det > 0 else -1
            status[row, col] = code
            det_out[row, col] = det if code == OK else 0.0
            if code == OK:
                prev[row, :] = last[row, :]
                last[row, :] = u
                run[row] += 1
                for i in range(m):
                    U[row, col, i] = u[i]
            else:
                run[row] = 0
                for i in range(m):
                    U[row, col, i] = math.nan
        for col in range(n_regular, n_cols):
            if from_start:
                j = col - n_regular
                status[row, col] = NO_CONVERGENCE
                det_out[row, col] = 0.0
                usable = True
                for i in range(m):
                    u[i] = start_u[row, j, i]
                    U[row, col, i] = math.nan
                    usable = usable and math.isfinite(u[i])
                if not usable:
                    continue
                size = _size(K, row, col, unk, src)
                ok, det, ratio = _newton(K, row, col, u, eq0, dim, sgn, unk, scl, src,
                                         angle, size, F, J, dx)
                if ok:
                    _settle(status, det_out, U, u, row, col, det, ratio, singular_sin,
                            start_sign[row, j])
                continue
            s = extra_start[row, col - n_regular]
            near = -1
            for d in range(n_regular):
                if s - d >= 0 and status[row, s - d] == OK:
                    near = s - d
                    break
                if s + d < n_regular and status[row, s + d] == OK:
                    near = s + d
                    break
            status[row, col] = NO_CONVERGENCE
            det_out[row, col] = 0.0
            for i in range(m):
                U[row, col, i] = math.nan
            if near < 0:
                continue
            for i in range(m):
                u[i] = U[row, near, i]
            size = _size(K, row, col, unk, src)
            ok, det, ratio = _newton(K, row, col, u, eq0, dim, sgn, unk, scl, src, angle,
                                     size, F, J, dx)
            if ok:
                _settle(status, det_out, U, u, row, col, det, ratio, singular_sin,
                        1.0 if det_out[row, near] > 0 else -1.0)


@njit(cache=True, nogil=True, inline="always")
def _settle(status, det_out, U, u, row, col, det, ratio, singular_sin, sign
            ):  # pragma: no cover - compiled
    """Record a converged Newton solve ``u`` at ``[row, col]``: a dead point when the
    Jacobian's scale-free ratio is not above ``singular_sin``, a jump when ``det``'s sign
    is not ``sign`` (0: either sign will do), else the solution and ``det``."""
    if not ratio > singular_sin:
        status[row, col] = DEAD
    elif sign != 0 and (det > 0) != (sign > 0):
        status[row, col] = JUMP
    else:
        status[row, col] = OK
        det_out[row, col] = det
        for i in range(u.shape[0]):
            U[row, col, i] = u[i]


@njit(cache=True, nogil=True)
def _signed_ratios(eq, ru, au, r, a, rs, as_, m, out):  # pragma: no cover - compiled
    """``sign(det J)·|det J| / Π ‖column‖`` of the block Jacobian at every element ``n``
    of the term values ``r[t, n]``, ``a[t, n]`` (scales ``rs``, ``as_`` likewise), into
    ``out[n]`` (NaN where a value is not finite)."""
    J = np.empty((m, m))
    F = np.zeros(m)
    dx = np.empty(m)
    for n in range(out.shape[0]):
        for i in range(m):
            F[i] = 0.0
            for j in range(m):
                J[i, j] = 0.0
        finite = True
        for t in range(eq.shape[0]):
            c = math.cos(a[t, n])
            s = math.sin(a[t, n])
            e = 2 * eq[t]
            if ru[t] >= 0:
                J[e, ru[t]] += rs[t, n] * c
                J[e + 1, ru[t]] += rs[t, n] * s
            if au[t] >= 0:
                J[e, au[t]] -= as_[t, n] * r[t, n] * s
                J[e + 1, au[t]] += as_[t, n] * r[t, n] * c
            finite = finite and math.isfinite(r[t, n]) and math.isfinite(a[t, n])
        if not finite:
            out[n] = math.nan
            continue
        det, ratio = _step(J, F, dx)
        out[n] = ratio if det > 0 else -ratio


def block_signed_ratio(plan: Plan, r: list[Array], a: list[Array], r_scale: list,
                       a_scale: list, shape: tuple[int, ...]) -> Array:
    """``sign(det J)·|det J| / Π ‖column‖`` of the block Jacobian, ``shape`` (NaN where a
    value is): :func:`block_hadamard` with the determinant's sign, compiled."""
    size = int(np.prod(shape, dtype=np.int64))

    def stack(values: list) -> Array:
        return np.ascontiguousarray(np.stack([np.broadcast_to(np.asarray(v, dtype=float),
                                                              shape).reshape(size)
                                              for v in values]))

    out = np.empty(size)
    _signed_ratios(plan.eq, plan.r_unknown, plan.a_unknown, stack(r), stack(a),
                   stack(r_scale), stack(a_scale), len(plan.unknowns), out)
    return out.reshape(shape)


@functools.lru_cache(maxsize=8)
def start_points(m: int) -> Array:
    """The fixed starts of the first assembly, ``(STARTS, m)`` fractions in [0, 1): a
    scrambled Halton sequence with a fixed seed (reproducible), the middle of the box
    first."""
    from scipy.stats import qmc

    points = qmc.Halton(d=m, scramble=True, seed=20261124).random(STARTS - 1)
    return np.vstack([np.full((1, m), 0.5), points])


@dataclass
class Carry:
    """The continuation state of one block between two calls (the overlap position of
    :func:`mechloop.solve.solve`'s blocks of positions): per row the last two good
    solutions, the good run before, the branch's determinant sign, whether an assembly
    was found, and the solution, status and determinant at the last column."""

    last: Array
    prev: Array
    run: NDArray[np.int64]
    sign: NDArray[np.int64]
    found: NDArray[np.bool_]
    u_end: Array
    status_end: NDArray[np.int8]
    det_end: Array


class TermPlan(Protocol):
    """What :func:`continue_block` reads of a block's plan: a planar :class:`Plan` or a
    :class:`mechloop.spatial.block.Plan`."""

    unknowns: tuple[str, ...]
    angle: NDArray[np.bool_]

    @property
    def terms(self) -> Terms: ...


def continue_block(plan: TermPlan, known: Array, *, want: int, guess: dict[int, float],
                   singular_sin: float, carry: Carry | None = None,
                   n_regular: int | None = None,
                   extra_start: NDArray[np.int64] | None = None,
                   extra_from: tuple[Array, Array] | None = None,
                   track: bool = False
                   ) -> tuple[Array, NDArray[np.int8], Array, Carry]:
    """Solve the block at every row and column of the known stack.

    ``known`` : shape ``(n_known, R, C)`` — every known column (values, link offsets and
    scales) per row (design) and column (position).  ``want`` the determinant sign of the
    first assembly (−1: variant 1, +1: variant 2, 0: any); ``guess`` approximate values
    (SI) of some unknowns by index.  ``carry`` continues an earlier call whose last
    column is this call's column 0.  Columns from ``n_regular`` on are arbitrary inputs,
    each solved from the regular column ``extra_start[row, j]`` (or the nearest good one)
    — or, with ``extra_from = (start, sign)`` (``(R, C − n_regular, m)`` and
    ``(R, C − n_regular)``), each from its own start, kept only on the branch of the
    determinant sign given (the existence check's zoom between positions; a NaN start is
    not solved and counts as :data:`NO_CONVERGENCE`; a sign 0 accepts either).
    ``track``: ``variant: auto`` — the assembly is followed by continuity, its
    determinant's sign changing where the solution passes the jump test (see
    :func:`_continue`).

    Returns the unknowns ``(R, C, m)`` (NaN where not OK), the status ``(R, C)``
    (:data:`OK`, :data:`NO_CONVERGENCE`, :data:`DEAD`, :data:`JUMP`), the determinant
    ``(R, C)`` (0 where not OK) and the carry for a next call.
    """
    _, n_rows, n_cols = known.shape
    m = len(plan.unknowns)
    n_regular = n_cols if n_regular is None else n_regular
    extra = (np.zeros((n_rows, 0), dtype=np.int64) if extra_start is None
             else np.ascontiguousarray(extra_start, dtype=np.int64))
    U = np.empty((n_rows, n_cols, m))
    status = np.empty((n_rows, n_cols), dtype=np.int8)
    det = np.empty((n_rows, n_cols))
    first = 0
    if carry is None:
        carry = Carry(np.zeros((n_rows, m)), np.zeros((n_rows, m)),
                      np.zeros(n_rows, dtype=np.int64), np.zeros(n_rows, dtype=np.int64),
                      np.zeros(n_rows, dtype=bool), np.empty((n_rows, m)),
                      np.empty(n_rows, dtype=np.int8), np.empty(n_rows))
    else:
        carry = Carry(*(np.array(a, copy=True) for a in (
            carry.last, carry.prev, carry.run, carry.sign, carry.found, carry.u_end,
            carry.status_end, carry.det_end)))
        U[:, 0], status[:, 0], det[:, 0] = carry.u_end, carry.status_end, carry.det_end
        first = 1
    n_extra = n_cols - n_regular
    if extra_from is None:
        start_u, start_sign = np.zeros((n_rows, n_extra, m)), np.zeros((n_rows, n_extra))
    else:
        start_u = np.ascontiguousarray(extra_from[0], dtype=float).reshape(n_rows, n_extra, m)
        start_sign = np.ascontiguousarray(extra_from[1], dtype=float).reshape(n_rows, n_extra)
    guessed = np.zeros(m, dtype=bool)
    values = np.zeros(m)
    for i, v in guess.items():
        guessed[i], values[i] = True, v
    terms = plan.terms
    _continue(np.ascontiguousarray(known), terms.row, terms.dim, terms.sign, terms.unknown,
              terms.scale, terms.col, plan.angle, first,
              n_regular, extra, start_points(m), int(want), guessed, values,
              float(singular_sin), carry.last, carry.prev, carry.run, carry.sign,
              carry.found, U, status, det, extra_from is not None, start_u, start_sign,
              bool(track))
    end = n_regular - 1
    carry.u_end, carry.status_end, carry.det_end = (U[:, end].copy(), status[:, end].copy(),
                                                    det[:, end].copy())
    return U, status, det, carry


def block_jacobian(plan: Plan, r: list[Array], a: list[Array], r_scale: list[Array],
                   a_scale: list[Array], shape: tuple[int, ...]) -> Array:
    """The block Jacobian ``(*shape, m, m)`` at the values ``r[t]``, ``a[t]`` of its terms
    (columns: ``scale·e`` for a length unknown, ``scale·r·n`` for an angle unknown)."""
    return _assembled(plan, r, [(np.cos(at), np.sin(at)) for at in a], r_scale, a_scale,
                      shape)


def _assembled(plan: Plan, r: list[Array], cs: list[tuple[Array, Array]],
               r_scale: list[Array], a_scale: list[Array], shape: tuple[int, ...]) -> Array:
    """The block Jacobian ``(*shape, m, m)`` from the cosines and sines ``cs`` of the terms'
    angles."""
    m = len(plan.unknowns)
    J = np.zeros((*shape, m, m))
    for t, (c, s) in enumerate(cs):
        e = 2 * int(plan.eq[t])
        ru, au = int(plan.r_unknown[t]), int(plan.a_unknown[t])
        if ru >= 0:
            J[..., e, ru] += r_scale[t] * c
            J[..., e + 1, ru] += r_scale[t] * s
        if au >= 0:
            J[..., e, au] -= a_scale[t] * r[t] * s
            J[..., e + 1, au] += a_scale[t] * r[t] * c
    return J


def block_hadamard(plan: Plan, r: list[Array], a: list[Array], r_scale: list[Array],
                   a_scale: list[Array], shape: tuple[int, ...]) -> Array:
    """``|det J| / Π ‖column‖`` of the block Jacobian, ``shape`` (NaN where a value is):
    the dead-point measure of :func:`continue_block`."""
    J = block_jacobian(plan, r, a, r_scale, a_scale, shape)
    finite = np.isfinite(J).all(axis=(-2, -1))
    J[~finite] = np.eye(len(plan.unknowns))
    ratio = np.abs(np.linalg.det(J)) / np.prod(np.linalg.norm(J, axis=-2), axis=-1)
    return np.where(finite, ratio, np.nan)


def block_rates(plan: Plan, r: list[Array], a: list[Array], r_rate: list[Array],
                a_rate: list[Array], r_accel: list[Array] | None,
                a_accel: list[Array] | None, r_scale: list[Array], a_scale: list[Array],
                good: NDArray[np.bool_]) -> tuple[Array, Array | None]:
    """Rates and accelerations of the block's unknowns, ``(..., m)`` each (NaN where not
    ``good``), from the block Jacobian: DESIGN §3's linear systems, ``2k × 2k``.

    Per term ``t`` (one per vector): ``r[t]``, ``a[t]`` the values; ``r_rate[t]``,
    ``a_rate[t]`` the *known* rates (the part not carried by an unknown: zero for a
    parameter linked to an unknown) and likewise the known accelerations;
    ``r_scale[t]``, ``a_scale[t]`` the scale of the unknown a parameter is linked to
    (unused for known ones).  With ``r_accel`` None only the rates are solved.
    """
    m = len(plan.unknowns)
    shape = good.shape
    cs = [(np.cos(at), np.sin(at)) for at in a]
    J = _assembled(plan, r, cs, r_scale, a_scale, shape)
    b = np.zeros((*shape, m))
    for t, (c, s) in enumerate(cs):
        e = 2 * int(plan.eq[t])
        w = r[t] * a_rate[t]
        b[..., e] += r_rate[t] * c - w * s
        b[..., e + 1] += r_rate[t] * s + w * c
    J[~good] = np.eye(m)
    b[~good] = 0.0
    inverse = np.linalg.inv(J)  # one factorization for both right-hand sides
    rate = -(inverse @ b[..., None])[..., 0]
    rate[~good] = np.nan
    if r_accel is None:
        return rate, None
    b = np.zeros((*shape, m))
    for t, (c, s) in enumerate(cs):
        e = 2 * int(plan.eq[t])
        ru, au = int(plan.r_unknown[t]), int(plan.a_unknown[t])
        dr = r_rate[t] + (r_scale[t] * rate[..., ru] if ru >= 0 else 0.0)
        da = a_rate[t] + (a_scale[t] * rate[..., au] if au >= 0 else 0.0)
        radial = r_accel[t] - r[t] * da * da
        tangential = 2.0 * dr * da + r[t] * a_accel[t]
        b[..., e] += radial * c - tangential * s
        b[..., e + 1] += radial * s + tangential * c
    b[~good] = 0.0
    accel = -(inverse @ b[..., None])[..., 0]
    accel[~good] = np.nan
    return rate, accel
