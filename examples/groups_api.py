"""Mechanisms built from Assur groups in Python: describe a crank and its dyads, let
mechloop write the vector model, solve it, and read named points and dimensions.

Run from anywhere:  python examples/groups_api.py
"""

from pathlib import Path

import numpy as np

import mechloop
from mechloop.model.groups import build, point_vectors
from mechloop.structure import analyze

HERE = Path(__file__).parent

# 1. a group-built model file loads like any model (the vector model is generated)
model = mechloop.load_model(HERE / "four_bar_groups.yaml")
print(f"{model.name}: {len(model.vectors)} vectors, contours "
      f"{[c.vectors for c in model.contours]}")

# 2. the same kind of mechanism in code: a crank-rocker with a coupler point, then an RRP
#    dyad driven from the rocker (numbers in the model's units: m and deg)
mech = mechloop.GroupMechanism.model_validate({
    "positions": 36,
    "time": {"rpm": 60},
    "arguments": {1: {"table": {0: 0, 36: 360}}},
    "ground": {"O": [0, 0], "C": [0.3, 0], "G": [0.3, -0.22]},
    "input": {"kind": "crank", "pivot": "O", "joint": "A", "length": 0.08},
    "groups": [
        {"kind": "L1", "links": ["coupler", "rocker"], "at": ["A", "C"], "joint": "B",
         "lengths": [0.32, 0.22]},
        {"kind": "L2", "links": ["rod", "ram"], "at": "D", "joint": "E", "length": 0.3,
         "guide": {"through": "G", "angle": 0}},
    ],
    "points": {"D": {"link": "rocker", "from": "C", "distance": 0.2, "angle": 135},
               "P": {"link": "coupler", "from": "A", "distance": 0.15, "angle": 20}},
    "masses": {"ram": {"mass": 5.0, "center": "E"}},
})
built = build(mech)                      # the model, body numbers, points, carriers
model = mechloop.build_model(mech)       # just the model
results = mechloop.solve(model)
print("structure formula:", analyze(model)[1].formula, "(expected", mech.formula + ")")
print("bodies:", built.links)

# 3. named points: where they are in the vector model, and their path
location = point_vectors(mech, model, "E")
x, y = location.xy(results)              # m, one value per position
print(f"ram E: chain {location.vectors} from {location.start}; stroke "
      f"{1000 * np.ptp(x):.1f} mm, y stays {y.min():.3f} m")
px, py = built.points["P"].xy(results)
print(f"coupler point P spans {1000 * np.ptp(px):.1f} x {1000 * np.ptp(py):.1f} mm")

# 4. the dimensions synthesis can vary, and the vector parameters that carry them
for dimension, carriers in built.dimensions.items():
    print(f"  {dimension:24s} -> {', '.join(map(str, carriers))}")

# 5. a few columns of the solution (the ram's slide vector is the dyad's length unknown)
ram = next(n for n, v in model.vectors.items() if v.name == "ram E along guide")
frame = results.to_frame()
print(frame[["position", "a1 [deg]", f"r{ram} [m]", f"dr{ram} [m/s]"]].head())
