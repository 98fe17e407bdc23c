"""What ``mechloop gear pair`` and ``mechloop gear planetary`` do, called by the command
line with its consoles (the CLI only parses options)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import yaml
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from mechloop.errors import HintedError, ModelError, Problem
from mechloop.gears.document import (
    GearDocument,
    choice_of,
    no_design,
    pair_of,
    read_gear_document,
    section,
    train_of,
)
from mechloop.gears.tables import choice_table, pair_table, thickness_table, train_table
from mechloop.model.document import located_error, validate_data

TABLE_SUFFIXES = (".csv", ".json", ".parquet", ".xlsx")
FIGURES = (".png", ".svg", ".pdf")


def _document(path: Path | None, options: dict[str, Any], key: str
              ) -> tuple[GearDocument, str | None, dict]:
    """The document of a file, or of the command line's options (``{key: options}``)."""
    given = {k: v for k, v in options.items() if v is not None}
    if path is not None:
        if given:
            raise HintedError("give a gear file or options like --module, not both",
                              f"drop {', '.join('--' + k.replace('_', '-') for k in given)} "
                              "or the file")
        doc, lines = read_gear_document(path)
        return doc, str(path), lines
    if not given:
        raise HintedError("no gear data: give a file or the options",
                          "e.g. mechloop gear pair examples/gears/gear_pair.yaml")
    doc, problems = validate_data(GearDocument, {key: given}, None)
    if problems or doc is None:  # told by the option's name
        raise ModelError([Problem((), f"--{str(p.path[-1]).replace('_', '-')}: {p.message}"
                                  if len(p.path) > 1 else p.message, p.hint)
                          for p in problems])
    return doc, None, {}


def _print_frame(console: Console, frame, title: str) -> None:
    table = Table(title=title)
    for column in frame.columns:
        table.add_column(escape(str(column)), justify="left" if frame[column].dtype == object
                         else "right")
    for row in frame.itertuples(index=False):
        table.add_row(*("" if isinstance(v, float) and math.isnan(v) else
                        f"{v:.6g}" if isinstance(v, float | np.floating) else escape(str(v))
                        for v in row))
    console.print(table)


def _check_outputs(*pairs: tuple[Path | None, tuple[str, ...]], inputs: list[Path],
                   force: bool) -> None:
    from mechloop.output.paths import check_output

    for path, suffixes in pairs:
        if path is not None:
            check_output(path, suffixes=suffixes, inputs=inputs, force=force)


def run_pair(path: Path | None, options: dict[str, Any], *, out: Console, plot: Path | None,
             sliding: Path | None, table: Path | None, force: bool,
             diameters: list[float] | None = None) -> None:
    """Compute, print and write what ``mechloop gear pair`` asks for."""
    _check_outputs((plot, FIGURES), (sliding, FIGURES), (table, TABLE_SUFFIXES),
                   inputs=[path] if path else [], force=force)
    doc, file, lines = _document(path, options, "gear_pair")
    spec = section(doc, "gear_pair", file or "the options", lines)
    pair = pair_of(spec, file=file, lines=lines)
    frame = pair_table(pair)
    _print_frame(out, frame, spec.name or "External involute spur gear pair")
    if diameters:
        _print_frame(out, thickness_table(pair, diameters), "Tooth thickness on the circles "
                     "asked for (where the circle cuts the gear's involute)")
    for check in pair.checks():
        mark = "[green]ok[/]" if check.ok else "[bold red]FAILS[/]"
        out.print(f"{mark} {check.name}: {check.text}", markup=True)
    if table is not None:
        from mechloop.output.tables import write_frame

        write_frame(frame, table)
        out.print(f"wrote {table}")
    if plot is not None or sliding is not None:
        from mechloop.gears.drawing import draw_mesh, plot_sliding
        from mechloop.views.figure import save_figure

        if plot is not None:
            out.print(f"wrote {save_figure(draw_mesh(pair, title=spec.name), plot)}")
        if sliding is not None:
            out.print(f"wrote {save_figure(plot_sliding(pair), sliding)}")


def run_planetary(path: Path | None, options: dict[str, Any], *, out: Console,
                  plot: Path | None, model: Path | None, table: Path | None,
                  force: bool) -> None:
    """Analyse a planetary train, or choose its tooth numbers, as ``mechloop gear
    planetary`` asks."""
    _check_outputs((plot, FIGURES), (model, (".yaml", ".yml", ".json")),
                   (table, TABLE_SUFFIXES), inputs=[path] if path else [], force=force)
    doc, file, lines = _document(path, options, "planetary")
    spec = section(doc, "planetary", file or "the options", lines)
    train = train_of(spec, file=file, lines=lines)
    frame = None
    if train is None:
        choice = choice_of(spec, file=file, lines=lines)
        s = spec.search
        frame = choice_table(choice, s.show)
        out.print(f"{choice.tried:,} combinations of teeth tried, {len(choice):,} meet the "
                  f"ratio {spec.target_ratio:g} ± {100 * s.tolerance:g} % with "
                  f"{spec.planets} planets (coaxial, assembled, clear of each other)")
        if not len(choice):
            raise located_error([no_design(spec)], file, lines)
        _print_frame(out, frame, f"Designs of the {choice.scheme_name} scheme, best first")
        train = choice.train(0, spec.module, spec.addendum)
        out.print("the best design is analysed below")
    from mechloop.gears.wolfrom import WolfromTrain

    wolfrom = isinstance(train, WolfromTrain)
    if wolfrom and model is not None:
        raise HintedError("--model writes the 2K-H schemes (simple, two-row) as vector "
                          "models; the wolfrom train is not written", "drop --model")
    summary = train_table(train, spec.input_speed)
    title = spec.name or f"Planetary train ({train.title if wolfrom else train.scheme.title})"
    _print_frame(out, summary, title + ": " + ", ".join(f"z_{k} = {v}" for k, v in
                                                         train.teeth.items()))
    for ok, text in ((train.coaxial, "coaxiality"), (train.assembles, "assembly"),
                     (train.neighbour_margin > 0, "neighbours")):
        out.print(("[green]ok[/] " if ok else "[bold red]FAILS[/] ") + text, markup=True)
    if spec.target_ratio is not None:
        error = abs(train.ratio - spec.target_ratio) / abs(spec.target_ratio)
        out.print(f"ratio {train.ratio:.6g} against the target {spec.target_ratio:g}: "
                  f"error {100 * error:.3g} %")
    if table is not None:
        from mechloop.output.tables import write_frame

        write_frame(frame if frame is not None else summary, table)
        out.print(f"wrote {table}")
    if plot is not None:
        from mechloop.gears.velocity_plan import plot_velocity_plan, plot_wolfrom_plan
        from mechloop.views.figure import save_figure

        draw = plot_wolfrom_plan if wolfrom else plot_velocity_plan
        out.print(f"wrote {save_figure(draw(train, spec.input_speed), plot)}")
    if model is not None:
        from mechloop.gears.vector_model import vector_model
        from mechloop.model.load import model_from_data
        from mechloop.output.atomic import atomic_write_text

        data = vector_model(train)
        model_from_data(data)  # the written model loads
        atomic_write_text(model, yaml.safe_dump(data, sort_keys=False, allow_unicode=True))
        out.print(f"wrote {model} (the train as a vector model: mechloop solve {model})")

