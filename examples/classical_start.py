"""A classical closed-form synthesis as the starting point of the optimization search.

The log10 function generator (examples/log10_function_generator.yaml): a four-bar whose
rocker turns by ψ − ψ0 = 60°·log10 x while the crank turns by φ − φ0 = 60°·(x − 1)/9,
1 ≤ x ≤ 10.  Freudenstein's equation with three Chebyshev precision points
(mechloop.synthesis.classical) gives a four-bar exact at three points; here it is mapped
onto the model's variables (crank r1, coupler r2, rocker r3, the crank's starting angle
a1; the frame r4 = 100 mm stays), scored by the model's own Q (the largest error of the
rocker's increment, degrees), and handed to the search as its starting design.

The classical method needs the start angles φ0, ψ0, which the example leaves free (a1 is
varied, the target compares increments).  The model's own design gives φ0 = 60° and its
rocker angle at position 0; if that pair gives no usable four-bar, the script says so and
scans φ0, ψ0 on a 2° grid instead (one vectorized call of the classical function, one
call of SynthesisProblem.evaluate), keeping only designs inside the bounds that assemble
on the model's branch (variant 1).  Bounds are never widened.

Run from the repository root:  python examples/classical_start.py
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np

import mechloop
from mechloop.synthesis.classical import freudenstein_three_point, function_generator_points
from mechloop.synthesis.problem import SynthesisProblem
from mechloop.synthesis.search import synthesize

HERE = Path(__file__).parent
DPHI = np.radians(60.0)  # argument 1 runs 0..60 deg over the positions
DPSI = np.radians(60.0)  # the target 60*log10(1 + 9t): the rocker turns +60 deg


def classical(phi0, psi0, frame: float, *, errors: str = "raise"):
    """Freudenstein's four-bar for log10 x on 1..10 at three Chebyshev points, for start
    angles ``phi0``, ``psi0`` (rad, any shape) and the frame length ``frame``."""
    phi, psi = function_generator_points(np.log10, 1.0, 10.0, phi0, DPHI, psi0, DPSI)
    return freudenstein_three_point(phi, psi, frame=frame, errors=errors)


def as_variables(fg, phi0) -> np.ndarray:
    """The model's variables (r1, r2, r3 in mm, a1 in deg), shape (..., 4): a signed
    crank length (crank_phase = π) is a crank turned by 180°."""
    a1 = np.mod(np.degrees(np.asarray(phi0) + fg.crank_phase), 360.0)
    return np.stack([fg.a, fg.b, fg.c, a1], axis=-1)


def on_model_branch(problem: SynthesisProblem, fg, designs_si: np.ndarray) -> np.ndarray:
    """True where the model (its variant) assembles the classical four-bar on the same
    branch as Freudenstein's solution: the side of B with respect to the line A -> O4
    (classical.py's ``branch``) at position 0, and no branch defect."""
    res = problem.solve(designs_si)
    v = res.values
    a = v["r1"][:, 0] * np.exp(1j * v["a1"][:, 0])
    b = a + v["r2"][:, 0] * np.exp(1j * v["a2"][:, 0])
    o4 = -v["r4"][:, 0] * np.exp(1j * v["a4"][:, 0])  # vector 4 runs O4 -> O
    side = np.sign(((o4 - a).conj() * (b - a)).imag)
    branch = np.asarray(fg.branch)
    return res.assembles & (side == branch[..., 0]) & np.all(branch == branch[..., :1],
                                                             axis=-1)


def main(iterations: int = 60, seed: int = 1) -> dict:
    model = mechloop.load_model(HERE / "log10_function_generator.yaml")
    problem = SynthesisProblem(model)
    variables = problem.variables
    frame = model.vectors[4].r  # mm, the model's ground length
    to_si = np.array([1e-3, 1e-3, 1e-3, np.pi / 180])

    # 1. the model's own start angles
    phi0 = np.radians(model.vectors[1].a.offset)
    psi0 = float(mechloop.solve(model).values["a3"][0]) - np.pi
    fg = classical(phi0, psi0, frame, errors="mask")
    x = as_variables(fg, phi0)
    inside = bool(np.all((x * to_si >= variables.low) & (x * to_si <= variables.high)))
    print(f"Freudenstein at the model's own start angles (phi0 = {np.degrees(phi0):.1f}, "
          f"psi0 = {np.degrees(psi0):.2f} deg): crank {fg.a:.1f}, coupler {fg.b:.1f}, "
          f"rocker {fg.c:.1f} mm" + ("" if inside else " -- outside the bounds")
          + (", precision points on different branches" if fg.branch_defect else ""))

    # 2. else scan the two free start angles (vectorized) and keep usable designs
    if not inside:
        grid = np.radians(np.arange(0.0, 360.0, 2.0))
        phi0, psi0 = (g.ravel() for g in np.meshgrid(grid, grid, indexing="ij"))
        family = classical(phi0, psi0, frame, errors="mask")
        x_all = as_variables(family, phi0)
        inside_all = family.ok & np.all((x_all * to_si >= variables.low)
                                        & (x_all * to_si <= variables.high), axis=-1)
        rows = np.flatnonzero(inside_all)
        designs = x_all[rows] * to_si
        branch = on_model_branch(problem, _take(family, rows), designs)
        q = np.where(branch, problem.evaluate(designs).q, np.nan)
        best = rows[int(np.nanargmin(q))]
        print(f"scan of phi0, psi0 on a 2 deg grid: {phi0.size} pairs, {family.ok.sum()} "
              f"real four-bars, {rows.size} inside the bounds, {branch.sum()} of them "
              "assemble on the model's branch")
        phi0, psi0 = phi0[best], psi0[best]
        fg = classical(phi0, psi0, frame)
        x = as_variables(fg, phi0)
    values = dict(zip(variables.names, map(float, x), strict=True))
    q_classical = float(problem.evaluate((x * to_si)[None, :]).q[0])
    print(f"classical design: phi0 = {np.degrees(phi0):.0f}, psi0 = {np.degrees(psi0):.0f} "
          "deg; " + ", ".join(f"{k} = {v:.3f}" for k, v in values.items()))
    print(f"  its structural error (the model's Q): {q_classical:.4f} deg")

    # 3. the same search from the classical design and from the model's own design
    out = {"phi0": float(phi0), "psi0": float(psi0), "frame": float(frame), "fg": fg,
           "values": values, "q_classical": q_classical}
    for label, start in (("with", values), ("without", None)):
        clock = time.perf_counter()
        result = synthesize(model, seed=seed, iterations=iterations, start=start)
        seconds = time.perf_counter() - clock
        out[f"q_{label}"] = result.q
        print(f"search {label} the classical start (de, seed {seed}, {iterations} "
              f"generations): Q = {result.q:.4f} deg, {result.evaluations} designs, "
              f"{seconds:.1f} s")
    return out


def _take(fg, rows: np.ndarray):
    """The classical designs ``rows`` of a flat family (the fields on_model_branch uses)."""
    from types import SimpleNamespace

    return SimpleNamespace(branch=np.asarray(fg.branch)[rows])


if __name__ == "__main__":
    main()
