"""Design variables: which constants of a model a synthesis varies, their bounds, and the
way back from a vector of values to a model file.

A variable is a vector parameter (``r3``, ``a5``: a constant, a link's delta or an
argument's offset) or a coordinate of a contour's fixed start (``start1.x``).  Inside the
search every value is SI (m, rad); bounds and saved models are in the model's units.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.model.schema import ArgumentRole, LinkRole, Model
from mechloop.model.units import to_si, unit_factor

Array = NDArray[np.float64]


def kind_of(name: str) -> str:
    """``'length'`` or ``'angle'``: the kind of quantity a variable is."""
    return "angle" if name[0] == "a" else "length"


@dataclass(frozen=True)
class Variables:
    """The design variables of a task, in the order of the columns of a design matrix.

    ``low`` and ``high`` are SI bounds, shape ``(V,)``.
    """

    names: tuple[str, ...]
    low: Array
    high: Array
    units: tuple[str, ...]

    def __len__(self) -> int:
        return len(self.names)

    def overrides(self, designs: Array) -> dict[str, Array]:
        """Vector-parameter overrides for :func:`~mechloop.solve.designs.solve_designs`
        from a design matrix ``(D, V)`` (SI)."""
        return {name: designs[:, i] for i, name in enumerate(self.names)
                if not name.startswith("start")}

    def starts(self, designs: Array) -> dict[int, tuple[Array | None, Array | None]]:
        """Contour number -> (x, y) of its start per design, shape ``(D,)`` (None where
        that coordinate is not varied)."""
        out: dict[int, list[Array | None]] = {}
        for i, name in enumerate(self.names):
            if name.startswith("start"):
                number, axis = name[5:].split(".")
                out.setdefault(int(number), [None, None])["xy".index(axis)] = designs[:, i]
        return {k: (v[0], v[1]) for k, v in out.items()}

    def to_model_units(self, design: Array) -> dict[str, float]:
        """One design ``(V,)`` in SI -> {name: value in the model's units}."""
        return {name: float(value) / unit_factor(unit, kind_of(name))
                for name, value, unit in zip(self.names, design, self.units, strict=True)}

    def scale(self, unit: Array) -> Array:
        """Map ``[0, 1]^V`` to the bounds."""
        return self.low + unit * (self.high - self.low)

    def unscale(self, designs: Array) -> Array:
        """Map the bounds to ``[0, 1]^V``."""
        return (designs - self.low) / (self.high - self.low)


def compile_variables(model: Model) -> Variables:
    """The variables of ``model.synthesis`` with SI bounds."""
    task = model.synthesis
    if task is None:
        raise ValueError("the model has no synthesis task")
    names = tuple(task.vary)
    units = tuple(getattr(model.units, kind_of(n)) for n in names)
    low = np.array([to_si(task.vary[n][0], kind_of(n), u) for n, u in zip(names, units,
                                                                          strict=True)])
    high = np.array([to_si(task.vary[n][1], kind_of(n), u) for n, u in zip(names, units,
                                                                           strict=True)])
    return Variables(names, low, high, units)


def current_values(model: Model, variables: Variables) -> Array:
    """The model's own values of the variables, SI, shape ``(V,)`` (clipped to the
    bounds): the design the model file describes."""
    values = []
    for name in variables.names:
        if name.startswith("start"):
            number, axis = name[5:].split(".")
            raw = model.contours[int(number) - 1].start["xy".index(axis)]
        else:
            vector = model.vectors[int(name[1:])]
            role = vector.r if name[0] == "r" else vector.a
            raw = (role.offset if isinstance(role, ArgumentRole)
                   else role.delta if isinstance(role, LinkRole) else role)
        values.append(to_si(raw, kind_of(name), getattr(model.units, kind_of(name))))
    return np.clip(np.array(values), variables.low, variables.high)


def apply_design(model: Model, values: Mapping[str, float]) -> Model:
    """A copy of ``model`` with the variables set to ``values`` (model units); the
    synthesis task is kept, so the result can be refined by another run."""
    data = model.model_dump(mode="json", exclude_defaults=True)
    for name, value in values.items():
        value = float(value)
        if name.startswith("start"):
            number, axis = name[5:].split(".")
            start = list(data["contours"][int(number) - 1]["start"])
            start["xy".index(axis)] = value
            data["contours"][int(number) - 1]["start"] = start
            continue
        vector = data["vectors"][str(int(name[1:]))]
        role = vector[name[0]]
        if isinstance(role, dict) and "argument" in role:
            role["offset"] = value
        elif isinstance(role, dict) and "link" in role:
            role["delta"] = value
        else:
            vector[name[0]] = value
    return Model.model_validate(data)
