"""Sheet 4 of the course project, the cam mechanism (seed 000 sec. 2.3–2.6), as content: the
follower's motion program (s, v, a, j), the profile with its base circle, pitch curve and
roller, the pressure angle and the radius of curvature over the turn, a table of the design's
figures with their units, a table of the segments with their laws' peak coefficients, and
the checks in words — in English or Russian.

Every number comes from :meth:`mechloop.cams.CamDesign.summary` (decided over the
continuous cam angle), shown in the cam file's length unit, angles in degrees.
"""

from __future__ import annotations

import math

from matplotlib.figure import Figure

from mechloop.cams.design import CamDesign, Summary
from mechloop.cams.followers import (
    OscillatingFlat,
    OscillatingRoller,
    TranslatingFlat,
    TranslatingRoller,
)
from mechloop.cams.plots import plot_curvature, plot_pressure, plot_profile, plot_program
from mechloop.model.units import unit_factor
from mechloop.views.sheet import (
    FigureItem,
    Sheet,
    Table,
    localized_sheet,
    number_text,
    translate_figure,
)

TEXT: dict[str, dict[str, str]] = {
    "en": {
        "title": "Sheet 4. Cam mechanism",
        "fig_program": "Follower motion program: displacement, velocity, acceleration, jerk",
        "fig_profile": "Cam profile: working profile, pitch curve, base circle, follower",
        "fig_profile_flat": "Cam profile: working profile, base circle, follower's face",
        "fig_pressure": "Pressure angle over the turn",
        "fig_curvature": "Radius of curvature of the profile over the turn",
        "table": "Design of the cam",
        "segments": "Motion program by segments",
        "quantity": "quantity", "symbol": "symbol", "value": "value", "unit": "unit",
        "segment": "segment", "angle": "angle φ, °", "lift": "lift", "law": "law",
        "follower": "follower", "name": "cam",
        "translating_roller": "translating roller follower",
        "oscillating_roller": "oscillating roller follower (rocker)",
        "translating_flat": "translating flat-faced follower",
        "oscillating_flat": "oscillating flat-faced follower (rocker)",
        "roller": "roller radius", "offset": "offset of the follower's axis",
        "pivot": "distance from the cam centre to the rocker's pivot",
        "arm": "rocker arm", "face_offset": "offset of the face from the pivot",
        "base_pitch": "base radius of the pitch curve",
        "base_profile": "base radius of the profile",
        "base_working": "base radius of the working profile",
        "min_pressure": "smallest base radius for the allowed pressure angle",
        "min_convex": "smallest base radius for a convex profile",
        "stroke": "stroke of the follower", "swing": "swing of the rocker",
        "allowed": "allowed pressure angle", "allowed_return": "allowed pressure angle on "
        "returns", "pressure": "largest pressure angle (at φ = {at} °)",
        "ratio": "largest pressure angle / allowed",
        "rho": "smallest radius of curvature of the profile (at φ = {at} °)",
        "rho_inf": "∞ (no convex part)", "allowed_rho": "allowed radius of curvature",
        "face_low": "contact on the face, nearest", "face_high": "contact on the face, "
        "farthest", "face_width": "smallest face width",
        "speed": "cam speed",
        "v": "largest velocity", "a": "largest acceleration", "j": "largest jerk",
        "v_an": "largest velocity analog", "a_an": "largest acceleration analog",
        "j_an": "largest jerk analog", "rpm": "rpm",
        "rise": "rise", "dwell": "dwell", "return": "return",
        "ok_pressure": "The pressure angle stays within the allowed over the whole turn "
                       "(largest {ratio} of the allowed).",
        "bad_pressure": "The pressure angle exceeds the allowed ({ratio} of it): raise the "
                        "base radius{fix}.",
        "fix": " to at least {value} {unit}",
        "ok_roller": "No undercut: the pitch curve's radius of curvature exceeds the roller "
                     "radius wherever the profile is convex.",
        "bad_roller": "Undercut (pointed profile): the pitch curve's radius of curvature "
                      "falls to the roller radius; use a smaller roller or a larger base "
                      "radius.",
        "ok_flat": "The profile is convex over the whole turn (its radius of curvature is at "
                   "least the allowed).",
        "bad_flat": "The profile is not convex: its radius of curvature falls below the "
                    "allowed; raise the base radius.",
        "checked": "Every figure is decided over the continuous cam angle, not at samples.",
    },
    "ru": {
        "title": "Лист 4. Кулачковый механизм",
        "fig_program": "Закон движения толкателя: перемещение, скорость, ускорение, "
                       "рывок",
        "fig_profile": "Профиль кулачка: рабочий и центровой профили, основная окружность, "
                       "толкатель",
        "fig_profile_flat": "Профиль кулачка: рабочий профиль, основная окружность, "
                            "тарелка толкателя",
        "fig_pressure": "Угол давления за оборот кулачка",
        "fig_curvature": "Радиус кривизны профиля за оборот кулачка",
        "table": "Параметры кулачкового механизма",
        "segments": "Фазы закона движения",
        "quantity": "величина", "symbol": "обозн.", "value": "значение",
        "unit": "ед. изм.",
        "segment": "фаза", "angle": "угол φ, °", "lift": "ход", "law": "закон",
        "follower": "толкатель", "name": "кулачок",
        "translating_roller": "поступательный толкатель с роликом",
        "oscillating_roller": "коромысло с роликом",
        "translating_flat": "поступательный толкатель с плоской тарелкой",
        "oscillating_flat": "коромысло с плоской тарелкой",
        "roller": "радиус ролика", "offset": "смещение (дезаксиал) оси толкателя",
        "pivot": "межосевое расстояние кулачок — коромысло",
        "arm": "длина коромысла", "face_offset": "смещение тарелки от оси коромысла",
        "base_pitch": "радиус основной окружности центрового профиля",
        "base_profile": "радиус основной окружности профиля",
        "base_working": "радиус основной окружности рабочего профиля",
        "min_pressure": "наименьший радиус по допустимому углу давления",
        "min_convex": "наименьший радиус по выпуклости профиля",
        "stroke": "ход толкателя", "swing": "угол размаха коромысла",
        "allowed": "допустимый угол давления", "allowed_return": "допустимый угол давления "
        "на фазе возврата", "pressure": "наибольший угол давления (при φ = {at} °)",
        "ratio": "отношение наибольшего угла давления к допустимому",
        "rho": "наименьший радиус кривизны профиля (при φ = {at} °)",
        "rho_inf": "∞ (выпуклых участков нет)",
        "allowed_rho": "допустимый радиус кривизны",
        "face_low": "точка касания на тарелке, ближайшая",
        "face_high": "точка касания на тарелке, дальняя",
        "face_width": "наименьшая ширина тарелки",
        "speed": "частота вращения кулачка",
        "v": "наибольшая скорость", "a": "наибольшее ускорение", "j": "наибольший рывок",
        "v_an": "наибольший аналог скорости", "a_an": "наибольший аналог ускорения",
        "j_an": "наибольший аналог рывка", "rpm": "об/мин",
        "rise": "удаление", "dwell": "выстой", "return": "возврат",
        "ok_pressure": "Угол давления не превышает допустимого за весь оборот кулачка "
                       "(наибольший — {ratio} от допустимого).",
        "bad_pressure": "Угол давления превышает допустимый ({ratio} от него): увеличьте "
                        "радиус основной окружности{fix}.",
        "fix": " не менее чем до {value} {unit}",
        "ok_roller": "Подрезания нет: радиус кривизны центрового профиля больше радиуса "
                     "ролика на всех выпуклых участках.",
        "bad_roller": "Подрезание (заострение) профиля: радиус кривизны центрового профиля "
                      "доходит до радиуса ролика; уменьшите ролик или увеличьте радиус "
                      "основной окружности.",
        "ok_flat": "Профиль выпуклый за весь оборот (радиус кривизны не меньше "
                   "допустимого).",
        "bad_flat": "Профиль не выпуклый: радиус кривизны меньше допустимого; увеличьте "
                    "радиус основной окружности.",
        "checked": "Все величины найдены на непрерывном интервале угла поворота кулачка, "
                   "а не только в расчётных точках.",
    },
}

