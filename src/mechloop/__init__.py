"""mechloop — kinematic and dynamic analysis and synthesis of mechanisms by the modular
vector-loop method.

>>> import mechloop
>>> model = mechloop.load_model("examples/crank_slider.yaml")  # doctest: +SKIP
>>> results = mechloop.solve(model)                              # doctest: +SKIP
>>> results.to_frame()                                           # doctest: +SKIP
"""

from mechloop.dynamics.analysis import DynamicResults, solve_dynamics
from mechloop.errors import MechloopError, ModelError, ModelFileError, Problem, SolveError
from mechloop.model.groups import GroupMechanism, build_model
from mechloop.model.load import load_model, save_model
from mechloop.model.schema import (
    ArgumentRole,
    Contour,
    LawArgument,
    LinkRole,
    Model,
    RpmTime,
    TableArgument,
    TableTime,
    Units,
    Vector,
)
from mechloop.solve.kinematics import solve
from mechloop.solve.results import ChainBreak, Results

__version__ = "0.1.0"

__all__ = [
    "ArgumentRole",
    "ChainBreak",
    "Contour",
    "DynamicResults",
    "GroupMechanism",
    "LawArgument",
    "LinkRole",
    "MechloopError",
    "Model",
    "ModelError",
    "ModelFileError",
    "Problem",
    "Results",
    "RpmTime",
    "SolveError",
    "TableArgument",
    "TableTime",
    "Units",
    "Vector",
    "build_model",
    "load_model",
    "save_model",
    "solve",
    "solve_dynamics",
]
