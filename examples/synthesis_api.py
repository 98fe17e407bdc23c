"""Synthesis from Python: evaluate a population of designs in one call, run the search,
read every term of the result and write the best design.  Files go to ./synthesis_out/.

Run from the repository root:  python examples/synthesis_api.py
"""

from pathlib import Path

import numpy as np

import mechloop
from mechloop.synthesis.output import write_model, write_table
from mechloop.synthesis.problem import SynthesisProblem
from mechloop.synthesis.search import synthesize
from mechloop.views.figure import save_figure
from mechloop.views.synthesis import plot_convergence, plot_fit

HERE = Path(__file__).parent
OUT = Path("synthesis_out")
OUT.mkdir(exist_ok=True)

model = mechloop.load_model(HERE / "four_bar_path_synthesis.yaml")

# 1000 random designs inside the bounds, solved and scored together (designs x positions)
problem = SynthesisProblem(model)
rng = np.random.default_rng(0)
designs = problem.variables.scale(rng.uniform(size=(1000, len(problem.variables))))
population = problem.evaluate(designs)
print(f"{population.feasible.sum()} of 1000 random designs assemble over the whole turn; "
      f"the best has Q = {np.nanmin(population.q):.3g} mm")

# the search (a short one here; the file's own settings reach Q of about 0.001 mm)
result = synthesize(model, method="cmaes", seed=1, iterations=60,
                    progress=lambda p: None)
print(f"Q = {result.q:.4g} mm after {result.evaluations} designs ({result.stopped})")
for name, value in result.values().items():
    print(f"  {name} = {value:.3f}")
for term, value in result.terms().items():
    print(f"  {term}: {value:.4g}")

write_model(result, OUT / "best.yaml")
write_table(result, OUT / "best.csv")
save_figure(plot_convergence(result), OUT / "convergence.png")
save_figure(plot_fit(result), OUT / "fit.png")
print("wrote", ", ".join(sorted(p.name for p in OUT.iterdir())))