#: Names of the motion laws (mechloop.cams.laws.LAW_NAMES) in each language.
LAWS: dict[str, dict[str, str]] = {
    "en": {"constant_speed": "constant velocity", "harmonic": "harmonic",
           "cycloidal": "cycloidal", "poly345": "3-4-5 polynomial",
           "poly4567": "4-5-6-7 polynomial", "modified_trapezoidal": "modified trapezoidal",
           "modified_sine": "modified sine", "table": "table"},
    "ru": {"constant_speed": "равномерный", "harmonic": "косинусоидальный",
           "cycloidal": "синусоидальный (циклоидальный)", "poly345": "полином 3-4-5",
           "poly4567": "полином 4-5-6-7", "modified_trapezoidal": "модифицированный "
           "трапецеидальный", "modified_sine": "модифицированный синусоидальный",
           "table": "табличный"},
}

#: The words of the cam figures (mechloop.cams.plots) in Russian; the titles are set here.
FIGURE_WORDS_RU: dict[str, str] = {
    "working profile": "рабочий профиль",
    "pitch curve": "центровой профиль",
    "base circle of the pitch curve": "основная окружность центрового профиля",
    "base circle": "основная окружность",
    "roller radius": "радиус ролика",
    "roller": "ролик",
    "face": "тарелка",
    "cam angle": "угол поворота кулачка",
    "pressure angle": "угол давления",
    "allowed on returns": "допустимый на возврате",
    "allowed": "допустимый",
    "clipped at": "ограничено",
}

