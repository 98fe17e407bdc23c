"""Unit names as the documents print them: ``N·m``, ``m/s²``, ``°``, and in Russian the
Russian designations of GOST 8.417 (``Н·м``, ``м/с²``, ``об/мин``)."""

from __future__ import annotations

import re

#: The Russian designations of the unit names mechloop prints (GOST 8.417).
RUSSIAN_UNITS: dict[str, str] = {
    "m": "м", "mm": "мм", "cm": "см", "km": "км", "dm": "дм", "kg": "кг", "g": "г",
    "t": "т", "N": "Н", "kN": "кН", "MN": "МН", "kgf": "кгс", "s": "с", "ms": "мс",
    "min": "мин", "h": "ч", "rad": "рад", "grad": "гон", "rpm": "об/мин", "W": "Вт",
    "kW": "кВт", "MW": "МВт", "hp": "л. с.", "J": "Дж", "kJ": "кДж", "Pa": "Па",
    "kPa": "кПа", "MPa": "МПа", "bar": "бар", "turn": "об", "rev": "об", "Hz": "Гц",
}
_TOKEN = re.compile(r"[A-Za-z_]+")
_POWERS = {"2": "²", "3": "³", "4": "⁴", "-1": "⁻¹", "-2": "⁻²"}


def unit_text(unit: str, lang: str) -> str:
    """A unit as printed: ``'N*m'`` -> ``'N·m'`` (``'Н·м'`` in Russian),
    ``'m/s^2'`` -> ``'m/s²'``, ``'deg'`` -> ``'°'``."""
    if unit in ("deg", "degree"):
        return "°"
    text = unit.replace("**", "^").replace(" ", "")
    text = re.sub(r"\^\(?(-?\d)\)?", lambda m: _POWERS.get(m.group(1), "^" + m.group(1)),
                  text)
    text = text.replace("*", "·")
    if lang == "ru":
        text = _TOKEN.sub(lambda m: RUSSIAN_UNITS.get(m.group(0), m.group(0)), text)
    text = text.replace("deg", "°")
    # '(kN·m)/рад' keeps its brackets; a lone '(м)' does not need them
    return re.sub(r"\(([^()·/]+)\)", r"\1", text)
