// Every string of the interface, in English and Russian.  An element with data-i18n="key"
// shows WORDS[lang][key]; the scripts ask t(key, values) for the strings they build.
"use strict";

const WORDS = {
  en: {
    model: "Model", file: "File", save: "Save", report: "Report",
    addCurve: "+ curve", removeCurve: "remove this curve",
    overlay: "all positions", addTrace: "+ trajectory", removeTrace: "remove this trajectory",
    pointHead: "head of vector {n}", pointTail: "tail of vector {n}",
    pointCenter: "centre of mass {n}", pointJoint: "joint {n}",
    downloads: "Download", tableFile: "Table", figureFile: "Plot", modelFile: "Model file",
    downloading: "preparing {name}…", downloaded: "downloaded {name}",
    structure: "Structure", formula: "structure formula",
    mechanismClass: "class of the mechanism", noClass: "not determined",
    mobility: "mobility (Chebyshev)", inputs: "inputs",
    group: "Group", links: "Links", pairs: "Pairs", variant: "Variant",
    noBodies: "the model has no bodies, so only the vector model's structure is shown",
    editor: "Model (YAML)", problems: "Problems", mechanism: "Mechanism", play: "Play",
    pause: "Pause", plot: "Plot", table: "Results at this position", quantity: "Quantity",
    value: "Value", unit: "Unit", files: "Files in the folder", examples: "Bundled examples",
    position: "position {k} of 0..{n}", time: "t = {t} s",
    fix: "fix", line: "line {n}", solving: "solving…", solved: "solved",
    checking: "checking…", saved: "saved {path}", saving: "saving…",
    writing: "writing the report…", written: "report downloaded",
    invalid: "the model has problems", broken: "chain break at position {k}",
    breakReason: "contour {contour} ({module}): {reason}", failed: "failed: {error}",
    axisPosition: "position", ok: "no problems", unsaved: "give a file name to save to",
    stepBack: "one position back", stepForward: "one position forward",
    forward: "forward", backward: "backward",
    synthesis: "Synthesis", jobStart: "Synthesize", jobCancel: "Cancel",
    jobOpen: "Open the result", jobStarting: "starting…",
    jobProgress: "generation {k} of {n}, best Q = {q}", jobNoFeasible: "no feasible design yet",
    jobStopping: "stopping, keeping the best…",
    jobDone: "done ({stopped}): best Q = {q}", jobInfeasible: "done ({stopped}): no feasible design",
    jobFailed: "the synthesis failed — {error}", jobOpened: "the synthesized model is in the editor",
    stopInterrupted: "cancelled", stopLimit: "generation limit", stopGood: "good enough",
    stopTime: "time budget spent", stopPatience: "no progress", stopOther: "stopped",
    view: "View", viewNone: "none", viewIncrement: "increment",
    viewAngle: "angle between vectors", viewReduced: "reduced characteristics",
    viewBalancing: "balancing load", viewReactions: "reactions", viewHodograph: "hodograph",
    viewSummary: "energy summary", viewMotion: "machine motion",
    viewNames: "names, comma-separated (a parameter; two vector numbers; joints)",
    viewJoint: "joint of the hodograph", viewFailed: "the view cannot be drawn — {error}",
    undo: "Undo", redo: "Redo", undoTitle: "undo (Ctrl+Z)",
    redoTitle: "redo (Ctrl+Shift+Z, Ctrl+Y)",
    restore: "Restore", discard: "Discard",
    restoreOffer: "an unsaved working copy of this model ({time}) differs from the file",
    restored: "the working copy is back in the editor",
    newModel: "New…", newModelTitle: "a new model from a course task or an example",
    courseTasks: "Course project tasks", newOpened: "new model from {name}: not saved yet",
    saveAs: "Save as", cancel: "Cancel",
    plotHelp: "wheel or a dragged box zooms, a double click shows all positions, a click goes to a position",
    tab_yaml: "Text (YAML)", tab_arguments: "Arguments", tab_time: "Time", tab_vectors: "Vectors",
    tab_bodies: "Masses", tab_loads: "Forces", tab_synthesis: "Synthesis",
    editFailed: "the edit was not made — {error}", formDelete: "✕",
    formDeleteTitle: "delete this entry", formArgument: "Argument",
    formArgumentN: "Argument {n}", formFill: "filled by", formKind_table: "table",
    formKind_law: "motion law", formKind_intermediate: "intermediate sweep",
    formKind_csv: "CSV file", formDerivatives: "derivatives",
    formRule_linear: "linear fill", formRule_spline: "cubic spline",
    formPosition: "position", formValue: "value", formAddRow: "+ row",
    formImportCsv: "import CSV…", formCsvEmpty: "the CSV file has no rows of two numbers",
    formLaw: "law", formLaw_constant_speed: "constant speed", formLaw_harmonic: "harmonic",
    formLaw_cycloidal: "cycloidal", formLaw_poly345: "polynomial 3-4-5",
    formLawStart: "from (position, value)", formLawEnd: "to (position, value)",
    formUnit: "unit", formAddArgument: "+ argument",
    formPositions: "Calculation positions", formPositionsN: "N (positions 0..N)",
    formTime: "Model time", formTime_none: "no time (positions only)",
    formTime_rpm: "speed of the input", formTime_table: "time table",
    formRpm: "rpm", formTurns: "turns over the positions",
    formVectors: "Vectors", formNumber: "No.", formLength: "length r",
    formAngle: "angle α", formName: "name", formRole_constant: "constant",
    formRole_function: "function", formRole_argument: "argument", formRole_link: "link",
    formArgNumber: "argument number", formOffset: "offset",
    formLinkTo: "linked parameter (a2, r3)", formRatio: "ratio", formDelta: "added constant",
    formAddVector: "+ vector", formContours: "Contours",
    formContourVectors: "vectors of the loop", formVariant: "variant",
    formVariant_1: "1", formVariant_2: "2", formVariant_auto: "auto",
    formAddContour: "+ contour", formBodies: "Bodies (masses)",
    formBodyVectors: "vectors", formMass: "mass", formInertia: "moment of inertia",
    formCenter: "centre of mass", formAddBody: "+ body", formGravity: "Gravity",
    formJoints: "Joints", formFriction: "Friction", formSprings: "Springs",
    formDampers: "Dampers",
    formForces: "Forces", formMoments: "Moments", formLoad_body: "body",
    formLoad_at: "point", formLoad_value: "value", formLoad_angle: "angle",
    formLoad_along: "along vector", formLoad_name: "name", formAddForce: "+ force",
    formAddMoment: "+ moment", formSynthesis: "Synthesis settings",
    formNoSynthesis: "the model has no synthesis section",
    formStale: "the YAML cannot be read, so the forms show the last model that could",
    dragHelp: "drag a round handle to change a vector's length, a yellow one to move a ground point",
    dragLength: "drag: the length of vector {n}",
    dragGround: "drag: the ground point at the head of vector {n} (length and angle)",
  },
  ru: {
    model: "Модель", file: "Файл", save: "Сохранить", report: "Отчёт",
    addCurve: "+ кривая", removeCurve: "убрать эту кривую",
    overlay: "все положения", addTrace: "+ траектория",
    removeTrace: "убрать эту траекторию", pointHead: "конец вектора {n}",
    pointTail: "начало вектора {n}", pointCenter: "центр масс {n}", pointJoint: "пара {n}",
    downloads: "Скачать", tableFile: "Таблица", figureFile: "График",
    modelFile: "Файл модели", downloading: "подготовка {name}…",
    downloaded: "загружено: {name}", structure: "Строение",
    formula: "формула строения", mechanismClass: "класс механизма",
    noClass: "не определён",
    mobility: "подвижность (по Чебышёву)", inputs: "входов",
    group: "Группа", links: "Звенья", pairs: "Пары", variant: "Вариант",
    noBodies: "в модели нет тел, поэтому показано только строение векторной модели",
    editor: "Модель (YAML)", problems: "Ошибки", mechanism: "Механизм", play: "Пуск",
    pause: "Пауза", plot: "График", table: "Результаты в этом положении",
    quantity: "Величина", value: "Значение", unit: "Единица", files: "Файлы папки",
    examples: "Встроенные примеры", position: "положение {k} из 0..{n}",
    time: "t = {t} с", fix: "исправление", line: "строка {n}",
    solving: "расчёт…", solved: "рассчитано", checking: "проверка…",
    saved: "сохранено: {path}", saving: "сохранение…", writing: "создание отчёта…",
    written: "отчёт загружен", invalid: "в модели есть ошибки",
    broken: "разрыв цепи в положении {k}",
    breakReason: "контур {contour} ({module}): {reason}", failed: "ошибка: {error}",
    axisPosition: "положение", ok: "ошибок нет", unsaved: "укажите имя файла для сохранения",
    stepBack: "на положение назад", stepForward: "на положение вперёд",
    forward: "вперёд", backward: "назад",
    synthesis: "Синтез", jobStart: "Синтезировать", jobCancel: "Прервать",
    jobOpen: "Открыть результат", jobStarting: "запуск…",
    jobProgress: "поколение {k} из {n}, лучшее Q = {q}",
    jobNoFeasible: "допустимого решения пока нет",
    jobStopping: "остановка с сохранением лучшего…",
    jobDone: "готово ({stopped}): лучшее Q = {q}",
    jobInfeasible: "готово ({stopped}): допустимого решения нет",
    jobFailed: "синтез не удался — {error}", jobOpened: "синтезированная модель в редакторе",
    stopInterrupted: "прервано", stopLimit: "предел поколений", stopGood: "достаточно точно",
    stopTime: "время вышло", stopPatience: "нет улучшения", stopOther: "остановлено",
    view: "Вид", viewNone: "нет", viewIncrement: "приращение",
    viewAngle: "угол между векторами", viewReduced: "приведённые характеристики",
    viewBalancing: "уравновешивающая нагрузка", viewReactions: "реакции",
    viewHodograph: "годограф", viewSummary: "энергетический баланс",
    viewMotion: "движение машины",
    viewNames: "имена через запятую (параметр; два номера векторов; пары)",
    viewJoint: "пара годографа", viewFailed: "вид не построен — {error}",
    undo: "Отменить", redo: "Вернуть", undoTitle: "отменить (Ctrl+Z)",
    redoTitle: "вернуть (Ctrl+Shift+Z, Ctrl+Y)",
    restore: "Восстановить", discard: "Отбросить",
    restoreOffer: "несохранённая рабочая копия этой модели ({time}) отличается от файла",
    restored: "рабочая копия возвращена в редактор",
    newModel: "Новая…", newModelTitle: "новая модель из задания курсового проекта или примера",
    courseTasks: "Задания курсового проекта", newOpened: "новая модель из {name}: ещё не сохранена",
    saveAs: "Сохранить как", cancel: "Отмена",
    plotHelp: "колесо или рамка — масштаб, двойной щелчок — все положения, щелчок — переход к положению",
    tab_yaml: "Текст", tab_arguments: "Аргументы", tab_time: "Время", tab_vectors: "Векторы",
    tab_bodies: "Массы", tab_loads: "Силы", tab_synthesis: "Синтез",
    editFailed: "изменение не внесено — {error}", formDelete: "✕",
    formDeleteTitle: "удалить эту запись", formArgument: "Аргумент",
    formArgumentN: "Аргумент {n}", formFill: "задание", formKind_table: "таблица",
    formKind_law: "закон движения", formKind_intermediate: "промежуточный перебор",
    formKind_csv: "файл CSV", formDerivatives: "производные",
    formRule_linear: "линейное заполнение", formRule_spline: "кубический сплайн",
    formPosition: "положение", formValue: "значение", formAddRow: "+ строка",
    formImportCsv: "импорт CSV…", formCsvEmpty: "в файле CSV нет строк из двух чисел",
    formLaw: "закон", formLaw_constant_speed: "постоянная скорость",
    formLaw_harmonic: "гармонический", formLaw_cycloidal: "циклоидальный",
    formLaw_poly345: "полином 3-4-5",
    formLawStart: "от (положение, значение)", formLawEnd: "до (положение, значение)",
    formUnit: "единица", formAddArgument: "+ аргумент",
    formPositions: "Расчётные положения", formPositionsN: "N (положения 0..N)",
    formTime: "Время модели", formTime_none: "без времени (только положения)",
    formTime_rpm: "скорость входного звена", formTime_table: "таблица времени",
    formRpm: "об/мин", formTurns: "оборотов за положения",
    formVectors: "Векторы", formNumber: "№", formLength: "длина r",
    formAngle: "угол α", formName: "имя", formRole_constant: "постоянный",
    formRole_function: "функция", formRole_argument: "аргумент", formRole_link: "связь",
    formArgNumber: "номер аргумента", formOffset: "смещение",
    formLinkTo: "связанный параметр (a2, r3)", formRatio: "множитель",
    formDelta: "добавка", formAddVector: "+ вектор", formContours: "Контуры",
    formContourVectors: "векторы контура", formVariant: "вариант",
    formVariant_1: "1", formVariant_2: "2", formVariant_auto: "авто",
    formAddContour: "+ контур", formBodies: "Тела (массы)",
    formBodyVectors: "векторы", formMass: "масса", formInertia: "момент инерции",
    formCenter: "центр масс", formAddBody: "+ тело", formGravity: "Сила тяжести",
    formJoints: "Кинематические пары", formFriction: "Трение", formSprings: "Пружины",
    formDampers: "Демпферы",
    formForces: "Силы", formMoments: "Моменты", formLoad_body: "тело",
    formLoad_at: "точка", formLoad_value: "значение", formLoad_angle: "угол",
    formLoad_along: "вдоль вектора", formLoad_name: "имя", formAddForce: "+ сила",
    formAddMoment: "+ момент", formSynthesis: "Параметры синтеза",
    formNoSynthesis: "в модели нет раздела синтеза",
    formStale: "YAML не читается, поэтому формы показывают последнюю прочитанную модель",
    dragHelp: "тяните круглую метку, чтобы изменить длину вектора, жёлтую — чтобы сдвинуть точку стойки",
    dragLength: "тянуть: длина вектора {n}",
    dragGround: "тянуть: точка стойки в конце вектора {n} (длина и угол)",
  },
};