#: Units of the tables that differ by language.
UNITS: dict[str, dict[str, str]] = {"en": {"rad": "rad", "s": "s"},
                                    "ru": {"rad": "рад", "s": "с"}}


def cam_sheet(design: CamDesign, lang: str = "en") -> Sheet:
    """The cam sheet of ``design`` in ``lang`` ('en' or 'ru')."""
    text = TEXT[lang]
    summary = design.summary()
    length = design.units[0]
    to = 1.0 / unit_factor(length, "length")
    f = design.follower
    rocker = f.oscillating
    flat = f.flat
    rows: list[tuple[str, str, str, str]] = [(text["follower"], "", text[f.kind], "")]
    if design.name:
        rows.insert(0, (text["name"], "", design.name, ""))

    def add(key: str, symbol: str, value: float, unit: str, **fmt) -> None:
        rows.append((text[key].format(**fmt), symbol, number_text(value), unit))

    if isinstance(f, TranslatingRoller | OscillatingRoller):
        add("roller", "r", f.roller_radius * to, length)
    if isinstance(f, TranslatingRoller):
        add("offset", "e", f.offset * to, length)
    if isinstance(f, OscillatingRoller | OscillatingFlat):
        add("pivot", "a", f.pivot_distance * to, length)
    if isinstance(f, OscillatingRoller):
        add("arm", "l", f.arm * to, length)
    if isinstance(f, OscillatingFlat):
        add("face_offset", "f", f.face_offset * to, length)
    add("base_profile" if flat else "base_pitch", "R₀", summary.base_radius * to, length)
    if not flat:
        add("base_working", "R₀ − r", (summary.base_radius - f.roller_radius) * to,  # type: ignore[union-attr]
            length)
    if summary.minimum is not None:
        add("min_convex" if flat else "min_pressure", "R₀_min", summary.minimum * to, length)
    if rocker:
        add("swing", "ψ_max", math.degrees(summary.stroke), "°")
    else:
        add("stroke", "h", summary.stroke * to, length)
    if design.allowed is not None:
        add("allowed", "[α]", math.degrees(design.allowed), "°")
    if design.allowed_return is not None:
        add("allowed_return", "[α]′", math.degrees(design.allowed_return), "°")
    if summary.pressure is not None:
        add("pressure", "α_max", math.degrees(summary.pressure.value), "°",
            at=f"{math.degrees(summary.pressure.phi):.1f}")
    if summary.pressure_ratio is not None:
        add("ratio", "α/[α]", summary.pressure_ratio, "")
    rho = summary.rho
    at = f"{math.degrees(rho.phi):.1f}"
    if math.isinf(rho.value):
        rows.append((text["rho"].format(at=at), "ρ_min", text["rho_inf"], ""))
    else:
        add("rho", "ρ_min", rho.value * to, length, at=at)
    if flat and design.min_curvature > 0:
        add("allowed_rho", "[ρ]", design.min_curvature * to, length)
    if summary.face is not None:
        add("face_low", "u_min", summary.face.low.value * to, length)
        add("face_high", "u_max", summary.face.high.value * to, length)
        add("face_width", "b_min", summary.face.width * to, length)
    units = UNITS[lang]
    lift_unit, lift = (units["rad"], 1.0) if rocker else (length, to)
    w = design.omega
    if w is not None:
        add("speed", "n", w * 30 / math.pi, text["rpm"])
    for k, name in enumerate(("v", "a", "j"), start=1):
        power = "" if k == 1 else "²³"[k - 2]
        if w is None:
            add(f"{name}_an", f"{name}_max", summary.peak(name) * lift,
                f"{lift_unit}/{units['rad']}{power}")
        else:
            add(name, f"{name}_max", summary.peak(name) * lift * w**k,
                f"{lift_unit}/{units['s']}{power}")
    table = Table(text["table"], (text["quantity"], text["symbol"], text["value"],
                                  text["unit"]), rows)
    segments = []
    lift_shown = ("°", 180 / math.pi) if rocker else (length, to)
    for seg, peak in zip(design.program.segments, summary.peaks, strict=True):
        law = "—" if seg.law is None else LAWS[lang].get(seg.law.name, seg.law.name)
        lifted = "—" if seg.kind == "dwell" else number_text(seg.lift * lift_shown[1])
        coefficients = ("—", "—", "—") if peak is None else (
            number_text(peak.velocity), number_text(peak.acceleration), number_text(peak.jerk))
        segments.append((text[seg.kind], number_text(math.degrees(seg.angle)), lifted, law,
                         *coefficients))
    segment_table = Table(text["segments"], (text["segment"], text["angle"],
                                             f"{text['lift']}, {lift_shown[0]}",
                                             text["law"], "C_v", "C_a", "C_j"), segments)
    return localized_sheet(Sheet(4, text["title"], lang, _figures(design, lang),
                                 [table, segment_table],
                                 _verdicts(design, summary, text, length, to)))


