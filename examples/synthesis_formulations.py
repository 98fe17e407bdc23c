"""The formulations of the literature's path problems, each scored on a known design.

The known design is the four-bar of examples/four_bar_path_synthesis.yaml (its targets
lie on this design's coupler curve).  Shown: both assembly circuits in one run, the crank
reaching the targets either way, periodic angle variables, a timed parametric curve, the
distance to the continuous curve, and the shape-only objective with the mechanism placed
on the targets.

Run from the repository root:  python examples/synthesis_formulations.py
"""

from pathlib import Path

import numpy as np

import mechloop
from mechloop.synthesis.problem import SynthesisProblem

HERE = Path(__file__).parent
KNOWN = {"r1": 100, "r2": 350, "r3": 250, "r4": 300, "a4": 180, "r6": 250, "a6": 30}


def task(name: str, **synthesis) -> dict:
    data = mechloop.load_model(HERE / name).model_dump(mode="json", exclude_defaults=True)
    data["synthesis"].pop("pressure_angle", None)
    data["synthesis"].update(synthesis)
    return data


def design(problem: SynthesisProblem, values: dict) -> np.ndarray:
    """A design in SI, one row, from values in the model's units (mm, deg)."""
    v = problem.variables
    return np.array([[values.get(n, 0.0) * (np.pi / 180 if v.kind(i) == "angle" else 1e-3)
                      for i, n in enumerate(v.names)]])


# 1. both circuits: the file's contour 1 on variant 2 cannot reach its targets; with
#    circuits: both every design is solved on each circuit and keeps the better
data = task("four_bar_path_synthesis.yaml")
data["contours"][0]["variant"] = 2
one = SynthesisProblem(mechloop.Model.from_dict(data))
data["synthesis"]["circuits"] = "both"
both = SynthesisProblem(mechloop.Model.from_dict(data))
x = design(both, KNOWN)
ev = both.evaluate(x)
print(f"circuits: given Q = {one.evaluate(x).q[0]:.4g} mm, both Q = {ev.q[0]:.3g} mm "
      f"on variant {ev.measures['variant1'][0]:.0f}; written with variant "
      f"{both.design_model(x[0]).contours[0].variant}")

# 2. crank direction: free timing, the six targets reached while the input decreases
data = task("six_points_free_timing_synthesis.yaml")
for direction in ("increasing", "decreasing", "either"):
    data["synthesis"]["path"]["direction"] = direction
    problem = SynthesisProblem(mechloop.Model.from_dict(data))
    row = problem.variables.scale(np.full((1, len(problem.variables)), 0.5))
    row[0, problem.variables.input_columns] = np.radians([300, 250, 200, 150, 100, 50])
    print(f"direction {direction}: order penalty of decreasing inputs "
          f"{problem.order_violation(row)[0]:.4g} rad")

# 3. periodic angles: a4 has no bound at 0/360 deg; the search's unit coordinate wraps
data = task("four_bar_path_synthesis.yaml", vary={**task(
    "four_bar_path_synthesis.yaml")["synthesis"]["vary"], "a4": "periodic"})
problem = SynthesisProblem(mechloop.Model.from_dict(data))
i4 = problem.variables.names.index("a4")
unit = np.full(len(problem.variables), 0.5)
unit[i4] = -0.25  # a quarter turn below the cut
print(f"periodic a4: unit -0.25 is {np.degrees(problem.variables.scale(unit)[i4]):.1f} deg;"
      f" Q of the known design at a4 and a4 + 360 deg: "
      f"{problem.evaluate(design(problem, KNOWN)).q[0]:.3g}, "
      f"{problem.evaluate(design(problem, {**KNOWN, 'a4': 540})).q[0]:.3g} mm")

# 4. a timed parametric curve: x(t), y(t) is the coupler point at the crank angle t (deg),
#    by circle intersection; target k is reached where argument 1 equals t_k
ax, ay = "(100*cos(radians(t)))", "(100*sin(radians(t)))"
dx, dy = f"(300 - {ax})", f"(-{ay})"
d2 = f"({dx}**2 + {dy}**2)"
along = f"((350**2 - 250**2 + {d2}) / (2*sqrt({d2})))"
h = f"sqrt(350**2 - {along}**2)"
phi = f"(arctan2({dy}*{along} + {dx}*{h}, {dx}*{along} - {dy}*{h}) + radians(30))"
curve = {"x": f"{ax} + 250*cos({phi})", "y": f"{ay} + 250*sin({phi})", "t": [10, 300],
         "count": 7}
data = task("four_bar_path_synthesis.yaml")
data["synthesis"]["path"].update(targets=curve, timing=True)
timed = SynthesisProblem(mechloop.Model.from_dict(data))
data["vectors"]["1"]["a"]["offset"] = 5
late = SynthesisProblem(mechloop.Model.from_dict(data))
print(f"timed curve: Q = {timed.evaluate(design(timed, KNOWN)).q[0]:.2g} mm; with the "
      f"crank 5 deg ahead Q = {late.evaluate(design(late, KNOWN)).q[0]:.4g} mm")

# 5. the continuous curve: the search measures the distance to the polyline through the
#    positions, the result the distance to the curve itself
problem = SynthesisProblem(mechloop.Model.from_dict(task("four_bar_path_synthesis.yaml")))
x = design(problem, KNOWN)
print(f"nearest point: polyline Q = {problem.evaluate(x).q[0]:.6g} mm, continuous curve "
      f"Q = {problem.evaluate(x, continuous=True).q[0]:.6g} mm")

# 6. shape only: the targets of examples/four_bar_shape_synthesis.yaml are this curve
#    turned, scaled and moved; the known design (its crank is the file's own) fits them
#    exactly once placed, on the circuit of variant 1 (the file says 2: circuits: both)
shape = SynthesisProblem(mechloop.load_model(HERE / "four_bar_shape_synthesis.yaml"))
x = design(shape, KNOWN)
a, b = shape.placement(x)
placed = shape.design_model(x[0])
print(f"shape only: Q = {shape.evaluate(x, continuous=True).q[0]:.2g} mm, placed by a "
      f"turn of {np.degrees(np.angle(a[0])):.2f} deg, a scale of {abs(a[0]):.4f} and a "
      f"shift of ({b[0].real * 1e3:.2f}, {b[0].imag * 1e3:.2f}) mm; the written crank is "
      f"{placed.vectors[1].r:.3f} mm, variant {placed.contours[0].variant}")
