"""The breaks of the kinematic chain in words, in the report's language: where (which
contour or coupled block, at which positions or between which two), and why."""

from __future__ import annotations

import math

from mechloop.report.numbers import Shown
from mechloop.report.values import module_text
from mechloop.report.words import reason
from mechloop.solve.results import BreakBetween, ChainBreak, Results, compress_positions


def break_text(found: ChainBreak, shown: Shown, w: dict[str, str]) -> str:
    """'contour 1 (Pl4) breaks at positions 30-42: the two vectors cannot close …'."""
    if len(found.contours) > 1:
        where = w["break_block"].format(list=", ".join(map(str, found.contours)))
    else:
        where = w["break_contour"].format(n=found.contour,
                                          module=module_text(found.module, shown.lang))
    return w["break_at"].format(where=where[0].upper() + where[1:],
                                positions=compress_positions(found.positions),
                                reason=reason(found.reason, shown.lang))


def between_text(found: BreakBetween, shown: Shown, w: dict[str, str]) -> str:
    """'contour 1 (Pl4) cannot be assembled between positions 36 and 37 …'."""
    def value(x: float) -> str:
        return shown.angle(x) if found.kind == "angle" else shown.text(x, "m")

    at = (w["break_at_value"].format(x=value(found.start))
          if math.isclose(found.start, found.stop) else
          w["break_range"].format(x=value(found.start), y=value(found.stop)))
    text = w["break_between"].format(n=found.contour,
                                     module=module_text(found.module, shown.lang),
                                     a=found.after, b=found.after + 1,
                                     x=value(found.at[0]), y=value(found.at[1]), at=at)
    return text[0].upper() + text[1:]


def break_lines(results: Results, shown: Shown, w: dict[str, str]) -> list[str]:
    """Every break of ``results`` described, at positions and between them."""
    return ([break_text(b, shown, w) for b in results.breaks]
            + [between_text(b, shown, w) for b in results.breaks_between])
