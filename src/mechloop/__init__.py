"""mechloop — kinematic and dynamic analysis and synthesis of mechanisms by the modular
vector-loop method.

>>> import mechloop
>>> model = mechloop.load_model("examples/crank_slider.yaml")  # doctest: +SKIP
>>> results = mechloop.solve(model)                              # doctest: +SKIP
>>> results.to_frame()                                           # doctest: +SKIP

The public names are imported on first use (module ``__getattr__``), so that
``import mechloop.cli`` — and ``mechloop --help`` — does not load NumPy, pandas, SciPy or
pint; ``from mechloop import solve`` works as usual.
"""

from __future__ import annotations

import importlib
import sys
import types
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

# public name -> module that defines it
_EXPORTS: dict[str, str] = {
    "ArgumentRole": "mechloop.model.schema",
    "ChainBreak": "mechloop.solve.results",
    "Contour": "mechloop.model.schema",
    "DynamicResults": "mechloop.dynamics.analysis",
    "GroupMechanism": "mechloop.model.groups",
    "IntermediateArgument": "mechloop.model.schema",
    "LawArgument": "mechloop.model.schema",
    "LinkRole": "mechloop.model.schema",
    "MechloopError": "mechloop.errors",
    "Model": "mechloop.model.schema",
    "ModelError": "mechloop.errors",
    "ModelFileError": "mechloop.errors",
    "Problem": "mechloop.errors",
    "Results": "mechloop.solve.results",
    "RpmTime": "mechloop.model.schema",
    "SolveError": "mechloop.errors",
    "TableArgument": "mechloop.model.schema",
    "TableTime": "mechloop.model.schema",
    "Units": "mechloop.model.schema",
    "Vector": "mechloop.model.schema",
    "build_model": "mechloop.model.groups",
    "load_model": "mechloop.model.load",
    "save_model": "mechloop.model.load",
    "simulate": "mechloop.dynamics.simulate",
    "solve": "mechloop.solve.kinematics",
    "solve_dynamics": "mechloop.dynamics.analysis",
    "solve_intermediate": "mechloop.solve.intermediate",
}

__all__ = [
    "ArgumentRole",
    "ChainBreak",
    "Contour",
    "DynamicResults",
    "GroupMechanism",
    "IntermediateArgument",
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
    "simulate",
    "solve",
    "solve_dynamics",
    "solve_intermediate",
]  # the keys of _EXPORTS


def __getattr__(name: str) -> Any:
    """Import a public name from its module on first use and cache it here."""
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'mechloop' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_EXPORTS))


class _Package(types.ModuleType):
    """The package module: importing the subpackage ``mechloop.solve`` must not replace the
    function ``mechloop.solve`` (the import system sets a subpackage as an attribute of its
    parent; the function, imported lazily, keeps the name as before)."""

    def __setattr__(self, name: str, value: Any) -> None:
        if (name in _EXPORTS and isinstance(value, types.ModuleType)
                and value.__name__ == f"{__name__}.{name}"):
            return
        super().__setattr__(name, value)


sys.modules[__name__].__class__ = _Package


if TYPE_CHECKING:  # pragma: no cover - for type checkers and IDEs only
    from mechloop.dynamics.analysis import DynamicResults, solve_dynamics
    from mechloop.errors import (
        MechloopError,
        ModelError,
        ModelFileError,
        Problem,
        SolveError,
    )
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
