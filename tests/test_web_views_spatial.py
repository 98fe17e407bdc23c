"""The page's views of a spatial model with joints (issue 17 in the web app, issue 16):
the reduced characteristics, the reactions and a reaction's hodograph (its three
projections as panels) carry the spatial dynamics' numbers; the machine motion is refused
with its reason."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from starlette.testclient import TestClient

from mechloop.model.load import load_model
from mechloop.spatial.dynamics import solve_spatial_dynamics
from mechloop.web.app import create_app

RSSR = Path(__file__).resolve().parents[1] / "examples" / "spatial" / "rssr_reactions.yaml"


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    folder = tmp_path_factory.mktemp("served")
    (folder / RSSR.name).write_text(RSSR.read_text(encoding="utf-8"), encoding="utf-8")
    return TestClient(create_app(folder))


def _view(client, kind: str, status: int = 200, **extra) -> dict:
    answer = client.post("/api/view", json={"text": RSSR.read_text(encoding="utf-8"),
                                            "path": RSSR.name, "kind": kind,
                                            "format": "data", "lang": "en", **extra})
    assert answer.status_code == status, answer.text
    return answer.json()


def _series(data: dict) -> dict[str, dict]:
    return {s["label"].split(" [")[0]: s for p in data["panels"] for y in p["yaxes"]
            for s in y["series"]}


def _values(values: list) -> np.ndarray:
    return np.array([np.nan if v is None else v for v in values], dtype=float)


def test_a_spatial_models_views_carry_its_dynamics(client):
    dyn = solve_spatial_dynamics(load_model(RSSR))
    reactions = _series(_view(client, "reactions"))
    for name, joint in dyn.reactions.joints.items():
        np.testing.assert_allclose(_values(reactions[f"|R{name}|"]["y"]),
                                   np.linalg.norm(joint.force, axis=0), rtol=1e-9)
    hodograph = _view(client, "hodograph", joint="A", position=4)
    assert len(hodograph["panels"]) == 3  # XY, ZY, XZ; the 3-D view is the page's own
    front = hodograph["panels"][0]
    (curve,) = [s for y in front["yaxes"] for s in y["series"]
                if len(s["x"]) == dyn.kinematics.positions.size]
    np.testing.assert_allclose(_values(curve["x"]), dyn.reactions.joints["A"].force[0],
                               rtol=1e-9)
    np.testing.assert_allclose(_values(curve["y"]), dyn.reactions.joints["A"].force[1],
                               rtol=1e-9)
    reduced = _series(_view(client, "reduced"))
    j_red = next(s for name, s in reduced.items() if name.startswith("J_red"))
    np.testing.assert_allclose(_values(j_red["y"]), dyn.reduced[0], rtol=1e-9)
    refused = _view(client, "motion", status=422)
    assert "machine motion" in str(refused)
