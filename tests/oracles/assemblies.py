"""Assembly oracle: every assembly of a whole model, position by position, with SciPy.

The fast solver orders contours into blocks and continues Newton's method along
positions (:mod:`mechloop.modules.coupled`).  This oracle knows nothing of blocks, order,
modules or continuation: at each position it writes the closure equations of *all*
contours at once,

    ``Σ_{i ∈ contour j} r_i (cos α_i, sin α_i) = 0``   for every contour ``j``,

in *all* function parameters of the model, and solves them with
:func:`scipy.optimize.least_squares` (MINPACK's Levenberg–Marquardt, the Jacobian
differenced by SciPy) from many starts (angles over the turn, lengths
over the model's size), keeping every distinct root that closes the loops to round-off:
the assemblies of the mechanism at that position.  Derivatives by the oracle are central
finite differences of a root followed to neighbouring inputs (Richardson-extrapolated).
From mechloop it uses only the model data classes, the unit conversion and the argument
values (through :mod:`oracles.newton`'s bookkeeping helpers).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import least_squares

from mechloop.model.schema import ArgumentRole, LinkRole, Model
from oracles.newton import _is_function, _role, _si, known_inputs


def unknowns(model: Model) -> list[str]:
    """Every function parameter of the model, in vector order."""
    return [f"{letter}{n}" for n in sorted(model.vectors) for letter in "ra"
            if _is_function(_role(model, f"{letter}{n}"))]


class Equations:
    """The model's closure equations at one value of argument 1 (the others as at the
    position nearest)."""

    def __init__(self, model: Model):
        self.model = model
        self.names = unknowns(model)
        self.base = known_inputs(model)
        self.driven = {}
        for number, vector in model.vectors.items():
            for letter in "ra":
                role = vector.r if letter == "r" else vector.a
                if isinstance(role, ArgumentRole):
                    self.driven[f"{letter}{number}"] = (role.argument,
                                                        _si(model, f"{letter}{number}",
                                                            role.offset))
        self.size = sum(abs(v) for k, v in self.base.items()
                        if k[0] == "r" and np.ndim(v) == 0) or 1.0

    def parameter(self, name: str, u: np.ndarray, k: int, shift: float) -> float:
        """Value of ``name`` at position ``k`` with argument 1 moved by ``shift``."""
        delta = 0.0
        while True:
            if name in self.names:
                return u[self.names.index(name)] + delta
            if name in self.base:
                value = self.base[name]
                value = float(value if np.ndim(value) == 0 else value[k])
                if name in self.driven and self.driven[name][0] == 1:
                    value += shift
                return value + delta
            role = _role(self.model, name)
            assert isinstance(role, LinkRole), name
            delta += _si(self.model, name, role.delta)
            name = role.link

    def residual(self, u: np.ndarray, k: int, shift: float = 0.0) -> np.ndarray:
        out = []
        for contour in self.model.contours:
            x = y = 0.0
            for n in contour.vectors:
                r = self.parameter(f"r{n}", u, k, shift)
                a = self.parameter(f"a{n}", u, k, shift)
                x += r * math.cos(a)
                y += r * math.sin(a)
            out += [x, y]
        return np.array(out)

    def solve_from(self, start: np.ndarray, k: int, shift: float = 0.0
                   ) -> np.ndarray | None:
        """A root from ``start``, or None when the loops do not close to round-off."""
        fit = least_squares(self.residual, start, args=(k, shift), method="lm",
                            xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=2000)
        if not np.all(np.abs(fit.fun) <= 1e-10 * self.size):
            return None
        root = fit.x
        for _ in range(2):  # polish: Newton steps with a differenced Jacobian
            jac = self.jacobian(root, k, shift)
            if not np.isfinite(jac).all() or np.linalg.cond(jac) > 1e12:
                break
            root = root - np.linalg.solve(jac, self.residual(root, k, shift))
        return root

    def jacobian(self, u: np.ndarray, k: int, shift: float = 0.0) -> np.ndarray:
        """∂F/∂u by central differences (step 1e-7)."""
        h = 1e-7
        cols = []
        for i in range(len(u)):
            e = np.zeros(len(u))
            e[i] = h
            cols.append((self.residual(u + e, k, shift) - self.residual(u - e, k, shift))
                        / (2 * h))
        return np.array(cols).T

    def wrap(self, u: np.ndarray) -> np.ndarray:
        out = np.array(u, dtype=float)
        for i, name in enumerate(self.names):
            if name[0] == "a":
                out[i] = (out[i] + math.pi) % (2 * math.pi) - math.pi
        return out

    def assemblies(self, k: int, *, starts: int = 60, seed: int = 1) -> list[np.ndarray]:
        """Every distinct root found at position ``k`` (angles wrapped to [−π, π))."""
        rng = np.random.default_rng(seed)
        found: list[np.ndarray] = []
        for _ in range(starts):
            start = np.array([rng.uniform(-math.pi, math.pi) if n[0] == "a"
                              else rng.uniform(0, 2 * self.size) for n in self.names])
            root = self.solve_from(start, k)
            if root is None:
                continue
            root = self.wrap(root)
            if not any(self.distance(root, other) < 1e-7 for other in found):
                found.append(root)
        return found

    def distance(self, u: np.ndarray, v: np.ndarray) -> float:
        d = np.asarray(u, dtype=float) - np.asarray(v, dtype=float)
        for i, name in enumerate(self.names):
            if name[0] == "a":
                d[i] = (d[i] + math.pi) % (2 * math.pi) - math.pi
            else:
                d[i] /= self.size
        return float(np.max(np.abs(d)))

    def jacobian_sign(self, u: np.ndarray, k: int) -> float:
        """Sign of det(∂F/∂u) (differenced)."""
        return float(np.sign(np.linalg.det(self.jacobian(u, k))))

    def rates(self, u: np.ndarray, k: int
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None:
        """First and second derivatives of the root ``u`` at position ``k`` by argument 1,
        with an estimate of their error: central differences of the root followed to
        ``x ± h`` and ``x ± h/2``, combined by Richardson's extrapolation (error O(h⁴)),
        the error estimated as the extrapolation's change; of the steps ``h`` tried (2e-3
        down to 2e-5, smaller near a limit position) the one with the least estimate.
        None when the branch does not reach ``x ± h`` for any of them."""
        def central(step: float) -> tuple[np.ndarray, np.ndarray] | None:
            plus = self.solve_from(u, k, step)
            minus = self.solve_from(u, k, -step)
            if plus is None or minus is None or max(self.distance(plus, u),
                                                    self.distance(minus, u)) > 0.1:
                return None
            return (plus - minus) / (2 * step), (plus - 2 * u + minus) / (step * step)

        best = None
        for h in (2e-3, 2e-4, 2e-5):
            wide, narrow = central(h), central(h / 2)
            if wide is None or narrow is None:
                continue
            d1, d2 = (4 * narrow[0] - wide[0]) / 3, (4 * narrow[1] - wide[1]) / 3
            e1, e2 = np.abs(d1 - narrow[0]), np.abs(d2 - narrow[1])
            if best is None or e1.max() < best[2].max():
                best = (d1, d2, e1, e2)
        return best
