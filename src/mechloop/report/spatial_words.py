"""The words the report of a model with spatial contours adds to
:data:`mechloop.report.words.TEXT` (issue 17), in English and Russian: the β column, the
3-D scheme and its projections, the coordinates of the vector ends, the angles between
vectors in space, the trajectories, the inertia tensors, the 3-D directions of the loads
and the dynamics by virtual power with the kinetic energy."""

from __future__ import annotations

from mechloop.report.words import words

SPATIAL_TEXT: dict[str, dict[str, str]] = {
    "en": {
        "t_vectors3": "Vectors of the model (r — length, α — elevation above the XZ "
                      "plane, β — rotation about the Y axis)",
        "f_plan3": "Vector scheme of the mechanism in the intermediate position "
                   "{position}: the projections on the XY, ZY and XZ planes and the "
                   "3-D view",
        "t_joints": "Coordinates of the vector ends in the intermediate position "
                    "{position}",
        "h_tail": "tail", "h_head": "head",
        "s_angles3": "Angles between the links in space",
        "f_angle3": "Angle between vectors {a} and {b} in space",
        "no_angles3": "No angle between adjacent vectors varies.",
        "s_trajectories": "Trajectories of the points of the mechanism",
        "f_trajectories": "Trajectories of the moving vector ends over the cycle: the "
                          "projections and the 3-D view",
        "t_bodies3": "Bodies: mass characteristics (the inertia tensor about the centre of "
                     "mass in the body's axes: e1 along its first vector, e3 normal to "
                     "its first two vectors)",
        "h_axial": "J11; J22; J33", "h_products": "J12; J23; J13",
        "d_vector": "({x}; {y}; {z})",
        "d_along3": "along vector {v}",
        "d_plane": "{angle} from the X axis in the XY plane",
        "h_axis": "axis (x; y; z)",
        "o_gravity_v3": "g = {g}, direction {angle} from the X axis in the XY plane",
        "p_virtual_power": "The dynamics of the spatial mechanism is computed by the "
                           "principle of virtual power: the balancing load on the input, "
                           "the reduced characteristics and the kinetic energy. The "
                           "reactions in the kinematic pairs and the machine motion are "
                           "not computed for a model with spatial contours.",
        "p_static": "The model has no time: the analysis is static (no inertia loads, "
                    "no kinetic energy).",
        "f_balancing3": "Balancing load by virtual power",
        "s_energy": "Work of the loads and kinetic energy",
        "t_works": "Work of the loads over the cycle",
        "h_load": "load", "h_work_plus": "A+", "h_work_minus": "A−", "h_work": "A",
        "t_energy": "Kinetic energy and the balance of works over the cycle",
        "e_t_span": "kinetic energy T over the cycle",
        "e_t_change": "change of the kinetic energy T(N) − T(0)",
        "e_works_sum": "sum of the works of every load and the balancing load",
        "f_energy": "Kinetic energy of the mechanism",
        "energy_range": "Kinetic energy of the mechanism T: {low} … {high}.",
        "bal_load": "balancing load {name}",
        "at_positions": "positions {list}",
    },
    "ru": {
        "t_vectors3": "Векторы модели (r — длина, α — угол возвышения над плоскостью XZ, "
                      "β — угол поворота вокруг оси Y)",
        "f_plan3": "Векторная схема механизма в промежуточном положении {position}: "
                   "проекции на плоскости XY, ZY, XZ и пространственный вид",
        "t_joints": "Координаты концов векторов в промежуточном положении {position}",
        "h_tail": "начало", "h_head": "конец",
        "s_angles3": "Углы между звеньями в пространстве",
        "f_angle3": "Угол между векторами {a} и {b} в пространстве",
        "no_angles3": "Углы между соседними векторами не меняются.",
        "s_trajectories": "Траектории точек механизма",
        "f_trajectories": "Траектории подвижных концов векторов за цикл: проекции и "
                          "пространственный вид",
        "t_bodies3": "Звенья: массовые характеристики (тензор инерции относительно центра "
                     "масс в осях звена: e1 вдоль его первого вектора, e3 по нормали к "
                     "двум первым векторам)",
        "h_axial": "J11; J22; J33", "h_products": "J12; J23; J13",
        "d_vector": "({x}; {y}; {z})",
        "d_along3": "вдоль вектора {v}",
        "d_plane": "{angle} от оси X в плоскости XY",
        "h_axis": "ось (x; y; z)",
        "o_gravity_v3": "g = {g}, направление {angle} от оси X в плоскости XY",
        "p_virtual_power": "Динамика пространственного механизма рассчитана методом "
                           "мощностей (принцип возможных мощностей): уравновешивающая "
                           "нагрузка на входном звене, приведённые характеристики и "
                           "кинетическая энергия. Реакции в кинематических парах и "
                           "движение машины для модели с пространственными контурами не "
                           "рассчитываются.",
        "p_static": "Время в модели не задано: расчёт статический (без сил инерции и "
                    "кинетической энергии).",
        "f_balancing3": "Уравновешивающая нагрузка по методу мощностей",
        "s_energy": "Работа нагрузок и кинетическая энергия",
        "t_works": "Работа нагрузок за цикл",
        "h_load": "нагрузка", "h_work_plus": "A+", "h_work_minus": "A−", "h_work": "A",
        "t_energy": "Кинетическая энергия и баланс работ за цикл",
        "e_t_span": "кинетическая энергия T за цикл",
        "e_t_change": "изменение кинетической энергии T(N) − T(0)",
        "e_works_sum": "сумма работ всех нагрузок и уравновешивающей нагрузки",
        "f_energy": "Кинетическая энергия механизма",
        "energy_range": "Кинетическая энергия механизма T: {low} … {high}.",
        "bal_load": "уравновешивающая нагрузка {name}",
        "at_positions": "положения {list}",
    },
}


def spatial_words(lang: str) -> dict[str, str]:
    """The report's words of ``lang`` with the spatial ones added."""
    return {**words(lang), **SPATIAL_TEXT[lang]}
