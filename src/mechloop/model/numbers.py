"""The numbers a model file may hold: finite, of a sane size, and short quantity strings.

Every numeric field of the schema uses :data:`Number` (a plain number) or
:data:`Scalar` (a number, or a string with its unit such as ``"50 mm"``), so a ``.inf``,
a ``.nan`` or a ``1e200`` is refused where it enters, with its place in the file:

* a number is finite and at most :data:`MAX_MAGNITUDE` (1e12) in size, in the model's
  units — a kilometre in micrometres is 1e9, so real models stay far inside, while the
  squares and products the solvers form stay finite; a number smaller than
  :data:`MIN_MAGNITUDE` (1e-100) in size counts as 0 (subnormal numbers such as 5e-324
  overflow once divided, and no physical value is that close to 0 in any unit);
* a quantity string is at most :data:`MAX_QUANTITY_CHARS` (100) characters: pint takes
  time quadratic in the length of a name it does not know (8,000 characters: 0.9 s;
  100,000: minutes), and recurses once per token of a unit expression; its value is
  checked the same way once converted (:func:`mechloop.model.units.to_si`).
"""

from __future__ import annotations

import math
from typing import Annotated

from pydantic import AfterValidator, StringConstraints
from pydantic_core import PydanticCustomError

#: Largest magnitude of a number in a model file (in the model's units) and in SI.
MAX_MAGNITUDE = 1e12
#: Numbers smaller than this in size count as 0, likewise.
MIN_MAGNITUDE = 1e-100
#: Longest quantity string such as ``"50 mm"``, characters.
MAX_QUANTITY_CHARS = 100

RANGE = "a finite number between -{0} and {0}".format(f"{MAX_MAGNITUDE:.0e}".replace("e+", "e"))


def usable(value: float) -> bool:
    """Whether ``value`` is finite and at most :data:`MAX_MAGNITUDE` in size."""
    return math.isfinite(value) and abs(value) <= MAX_MAGNITUDE


def flush(value: float) -> float:
    """``value``, or 0.0 when it is smaller than :data:`MIN_MAGNITUDE` in size."""
    return 0.0 if abs(value) < MIN_MAGNITUDE else value


def _number(value: float) -> float:
    if not usable(value):
        raise PydanticCustomError("number_range", f"{value} is outside the range of a "
                                  f"model value ({RANGE})")
    return flush(value)


def _scalar(value: float | str) -> float | str:
    if isinstance(value, str):
        if len(value) > MAX_QUANTITY_CHARS:
            raise PydanticCustomError(
                "quantity_length", f"a quantity of {len(value)} characters (a number and a "
                f"unit are at most {MAX_QUANTITY_CHARS})")
        return value
    return _number(value)


#: A plain number: finite, at most 1e12 in size (below 1e-100 it counts as 0).
Number = Annotated[float, AfterValidator(_number)]

#: A constant: a number in the model's units, or a string with its own unit ("50 mm").
Scalar = Annotated[float | str, AfterValidator(_scalar)]

#: A unit such as ``"mm"`` or ``"kN*m"``: at most 100 characters.
UnitName = Annotated[str, StringConstraints(max_length=MAX_QUANTITY_CHARS)]

#: A quantity string alone (the string branch of a tagged union).
QuantityText = Annotated[str, AfterValidator(_scalar)]
