"""Writing a synthesis result: the best design as a model file, the table of the best
designs with every term of the best one, and the plots — each file written atomically."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pandas as pd

from mechloop.model.groups import GroupMechanism, mechanism_text, with_dimensions
from mechloop.model.load import model_to_data
from mechloop.output.atomic import atomic_file, atomic_write_text
from mechloop.output.tables import check_table_size, write_frame
from mechloop.synthesis.search import SynthesisResult
from mechloop.synthesis.variables import is_input


def terms_frame(result: SynthesisResult) -> pd.DataFrame:
    """One row per term of the best design: Q, the mandatory conditions, each measured
    quantity and each penalty."""
    return pd.DataFrame({"term": list(result.terms()), "value": list(result.terms().values())})


def write_table(result: SynthesisResult, path: str | os.PathLike[str]) -> Path:
    """The best designs (CSV, JSON, Parquet or XLSX by the suffix); an XLSX file also gets
    a sheet with the terms of the best design and one with the convergence history."""
    target = Path(path)
    if target.suffix.lower() != ".xlsx":
        return write_frame(result.designs, target)
    for frame in (result.designs, result.history):
        check_table_size(len(frame), len(frame.columns), target)
    with atomic_file(target) as handle, pd.ExcelWriter(handle, engine="openpyxl") as writer:
        result.designs.to_excel(writer, sheet_name="designs", index=False)
        terms_frame(result).to_excel(writer, sheet_name="terms", index=False)
        result.history.to_excel(writer, sheet_name="history", index=False)
    return target


def write_model(result: SynthesisResult, path: str | os.PathLike[str], *,
                mechanism: GroupMechanism | None = None) -> Path:
    """The model with the best design written in (YAML, or JSON by the suffix).

    With ``mechanism`` (the :class:`~mechloop.model.groups.GroupMechanism` the model was
    built from, default: none) the group file is written instead: the mechanism with the
    best dimensions (``result.values()``, keyed by their names) and its ``synthesis:``
    section kept, to refine or solve.

    With free timing the written model is the mechanism alone: the target inputs
    (``input@target1`` ...) are no constants of it.  A YAML file gets them in a comment
    at its top (argument 1 in its model unit), so that the file says where each target
    is reached; ``result.values()``, the table and ``mechloop synthesize`` report them
    with the other variables.  The file is written once, atomically, comment included.
    """
    target = Path(path)
    json_form = target.suffix.lower() == ".json"
    inputs = {name: value for name, value in result.values().items() if is_input(name)}
    if mechanism is not None:
        text = mechanism_text(with_dimensions(
            mechanism, {k: v for k, v in result.values().items() if not is_input(k)}),
            json_form=json_form)
    elif json_form:
        text = json.dumps(model_to_data(result.model), indent=2, ensure_ascii=False) + "\n"
    else:
        import yaml

        text = yaml.safe_dump(model_to_data(result.model), sort_keys=False,
                              allow_unicode=True)
    if not json_form:  # how the design was found, and its verdict
        text = "".join(f"# {line}\n" for line in result.summary()) + text
    if inputs and not json_form:
        unit = result.problem.variables.units[result.problem.variables.input_columns[0]]
        lines = [f"# free timing: target k is reached at argument 1 = input@targetk ({unit})"]
        lines += [f"#   {name}: {value:.12g}" for name, value in inputs.items()]
        text = "\n".join(lines) + "\n" + text
    atomic_write_text(target, text)
    return target
