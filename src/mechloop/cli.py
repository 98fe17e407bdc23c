"""The ``mechloop`` command: a thin shell over the public API.

Every error a user can cause prints the :class:`~mechloop.errors.MechloopError` message and
exits with code 2, without a traceback.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Callable
from functools import wraps
from pathlib import Path
from typing import Annotated, Any

import typer
from rich.console import Console
from rich.table import Table

from mechloop.errors import MechloopError
from mechloop.model.formula import describe_structure
from mechloop.model.load import atomic_write_bytes, atomic_write_text, load_model
from mechloop.model.schema import model_json_schema
from mechloop.solve.kinematics import solve as solve_model

app = typer.Typer(
    name="mechloop",
    help="Kinematic analysis of mechanisms by the modular vector-loop method.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
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
            err.print(f"[bold red]error:[/] {exc}", markup=True, soft_wrap=True)
            raise typer.Exit(code=2) from None

    return wrapper


@app.command()
@user_errors
def check(model: ModelPath) -> None:
    """Validate a model file; every problem is listed with its line and the fix.

    Example: mechloop check examples/crank_slider.yaml
    """
    m = load_model(model)
    n_vec = len(m.vectors)
    out.print(f"{model}: OK — {len(m.contours)} contour(s), {n_vec} vectors, "
              f"{len(m.arguments)} argument(s), positions 0..{m.positions}")


@app.command()
@user_errors
def info(model: ModelPath) -> None:
    """Print the structure and parametric formula of every contour (KDAM's "structure of
    the vector model" panel).

    Example: mechloop info examples/four_bar.yaml
    """
    m = load_model(model)
    out.print(describe_structure(m))


SUFFIXES = (".csv", ".json", ".xlsx")


@app.command()
@user_errors
def solve(
    model: ModelPath,
    output: Annotated[Path | None, typer.Option(
        "-o", "--output", help="write the table here: .csv, .json or .xlsx (default: print "
        "a summary only)")] = None,
) -> None:
    """Solve positions, velocities and accelerations at every position.

    Example: mechloop solve examples/crank_slider.yaml -o results.csv
    """
    if output is not None and output.suffix.lower() not in SUFFIXES:
        err.print(f"[bold red]error:[/] {output}: unknown output format "
                  f"'{output.suffix}'\n    fix: use a file name ending in .csv, .json or .xlsx")
        raise typer.Exit(code=2)
    m = load_model(model)
    results = solve_model(m)
    frame = results.to_frame()
    for brk in results.breaks:
        err.print(f"[yellow]chain break:[/] {brk.describe()} — check the kinematic chain "
                  "for a break (dimensions, variant, argument range)")
    if output is None:
        out.print(frame.to_string(max_rows=20, max_cols=12))
        return
    _write_frame(frame, output)
    rows = len(frame)
    broken = int(results.broken.sum())
    out.print(f"wrote {output} ({rows} positions, {len(frame.columns)} columns"
              + (f", {broken} with a chain break" if broken else "") + ")")


def _write_frame(frame, output: Path) -> None:
    suffix = output.suffix.lower()
    if suffix == ".csv":
        atomic_write_text(output, frame.to_csv(index=False))
    elif suffix == ".json":
        records = json.loads(frame.to_json(orient="records", double_precision=15))
        atomic_write_text(output, json.dumps(records, indent=1) + "\n")
    else:
        import io

        buffer = io.BytesIO()
        frame.to_excel(buffer, index=False, sheet_name="results")
        atomic_write_bytes(output, buffer.getvalue())


@app.command()
def schema(
    output: Annotated[Path | None, typer.Option("-o", "--output",
                                                help="write the schema to this file "
                                                "(default: print it)")] = None,
) -> None:
    """Print the JSON Schema of model files (generated from the code).

    Example: mechloop schema -o model.schema.json
    """
    text = json.dumps(model_json_schema(), indent=2, ensure_ascii=False) + "\n"
    if output is None:
        sys.stdout.write(text)
    else:
        atomic_write_text(output, text)


def _table(title: str, headers: list[str]) -> Table:
    table = Table(title=title)
    for h in headers:
        table.add_column(h)
    return table


if __name__ == "__main__":  # pragma: no cover
    app()