def _verdicts(design: CamDesign, s: Summary, text: dict[str, str], length: str, to: float
              ) -> list[str]:
    lines = []
    if s.pressure_ratio is not None:
        ratio = f"{s.pressure_ratio:.3g}"
        if s.pressure_ratio <= 1 + 1e-9:
            lines.append(text["ok_pressure"].format(ratio=ratio))
        else:
            fix = "" if s.minimum is None else text["fix"].format(
                value=number_text(s.minimum * to), unit=length)
            lines.append(text["bad_pressure"].format(ratio=ratio, fix=fix))
    if design.follower.flat:
        lines.append(text["bad_flat" if s.undercut else "ok_flat"])
    else:
        lines.append(text["bad_roller" if s.undercut else "ok_roller"])
    lines.append(text["checked"])
    return lines


def _figures(design: CamDesign, lang: str) -> list[FigureItem]:
    text = TEXT[lang]

    def titled(draw, key: str):
        def make() -> Figure:  # the caption says what it is; the name is in the table
            figure = draw(design)
            figure.axes[0].set_title("")
            return translate_figure(figure, FIGURE_WORDS_RU) if lang == "ru" else figure
        return FigureItem(text[key], make)

    profile = "fig_profile_flat" if design.follower.flat else "fig_profile"
    items = [titled(plot_program, "fig_program"), titled(plot_profile, profile)]
    if not isinstance(design.follower, TranslatingFlat):  # its pressure angle is 0
        items.append(titled(plot_pressure, "fig_pressure"))
    items.append(titled(plot_curvature, "fig_curvature"))
    return items
