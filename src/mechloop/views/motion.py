"""Views of a machine's motion in time (:class:`~mechloop.dynamics.simulate.Simulation`):
the input's angle, speed and acceleration over time, and the phase portrait ω(q); for a
machine with several inputs
(:class:`~mechloop.dynamics.simulate_inputs.InputsSimulation`) the same per input."""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.figure import Figure
from numpy.typing import NDArray

from mechloop.dynamics.motors import RPM
from mechloop.dynamics.simulate import Simulation
from mechloop.views.figure import ViewError, new_figure
from mechloop.views.russian import keep_names


def plot_simulation(sim: Simulation, *, title: str = "") -> Figure:
    """Four panels: the input's angle (turns), speed (rpm) and acceleration (rad/s²) over
    time, with the steady state and the motor's switch-off marked, and the phase portrait
    — the speed over the angle within the cycle, one line per cycle, darker as time goes
    on (lines with gid ``'q'``, ``'omega'``, ``'epsilon'``, ``'phase'``)."""
    from mechloop.dynamics.simulate_inputs import InputsSimulation

    if isinstance(sim, InputsSimulation):
        return _plot_inputs(sim, title=title)
    if not isinstance(sim, Simulation):
        raise ViewError(f"expected a Simulation, got {type(sim).__name__}",
                        "pass the result of mechloop.simulate(...)")
    figure, axes, t, panels = _panels(sim)
    for ax, values, gid, label in panels:
        ax.plot(t, values, color="C0", linewidth=1.0, gid=gid)
        ax.set_xlabel("time [s]")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
        for event in sim.events[1:]:
            if event.kind == "motor off":
                ax.axvline(event.t, color="C3", linestyle="--", linewidth=0.8,
                           label="motor off")
        if sim.steady_time is not None:
            ax.axvline(sim.steady_time, color="C2", linestyle=":", linewidth=1.0,
                       label=f"steady at {sim.steady_time:.4g} s")
    if sim.steady_time is not None or any(e.kind == "motor off" for e in sim.events):
        axes[0, 1].legend(loc="best", fontsize="small")
    _phase(axes[1, 1], sim)
    figure.suptitle(title or f"motion in time — ended: {sim.end.kind} at "
                             f"{sim.end.t:.4g} s")
    return keep_names(figure, [title])  # the title: the user's name of the model


def _panels(sim) -> tuple[Figure, Any, NDArray[np.float64], tuple]:
    """The 2×2 figure of a motion in time, its axes, the times and the three time panels
    (axes, values in turns, rpm and rad/s², gid, label); the fourth is the phase portrait."""
    figure = new_figure(10.0, 7.5)
    axes = figure.subplots(2, 2)
    panels = ((axes[0, 0], sim.q / (2 * np.pi), "q", "input angle [turns]"),
              (axes[0, 1], sim.omega / RPM, "omega", "speed n [rpm]"),
              (axes[1, 0], sim.epsilon, "epsilon", "acceleration ε [rad/s²]"))
    return figure, axes, sim.time, panels


def _phase(ax, sim: Simulation) -> None:
    """ω over the angle within the cycle (degrees), one line per cycle."""
    machine = sim.machine
    t = np.linspace(0.0, sim.end.t, max(2000, 50 * (sim.cycle_start.size + 1)))
    q, w = sim.state(t)
    if machine.periodic:
        turns, inside = machine.wrap(q)
        cuts = np.flatnonzero(np.diff(turns)) + 1
    else:
        inside, cuts = q, np.empty(0, dtype=int)
    pieces = np.split(np.arange(t.size), cuts)
    colors = np.linspace(0.25, 1.0, len(pieces))
    for piece, shade in zip(pieces, colors, strict=True):
        ax.plot(np.degrees(inside[piece]), w[piece] / RPM, color=(0.0, 0.2, 0.6, shade),
                linewidth=0.9, gid="phase")
    ax.set_xlabel("input angle within the cycle [deg]")
    ax.set_ylabel("speed n [rpm]")
    ax.set_title("phase portrait (later cycles darker)", fontsize="medium")
    ax.grid(True, alpha=0.3)


def _plot_inputs(sim, *, title: str = "") -> Figure:
    """Four panels: every input's angle (turns), speed (rpm) and acceleration (rad/s²)
    over time, one line per input (gid ``'q<k>'``, ``'omega<k>'``, ``'epsilon<k>'``,
    ``k`` its argument number), the motors' switch-offs marked, and each input's phase
    portrait ω(q) (gid ``'phase<k>'``)."""
    figure, axes, t, panels = _panels(sim)
    for ax, values, gid, label in panels:
        for i, k in enumerate(sim.inputs):
            ax.plot(t, values[i], color=f"C{i}", linewidth=1.0, gid=f"{gid}{k}",
                    label=f"input {k}")
        for event in sim.events[1:]:
            if event.kind == "motor off":
                ax.axvline(event.t, color="C3", linestyle="--", linewidth=0.8)
        ax.set_xlabel("time [s]")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes[0, 0].legend(loc="best", fontsize="small")
    phase = axes[1, 1]
    for i, k in enumerate(sim.inputs):
        phase.plot(np.degrees(sim.q[i]), sim.omega[i] / RPM, color=f"C{i}", linewidth=0.9,
                   gid=f"phase{k}", label=f"input {k}")
    phase.set_xlabel("input angle [deg]")
    phase.set_ylabel("speed n [rpm]")
    phase.set_title("phase portraits", fontsize="medium")
    phase.grid(True, alpha=0.3)
    end = sim.end
    figure.suptitle(title or f"motion in time, {len(sim.inputs)} inputs — ended: "
                             f"{end.kind} at {end.t:.4g} s")
    return keep_names(figure, [title])
