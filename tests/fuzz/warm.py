"""Imported by the fuzz harness's fork server: run every command on every example and on a
model with a CSV table once, so the children forked from the server start warm."""

from __future__ import annotations

import tempfile
from pathlib import Path

from .harness import COMMANDS, warm_up
from .mutations import EXAMPLES

for _example in EXAMPLES:  # the JSON writer is warmed once, below
    warm_up(_example, COMMANDS[:2])

with tempfile.TemporaryDirectory() as _tmp:
    _model = Path(_tmp) / "model.yaml"
    _model.write_text(EXAMPLES[0].read_text(encoding="utf-8").replace(
        "{table: {0: 0, 72: 360}}", "{csv: table.csv}"), encoding="utf-8")
    (Path(_tmp) / "table.csv").write_text("position,value\n0,0\n72,360\n", encoding="utf-8")
    warm_up(_model)
