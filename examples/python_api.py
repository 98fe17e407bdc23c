"""The Python API of mechloop: load or build a model, solve it, read the results.

Run from the repository root:  python examples/python_api.py
"""

from pathlib import Path

import mechloop

HERE = Path(__file__).parent

# 1. a model file
model = mechloop.load_model(HERE / "crank_slider.yaml")
results = mechloop.solve(model)
frame = results.to_frame()  # pandas DataFrame: one row per position
print(frame[["position", "a1 [deg]", "r3 [m]", "dr3 [m/s]", "ddr3 [m/s^2]"]].head())

# 2. the same mechanism built in code (numbers in the model's units: m and deg)
built = mechloop.Model.from_dict({
    "positions": 72,
    "time": {"rpm": 3000},
    "arguments": {1: {"table": {0: 0, 72: 360}}},
    "vectors": {
        1: {"r": 0.05, "a": {"argument": 1}},
        2: {"r": 0.2, "a": "function"},
        3: {"r": "function", "a": 180},
        4: {"r": 0.01, "a": 90},
    },
    "contours": [{"vectors": [1, 2, 3, 4]}],
})
again = mechloop.solve(built)
r3 = again.value("r3")  # m, shape (73,)
print(f"stroke {1000 * (r3.max() - r3.min()):.3f} mm, "
      f"peak piston speed {abs(again.rate('r3')).max():.2f} m/s")

# 3. a mistake is reported with its place and the fix
try:
    mechloop.Model.from_dict({**built.model_dump(), "positions": 0})
except mechloop.ModelError as exc:
    print("error:", exc)

# 4. an impossible geometry is a chain break, not a crash
short_rod = built.model_copy(update={"vectors": {**built.vectors,
                                                 2: mechloop.Vector(r=0.03, a="function")}})
for brk in mechloop.solve(short_rod).breaks:
    print(brk.describe())
