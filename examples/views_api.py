"""Views from Python: a position plan, trajectories, parameter plots, a hodograph, an
animation and the course-project report (PDF and an editable DOCX, its title page from the
model's report: section and from Python).  Files go to ./views_out/.

Run from the repository root:  python examples/views_api.py
"""

from pathlib import Path

import mechloop
from mechloop.report.write import write_report
from mechloop.views import curves, dynamics, plan
from mechloop.views.animation import animate
from mechloop.views.display import Display
from mechloop.views.figure import save_figure

HERE = Path(__file__).parent
OUT = Path("views_out")
OUT.mkdir(exist_ok=True)

four_bar = mechloop.solve(mechloop.load_model(HERE / "four_bar.yaml"))
save_figure(plan.plot_plan(four_bar, 12), OUT / "plan.png")              # one position
save_figure(plan.plot_overlay(four_bar), OUT / "photo.png")              # all positions
save_figure(plan.plot_trajectories(four_bar, [{"head": 6}]), OUT / "coupler.svg")
save_figure(curves.plot_angle_between(four_bar, 2, 3), OUT / "transmission.png")
animate(four_bar, OUT / "cycle.gif")                   # a frame a position, a seamless loop

model = mechloop.load_model(HERE / "crank_slider_dynamics.yaml")
dyn = mechloop.solve_dynamics(model)
mm = Display(length="mm", force="kN")
save_figure(curves.plot_parameters(dyn, ["r3", "dr3"], against="arg1", display=mm),
            OUT / "piston.png")
save_figure(curves.plot_increment(dyn, "r3", 0), OUT / "increment.png")
save_figure(dynamics.plot_hodograph(dyn, "A", display=mm), OUT / "hodograph_A.pdf")
save_figure(dynamics.plot_reduced(dyn), OUT / "reduced.png")
write_report(model, OUT / "report_ru.pdf", lang="ru", position=12)     # scheme at 12
write_report(model, OUT / "report_en.docx", lang="en",                  # editable Word
             title={"student": "J. Smith", "group": "MT-21"})   # over the report: section
print(f"wrote {len(list(OUT.iterdir()))} files to {OUT}/")
