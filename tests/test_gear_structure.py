"""Gear meshes in the structure tool (:mod:`mechloop.structure.meshes`): a ratio link
between two bodies is a higher pair, counted as p4 in Chebyshev's formula, and replaced by
its equivalent link with two revolute pairs for the Assur decomposition — against hand
counts of a compound gear train and of a four-bar whose rocker carries a gear.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from test_ratio_solved_angles import geared_four_bar
from typer.testing import CliRunner

from mechloop import ModelError, load_model
from mechloop.cli import app
from mechloop.structure.analysis import analyze

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
TRAIN_BODIES = ("bodies:\n  1: {name: pinion, vectors: [1]}\n"
                "  2: {name: shaft II, vectors: [2, 3]}\n  3: {name: wheel 4, vectors: [4]}\n")


def test_compound_train_two_meshes(tmp_path) -> None:
    """Pinion 1, shaft II (wheel 2 and gear 3 on one body), wheel 4, each pinned to the
    frame: n = 3, p5 = 3, p4 = 2 meshes, W = 9 − 6 − 2 = 1 (the one input).  Each mesh
    replaced by a link with two pins: L0(1) → L1(2,4) → L1(3,5)."""
    file = tmp_path / "train.yaml"
    file.write_text((EXAMPLES / "gear_train.yaml").read_text() + TRAIN_BODIES)
    mob, dec = analyze(load_model(file))
    assert (mob.n, mob.p5, mob.p4, mob.W, mob.inputs) == (3, 3, 2, 1, 1) and mob.ok
    text = str(mob)
    assert "between bodies 1 and 2, ratio -0.4" in text
    assert "between bodies 2 and 3, ratio -0.5" in text
    assert dec.formula == "L0(1) → L1(2,4) → L1(3,5)"
    assert sum("replaced by its equivalent" in n for n in dec.notes) == 2


def test_geared_rocker_structure() -> None:
    """Crank 1, coupler 2, rocker 3 (carrying the pinion's mark 5), wheel 4 pinned to the
    frame: n = 4, p5 = 4 + 1, p4 = 1, W = 12 − 10 − 1 = 1; the four-bar's dyad, then the
    wheel and the mesh's equivalent link 5 as a second RRR dyad."""
    import mechloop

    base = geared_four_bar(0.1, 0.3, 0.25, 0.3, k=-0.4, n=36)
    data = base.model_dump(mode="python", exclude_none=True)
    data["bodies"] = {1: {"vectors": [1]}, 2: {"vectors": [2]}, 3: {"vectors": [3, 5]},
                      4: {"vectors": [7]}}
    model = mechloop.Model.from_dict(data)
    mob, dec = analyze(model)
    assert (mob.n, mob.p5, mob.p4, mob.W, mob.inputs) == (4, 5, 1, 1, 1) and mob.ok
    assert "between bodies 3 and 4, ratio -0.4" in str(mob)
    assert dec.formula == "L0(1) → L1(2,3) → L1(4,5)"


def test_a_mesh_with_no_partner_body_is_located(tmp_path) -> None:
    """The wheel is a body, the pinion is not: the mesh's other member is no link."""
    file = tmp_path / "pair.yaml"
    text = (EXAMPLES / "gear_pair.yaml").read_text() + "bodies:\n  2: {vectors: [3]}\n"
    file.write_text(text)
    with pytest.raises(ModelError) as info:
        analyze(load_model(file))
    (problem,) = info.value.problems
    assert problem.path == ("vectors", 3, "a", "ratio") and "in no body" in problem.message
    assert "add vector 1" in problem.hint


def test_structure_command_prints_the_meshes(tmp_path) -> None:
    file = tmp_path / "train.yaml"
    file.write_text((EXAMPLES / "gear_train.yaml").read_text() + TRAIN_BODIES)
    out = CliRunner().invoke(app, ["structure", str(file)])
    assert out.exit_code == 0, out.output
    assert "p4 = 2" in out.output and "W = 3·3 − 2·3 − 2 = 1" in out.output
    assert "structure formula: L0(1) → L1(2,4) → L1(3,5)" in out.output
