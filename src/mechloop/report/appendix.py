"""The appendix of the report: the values of every parameter at every position, the
results table (:meth:`Results.to_frame` / :meth:`DynamicResults.to_frame`) in the display
units, as tables of at most :data:`COLUMNS` columns (the position and seven more), each
header 'name, unit'.

A column with no value at any position is left out; the chain-break column only when the
chain breaks somewhere, as a word of the report's language; every column's numbers are
printed to the precision of its largest value (zero to that precision is 0), a value
below :data:`NOISE` of the largest of its unit in the table printed as 0; a broken row's
values are '—'."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd

from mechloop.output.display import convert_frame
from mechloop.report.document import Table
from mechloop.report.numbers import Shown, unit_text
from mechloop.report.values import symbol

#: Columns of one appendix table, the position's included.
COLUMNS = 8

_HEADER = re.compile(r"^(.*) \[([^\[\]]+)\]$")
_ANGLE = re.compile(r"d{0,2}[ab]\d+")
#: Column names that are words, as symbols.
_NAMES = {"time": "t", "omega": "ω", "epsilon": "ε", "omega_fw": "ω_fw",
          "epsilon_fw": "ε_fw", "friction_loss": "P_fr"}
_TO = re.compile(r"^(R\w+?)_to_a(\d+)$")


def header_text(column: str, lang: str, names: tuple[str, ...] = ()) -> str:
    """'r3 [m]' -> 'r3, m'; 'da2 [rad/s]' -> 'dα2, rad/s' ('рад/с' in Russian); a
    reaction or mesh column of a joint or mesh of ``names`` longer than two letters with
    the name in brackets ('Gmesh_n [N]' -> 'G(mesh)_n, N')."""
    match = _HEADER.match(column)
    if match is None:
        return column
    name, unit = match.groups()
    for joint in sorted(names, key=len, reverse=True):
        if len(joint) > 2 and name[:1] in "RG" and name[1:].startswith(joint) \
                and name[1 + len(joint):][:1] in ("", "_"):
            name = f"{name[0]}({joint}){name[1 + len(joint):]}"
            break
    to = _TO.match(name)
    shown = (symbol(name) if _ANGLE.fullmatch(name) else
             f"∠({to.group(1)}, α{to.group(2)})" if to else _NAMES.get(name, name))
    return f"{shown}, {unit_text(unit, lang)}"


def shown_frame(frame: pd.DataFrame, shown: Shown) -> pd.DataFrame:
    """``frame`` in the display units, its empty columns left out (the chain-break
    column too when nothing breaks)."""
    # converted only: the cells are rounded once, to their column's precision
    converted = convert_frame(frame, shown.td) if shown.td is not None and shown.td.units \
        else frame
    keep = []
    for column in converted.columns:
        values = converted[column]
        if column == "chain_break":
            if values.any():
                keep.append(column)
        elif values.dtype.kind in "biu" or np.isfinite(values.to_numpy(dtype=float)).any():
            keep.append(column)
    return converted[keep]


#: A value below this share of the largest value of its unit in the whole table is the
#: solver's rounding noise (1e-12 N·m of a slider's inertia moment beside 50 N·m).
NOISE = 1e-9


def _rounding_noise_as_zero(data: pd.DataFrame) -> pd.DataFrame:
    """``data`` with the values that are rounding noise beside the largest value of the
    same unit (over every column of that unit) set to 0."""
    units: dict[str, list[str]] = {}
    for column in data.columns:
        match = _HEADER.match(column)
        if match is not None and data[column].dtype.kind == "f":
            units.setdefault(match.group(2), []).append(column)
    data = data.copy()
    for columns in units.values():
        values = data[columns].to_numpy(dtype=float)
        finite = np.isfinite(values)
        if not finite.any():
            continue
        scale = np.abs(values[finite]).max()
        noise = finite & (np.abs(np.where(finite, values, 0.0)) <= NOISE * scale)
        data[columns] = np.where(noise, 0.0, values)
    return data


def appendix_tables(frame: pd.DataFrame, shown: Shown, w: dict[str, str],
                    names: tuple[str, ...] = ()) -> list[Table]:
    """The appendix's tables of ``frame`` (a results table in SI headers); ``names``:
    the joints and gear meshes (see :func:`header_text`)."""
    data = shown_frame(frame, shown)
    broken = data["chain_break"].to_numpy(dtype=bool) if "chain_break" in data \
        else np.zeros(len(data), dtype=bool)
    data = _rounding_noise_as_zero(data)
    texts: dict[str, list[str]] = {}
    for column in data.columns:
        values = data[column]
        if column == "chain_break":
            texts[w["chain_break"]] = [w["chain_break"] if b else "" for b in broken]
        elif values.dtype.kind in "biu":
            texts[header_text(column, shown.lang, names)] = [str(int(v)) for v in values]
        else:
            texts[header_text(column, shown.lang, names)] = shown.column(
                values.to_numpy(dtype=float))
    first, *rest = list(texts)
    parts = [rest[i:i + COLUMNS - 1] for i in range(0, len(rest), COLUMNS - 1)]
    first_name = w["h_position"]
    tables = []
    for k, part in enumerate(parts, start=1):
        columns = [first, *part]
        rows = [tuple(texts[c][i] for c in columns) for i in range(len(data))]
        tables.append(Table(w["t_appendix"].format(part=k, parts=len(parts)),
                            (first_name, *part), rows))
    return tables
