"""The ``mechloop`` command: a thin shell over the public API.

Every error a user can cause prints the :class:`~mechloop.errors.MechloopError` message and
exits with code 2, without a traceback.

Start-up is kept short (``mechloop --help`` loads no NumPy, pandas, SciPy, pint or
matplotlib): the library is imported inside the commands that use it. Help texts are
Markdown: docstrings are written as paragraphs (re-flowed to the terminal's width), examples
as indented code lines.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Callable
from functools import wraps
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table
from rich.text import Text
from typer.core import TyperCommand, TyperGroup

from mechloop.errors import HintedError, MechloopError, ModelError, Problem
from mechloop.messages import error_label, message_language, render_error

if TYPE_CHECKING:
    from mechloop.dynamics.analysis import DynamicResults


class _NoFlagType:
    """Help without a ``<bool>`` type beside an on/off flag (``--polar``, ``--help``)."""

    def get_params(self, ctx: Any) -> list[Any]:
        params = super().get_params(ctx)  # type: ignore[misc]
        for param in params:
            if getattr(param, "is_flag", False):
                param.metavar = ""
        return params


class _Command(_NoFlagType, TyperCommand):
    pass


class _Group(_NoFlagType, TyperGroup):
    def main(self, *args: Any, **kwargs: Any) -> Any:
        """Run the command line, its usage errors in the language of the messages."""
        if message_language() == "ru":  # Typer's printer is imported only then
            from mechloop.messages.usage import install

            install()
        return super().main(*args, **kwargs)


app = typer.Typer(
    name="mechloop",
    help="Kinematic and dynamic analysis of mechanisms by the modular vector-loop method.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode="markdown",
    cls=_Group,
)
out = Console(highlight=False, soft_wrap=True)
err = Console(stderr=True, highlight=False, soft_wrap=True)

ModelPath = Annotated[Path, typer.Argument(help="model file (.yaml, .yml or .json)",
                                           show_default=False)]


def user_errors(func: Callable[..., Any]) -> Callable[..., Any]:
    """Turn a MechloopError into its message on stderr and exit code 2."""

    @wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return func(*args, **kwargs)
        except MechloopError as exc:
            if isinstance(exc, ModelError) and exc.file is None and isinstance(
                    kwargs.get("model"), Path):  # raised by a solver: name file and line
                from mechloop.model.load import locate

                exc = locate(exc, kwargs["model"])
            lang = _message_lang(kwargs)
            err.print(f"[bold red]{error_label(lang)}[/] {escape(render_error(exc, lang))}",
                      markup=True, soft_wrap=True)  # escaped: '[m]' is a unit, not markup
            raise typer.Exit(code=2) from None

    return wrapper


def _message_lang(kwargs: dict[str, Any]) -> str:
    """The language of a command's error: its ``--lang`` when given (en or ru), else
    ``MECHLOOP_LANG`` (:func:`mechloop.messages.message_language`)."""
    return message_language(kwargs.get("lang"))


@app.command(cls=_Command)
@user_errors
def check(model: ModelPath) -> None:
    """Validate a model file; every problem is listed with its line and the fix.

    Example:

    ```
    mechloop check examples/crank_slider.yaml
    ```
    """
    from mechloop.model.load import load_model

    m = load_model(model)
    from mechloop.solve.memory import require_memory

    require_memory(m, dynamics=bool(m.bodies))  # what solve would need, on this machine
    n_vec = len(m.vectors)
    text = (f"{model}: OK — {len(m.contours)} contour(s), {n_vec} vectors, "
            f"{len(m.arguments)} argument(s), positions 0..{m.positions}")
    if m.bodies and any(c.spatial for c in m.contours):  # issue 17: spatial dynamics
        spatial = _spatial_dynamics(m, model)
        text += f"; {len(spatial.mechanism.bodies)} moving bodies"
        if spatial.reactions is not None:  # the joints' force analysis is determinate
            text += (f", {len(spatial.reactions.joints)} joints "
                     f"({', '.join(spatial.reactions.joints)})")
    elif m.bodies:
        mech = _dynamics(m, model).mechanism
        text += (f"; {len(mech.bodies)} moving bodies, {len(mech.pairs)} pairs "
                 f"({', '.join(p.name for p in mech.pairs)}), {len(mech.drives)} drive(s)")
    out.print(text)


def _dynamics(m, path: Path) -> DynamicResults:
    """Solve the dynamics of a loaded model; model problems name the file and line."""
    from mechloop.dynamics.analysis import solve_dynamics
    from mechloop.model.load import locate

    try:
        return solve_dynamics(m)
    except ModelError as exc:
        raise locate(exc, path) from None


def _spatial_dynamics(m, path: Path):
    """Solve the dynamics of a loaded model with spatial contours (issue 17); model
    problems name the file and line."""
    from mechloop.model.load import locate
    from mechloop.spatial.dynamics import solve_spatial_dynamics

    try:
        return solve_spatial_dynamics(m)
    except ModelError as exc:
        raise locate(exc, path) from None


@app.command(cls=_Command)
@user_errors
def info(
    model: ModelPath,
    lang: Annotated[str | None, typer.Option(help="language of the description: en or ru "
                                             "(default: MECHLOOP_LANG, else en)")] = None,
) -> None:
    """Print the structure and parametric formula of every contour (KDAM's "structure of
    the vector model" panel).

    Example:

    ```
    mechloop info examples/four_bar.yaml
    ```
    """
    from mechloop.model.formula import describe_structure
    from mechloop.model.load import load_model

    lang = _text_lang(lang)
    m = load_model(model)
    out.print(escape(describe_structure(m, lang)))


def _text_lang(lang: str | None) -> str:
    """The language of a command's texts: ``--lang`` (en or ru), else ``MECHLOOP_LANG``."""
    lang = message_language() if lang is None else lang
    if lang not in ("en", "ru"):
        raise HintedError(f"no text language {lang!r}", "use --lang en or --lang ru")
    return lang


from mechloop.output.paths import TABLE_SUFFIXES as SUFFIXES  # noqa: E402 (no NumPy)

Force = Annotated[bool, typer.Option("--force", help="write the output even when it is the "
                                     "input model file or a CSV table the model reads, "
                                     "which is then replaced")]
UnitsOption = Annotated[str | None, typer.Option(
    "--units", help="units of the results as KIND=UNIT pairs, e.g. omega=rpm,force=kN; "
    "kinds: length, angle, time, velocity, acceleration, angular_velocity (omega), "
    "angular_acceleration (epsilon), mass, inertia, force, moment, energy (work), power "
    "(default: the model's display: section, else the tables' own units)")]
DigitsOption = Annotated[int | None, typer.Option(
    "--digits", help="significant digits of every number written, Parquet included "
    "(default: the model's display: section, else every digit)")]
DecimalsOption = Annotated[int | None, typer.Option(
    "--decimals", help="digits after the point of every number written, instead of "
    "--digits (default: none)")]


def _outputs(model: Path | None, force: bool, *pairs: tuple[Path | None, tuple[str, ...]]
             ) -> None:
    """Check every output path (file type, folder, not the input model nor a CSV table it
    reads) before the run."""
    from mechloop.output.paths import check_output, model_inputs

    inputs = model_inputs(model) if model is not None and any(p for p, _ in pairs) else []
    for path, suffixes in pairs:
        if path is not None:
            check_output(path, suffixes=suffixes, inputs=inputs, force=force)


@app.command(cls=_Command)
@user_errors
def solve(
    model: ModelPath,
    output: Annotated[Path | None, typer.Option(
        "-o", "--output", help="write the table here: .csv, .json, .parquet or .xlsx "
        "(default: print a summary only)")] = None,
    force: Force = False,
    units: UnitsOption = None,
    digits: DigitsOption = None,
    decimals: DecimalsOption = None,
) -> None:
    """Solve positions, velocities and accelerations at every position; for a model with
    bodies also the balancing load, reduced characteristics, centres of mass and the
    reaction in every joint.

    Values are in SI units (m, s, N) and degrees, one row per position, unless the
    model's display: section or --units/--digits say otherwise. Example:

    ```
    mechloop solve examples/crank_slider.yaml -o results.csv
    ```
    """
    import numpy as np

    from mechloop.model.load import load_model
    from mechloop.output.display import apply_display, resolve
    from mechloop.output.tables import check_table_size
    from mechloop.solve.kinematics import solve as solve_model
    from mechloop.solve.results import compress_positions

    _outputs(model, force, (output, SUFFIXES))
    m = load_model(model)
    shown = resolve(m.display, units, digits, decimals)
    if output is not None:
        check_table_size(m.positions + 1, 0, output)
    extra = _intermediate_outputs(m, output)
    _outputs(model, force, *((path, SUFFIXES) for path in extra))
    if m.bodies and any(c.spatial for c in m.contours):  # issue 17: spatial dynamics
        dynamic = _spatial_dynamics(m, model)
        results, frame = dynamic.kinematics, dynamic.to_frame()
        if dynamic.static:
            err.print("[yellow]note:[/] the model has no time: the analysis is static "
                      "(no inertia loads)")
        if dynamic.reactions is not None and dynamic.reactions.singular.any():
            err.print("[yellow]force analysis singular[/] at positions "
                      f"{compress_positions(np.flatnonzero(dynamic.reactions.singular))}: "
                      "reactions are unbounded there (empty values)")
    elif m.bodies:
        dynamic = _dynamics(m, model)
        results, frame = dynamic.kinematics, dynamic.to_frame()
        if dynamic.static:
            err.print("[yellow]note:[/] the model has no time: the force analysis is static "
                      "(no inertia loads)")
        if dynamic.forces.singular.any():
            err.print("[yellow]force analysis singular[/] at positions "
                      f"{compress_positions(np.flatnonzero(dynamic.forces.singular))}: "
                      "reactions are unbounded there (empty values)")
    else:
        results = solve_model(m)
        frame = results.to_frame()
    for brk in results.breaks:
        err.print(f"[yellow]chain break:[/] {brk.describe()} — check the kinematic chain "
                  "for a break (dimensions, variant, argument range)")
    for gap in results.breaks_between:
        err.print(f"[yellow]chain break between positions:[/] {gap.describe()} — the "
                  "values of these two positions are joined across a break; refine the "
                  "positions there or change the dimensions")
    if output is None:
        out.print(apply_display(frame, shown).to_string(max_rows=20, max_cols=12))
        return
    _write_frame(frame, output, shown)
    rows = len(frame)
    broken = int(results.broken.sum())
    out.print(f"wrote {output} ({rows} positions, {len(frame.columns)} columns"
              + (f", {broken} with a chain break" if broken else "") + ")")
    if extra:
        _write_intermediate(m, results, *extra, shown=shown)


def _intermediate_outputs(m, output: Path | None) -> tuple[Path, ...]:
    """The tables a model with an intermediate argument adds beside ``output``: the long
    table and the envelopes (``name.intermediate.csv``, ``name.envelopes.csv``)."""
    from mechloop.model.intermediate import intermediate_numbers

    if output is None or not intermediate_numbers(m):
        return ()
    return (output.with_suffix(f".intermediate{output.suffix}"),
            output.with_suffix(f".envelopes{output.suffix}"))


def _write_intermediate(m, results, long: Path, envelopes: Path, shown=None) -> None:
    """Solve over the intermediate argument and write its two tables."""
    from mechloop.output.tables import check_table_size
    from mechloop.solve.intermediate import solve_intermediate

    solved = solve_intermediate(m, results=results)
    frame = solved.to_frame()
    check_table_size(len(frame), len(frame.columns), long)
    _write_frame(frame, long, shown)
    bad = int(solved.broken.sum())
    out.print(f"wrote {long} ({solved.broken.shape[0]} positions × {solved.theta.size} "
              f"values of argument {solved.argument}"
              + (f", {bad} with a chain break" if bad else "") + ")")
    table = solved.envelope_frame()
    _write_frame(table, envelopes, shown)
    out.print(f"wrote {envelopes} ({len(table)} envelope points of "
              f"{len(solved.envelopes)} envelope(s))")


def _write_frame(frame, output: Path, shown=None) -> None:
    """Write ``frame`` to ``output`` in the units and precision ``shown`` (a
    :class:`~mechloop.output.display.TableDisplay`; None: as it is)."""
    from mechloop.output.display import apply_display
    from mechloop.output.tables import write_frame

    write_frame(apply_display(frame, shown, output.suffix), output)


@app.command(cls=_Command)
@user_errors
def energy(model: ModelPath, units: UnitsOption = None, digits: DigitsOption = None,
           decimals: DecimalsOption = None) -> None:
    """Print the summary characteristics of a cycle: work and power of every load and of
    friction, the mechanical loss coefficient and the efficiency; and the machine motion
    and flywheel when the model has a machine: section.

    The efficiency is defined when a load does net positive (driving) work over the cycle
    and there is friction to lose; without friction it is 100 %. Example (friction 0.1 in
    every pair):

    ```
    mechloop energy examples/crank_slider_friction.yaml
    ```
    """
    import numpy as np

    from mechloop.model.load import load_model
    from mechloop.output.display import apply_display, number, resolve
    from mechloop.output.display import quantity as q

    m = load_model(model)
    shown = resolve(m.display, units, digits, decimals)
    if not m.bodies:
        raise ModelError([Problem(("bodies",), "the model has no bodies, so no loads",
                                  "add bodies with masses, and forces or moments")],
                         str(model))
    dynamic = _dynamics(m, model)
    summary = dynamic.summary
    clock = "s" if not dynamic.static else "argument 1"
    broken = _warn_cycle_breaks(dynamic, "below")
    table = Table(title=f"Summary characteristics — {m.name or model}")
    rows = apply_display(summary.to_frame(), None if shown is None else
                         type(shown)(shown.units))  # units here, digits when printed
    for head in rows.columns:
        table.add_column(Text(head), justify="left" if head == "load" else "right",
                         no_wrap=True)
    for row in rows.itertuples(index=False):
        table.add_row(row[0], *(number(v, shown, ".5g") for v in row[1:]))
    Console(highlight=False, width=max(out.width, 110)).print(table)
    out.print(f"total mass {q(dynamic.mechanism.total_mass, 'kg', shown)}; work over the "
              f"cycle ({clock}): driving {q(summary.driving_work, 'J', shown)}, friction "
              f"{q(summary.friction_work, 'J', shown)}, change of kinetic energy "
              f"{q(summary.kinetic_energy_change, 'J', shown)}")
    residual = sum(r.positive_work + r.negative_work for r in summary.rows) \
        - summary.kinetic_energy_change
    largest = max((r.positive_work - r.negative_work for r in summary.rows), default=0.0)
    out.print(f"energy balance: the works of all loads, the drive and friction less the "
              f"change of kinetic energy leave {q(residual, 'J', shown, '.3g')}"
              + (f" ({abs(residual) / largest:.2g} of the largest work; the trapezoidal "
                 "rule over the positions)" if largest > 0 else "")
              + (" — positions with a break are left out"
                 if broken is not None and broken.positions.size else ""))
    if broken is not None:
        out.print("mechanical loss coefficient and efficiency: not given — the chain "
                  "breaks in the cycle (see the warning)")
    elif np.isnan(summary.efficiency):
        out.print("no load does net positive work over the cycle: loss coefficient and "
                  "efficiency are undefined")
    else:
        out.print(f"mechanical loss coefficient {100 * summary.loss_coefficient:.4g} %, "
                  f"efficiency {100 * summary.efficiency:.4g} %")
    cycle = dynamic.cycle
    if cycle is not None:
        angle = dynamic.kinematics.argument_kinds[
            dynamic.mechanism.drives[0].argument] == "angle"
        unit, speed, mass = ("N*m", "rad/s", "kg*m^2") if angle else ("N", "m/s", "kg")
        out.print(f"machine motion: mean speed {q(cycle.omega_mean, speed, shown)}; "
                  "constant load on the input that balances the cycle "
                  f"{q(cycle.constant_load, unit, shown)}"
                  + ("" if cycle.bare_constant_load is None else
                     " (with the flywheel; without it "
                     f"{q(cycle.bare_constant_load, unit, shown)})")
                  + ("" if not cycle.iterations else
                     f" — the loads that depend on the speed taken at the cycle's own speed "
                     f"({cycle.iterations} iterations)") + "; "
                  f"without a flywheel δ = {cycle.motion.delta:.4g} "
                  f"(speed {q(cycle.motion.omega_min, speed, shown).split()[0]} … "
                  f"{q(cycle.motion.omega_max, speed, shown)})")
        if cycle.flywheel is not None:
            out.print(f"flywheel for δ = {cycle.delta:.4g}: {q(cycle.flywheel, mass, shown)} "
                      f"(approximate method: {q(cycle.flywheel_approx, mass, shown)}); speed "
                      f"{q(cycle.with_flywheel.omega_min, speed, shown).split()[0]} … "
                      f"{q(cycle.with_flywheel.omega_max, speed, shown)}")


@app.command(cls=_Command)
@user_errors
def simulate(
    model: ModelPath,
    output: Annotated[Path | None, typer.Option(
        "-o", "--output", help="write the time series here: .csv, .json, .parquet or "
        ".xlsx (default: print a summary only)")] = None,
    plot_file: Annotated[Path | None, typer.Option(
        "--plot", help="draw angle, speed and acceleration over time and the phase "
        "portrait: .png, .svg or .pdf (default: none)")] = None,
    duration: Annotated[float | None, typer.Option(
        help="simulated time, s (default: the model's simulate.duration)")] = None,
    cycles: Annotated[int | None, typer.Option(
        help="stop after this many cycles (default: the model's simulate.cycles)")] = None,
    force: Force = False,
    units: UnitsOption = None,
    digits: DigitsOption = None,
    decimals: DecimalsOption = None,
    lang: Annotated[str | None, typer.Option(help="language of the summary: en or ru "
                                             "(default: MECHLOOP_LANG, else en)")] = None,
) -> None:
    """Simulate the machine's motion in time (start-up, run-down, the approach to the
    steady cycle) from the model's simulate: section: a motor on the input, the start
    state, the loads over the positions.  A model with several inputs moves by
    Lagrange's equations (motors, start and stop_at per input).

    Prints how the run ended, the cycles, the time to steady state and the energy balance.
    Example:

    ```
    mechloop simulate examples/compressor_startup.yaml --plot startup.png
    ```
    """
    from mechloop.dynamics.simulate import simulate as run
    from mechloop.model.load import load_model
    from mechloop.output.display import resolve
    from mechloop.views.figure import FIGURE_SUFFIXES

    lang = _text_lang(lang)
    _outputs(model, force, (output, SUFFIXES), (plot_file, FIGURE_SUFFIXES))
    m = load_model(model)
    if m.simulate is None:
        raise ModelError([Problem(("simulate",), "the model has no simulate: section",
                                  "add simulate: {motor: {kloss: ...}, duration: 5}")],
                         str(model))
    shown = resolve(m.display, units, digits, decimals)
    settings = m.simulate
    if duration is not None or cycles is not None:
        settings = settings.model_copy(update={
            "duration": duration if duration is not None else settings.duration,
            "cycles": cycles if cycles is not None else settings.cycles})
    dynamic = _dynamics(m, model)
    with _progress("simulating") as bar:
        task = bar.add_task("simulating", total=None)
        sim = run(m, settings, dynamics=dynamic,
                  progress=lambda done, total: bar.update(task, completed=done,
                                                          total=total or None))
    _print_simulation(sim, lang)
    if output is not None:
        _write_frame(sim.to_frame(), output, shown)
        out.print(f"wrote {output} ({sim.time.size} rows)")
    if plot_file is not None:
        from mechloop.views.figure import save_figure
        from mechloop.views.motion import plot_simulation

        save_figure(plot_simulation(sim, title=m.name), plot_file)
        out.print(f"wrote {plot_file}")


def _print_simulation(sim, lang: str = "en") -> None:
    """The summary of a run (:mod:`mechloop.dynamics.simulate_summary`): machine, events,
    cycles, steady state, energy balance; warnings to the error stream."""
    from mechloop.dynamics.simulate_summary import summary_lines

    for text, warning in summary_lines(sim, lang):
        if warning:
            err.print(f"[bold yellow]{'предупреждение' if lang == 'ru' else 'warning'}:[/] "
                      f"{text}", markup=True)
        else:
            out.print(text, markup=False)


def _warn_cycle_breaks(dynamic: DynamicResults, where: str):
    """Warn that the cycle's works (and ψ, η, δ, the flywheel) are not the cycle's where
    the chain breaks or the force analysis is singular at positions, or the chain breaks
    between two positions (the exact existence check); the
    :class:`~mechloop.dynamics.cycle_validity.CycleBreaks` or None."""
    from mechloop.dynamics.cycle_validity import cycle_breaks
    from mechloop.solve.results import compress_positions

    found = cycle_breaks(dynamic)
    if found is None:
        return None
    parts = []
    if found.positions.size:
        parts.append(f"the chain breaks (or the force analysis is singular) at "
                     f"{found.positions.size} of {found.count} positions "
                     f"({compress_positions(found.positions)}): the works {where} leave "
                     "out the steps next to them")
    if found.between:
        parts.append("the chain breaks " + ", ".join(
            f"between positions {i} and {j}" for i, j in found.between)
            + " (the existence check over the continuous range; mechloop solve describes "
            "it): the machine cannot pass there")
    err.print(f"[bold yellow]warning:[/] {'; '.join(parts)} — so the work over the cycle, "
              "the loss coefficient and the efficiency are not the cycle's and are not "
              "given; remove the break (dimensions, variant, argument range) first")
    return found


PLOTS = ("plan", "overlay", "trajectories", "parameters", "combination", "angle",
         "increment", "reduced", "balancing", "reactions", "hodograph", "summary", "motion",
         "structure", "envelope")


def _split(text: str | None) -> list[str]:
    return [part.strip() for part in (text or "").split(",") if part.strip()]


def _point(text: str) -> Any:
    """'head:6' -> {'head': 6}; 'vector:2:0.3' -> {'vector': 2, 'share': 0.3}; 'S2' as is."""
    parts = text.split(":")
    if parts[0] in ("tail", "head") and len(parts) == 2:
        return {parts[0]: int(parts[1])}
    if parts[0] == "vector" and len(parts) == 3:
        return {"vector": int(parts[1]), "share": float(parts[2])}
    return text


@app.command(cls=_Command)
@user_errors
def plot(
    model: ModelPath,
    kind: Annotated[str, typer.Argument(help=f"what to draw: {', '.join(PLOTS)}",
                                        show_default=False)],
    output: Annotated[Path, typer.Option("-o", "--output", help="image file: .png, .svg "
                                         "or .pdf (no default)")],
    position: Annotated[int | None, typer.Option("-p", "--position", help="position "
                        "number drawn by plan and trajectories, and the reference of "
                        "increment (default: 0)")] = None,
    names: Annotated[str | None, typer.Option("-n", "--names", help="comma-separated "
                     "names: parameters (r3,dr3,M_bal) for parameters and increment; two "
                     "for combination; two vector numbers (2,3) for angle (no default)")
                     ] = None,
    against: Annotated[str, typer.Option(help="x axis: position, time, arg1, ... "
                                         "(drawn in its own unit)")] = "position",
    op: Annotated[str, typer.Option(help="combination: sum, difference, product, ratio, "
                                    "power")] = "ratio",
    points: Annotated[str | None, typer.Option(help="trajectories: comma-separated "
                      "points, e.g. head:6, tail:2, vector:2:0.3 (0.3 of vector 2 from its "
                      "tail), S2 (centre of mass of body 2); default: none")] = None,
    joint: Annotated[str | None, typer.Option(help="hodograph: the joint name, e.g. A "
                                              "(no default)")] = None,
    polar: Annotated[bool, typer.Option(help="hodograph in polar form (magnitude and "
                                        "angle) instead of x-y")] = False,
    units: Annotated[str | None, typer.Option(help="display units as KIND=UNIT pairs, "
                     "e.g. length=mm,force=kN,omega=rpm; kinds: length, angle, time, "
                     "velocity, acceleration, angular_velocity (omega), angular_acceleration "
                     "(epsilon), mass, inertia, force, moment, energy, power (default: the "
                     "model's display: section, else SI units and degrees)")] = None,
    panels: Annotated[bool, typer.Option(help="parameters: one stacked panel per unit "
                      "(default: a y-axis per unit up to 3 units, panels for more)")
                      ] = False,
    lang: Annotated[str | None, typer.Option(help="language of the figure's texts and the "
                    "messages: en or ru (default: MECHLOOP_LANG, else en)")] = None,
    elev: Annotated[float, typer.Option(help="plan, overlay, trajectories, hodograph of "
                    "a spatial model: the viewing elevation, deg")] = 20.0,
    azim: Annotated[float, typer.Option(help="plan, overlay, trajectories, hodograph of "
                    "a spatial model: the viewing azimuth about the Y axis, deg")] = 30.0,
    views: Annotated[str, typer.Option(help="plan, overlay, trajectories, hodograph of "
                     "a spatial model: all (the 3-D view and the projections XY, ZY, XZ) "
                     "or 3d")
                     ] = "all",
    force: Force = False,
) -> None:
    """Draw one view of a model to an image file.

    Examples:

    ```
    mechloop plot examples/four_bar.yaml plan -p 12 -o plan.png
    mechloop plot examples/crank_slider.yaml parameters -n r3,dr3 \\
        --against arg1 -o s.png
    mechloop plot examples/crank_slider_dynamics.yaml hodograph \\
        --joint A -o hod.svg
    mechloop plot examples/cam_roller_follower.yaml envelope -o cam.png
    mechloop plot examples/four_bar.yaml plan --lang ru -o plan_ru.png
    ```
    """
    from mechloop.model.load import load_model
    from mechloop.model.spatial import is_spatial
    from mechloop.output.display import plot_display, resolve
    from mechloop.solve.kinematics import solve as solve_model
    from mechloop.views import curves, dynamics, formula
    from mechloop.views import plan as plans
    from mechloop.views.display import DEFAULT_DISPLAY
    from mechloop.views.figure import FIGURE_SUFFIXES, ViewError, save_figure
    from mechloop.views.russian import translate

    if kind not in PLOTS:
        raise ViewError(f"unknown view {kind!r}", f"use one of {', '.join(PLOTS)}")
    lang = message_language() if lang is None else lang
    if lang not in ("en", "ru"):
        raise ViewError(f"no figure language {lang!r}", "use --lang en or --lang ru")
    wrote = "записан файл" if lang == "ru" else "wrote"
    _outputs(model, force, (output, FIGURE_SUFFIXES))
    m = load_model(model)
    display = plot_display(resolve(m.display, units)) or DEFAULT_DISPLAY
    if kind == "structure":
        save_figure(translate(formula.plot_structure(m), lang), output)
        out.print(f"{wrote} {output}")
        return
    if kind == "envelope":  # the family over the intermediate argument and its envelope
        from mechloop.solve.intermediate import solve_intermediate
        from mechloop.views.envelope import plot_envelope

        listed = _split(names)
        save_figure(translate(plot_envelope(solve_intermediate(m),
                                            listed[0] if listed else None, display=display),
                              lang), output)
        out.print(f"{wrote} {output}")
        return
    dynamic_kinds = ("reduced", "balancing", "reactions", "hodograph", "summary", "motion")
    if kind in dynamic_kinds and not m.bodies:
        raise ViewError(f"'{kind}' needs a model with bodies",
                        "add bodies (see examples/crank_slider_dynamics.yaml)")
    if kind in dynamic_kinds and is_spatial(m):  # issue 17: by virtual power
        from mechloop.views.spatial_dynamics import plot_spatial_dynamics

        figure = plot_spatial_dynamics(_spatial_dynamics(m, model), kind, against=against,
                                       display=display, names=_split(names), joint=joint,
                                       position=position, elev=elev, azim=azim,
                                       views=views)
        save_figure(translate(figure, lang), output)
        out.print(f"{wrote} {output}")
        return
    results = _dynamics(m, model) if m.bodies and not is_spatial(m) else solve_model(m)
    listed = _split(names)
    if kind in ("plan", "overlay", "trajectories") and is_spatial(m):  # issue 17: in 3-D
        figure = _spatial_plot(results, kind, position or 0, _split(points), elev=elev,
                               azim=azim, views=views)
    elif kind == "plan":
        figure = plans.plot_plan(results, position or 0)
    elif kind == "overlay":
        figure = plans.plot_overlay(results)
    elif kind == "trajectories":
        figure = plans.plot_trajectories(results, [_point(p) for p in _split(points)],
                                         position=position or 0)
    elif kind == "parameters":
        figure = curves.plot_parameters(results, listed, against=against, display=display,
                                        layout="panels" if panels else "auto")
    elif kind == "combination":
        if len(listed) != 2:
            raise ViewError("a combination needs two names", "give -n r3,r1")
        b: str | float = listed[1]
        try:
            b = float(listed[1])
        except ValueError:
            pass
        figure = curves.plot_combination(results, listed[0], b, op, against=against,
                                         display=display)
    elif kind == "angle":
        if len(listed) != 2:
            raise ViewError("the angle between two vectors needs two vector numbers",
                            "give -n 2,3")
        figure = curves.plot_angle_between(results, *listed, against=against,
                                           display=display)
    elif kind == "increment":
        if len(listed) != 1:
            raise ViewError("the increment needs one parameter", "give -n r3")
        figure = curves.plot_increment(results, listed[0], position or 0, against=against,
                                       display=display)
    elif kind == "reduced":
        figure = dynamics.plot_reduced(results, against=against, display=display)
    elif kind == "balancing":
        figure = dynamics.plot_balancing(results, against=against, display=display)
    elif kind == "reactions":
        figure = dynamics.plot_reactions(results, listed or None, against=against,
                                         display=display)
    elif kind == "hodograph":
        if joint is None:
            raise ViewError("a hodograph needs a joint",
                            f"give --joint, one of {', '.join(results.forces.reactions)}")
        figure = dynamics.plot_hodograph(results, joint, polar=polar, display=display)
    elif kind == "summary":
        _warn_cycle_breaks(results, "drawn")
        figure = dynamics.plot_summary(results, display=display)
    else:
        figure = dynamics.plot_machine_motion(results, display=display)
    save_figure(translate(figure, lang), output)
    out.print(f"{wrote} {output}")


def _progress(description: str):
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TimeRemainingColumn

    return Progress("[progress.description]{task.description}", BarColumn(),
                    MofNCompleteColumn(), TimeRemainingColumn(), console=err,
                    transient=True)


@app.command(cls=_Command)
@user_errors
def animate(
    model: ModelPath,
    output: Annotated[Path, typer.Option("-o", "--output", help="animation file: .gif, "
                                         ".mp4 or .html (no default)")],
    fps: Annotated[float | None, typer.Option(help="frames per second, 1/s (default: "
                                              "from the model time, at least 20 ms a "
                                              "frame)")] = None,
    elev: Annotated[float, typer.Option(help="a spatial model: the viewing elevation, "
                                        "deg")] = 20.0,
    azim: Annotated[float, typer.Option(help="a spatial model: the viewing azimuth about "
                                        "the Y axis, deg")] = 30.0,
    views: Annotated[str, typer.Option(help="a spatial model: all (the 3-D view and the "
                                       "projections XY, ZY, XZ) or 3d")] = "all",
    lang: Annotated[str | None, typer.Option(help="a spatial model's .html page: its "
                    "language, en or ru (default: MECHLOOP_LANG, else en)")] = None,
    force: Force = False,
) -> None:
    """Animate a cycle ("cinema"): one frame per position.

    Example:

    ```
    mechloop animate examples/four_bar.yaml -o cycle.gif
    ```
    """
    from mechloop.model.load import load_model
    from mechloop.model.spatial import is_spatial
    from mechloop.solve.kinematics import solve as solve_model
    from mechloop.views.animation import ANIMATION_SUFFIXES
    from mechloop.views.animation import animate as make_animation

    lang = _text_lang(lang)
    _outputs(model, force, (output, ANIMATION_SUFFIXES))
    m = load_model(model)
    results = _dynamics(m, model) if m.bodies else solve_model(m)
    frames = [m.positions + 1]  # a closed cycle leaves out its last, repeated pose
    with _progress("frames") as bar:
        task = bar.add_task("frames", total=m.positions + 1)

        def advance(done: int, total: int) -> None:
            frames[0] = total
            bar.update(task, completed=done, total=total)

        if is_spatial(m):  # issue 17: the 3-D plan and its projections
            from mechloop.views.spatial_animation import animate_spatial

            animate_spatial(results, output, fps=fps, progress=advance, elev=elev,
                            azim=azim, views=views, lang=lang)
        else:
            make_animation(results, output, fps=fps, progress=advance)
    out.print(f"wrote {output} ({frames[0]} frames)")


@app.command(cls=_Command)
@user_errors
def report(
    model: ModelPath,
    output: Annotated[list[Path], typer.Option("-o", "--output", help="the report: .pdf "
                                               "or .docx; repeat for both (-o r.pdf -o "
                                               "r.docx)")],
    lang: Annotated[str | None, typer.Option(help="language of the report and the "
                    "messages: en or ru (default: MECHLOOP_LANG, else en)")] = None,
    parameter: Annotated[str | None, typer.Option(help="output parameter (r3, a3; default: "
                         "the first contour's length function, else its last angle)")
                         ] = None,
    position: Annotated[int | None, typer.Option(help="the intermediate position of the "
                        "vector scheme and the trajectories (default: one near the "
                        "first third of the cycle where the chain assembles)")] = None,
    cam: Annotated[Path | None, typer.Option(help="the course project's cam (a mechloop "
                   "cam document): adds sheet 4; default: the model's project.cam")] = None,
    gears: Annotated[Path | None, typer.Option(help="the course project's gear pair or "
                     "planetary train (a mechloop gear document): adds sheet 3; default: "
                     "the model's project.gears")] = None,
    student: Annotated[str | None, typer.Option(help="title page: the student (default: "
                       "the model's report.student)")] = None,
    group: Annotated[str | None, typer.Option(help="title page: the group (default: the "
                     "model's report.group)")] = None,
    supervisor: Annotated[str | None, typer.Option(help="title page: the supervisor "
                          "(default: the model's report.supervisor)")] = None,
    university: Annotated[str | None, typer.Option(help="title page: the university "
                          "(default: the model's report.university)")] = None,
    department: Annotated[str | None, typer.Option(help="title page: the department "
                          "(default: the model's report.department)")] = None,
    city: Annotated[str | None, typer.Option(help="title page: the city (default: the "
                    "model's report.city)")] = None,
    year: Annotated[int | None, typer.Option(help="title page: the year (default: this "
                    "year)")] = None,
    force: Force = False,
) -> None:
    """Write the course-project report (PDF and/or editable DOCX): title page, model
    parameters, formula, kinematics of the output link, angle differences, dynamics,
    reactions, centres of mass, the gears and the cam (sheets 3 and 4, from the model's
    project: section or --gears/--cam), conclusion, and the values at every position.
    The title page takes the model's report: section; the options override it.

    Example:

    ```
    mechloop report examples/crank_slider_dynamics.yaml -o report.pdf -o report.docx --lang ru
    ```
    """
    from mechloop.model.load import load_model, locate
    from mechloop.model.project import project_documents
    from mechloop.report.cli import run_report

    lang = message_language() if lang is None else lang
    _outputs(model, force, *((path, (".pdf", ".docx")) for path in output))
    m = load_model(model)
    project = project_documents(m, model, cam=cam, gears=gears)
    title = dict(student=student, group=group, supervisor=supervisor,
                 university=university, department=department, city=city, year=year)
    try:
        run_report(m, output, lang=lang, parameter=parameter, position=position,
                   title=title, project=project, progress=_progress, out=out, err=err)
    except ModelError as exc:
        raise locate(exc, model) from None




@app.command(cls=_Command)
@user_errors
def structure(
    model: ModelPath,
    lang: Annotated[str | None, typer.Option(help="language of the texts: en or ru "
                                             "(default: MECHLOOP_LANG, else en)")] = None,
) -> None:
    """Structural analysis: links, pairs, mobility by Chebyshev, the input groups and Assur
    groups with their pairs and assembly variants, the structure formula, the class of the
    mechanism, and the identification table.

    Example:

    ```
    mechloop structure examples/crank_slider_dynamics.yaml
    ```
    """
    from mechloop.model.load import load_model, locate
    from mechloop.structure import analyze
    from mechloop.structure.text import structure_lines, table_text
    from mechloop.structure.words_ru import WORDS

    lang = _text_lang(lang)
    m = load_model(model)
    if any(c.spatial for c in m.contours):  # issue 17: Somov–Malyshev, not Assur groups
        from mechloop.structure.spatial import spatial_structure
        from mechloop.structure.spatial_text import spatial_structure_lines

        try:
            lines = spatial_structure_lines(spatial_structure(m), m, lang)
        except ModelError as exc:
            raise locate(exc, model) from None
        out.print(escape("\n".join(lines)))
        return
    try:
        mob, dec = analyze(m)
    except ModelError as exc:
        raise locate(exc, model) from None
    for kind, line in structure_lines(mob, dec, lang):
        out.print(f"[yellow]{WORDS[lang]['note']}[/] {escape(line)}" if kind == "note"
                  else escape(line))
    out.print(escape(table_text(dec, lang)))


@app.command(cls=_Command)
@user_errors
def schema(
    output: Annotated[Path | None, typer.Option("-o", "--output",
                                                help="write the schema to this file "
                                                "(default: print it)")] = None,
    groups: Annotated[bool, typer.Option("--groups", help="the schema of files built from "
                                         "Assur groups (groups:) instead (default: the "
                                         "schema of vector models)")] = False,
    force: Annotated[bool, typer.Option("--force", help="replace the output file even when "
                                        "it holds something other than a schema (a model)")
                     ] = False,
    cam: Annotated[bool, typer.Option("--cam", help="the schema of cam designs (cam:, "
                                      "mechloop cam) instead")] = False,
) -> None:
    """Print the JSON Schema of model files (generated from the code): vector models, or
    with --groups models built from an input and Assur groups, or with --cam cam designs.

    Example:

    ```
    mechloop schema -o model.schema.json
    ```
    """
    if output is not None:
        from mechloop.output.paths import check_output, check_replaces_schema

        check_output(output)
        if not force:
            check_replaces_schema(output)
    if groups:
        from mechloop.model.groups import group_json_schema

        found = group_json_schema()
    elif cam:
        from mechloop.cams.document import cam_json_schema

        found = cam_json_schema()
    else:
        from mechloop.model.schema import model_json_schema

        found = model_json_schema()
    text = json.dumps(found, indent=2, ensure_ascii=False) + "\n"
    if output is None:
        sys.stdout.write(text)
    else:
        from mechloop.output.atomic import atomic_write_text

        atomic_write_text(output, text)
        out.print(f"wrote {output}")


@app.command(name="sweep", cls=_Command)
@user_errors
def sweep_command(
    model: ModelPath,
    vary: Annotated[list[str], typer.Option("--vary", metavar="PATH=VALUES",
                    help="once or twice (two: "
                    "the full grid): a path in the model data (vectors.2.r, time.rpm, "
                    "bodies.2.mass, forces.0.value, machine.delta) and a range "
                    "start:stop:count or a list v1,v2,... in the model's units (or with "
                    "a unit: '30 mm:60 mm:4'); no default", show_default=False)],
    collect: Annotated[list[str], typer.Option("--collect", metavar="COLUMN:REDUCTION",
                       help="repeatable: a column of the results table (r3, da2, M_bal, RA, "
                       "J_red, ...) and max, min, mean, rms, range, absmax or at=K "
                       "(position K); values in the unit of the column; no default",
                       show_default=False)],
    output: Annotated[Path | None, typer.Option("-o", "--output", help="write the table "
                      "here: .csv, .json, .parquet or .xlsx (default: print it only)")
                      ] = None,
    plot_file: Annotated[Path | None, typer.Option("--plot", help="draw the quantities "
                         "against the parameter(s): .png, .svg or .pdf (default: none)")
                         ] = None,
    scheduler: Annotated[str | None, typer.Option(help="serial, processes (a local Dask "
                         "cluster) or the address of a running dask.distributed scheduler, "
                         "tcp://host:8786 (default: serial unless the sweep would take "
                         "over 10 s)")] = None,
    contour: Annotated[bool | None, typer.Option("--contour/--lines", help="two "
                       "parameters: a contour map or one line per value of the second "
                       "(default: a map above 6 values)", show_default=False)] = None,
    units: Annotated[str | None, typer.Option(help="display units of the plot as "
                     "KIND=UNIT pairs, e.g. force=kN,moment=kN*m (default: SI units and "
                     "degrees)")] = None,
    force: Force = False,
) -> None:
    """Parametric analysis: solve the model for every value of one or two parameters and
    tabulate reductions of result columns (KDAM's "parametric analysis" panel).

    Example, the peak and rms balancing moment of the engine against its speed:

    ```
    mechloop sweep examples/single_cylinder_engine.yaml \\
        --vary time.rpm=1000:4000:7 --collect M_bal:max --collect M_bal:rms
    ```

    Add -o speed.csv to write the table and --plot speed.png to draw it; a second --vary
    (e.g. --vary vectors.2.r=120:160:5) gives the grid.
    """
    import numpy as np

    from mechloop.model.load import load_model, locate
    from mechloop.output.display import TableDisplay, parse_units, plot_display
    from mechloop.synthesis.parallel import check_scheduler
    from mechloop.synthesis.sweep import parse_vary
    from mechloop.synthesis.sweep import sweep as run_sweep
    from mechloop.views.figure import FIGURE_SUFFIXES, save_figure
    from mechloop.views.sweep import plot_sweep

    _outputs(model, force, (output, SUFFIXES), (plot_file, FIGURE_SUFFIXES))
    display = plot_display(TableDisplay(parse_units(units)))  # as the tables: m/rad, rad/s
    check_scheduler(scheduler)
    pairs = [parse_vary(text) for text in vary]
    m = load_model(model)
    try:
        with _progress("designs") as bar:
            task = bar.add_task("designs", total=None)
            frame = run_sweep(m, pairs, collect, scheduler=scheduler,
                              progress=lambda done, total: bar.update(
                                  task, completed=done, total=total))
    except ModelError as exc:
        raise (locate(exc, model) if exc.file is None else exc) from None
    failed = frame[(frame["broken"] > 0) | (frame["note"] != "")]
    shown = frame.drop(columns=["note"] + ([] if len(failed) else ["broken"]))
    table = Table(title=f"Parametric analysis — {m.name or model}")
    for head in shown.columns:
        table.add_column(Text(str(head)), justify="right")
    for row in shown.itertuples(index=False):
        table.add_row(*(Text("—" if isinstance(v, float) and np.isnan(v) else
                             f"{v:.6g}" if isinstance(v, float) else str(v)) for v in row))
    Console(highlight=False, width=max(out.width, 30 + 18 * len(shown.columns))
            ).print(table)
    params = frame.attrs["parameters"]
    for _, row in failed.iterrows():
        label = ", ".join(f"{p} = {row[p]:.6g}" if isinstance(row[p], float)
                          else f"{p} = {row[p]}" for p in params)
        err.print(Text.assemble(("no values", "yellow"), f" for {label}: {row['note']}"))
    if output is not None:
        _write_frame(frame, output)
        out.print(f"wrote {output} ({len(frame)} designs)")
    if plot_file is not None:
        save_figure(plot_sweep(frame, contour=contour, display=display), plot_file)
        out.print(f"wrote {plot_file}")


OBJECTIVES = {"max": "max |deviation|", "rms": "rms deviation",
              "ssq": "sum of squared deviations"}


def _print_objective(result: Any, objective: str) -> None:
    """The minimized total of the best design and its terms, then the measured quantities.

    With a target the total is Q (the main condition: the deviation from the target) plus
    every penalty; without one it is the sum of the criteria terms (each its weighted value
    plus its penalty). The printed terms add up to the printed total.
    """
    ev = result.evaluation
    has_target = bool(result.problem.target_kind)
    if not result.feasible:
        out.print("no feasible design found: every design tried breaks the chain or changes "
                  "its assembly variant; widen the bounds")
    else:
        table = _table("Minimized total and its terms", ["term", "value", "unit"])
        if has_target:
            table.add_row(f"Q: main condition, {OBJECTIVES[objective]}",
                          f"{result.q:.6g}", result.problem.q_shown_unit)
        for name, value in ev.terms.items():
            label = f"criterion {name}" if not has_target else f"penalty {name}"
            table.add_row(label, f"{float(value[0]):.6g}", "")
        table.add_row("total (minimized)", f"{float(ev.total[0]):.6g}", "")
        out.print(table)
    measured = _table("Conditions and measured quantities", ["quantity", "value"])
    measured.add_row("share of positions with a chain break", f"{float(ev.broken_share[0]):.6g}")
    measured.add_row("assembly variant kept", "yes" if bool(ev.keeps_variant[0]) else "no")
    for name, value in ev.measures.items():
        measured.add_row(name, f"{float(value[0]):.6g}")
    out.print(measured)
    if result.feasible:
        parts = [f"minimized total {float(ev.total[0]):.6g}"]
        if has_target:
            penalty = sum(float(v[0]) for v in ev.terms.values())
            parts.append(f"= Q + penalties: Q = {result.q:.6g} {result.problem.q_shown_unit} "
                         f"({OBJECTIVES[objective]}), penalties {penalty:.6g}")
        else:
            parts.append("= the sum of the criteria terms (no target)")
        verdict = " ".join(parts)
    else:
        verdict = "no feasible design"
    out.print(f"{verdict}; {result.stopped}; {result.evaluations} designs in "
              f"{result.elapsed:.1f} s ({result.evaluations_per_second:.0f}/s, "
              f"{result.method})")
    for line in result.summary():
        if line.startswith(("local search:", "note:", "feasible:")):
            out.print(line)


def _table(title: str, headers: list[str]) -> Table:
    table = Table(title=title)
    for h in headers:
        table.add_column(h)
    return table



@app.command(cls=_Command)
@user_errors
def synthesize(
    model: ModelPath,
    output: Annotated[Path | None, typer.Option("-o", "--output", help="write the best "
                      "design as a model file (.yaml or .json; a file built from Assur "
                      "groups is written back as a group file); default: none")] = None,
    table: Annotated[Path | None, typer.Option(help="the best designs: .csv, .json, "
                     ".parquet or .xlsx (with the terms and the history); default: none")
                     ] = None,
    plot: Annotated[Path | None, typer.Option(help="convergence plot (.png, .svg, .pdf); "
                    "default: none")] = None,
    fit: Annotated[Path | None, typer.Option(help="the result against its targets "
                   "(.png, .svg, .pdf); default: none")] = None,
    method: Annotated[str | None, typer.Option(help="auto, de, cmaes or multistart (default: the "
                      "model's search.method, else de)")] = None,
    seed: Annotated[int | None, typer.Option(help="random seed (default: the model's "
                    "search.seed)")] = None,
    iterations: Annotated[int | None, typer.Option(help="number of generations at most "
                          "(default: the model's search.iterations)")] = None,
    time_budget: Annotated[float | None, typer.Option("--time", help="time budget in "
                           "seconds, a hard wall-clock limit of the whole run, polish "
                           "included; a run stopped by time depends on the machine's speed "
                           "(default: the model's search.time, else none)")] = None,
    polish: Annotated[bool | None, typer.Option("--polish/--no-polish", help="polish the "
                      "best design by least squares and Nelder–Mead at the end (default: "
                      "the model's search.polish, else yes)", show_default=False)] = None,
    atlas: Annotated[bool | None, typer.Option("--atlas/--no-atlas", help="add starting "
                     "designs from the atlas of four-bar coupler curves where the task is a "
                     "four-bar path problem it applies to (default: the model's "
                     "search.atlas, else yes)", show_default=False)] = None,
    scheduler: Annotated[str | None, typer.Option(help="multistart only: serial, processes "
                         "or a dask scheduler address tcp://host:8786 (default: chosen by "
                         "the work's size)")] = None,
    force: Annotated[bool, typer.Option("--force", help="write -o even when it is the input "
                                        "model file, which is then replaced (its comments "
                                        "are lost)")] = False,
) -> None:
    """Synthesis by optimization: vary the dimensions listed in the model's synthesis:
    section to reach its target (a path, a function, poses) under its conditions.

    Ctrl-C stops the search and keeps the best design found so far. The summary prints the
    minimized total and each of its terms. Example:

    ```
    mechloop synthesize examples/four_bar_path_synthesis.yaml -o best.yaml \\
        --table best.csv --plot convergence.png
    ```
    """
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

    from mechloop.model.load import load_model, locate
    from mechloop.synthesis.output import write_model, write_table
    from mechloop.synthesis.search import synthesize as run
    from mechloop.views.figure import FIGURE_SUFFIXES, save_figure
    from mechloop.views.synthesis import plot_convergence, plot_fit

    if method is not None and method not in ("auto", "de", "cmaes", "multistart"):
        raise typer.BadParameter(f"{method!r}: use auto, de, cmaes or multistart",
                                 param_hint="--method")
    _outputs(model, force, (output, (".yaml", ".yml", ".json")), (table, SUFFIXES),
             (plot, FIGURE_SUFFIXES), (fit, FIGURE_SUFFIXES))
    m = load_model(model)
    if m.synthesis is None:
        raise ModelError([Problem(("synthesis",), "the model has no synthesis task",
                                  "add a synthesis: section, see "
                                  "examples/four_bar_path_synthesis.yaml")], str(model))
    search = m.synthesis.search
    total = iterations or search.iterations
    columns = (TextColumn("[progress.description]{task.description}"), BarColumn(),
               TextColumn("{task.completed}/{task.total} generations"),
               TextColumn("best Q {task.fields[best]}"), TimeElapsedColumn())
    with Progress(*columns, console=err, transient=True) as bar:
        task = bar.add_task("synthesis", total=total, best="—")

        def report(p) -> None:
            best = f"{p.best_q:.6g}" if p.feasible else "no feasible design yet"
            bar.update(task, completed=min(p.iteration, total), best=best)

        try:
            result = run(m, method=method, seed=seed, iterations=iterations,
                         time_budget=time_budget, polish=polish, progress=report,
                         scheduler=scheduler, atlas=atlas)
        except ModelError as exc:
            raise locate(exc, model) from None
    rows = _table("Best design", ["variable", "value", "unit"])
    for name, value in result.values().items():
        rows.add_row(name, f"{value:.6g}", result.problem.variables.units[
            result.problem.variables.names.index(name)])
    out.print(rows)
    _print_objective(result, m.synthesis.objective)
    if output is not None:
        if not result.feasible:
            raise ModelError([Problem((), "no feasible design to write",
                                      "widen the bounds or change the task")], str(model))
        from mechloop.model.groups import mechanism_of

        mech = mechanism_of(model)  # a group file is written back with the best dimensions
        what = ("the group file with the best dimensions" if mech is not None
                else "the model with the best design")
        out.print(f"wrote {write_model(result, output, mechanism=mech)} ({what})")
    if table is not None:
        out.print(f"wrote {write_table(result, table)}")
    if plot is not None:
        out.print(f"wrote {save_figure(plot_convergence(result), plot)}")
    if fit is not None:
        out.print(f"wrote {save_figure(plot_fit(result), fit)}")


@app.command(name="cam", cls=_Command)
@user_errors
def cam_command(
    model: Annotated[Path, typer.Argument(help="cam design file (.yaml, .yml or .json) "
                                          "holding cam:", show_default=False)],
    program: Annotated[Path | None, typer.Option(help="plot s, v, a, j over the cam angle "
                       "(.png, .svg, .pdf); default: none")] = None,
    profile: Annotated[Path | None, typer.Option(help="plot the profile, pitch curve, base "
                       "circle and rollers; default: none")] = None,
    pressure: Annotated[Path | None, typer.Option(help="plot the pressure angle; default: "
                        "none")] = None,
    curvature: Annotated[Path | None, typer.Option(help="plot the radius of curvature; "
                         "default: none")] = None,
    plan: Annotated[Path | None, typer.Option(help="draw cam and follower at --at; "
                    "default: none")] = None,
    at: Annotated[float, typer.Option(help="cam angle of the plan, deg")] = 0.0,
    animation: Annotated[Path | None, typer.Option("--animate", help="the plan over one "
                         "turn (.gif, .mp4, .html); default: none")] = None,
    frames: Annotated[int, typer.Option(min=2, max=3600, help="frames of the animation "
                      "over one turn")] = 72,
    table: Annotated[Path | None, typer.Option("--table", help="the cam over the turn: "
                     ".csv, .json, .parquet or .xlsx (SI units, angles in deg); default: "
                     "none")] = None,
    dxf: Annotated[Path | None, typer.Option(help="the profile as a DXF drawing (mm); "
                   "default: none")] = None,
    svg: Annotated[Path | None, typer.Option(help="the profile as an SVG drawing (mm); "
                   "default: none")] = None,
    vector_model: Annotated[Path | None, typer.Option("--model", help="the same cam as a "
                            "vector model with intermediate arguments (.yaml or .json; "
                            "translating followers; default: none)")] = None,
    force: Force = False,
) -> None:
    """Design a disc cam by inverted motion (course sheet 4): translating or oscillating
    roller follower, or flat-faced follower; the follower's motion by segments and laws.
    Prints the base radius (given, or the smallest for the allowed pressure angle or a
    convex profile), the largest pressure angle, the smallest radius of curvature with the
    undercut check, the face width, the peak coefficients, and writes figures and files.

    Example:

    ```
    mechloop cam examples/cams/roller.yaml --profile cam.png --dxf cam.dxf
    ```
    """
    import math

    from mechloop.cams.document import load_cam
    from mechloop.cams.export import write_dxf, write_svg, write_table
    from mechloop.cams.plots import animate_cam, plot_cam
    from mechloop.cams.summary import summary_rows
    from mechloop.views.animation import ANIMATION_SUFFIXES
    from mechloop.views.figure import FIGURE_SUFFIXES, save_figure

    if not math.isfinite(at):
        raise typer.BadParameter(f"{at}: give a cam angle in degrees", param_hint="--at")
    figures = {"program": program, "profile": profile, "pressure": pressure,
               "curvature": curvature, "plan": plan}
    _outputs(model, force, *((p, FIGURE_SUFFIXES) for p in figures.values()),
             (animation, ANIMATION_SUFFIXES), (table, SUFFIXES), (dxf, (".dxf",)),
             (svg, (".svg",)), (vector_model, (".yaml", ".yml", ".json")))
    design = load_cam(model)
    rows, segments, verdicts = summary_rows(design)
    shown = _table(f"Cam — {design.name or model}", ["quantity", "value", "unit"])
    for row in rows:
        shown.add_row(*row)
    out.print(shown)
    laws = _table("Segments and peak coefficients", ["segment", "law", "Cv, Ca, Cj"])
    for row in segments:
        laws.add_row(*row)
    out.print(laws)
    for line in verdicts:
        out.print(line)
    for view, path in figures.items():
        if path is not None:
            save_figure(plot_cam(design, view, phi=math.radians(at)), path)
            out.print(f"wrote {path}")
    if animation is not None:
        with _progress("frames") as bar:
            task = bar.add_task("frames", total=frames)
            animate_cam(design, animation, frames=frames,
                        progress=lambda done, total: bar.update(task, completed=done))
        out.print(f"wrote {animation}")
    for path, writer in ((table, write_table), (dxf, write_dxf), (svg, write_svg)):
        if path is not None:
            out.print(f"wrote {writer(design, path)}")
    if vector_model is not None:
        from mechloop.cams.vector_model import write_vector_model

        out.print(f"wrote {write_vector_model(design, vector_model)} (mechloop plot "
                  f"{vector_model} envelope draws its profile)")


@app.command(cls=_Command)
@user_errors
def indicator(
    model: ModelPath,
    output: Annotated[Path | None, typer.Option(
        "-o", "--output", help="write the diagrams over the positions here (angle, and "
        "each load's stroke, V, p, F): .csv, .json, .parquet or .xlsx (default: none)")
                      ] = None,
    plot_file: Annotated[Path | None, typer.Option(
        "--plot", help="draw p–V and p–φ of each indicator load: .png, .svg or .pdf "
        "(default: none)")] = None,
    force: Force = False,
) -> None:
    """The indicator diagrams of the model's gas forces (forces whose value is an engine's
    or compressor's cycle): stroke, swept and clearance volume, the diagram's work by its
    closed form and over the positions, the mean indicated pressure, the peak pressure.

    Example:

    ```
    mechloop indicator examples/engine_indicator.yaml --plot indicator.png
    ```
    """
    from mechloop.dynamics.indicator import model_indicators
    from mechloop.engines import CompressorCycle, volumetric_efficiency
    from mechloop.model.load import load_model, locate
    from mechloop.views.figure import FIGURE_SUFFIXES

    _outputs(model, force, (output, SUFFIXES), (plot_file, FIGURE_SUFFIXES))
    m = load_model(model)
    try:
        items = model_indicators(m)
    except ModelError as exc:
        raise locate(exc, model) from None
    for item in items:
        gas, cycle = item.gas, item.cycle
        compressor = isinstance(cycle, CompressorCycle)
        kind = "compressor" if compressor else f"{cycle.strokes}-stroke engine"
        rows = _table(f"{item.name}: {kind}", ["quantity", "value"])
        for name, value in (
                ("stroke [mm]", (gas.top - gas.bottom) * 1e3),
                ("swept volume V_h [cm³]", gas.swept * 1e6),
                ("clearance volume V_c [cm³]", gas.clearance * 1e6),
                ("∮p dV, closed form [J]", item.loop_work),
                ("∮p dV over the positions [J]", item.sampled_work),
                ("mean indicated pressure [MPa]", item.loop_work / gas.swept / 1e6),
                ("peak pressure [MPa]", gas.pressure.max() / 1e6)):
            rows.add_row(escape(name), f"{value:.6g}")  # [mm] is no markup tag
        if compressor:
            rows.add_row("volumetric efficiency λ_V", f"{volumetric_efficiency(cycle):.6g}")
        out.print(rows)
    out.print("∮p dV is negative for a compressor (the work it takes); over the positions: "
              "the trapezoidal rule in V through the model's positions")
    if output is not None:
        from mechloop.views.indicator import indicator_frame

        _write_frame(indicator_frame(items), output)
        out.print(f"wrote {output}")
    if plot_file is not None:
        from mechloop.views.figure import save_figure
        from mechloop.views.indicator import plot_indicators

        save_figure(plot_indicators(items, title=m.name), plot_file)
        out.print(f"wrote {plot_file}")
@app.command(name="examples", cls=_Command)
@user_errors
def examples_command(
    course: Annotated[bool, typer.Option("--course", help="the course-project models "
                                         "only")] = False,
) -> None:
    """List the bundled examples: the course-project models (task number, English and
    Russian titles), then every other example with its title.

    Copy one to start from with mechloop new. Example:

    ```
    mechloop examples --course
    ```
    """
    from mechloop.bundled import examples

    found = examples(course_only=course)
    course_rows = [e for e in found if e.course]
    if course_rows:
        rows = _table("Course project (seed 000 sec. 3)", ["No.", "file", "title", "название"])
        for e in course_rows:
            rows.add_row(str(e.number), e.path.name, e.title, e.title_ru)
        out.print(rows)
    others = [e for e in found if not e.course]
    if others:
        rows = _table("Examples", ["file", "title"])
        for e in others:
            rows.add_row(e.path.name, e.title)
        out.print(rows)
    out.print("start from one: mechloop new NAME [DIR] (a task number, a file name or a "
              "unique prefix)")


@app.command(name="new", cls=_Command)
@user_errors
def new_command(
    name: Annotated[str, typer.Argument(help="a course task number (1..20), an example's "
                                        "file name or a unique prefix of it",
                                        show_default=False)],
    target: Annotated[Path | None, typer.Argument(help="folder (default: the current one) "
                                                  "or file to write", show_default=False)
                      ] = None,
) -> None:
    """Copy a bundled example (mechloop examples lists them) to start a model from, with
    the cam and gear documents its project: section names; an existing file is never
    overwritten.

    Example:

    ```
    mechloop new 1 my_models/
    ```
    """
    from mechloop.bundled import new_model

    example, path = new_model(name, target)
    title = example.title + (f" — {example.title_ru}" if example.title_ru else "")
    out.print(f"wrote {path} ({title})")
    from mechloop.bundled.start import project_references

    for reference in project_references(path):
        out.print(f"  with its project document {path.parent / reference}")



gear_app = typer.Typer(help="Involute gear pairs and planetary trains (course project sheet "
                       "3): geometry, checks, drawings, the choice of tooth numbers.",
                       no_args_is_help=True, cls=_Group, rich_markup_mode="markdown")
app.add_typer(gear_app, name="gear")
GearFile = Annotated[Path | None, typer.Argument(help="gear file (.yaml or .json) with a "
                                                 "gear_pair: or planetary: section; or give "
                                                 "the options instead", show_default=False)]


@gear_app.command("pair", cls=_Command)
@user_errors
def gear_pair_command(
    model: GearFile = None,
    module: Annotated[float | None, typer.Option("-m", "--module", help="module m_n, mm "
                      "(without a file)")] = None,
    teeth: Annotated[tuple[int, int] | None, typer.Option("-z", "--teeth", help="z1 z2 "
                     "(without a file)")] = None,
    shifts: Annotated[tuple[float, float] | None, typer.Option("-x", "--shifts", help="x1 x2 "
                      "(without a file; default 0 0)")] = None,
    centre_distance: Annotated[float | None, typer.Option("-a", "--centre-distance",
                               help="centre distance a, mm (without a file; the shifts "
                               "are then balanced for equal specific sliding)")] = None,
    pressure_angle: Annotated[float | None, typer.Option("--pressure-angle", help="α_n, "
                              "degrees (without a file; default 20)")] = None,
    plot: Annotated[Path | None, typer.Option(help="the drawn meshing (.png, .svg, .pdf); "
                    "default: none")] = None,
    sliding: Annotated[Path | None, typer.Option(help="specific sliding over the line of "
                       "action (.png, .svg, .pdf); default: none")] = None,
    output: Annotated[Path | None, typer.Option("-o", "--output", help="the table (.csv, "
                      ".json, .parquet, .xlsx); default: print only")] = None,
    at_diameter: Annotated[list[float] | None, typer.Option("--at-diameter", help="also the "
                           "tooth thickness and chord on this circle, mm (repeat for more "
                           "circles); default: none")] = None,
    force: Force = False,
) -> None:
    """Geometry of an external involute spur gear pair: every diameter, tooth thickness,
    centre distance and working pressure angle, contact ratio, and the undercut,
    pointed-tooth and interference checks.

    Example:

    ```
    mechloop gear pair examples/gears/gear_pair.yaml --plot mesh.png
    mechloop gear pair -m 3 -z 12 24 -x 0.6 0.36
    ```
    """
    from mechloop.gears.commands import run_pair

    run_pair(model, {"module": module, "teeth": teeth, "shifts": shifts,
                     "centre_distance": centre_distance, "pressure_angle": pressure_angle},
             out=out, plot=plot, sliding=sliding, table=output, force=force,
             diameters=at_diameter)


@gear_app.command("planetary", cls=_Command)
@user_errors
def gear_planetary_command(
    model: Annotated[Path, typer.Argument(help="gear file (.yaml or .json) with a "
                                          "planetary: section", show_default=False)],
    plot: Annotated[Path | None, typer.Option(help="the velocity plan (Kutzbach diagram; "
                    ".png, .svg, .pdf); default: none")] = None,
    vector_model: Annotated[Path | None, typer.Option("--model", help="write the train as a "
                            "vector model (.yaml, .json); default: none")] = None,
    output: Annotated[Path | None, typer.Option("-o", "--output", help="the designs found, or "
                      "the analysis (.csv, .json, .parquet, .xlsx); default: print only")
                      ] = None,
    force: Force = False,
) -> None:
    """A planetary train: the ratio by Willis' formula and the coaxiality, assembly and
    neighbour conditions of given tooth numbers; or the choice of tooth numbers for a
    target ratio (every combination tried, best first).

    Example:

    ```
    mechloop gear planetary examples/gears/planetary_choice.yaml --plot plan.png
    ```
    """
    from mechloop.gears.commands import run_planetary

    run_planetary(model, {}, out=out, plot=plot, model=vector_model, table=output,
                  force=force)


@app.command(name="serve", cls=_Command)
@user_errors
def serve(
    target: Annotated[Path | None, typer.Argument(help="a model file (opened first) or a "
                      "folder; files are read and written only inside that folder "
                      "(default: the current folder)", show_default=False)] = None,
    host: Annotated[str, typer.Option(help="address to listen on; another than 127.0.0.1 "
                    "makes the server reachable from other machines (a token is then "
                    "required)")] = "127.0.0.1",
    port: Annotated[int | None, typer.Option(help="port (default: a free one)")] = None,
    browser: Annotated[bool, typer.Option("--browser/--no-browser", help="open the "
                       "browser at the address (default: open)")] = True,
    time_limit: Annotated[float, typer.Option("--time-limit", min=0.1, help="longest "
                          "solve, s (default: 60)")] = 60.0,
) -> None:
    """Start the web application: edit a model with live validation, see the mechanism move,
    plot a parameter, read the results table and download the report, in the browser.

    Example:

    ```
    mechloop serve examples/crank_slider.yaml
    ```
    """
    from mechloop.errors import HintedError

    try:
        from mechloop.web.serve import run
    except ImportError as exc:  # starlette / uvicorn: the web extra
        raise HintedError(f"the web application needs {exc.name}",
                          'pip install "mechloop[web]"') from None

    run(target, host=host, port=port, browser=browser, solve_seconds=time_limit,
        say=lambda text: out.print(text, markup=False))


def _spatial_plot(results, kind: str, position: int, points: list[str], *, elev: float,
                  azim: float, views: str):
    """The plan, overlay or trajectories of a spatial model, in 3-D (issue 17)."""
    from mechloop.views import spatial_plan

    if kind == "plan":
        return spatial_plan.plot_spatial_plan(results, position, views=views, elev=elev,
                                              azim=azim)
    if kind == "overlay":
        return spatial_plan.plot_spatial_overlay(results, views=views, elev=elev, azim=azim)
    return spatial_plan.plot_spatial_trajectories(results, [_point(p) for p in points],
                                                  position=position, views=views,
                                                  elev=elev, azim=azim)


if __name__ == "__main__":  # pragma: no cover
    app()
