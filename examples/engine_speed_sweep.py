"""Parametric analysis from Python: the balancing moment of the single-cylinder engine
against its speed (KDAM seed 000, Fig. 2.5), and a grid of speed and rod length.

Run from the repository root:  python examples/engine_speed_sweep.py
(writes engine_speed_sweep.png and engine_speed_rod_grid.png to the working folder)
"""

from pathlib import Path

import mechloop
from mechloop.synthesis.sweep import sweep
from mechloop.views.figure import save_figure
from mechloop.views.sweep import plot_sweep

HERE = Path(__file__).parent


def main() -> None:
    engine = mechloop.load_model(HERE / "single_cylinder_engine.yaml")

    # one parameter: 7 speeds from 1000 to 4000 rpm; the peak, rms and swing of the moment
    # on the crankshaft, and the peak force in the crank pin (joint J1_2: crank - rod)
    table = sweep(engine, {"time.rpm": "1000:4000:7"},
                  ["M_bal:max", "M_bal:min", "M_bal:rms", "RJ1_2:absmax"])
    print(table.drop(columns="note").to_string(index=False))
    save_figure(plot_sweep(table, ["M_bal:max", "M_bal:min", "M_bal:rms"]),
                "engine_speed_sweep.png")

    # two parameters: every speed with every rod length (values may carry their unit);
    # scheduler="processes" or "tcp://host:8786" would spread the designs over a Dask
    # cluster — this small grid solves faster in this process
    grid = sweep(engine, {"time.rpm": [1500, 3000, 4500],
                          "vectors.2.r": ["120 mm", "140 mm", "160 mm"]},
                 ["M_bal:absmax", "J_red:mean"], scheduler="serial")
    print(grid.drop(columns="note").to_string(index=False))
    save_figure(plot_sweep(grid), "engine_speed_rod_grid.png")
    print("wrote engine_speed_sweep.png and engine_speed_rod_grid.png")


if __name__ == "__main__":
    main()