// Units as the tables write them, in Russian (the rest are shown as written).
const UNITS_RU = {
  s: "с", m: "м", mm: "мм", cm: "см", deg: "град", rad: "рад", N: "Н", kN: "кН",
  "N*m": "Н·м", J: "Дж", W: "Вт", kW: "кВт", kg: "кг", "rad/s": "рад/с",
  "rad/s^2": "рад/с²", "m/s": "м/с", "m/s^2": "м/с²", "mm/s": "мм/с", "mm/s^2": "мм/с²",
  rpm: "об/мин", "rad/rad": "рад/рад", "m/rad": "м/рад", "rad/rad^2": "рад/рад²",
  "m/rad^2": "м/рад²", "kg*m^2": "кг·м²",
};

let LANG = "en";

function t(key, values) {
  let text = (WORDS[LANG] && WORDS[LANG][key]) || WORDS.en[key] || key;
  for (const [name, value] of Object.entries(values || {})) {
    text = text.split("{" + name + "}").join(String(value));
  }
  return text;
}

function unitText(unit) {
  return LANG === "ru" && UNITS_RU[unit] ? UNITS_RU[unit] : unit;
}

// A column of the results table by name: the parameters (a2, dr3, M_bal) are symbols,
// the same in both languages; time and the arguments are words.
function columnText(name) {
  if (name === "time") return LANG === "ru" ? "время" : "time";
  const argument = /^arg(\d+)$/.exec(name);
  if (argument) return (LANG === "ru" ? "аргумент " : "argument ") + argument[1];
  return name;
}

function applyWords() {
  document.documentElement.lang = LANG;
  for (const element of document.querySelectorAll("[data-i18n]")) {
    element.textContent = t(element.dataset.i18n);
  }
  for (const element of document.querySelectorAll("[data-i18n-title]")) {
    element.title = t(element.dataset.i18nTitle);
  }
  for (const button of document.querySelectorAll("button.lang")) {
    button.classList.toggle("active", button.dataset.lang === LANG);
  }
}
