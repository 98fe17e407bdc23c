"""mechloop plot of a spatial model's dynamics (issue 17): the reduced characteristics, the
balancing load and the summary draw the values of the spatial dynamics by virtual power in
the display units; the reactions and hodographs of a model with joints."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from matplotlib.lines import Line2D

from mechloop.model.load import load_model
from mechloop.spatial.dynamics import solve_spatial_dynamics
from mechloop.views.display import Display
from mechloop.views.figure import ViewError
from mechloop.views.spatial_dynamics import plot_spatial_dynamics

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "spatial"


@pytest.fixture(scope="module")
def dyn():
    return solve_spatial_dynamics(load_model(EXAMPLES / "rssr_dynamics.yaml"))


def _lines(figure) -> dict[str, np.ndarray]:
    """Every drawn curve's y data by its legend label's name (before ' [')."""
    out = {}
    for ax in figure.axes:
        for line in ax.get_lines():
            if isinstance(line, Line2D) and not line.get_label().startswith("_"):
                out[line.get_label().split(" [")[0]] = np.asarray(line.get_ydata(), float)
    return out


def test_reduced_plot_draws_the_reduced_characteristics_in_display_units(dyn):
    display = Display(inertia="kg*cm^2", moment="N*mm")
    lines = _lines(plot_spatial_dynamics(dyn, "reduced", display=display))
    j, dj, m = dyn.reduced
    np.testing.assert_allclose(lines["J_red"], j * 1e4, rtol=1e-12)
    np.testing.assert_allclose(lines["dJ_red"], dj * 1e4, rtol=1e-12)
    np.testing.assert_allclose(lines["M_red"], m * 1e3, rtol=1e-12)


def test_balancing_plot_draws_the_balancing_moment_against_the_argument(dyn):
    display = Display(moment="N*mm")
    figure = plot_spatial_dynamics(dyn, "balancing", against="arg1", display=display)
    (line,) = [ln for ln in figure.axes[0].get_lines() if not ln.get_label().startswith("_")]
    np.testing.assert_allclose(line.get_ydata(), dyn.balancing[1] * 1e3, rtol=1e-12)
    np.testing.assert_allclose(line.get_xdata(), np.degrees(dyn.kinematics.arguments[1]),
                               rtol=1e-12)


def test_summary_draws_the_kinetic_energy_and_works_that_balance_it(dyn):
    figure = plot_spatial_dynamics(dyn, "summary", display=Display(energy="mJ"))
    np.testing.assert_allclose(_lines(figure)["T"], dyn.kinetic_energy * 1e3, rtol=1e-12)
    table = figure.axes[0].tables[0]
    cells = {(r, c): t.get_text().get_text() for (r, c), t in table.get_celld().items()}
    names = [cells[r, 0] for r in range(1, 1 + len(dyn.powers))]
    assert names == list(dyn.powers)
    # over a closed cycle the works of all loads sum to T(end) - T(0) = 0 (mJ, 4 digits)
    total = sum(float(cells[r, 3]) for r in range(1, 1 + len(dyn.powers)))
    assert abs(total) < 1e-3


def test_the_machine_motion_is_refused(dyn):
    with pytest.raises(ViewError, match="not drawn for a model with spatial contours"):
        plot_spatial_dynamics(dyn, "motion")


@pytest.mark.parametrize("kind", ["reactions", "hodograph"])
def test_reactions_need_the_models_joints(dyn, kind):
    with pytest.raises(ViewError, match="no joint reactions"):
        plot_spatial_dynamics(dyn, kind, joint="A")


def test_cli_plots_a_spatial_models_reduced_characteristics(tmp_path):
    from typer.testing import CliRunner

    from mechloop.cli import app

    out = tmp_path / "r.png"
    run = CliRunner().invoke(app, ["plot", str(EXAMPLES / "rssr_dynamics.yaml"), "reduced",
                                   "-o", str(out), "--lang", "ru"])
    assert run.exit_code == 0, run.output
    assert out.stat().st_size > 1000
    run = CliRunner().invoke(app, ["plot", str(EXAMPLES / "rssr_dynamics.yaml"),
                                   "reactions", "-o", str(out), "--force"])
    assert run.exit_code == 2 and "joints:" in run.output and "mechloop.solve" not in \
        run.output


def test_reactions_and_hodographs_of_a_model_with_joints(tmp_path):
    """``plot reactions`` draws every joint's |R| as the solver gives it, ``plot hodograph
    --joint`` the force's tip over the positions; both through the command line."""
    from typer.testing import CliRunner

    from mechloop.cli import app

    path = EXAMPLES / "rssr_reactions.yaml"
    joints = solve_spatial_dynamics(load_model(path))
    figure = plot_spatial_dynamics(joints, "reactions")
    lines = _lines(figure)
    for name, joint in joints.reactions.joints.items():
        np.testing.assert_allclose(lines[f"|R{name}|"],
                                   np.linalg.norm(joint.force, axis=0), rtol=1e-12)
    hodograph = plot_spatial_dynamics(joints, "hodograph", joint="A", position=5)
    force = joints.reactions.joints["A"].force
    front = [line for line in hodograph.axes[0].get_lines() if np.size(line.get_xdata()) ==
             force.shape[1]]
    assert len(front) == 1  # the front view XY: the tip's x and y over the positions
    np.testing.assert_allclose(front[0].get_xdata(), force[0], rtol=1e-12)
    np.testing.assert_allclose(front[0].get_ydata(), force[1], rtol=1e-12)
    with pytest.raises(ViewError, match="needs a joint"):
        plot_spatial_dynamics(joints, "hodograph")
    for kind in ("reactions", "hodograph"):
        out = tmp_path / f"{kind}.png"
        run = CliRunner().invoke(app, ["plot", str(path), kind, "--joint", "A", "-o",
                                       str(out), "--lang", "ru"])
        assert run.exit_code == 0, run.output
        assert out.stat().st_size > 1000
