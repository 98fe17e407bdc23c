"""The words the report of a model with spatial contours adds to
:data:`mechloop.report.words.TEXT` (issue 17), in English and Russian: the β column, the
3-D scheme and its projections, the coordinates of the vector ends, the angles between
vectors in space, the trajectories, the inertia tensors, the 3-D directions of the loads,
the dynamics by virtual power with the kinetic energy, and the joint reactions by the
Newton–Euler equations (the joints, their reactions and hodographs, the idle motions and
singular positions)."""

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
                           "machine motion is not computed for a model with spatial "
                           "contours.",
        "p_no_joints": "The reactions in the kinematic pairs are computed when the model "
                       "names its joints (joints: the type, the two bodies, the point and "
                       "the axis of each).",
        "p_joints": "The reactions in the kinematic pairs are found from the Newton–Euler "
                    "equations of the bodies, which give the balancing load a second "
                    "time: both are shown below.",
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
        # joint reactions (report/spatial_reactions.py)
        "f_balancing3_ne": "Balancing load by the Newton–Euler equations (solid) and by "
                           "virtual power (dashed)",
        "bal_agree": "The balancing load {name} by the Newton–Euler equations equals the "
                     "one by virtual power to {diff} at every position ({share} of its "
                     "largest value {peak}).",
        "p_reactions3": "The reaction of the first body of each kinematic pair on the "
                        "second (a force through the pair's point and a moment about it, "
                        "in the model's axes) is found at every position from the "
                        "Newton–Euler equations of the moving bodies (bodies: {bodies}, "
                        "equations: {equations}) whose unknowns are the reactions' "
                        "components and the balancing load (unknowns: {unknowns}). The "
                        "rank of the equations is {rank}, as many as the unknowns: the "
                        "force analysis is statically determinate.",
        "t_pairs3": "Kinematic pairs of the spatial model",
        "h_axis3": "axis", "h_components": "components of R; R_m",
        "p_idle": "Idle motions that no pair resists (count: {count}) are balanced by "
                  "themselves: the loads and the inertia balance in them, so their "
                  "equations are dropped: {list}.",
        "p_no_idle": "Every motion of the bodies is resisted by a pair or a drive: no "
                     "equation is dropped.",
        "idle_turn": "body {body} turns about the axis {axis} at position {position}",
        "idle_slide": "body {body} slides along {axis} at position {position}",
        "idle_line": " (the line of joints {joints})",
        "p_singular": "The equations of the forces are singular at positions {list}: the "
                      "reactions are unbounded there and are not given.",
        "p_regular": "The equations of the forces are regular at every position where the "
                     "chain assembles.",
        "f_reactions3": "Magnitudes of the reaction forces in the joints",
        "f_reactions3m": "Magnitudes of the reaction forces and moments in the joints",
        "s_joint3": "Reaction in joint {name}",
        "t_reaction3": "Reaction of {a} on {b} in joint {name} (every position: in the "
                       "appendix)",
        "of_body": "body {n}", "of_body_ground": "the ground",
        "on_body": "body {n}", "on_body_ground": "the ground",
        "f_hodograph3": "Hodograph of the reaction force in joint {name}: the projections "
                        "on the XY, ZY and XZ planes and the 3-D view (the arrow: position "
                        "{position})",
        "peak_reaction_moment": "Peak reaction moment: joint {name}, {value} (at position "
                                "{position}).",
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
                           "кинетическая энергия. Движение машины для модели с "
                           "пространственными контурами не рассчитывается.",
        "p_no_joints": "Реакции в кинематических парах рассчитываются, когда в модели "
                       "заданы кинематические пары: вид, два звена, точка и ось каждой.",
        "p_joints": "Реакции в кинематических парах найдены из уравнений Ньютона — Эйлера "
                    "для звеньев, которые второй раз дают уравновешивающую нагрузку: "
                    "обе показаны ниже.",
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
        "f_balancing3_ne": "Уравновешивающая нагрузка по уравнениям Ньютона — Эйлера "
                           "(сплошная) и по методу мощностей (штрих)",
        "bal_agree": "Уравновешивающая нагрузка {name} по уравнениям Ньютона — Эйлера "
                     "совпадает с найденной методом мощностей во всех положениях с "
                     "точностью {diff} ({share} от её наибольшего значения {peak}).",
        "p_reactions3": "Реакция первого звена каждой кинематической пары на второе (сила, "
                        "проходящая через точку пары, и момент относительно неё, в осях "
                        "модели) найдена в каждом положении из уравнений Ньютона — Эйлера "
                        "для подвижных звеньев (звеньев: {bodies}, уравнений: {equations}); "
                        "неизвестные — составляющие реакций и уравновешивающая нагрузка "
                        "(неизвестных: {unknowns}). Ранг системы уравнений равен {rank}, "
                        "числу неизвестных: задача статически определима.",
        "t_pairs3": "Кинематические пары пространственной модели",
        "h_axis3": "ось", "h_components": "составляющие R; R_m",
        "p_idle": "Местные подвижности — движения, которым не препятствует ни одна пара "
                  "(всего: {count}), — уравновешены сами: нагрузки и силы инерции в них "
                  "взаимно уравновешены, и их уравнения исключены: {list}.",
        "p_no_idle": "Каждому движению звеньев препятствует пара или привод: местных "
                     "подвижностей нет, используются все уравнения.",
        "idle_turn": "звено {body} поворачивается вокруг оси {axis} в положении {position}",
        "idle_slide": "звено {body} смещается вдоль {axis} в положении {position}",
        "idle_line": " (линия шарниров {joints})",
        "p_singular": "Система уравнений сил вырождена в положениях {list}: реакции там "
                      "неограниченны и не приводятся.",
        "p_regular": "Система уравнений сил невырождена во всех положениях, где цепь "
                     "собирается.",
        "f_reactions3": "Модули сил реакций в шарнирах",
        "f_reactions3m": "Модули сил и моментов реакций в шарнирах",
        "s_joint3": "Реакция в шарнире {name}",
        "t_reaction3": "Реакция {a} на {b} в шарнире {name} (все положения — в "
                       "приложении)",
        "of_body": "звена {n}", "of_body_ground": "стойки",
        "on_body": "звено {n}", "on_body_ground": "стойку",
        "f_hodograph3": "Годограф силы реакции в шарнире {name}: проекции на плоскости XY, "
                        "ZY, XZ и пространственный вид (стрелка — положение {position})",
        "peak_reaction_moment": "Наибольший момент реакции: шарнир {name}, {value} (в "
                                "положении {position}).",
    },
}


def spatial_words(lang: str) -> dict[str, str]:
    """The report's words of ``lang`` with the spatial ones added."""
    return {**words(lang), **SPATIAL_TEXT[lang]}
