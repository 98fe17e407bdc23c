// The page: the editor with live validation, the mechanism at the current position, one
// plot and the results table, all following the position slider; save, report, language.
"use strict";

const query = new URLSearchParams(location.search);
const TOKEN = query.get("token");
const $ = (id) => document.getElementById(id);
const MAX_CURVES = 6;  // on one plot, as the library's plot_parameters

const state = {
  source: null,        // {path: ...} or {example: ...}
  solution: null,
  position: 0,
  column: null,        // the name of the plotted column
  extra: [],           // the names of the columns plotted with it (up to 5)
  traces: [],          // the points whose trajectories are drawn (keys of tracePoints)
  problems: [],
  timer: null,         // playing
  structure: null,     // the answer of api/structure
  version: 0,          // of the text: answers to older texts are dropped
  unsaved: null,       // a new model not saved yet: {template, file} (newmodel.js)
};

async function api(path, options) {
  const headers = Object.assign({}, (options && options.headers) || {});
  if (TOKEN) headers["X-Mechloop-Token"] = TOKEN;
  headers["X-Mechloop-Lang"] = LANG;  // the server's error messages in the page's language
  try {
    return await fetch(path, Object.assign({}, options, { headers }));
  } catch (error) {  // the server stopped or the network failed: said, not thrown
    return { ok: false, status: 0, json: async () => ({ error: String(error), hint: "" }) };
  }
}

// The JSON of an answer; an answer that is not JSON becomes an error with its status.
async function read(response) {
  try {
    return await response.json();
  } catch (error) {
    return { error: `${response.status} ${response.statusText || ""}`.trim(), hint: "" };
  }
}

async function postJSON(path, data) {
  return api(path, { method: "POST", body: JSON.stringify(data),
    headers: { "content-type": "application/json" } });
}

// The status line, kept as a key of WORDS (re-said when the language changes).
let lastStatus = ["", null, ""];
function status(key, values, kind) {
  lastStatus = [key, values, kind];
  const node = $("status");
  node.textContent = key ? t(key, values) : "";
  node.className = kind || "";
}

// ------------------------------------------------------------------ the editor
function lineCount() {
  return $("editor").value.split("\n").length;
}

function renderGutter() {
  const bad = new Set(state.problems.map((p) => p.line).filter((n) => n));
  const gutter = $("gutter");
  gutter.textContent = "";
  for (let n = 1; n <= lineCount(); n++) {
    const line = document.createElement("span");
    line.textContent = n + "\n";
    line.dataset.line = n;
    if (bad.has(n)) line.className = "bad";
    gutter.appendChild(line);
  }
  gutter.scrollTop = $("editor").scrollTop;
}

function goToLine(n) {
  const editor = $("editor");
  const lines = editor.value.split("\n");
  const start = lines.slice(0, n - 1).reduce((s, l) => s + l.length + 1, 0);
  editor.focus();
  editor.setSelectionRange(start, start + (lines[n - 1] || "").length);
  const height = editor.scrollHeight / Math.max(lines.length, 1);
  editor.scrollTop = Math.max(0, (n - 5) * height);
}

function renderProblems() {
  const list = $("problems");
  list.textContent = "";
  $("problem-count").textContent = state.problems.length ? `(${state.problems.length})` : "";
  if (!state.problems.length) {
    const item = document.createElement("li");
    item.className = "ok";
    item.textContent = t("ok");
    list.appendChild(item);
  }
  for (const problem of state.problems) {
    const item = document.createElement("li");
    item.className = "problem";
    if (problem.line) item.dataset.line = problem.line;
    const where = document.createElement("a");
    where.className = "where";
    where.textContent = [problem.line ? t("line", { n: problem.line }) : "", problem.path]
      .filter(Boolean).join(", ");
    if (problem.line) where.onclick = () => goToLine(problem.line);
    const message = document.createElement("span");
    message.className = "message";
    message.textContent = " " + problem.message;
    item.append(where, message);
    if (problem.hint) {
      const hint = document.createElement("div");
      hint.className = "hint";
      hint.textContent = `${t("fix")}: ${problem.hint}`;
      item.appendChild(hint);
    }
    list.appendChild(item);
  }
  renderGutter();
  highlighter.mark(state.problems.map((p) => p.line));
}

let pending = null;
function edited() {
  state.version += 1;
  if (window.mechloopForms) window.mechloopForms.changed();  // forms.js
  renderGutter();
  clearTimeout(pending);
  // while a handle is dragged (drag.js), at once: the mechanism follows the pointer
  pending = setTimeout(check, document.body.dataset.dragging ? 0 : 350);
}

// One check at a time; an edit made meanwhile is checked right after it (so a drag's
// texts, each a moment apart, are solved one after another and each drawn).
const checking = { busy: false, again: false };
async function check() {
  if (checking.busy) {
    checking.again = true;
    return;
  }
  checking.busy = true;
  try {
    await checkNow();
  } finally {
    checking.busy = false;
    if (checking.again) {
      checking.again = false;
      check();
    }
  }
}

async function checkNow() {
  const version = state.version;
  const text = $("editor").value;
  const body = Object.assign({ text }, state.source);
  status("checking", null);
  const response = await postJSON("api/validate", body);
  const answer = await read(response);
  if (version !== state.version && !document.body.dataset.dragging) return;
  if (!response.ok) {
    state.problems = answer.problems || [{ message: answer.error, hint: answer.hint }];
    renderProblems();
    status("failed", { error: answer.error }, "error");
    return;
  }
  state.problems = answer.problems;
  renderProblems();
  if (answer.ok) {
    await solve(version, text);
  } else {
    status("invalid", null, "error");
  }
}

// ------------------------------------------------------------------ the results
async function solve(version, text) {
  status("solving", null);
  const body = Object.assign({ text: text === undefined ? $("editor").value : text },
    state.source);
  const response = await postJSON("api/solve", body);
  const answer = await read(response);
  // an older text is drawn only during a drag (the mechanism follows the pointer)
  const current = version === state.version;
  if (!current && !(response.ok && document.body.dataset.dragging)) return;
  if (!response.ok) {
    state.problems = answer.problems || [];
    renderProblems();
    status("failed", { error: answer.error }, "error");
    return;
  }
  state.solution = answer;
  const slider = $("slider");
  slider.max = answer.count - 1;
  state.position = Math.min(state.position, answer.count - 1);
  slider.value = state.position;
  fillPlotChoices();
  fillTraces();
  render();
  if (!current) return;
  status("solved", null, "ok");
  document.body.dataset.solved = String(version);
  if (answer.structure) {  // made with the solution, in both languages
    state.structure = answer.structure;
    renderStructure();
  } else {
    loadStructure(version);
  }
  loadView();
}

function fillPlotChoices() {
  const select = $("plot-select");
  const columns = state.solution.columns;
  const names = columns.map((c) => c.name);
  if (!names.includes(state.column)) {
    // the first unknown of the loops (a function parameter) that varies
    const functions = state.solution.diagram.vectors.flatMap((v) => Object.entries(v.marks)
      .filter(([, role]) => role === "function").map(([letter]) => letter + v.number));
    const varying = columns.find((c) => functions.includes(c.name)
      && new Set(c.values).size > 1);
    state.column = (varying || columns[0] || {}).name || null;
  }
  select.textContent = "";
  for (const column of columns) {
    const option = document.createElement("option");
    option.value = column.name;
    option.textContent = `${columnText(column.name)}, ${unitText(column.unit)}`;
    select.appendChild(option);
  }
  select.value = state.column;
  state.extra = state.extra.filter((name) => names.includes(name) && name !== state.column);
  fillExtraCurves();
}

// The curves plotted with the first: a removable item each, and a list to add one.
function fillExtraCurves() {
  const columns = state.solution.columns;
  const add = $("plot-add");
  add.textContent = "";
  const prompt = document.createElement("option");
  prompt.value = "";
  prompt.textContent = t("addCurve");
  add.appendChild(prompt);
  for (const column of columns) {
    if (column.name === state.column || state.extra.includes(column.name)) continue;
    const option = document.createElement("option");
    option.value = column.name;
    option.textContent = `${columnText(column.name)}, ${unitText(column.unit)}`;
    add.appendChild(option);
  }
  add.value = "";
  add.disabled = state.extra.length >= MAX_CURVES - 1;
  const list = $("plot-curves");
  list.textContent = "";
  for (const name of state.extra) {
    const button = document.createElement("button");
    button.className = "curve-chip";
    button.dataset.name = name;
    button.title = t("removeCurve");
    button.textContent = `${columnText(name)} ✕`;
    button.onclick = () => {
      state.extra = state.extra.filter((other) => other !== name);
      fillExtraCurves();
      render();
    };
    list.appendChild(button);
  }
}

// The points whose trajectories are drawn: a removable item each, and a list to add one.
function fillTraces() {
  const points = tracePoints(state.solution.diagram);
  state.traces = state.traces.filter((key) => points.some((p) => p.key === key));
  const add = $("trace-add");
  add.textContent = "";
  const prompt = document.createElement("option");
  prompt.value = "";
  prompt.textContent = t("addTrace");
  add.appendChild(prompt);
  const text = (p) => t(p.word, { n: p.n });
  for (const point of points) {
    if (state.traces.includes(point.key)) continue;
    const option = document.createElement("option");
    option.value = point.key;
    option.textContent = text(point);
    add.appendChild(option);
  }
  add.value = "";
  const list = $("traces");
  list.textContent = "";
  for (const key of state.traces) {
    const button = document.createElement("button");
    button.className = "curve-chip";
    button.dataset.key = key;
    button.title = t("removeTrace");
    button.textContent = `${text(points.find((p) => p.key === key))} ✕`;
    button.onclick = () => {
      state.traces = state.traces.filter((other) => other !== key);
      fillTraces();
      render();
    };
    list.appendChild(button);
  }
}

function plotted() {
  return [state.column, ...state.extra].filter(Boolean);
}

function render() {
  const solution = state.solution;
  if (!solution) return;
  const k = state.position;
  const spatial = Boolean(solution.diagram.spatial);  // issue 17: the 3-D view
  $("diagram").style.display = spatial ? "none" : "";
  $("view3d").hidden = !spatial;
  document.querySelector(".drag-help").hidden = spatial;
  // at a chain break the mechanism is drawn faded at the nearest position that closes
  // (its handles too: a drag can bring the chain back)
  const drawn = solution.broken[k] && !spatial ? nearestClosed(solution, k) : k;
  $("diagram").dataset.shown = drawn === null ? k : drawn;
  if (spatial) {
    drawSpatial(solution, k);
  } else {
    drawDiagram($("diagram"), solution, drawn === null ? k : drawn, $("overlay").checked,
      state.traces);
    $("diagram").classList.toggle("faded", drawn !== k);
    if (window.mechloopDrag) window.mechloopDrag.render();  // drag.js: the handles
  }
  drawPlot($("plot"), solution,
    plotted().map((name) => solution.columns.find((c) => c.name === name)), k,
    plotZoom.rangeFor(solution.count - 1, k));
  drawViewPlot();  // plots.js: the view's cursor at this position
  let label = t("position", { k, n: solution.count - 1 });
  if (solution.time) label += ", " + t("time", { t: format(solution.time[k]) });
  $("position-label").textContent = label;
  const note = $("break-note");
  if (solution.broken[k]) {
    const reasons = solution.breaks.filter((b) => b.positions.includes(k))
      .map((b) => t("breakReason", Object.assign({}, b,
        LANG === "ru" && b.reason_ru ? { reason: b.reason_ru } : {})));
    const shownAt = $("diagram").dataset.shown;
    note.textContent = [t("broken", { k }), ...reasons].join("; ")
      + (Number(shownAt) !== k ? "; " + t("brokenShown", { j: shownAt }) : "");
    note.hidden = false;
  } else {
    note.hidden = true;
  }
  const body = $("results").tBodies[0];
  body.textContent = "";
  for (const c of solution.columns) {
    const row = body.insertRow();
    row.dataset.name = c.name;
    row.insertCell().textContent = columnText(c.name);
    const value = row.insertCell();
    const shown = (c.shown || c.values)[k];  // rounded by the server to the precision
    value.textContent = formatPrecise(shown === null ? NaN : shown, solution.precision);
    value.className = "number";
    row.insertCell().textContent = unitText(c.unit);
  }
}

// A spatial model's mechanism: the rotatable 3-D view of view3d.js, at the slider's
// position (its angles and zoom kept while the model is edited).
function drawSpatial(solution, k) {
  if (!state.view3d) {
    state.view3d = new View3d($("view3d"), { width: 560, height: 380 });
    window.mechloopView3d = state.view3d;
  }
  const view = state.view3d;
  if (view.lang !== LANG) {
    view.lang = LANG;
    view.words();
  }
  if (view.data !== solution.diagram) view.setData(solution.diagram);
  view.show(k, $("overlay").checked, state.traces);
}

// The position nearest to ``k`` where the chain closes (null: none).
function nearestClosed(solution, k) {
  for (let d = 1; d < solution.count; d++) {
    if (k - d >= 0 && !solution.broken[k - d]) return k - d;
    if (k + d < solution.count && !solution.broken[k + d]) return k + d;
  }
  return null;
}

function setPosition(k) {
  state.position = k;
  $("slider").value = k;
  render();
}

// KDAM's play modes: forward or backward, one cycle looped, at a chosen speed; the step
// buttons move one position (frame by frame), pausing the play.
const FRAME_MS = 60;  // one position per frame at speed ×1

function step(direction) {
  if (!state.solution) return;
  const n = state.solution.count;
  setPosition(((state.position + direction) % n + n) % n);
}

function startTimer() {
  clearInterval(state.timer);
  const speed = Number($("play-speed").value) || 1;
  state.timer = setInterval(playTick, FRAME_MS / speed);
}

// One frame of the play in the chosen mode (KDAM's): continuously (round the cycle), one
// cycle (to the last position in the direction, then it stops) or back and forth (the
// direction turns at either end).
function playTick() {
  if (!state.solution) return;
  const last = state.solution.count - 1;
  const mode = $("play-mode").value;
  let direction = Number($("play-direction").value) || 1;
  if (mode === "loop") {
    step(direction);
    return;
  }
  const end = direction > 0 ? last : 0;
  if (state.position === end) {
    if (mode === "once") {
      togglePlay();
      return;
    }
    direction = -direction;
    $("play-direction").value = String(direction);
  }
  setPosition(Math.min(Math.max(state.position + direction, 0), last));
}

function togglePlay() {
  if (state.timer) {
    clearInterval(state.timer);
    state.timer = null;
  } else if (state.solution) {
    const direction = Number($("play-direction").value) || 1;
    if ($("play-mode").value === "once"
      && state.position === (direction > 0 ? state.solution.count - 1 : 0)) {
      setPosition(direction > 0 ? 0 : state.solution.count - 1);  // the cycle from its start
    }
    startTimer();
  }
  $("play").dataset.i18n = state.timer ? "pause" : "play";
  $("play").textContent = t($("play").dataset.i18n);
}

function stepOnce(direction) {
  if (state.timer) togglePlay();
  step(direction);
}

// ------------------------------------------------------------------ other views
// The other plot kinds of mechloop plot, drawn by the page (plots.js) from the data the
// server reads back from the same figure, in the page's language; asked again when the
// model, the language or the view's choices change (the position only moves its cursor).
const view = { asked: 0 };
// The choices each kind takes: names, a joint, the operation, the increment's reference.
const VIEW_INPUTS = {
  combination: ["names", "op"], increment: ["names", "from"], angle: ["names"],
  reactions: ["names"], hodograph: ["joint"],
};

function viewBody(kind) {
  const names = $("view-names").value.split(",").map((n) => n.trim()).filter(Boolean);
  const joints = state.solution ? state.solution.diagram.joints.map((j) => j.name) : [];
  const joint = $("view-joint").value.trim() || (kind === "hodograph" ? joints[0] : null);
  return Object.assign({ text: $("editor").value, kind, names, joint: joint || null,
    position: Math.max(0, Math.round(Number($("view-from").value) || 0)),
    op: $("view-op").value, lang: LANG }, state.source);
}

async function loadView() {
  const kind = $("view-kind").value;
  const inputs = VIEW_INPUTS[kind] || [];
  $("view-names").hidden = !inputs.includes("names");
  $("view-joint").hidden = !inputs.includes("joint");
  $("view-op").hidden = !inputs.includes("op");
  $("view-from-label").hidden = !inputs.includes("from");
  const problem = $("view-problem");
  const shown = (on) => {
    $("view-downloads").hidden = !on;
    $("view-help").hidden = !on;
  };
  if (!kind || !state.solution) {
    hideViewData();
    problem.hidden = true;
    shown(false);
    return;
  }
  const asked = ++view.asked;
  const body = Object.assign(viewBody(kind), { format: "data" });
  const response = await postJSON("api/view", body);
  const answer = await read(response);
  if (asked !== view.asked) return;
  if (!response.ok) {
    problem.textContent = t("viewFailed", { error: answer.error })
      + (answer.hint ? ` (${t("fix")}: ${answer.hint})` : "");
    problem.hidden = false;
    hideViewData();
    shown(false);
    return;
  }
  problem.hidden = true;
  showViewData(answer);
  shown(true);
  document.body.dataset.view = `${kind}:${asked}`;
}

async function viewFile() {
  const kind = $("view-kind").value;
  if (!kind) return;
  const format = $("view-format").value;
  const body = viewBody(kind);
  delete body.text;  // download() sends the editor's text
  if (kind !== "increment") body.position = state.position;  // marked in the file
  await download("api/view", Object.assign(body, { format }),
    fileName(`-${kind}.${format}`), { busy: "downloading", done: "downloaded" });
}

// ------------------------------------------------------------------ background jobs
const job = { id: null, poll: null, result: null, info: ["", null] };

// The job's line, kept as a key of WORDS (re-said when the language changes); ``why``,
// the library's reason the search stopped, is said in the page's language.
function jobInfo(key, values) {
  job.info = [key, values];
  const shown = values && values.why !== undefined
    ? Object.assign({ stopped: stopText(values.why) }, values) : Object.assign({}, values);
  if (typeof shown.q === "number") shown.q = format(shown.q);  // in the page's language
  $("job-info").textContent = key ? t(key, shown) : "";
}

function stopText(why) {
  if (why === "interrupted") return t("stopInterrupted");
  if (why === "iteration limit") return t("stopLimit");
  if (why === "good enough") return t("stopGood");
  if (why === "time budget spent") return t("stopTime");
  if (why.startsWith("no progress")) return t("stopPatience");
  return t("stopOther");
}

async function jobStart() {
  const body = Object.assign({ text: $("editor").value, kind: "synthesis" }, state.source);
  job.result = null;
  $("job-open").hidden = true;
  jobInfo("jobStarting");
  const response = await postJSON("api/jobs", body);
  const answer = await read(response);
  if (!response.ok) {
    jobInfo("jobFailed", { error: answer.error });
    return;
  }
  job.id = answer.id;
  $("job-start").disabled = true;
  $("job-cancel").disabled = false;
  $("job-bar").value = 0;
  job.poll = setTimeout(jobPoll, 200);
}

async function jobPoll() {
  const response = await api("api/jobs/" + job.id);
  const answer = await read(response);
  if (!response.ok) {
    jobFinished();
    jobInfo("jobFailed", { error: answer.error });
    return;
  }
  const p = answer.progress;
  if (p.total) $("job-bar").value = p.iteration / p.total;
  if (answer.diagram) {
    $("job-diagram").removeAttribute("hidden");  // an SVG element has no .hidden
    drawDiagram($("job-diagram"), { diagram: answer.diagram }, 0, false, [], "best-");
  }
  $("job-bar").dataset.best = p.best === null || p.best === undefined ? "" : p.best;
  if (answer.state === "running" || answer.state === "stopping") {
    if (answer.state === "stopping") jobInfo("jobStopping");
    else if (p.total) {
      jobInfo("jobProgress", { k: p.iteration, n: p.total,
        q: p.feasible ? p.best : t("jobNoFeasible") });
    }
    job.poll = setTimeout(jobPoll, 250);
    return;
  }
  jobFinished();
  if (answer.state === "failed") {
    jobInfo("jobFailed", { error: (answer.problems[0] || {}).message });
    return;
  }
  const result = answer.result;
  job.result = result;
  $("job-open").hidden = false;
  $("job-bar").dataset.best = result.best === null ? "" : result.best;
  if (result.feasible) jobInfo("jobDone", { why: result.stopped, q: result.best });
  else jobInfo("jobInfeasible", { why: result.stopped });
}

function jobFinished() {
  clearTimeout(job.poll);
  $("job-start").disabled = false;
  $("job-cancel").disabled = true;
  document.body.dataset.job = job.id || "";
}

async function jobCancel() {
  if (!job.id) return;
  $("job-cancel").disabled = true;
  jobInfo("jobStopping");
  await postJSON("api/jobs/" + job.id + "/cancel", {});
}

// The synthesized model opens in the editor, to be saved under a new name.
function jobOpen() {
  if (!job.result) return;
  const name = $("save-path").value.replace(/\.(yaml|yml|json)$/i, "");
  $("save-path").value = name + "_synthesized.yaml";
  state.solution = null;
  state.position = 0;
  mechloopEditor.setText(job.result.text);  // one undo goes back to the model
  status("jobOpened", null, "ok");
}

// ------------------------------------------------------------------ files
async function loadList() {
  const response = await api("api/models");
  const answer = await read(response);
  const select = $("model-select");
  select.textContent = "";
  const files = document.createElement("optgroup");
  files.dataset.i18nLabel = "files";
  for (const path of answer.files) {
    const option = document.createElement("option");
    option.value = "path:" + path;
    option.textContent = path;
    files.appendChild(option);
  }
  const examples = document.createElement("optgroup");
  examples.dataset.i18nLabel = "examples";
  for (const example of answer.examples) {
    const option = document.createElement("option");
    option.value = "example:" + example.id;
    option.dataset.en = example.id + (example.title ? " — " + example.title : "");
    option.dataset.ru = example.id + (example.title_ru ? " — " + example.title_ru : "");
    examples.appendChild(option);
  }
  if (answer.files.length) select.appendChild(files);
  select.appendChild(examples);
  labelList();
  return answer;
}

function labelList() {
  for (const group of $("model-select").querySelectorAll("optgroup")) {
    group.label = t(group.dataset.i18nLabel);
  }
  for (const option of $("model-select").querySelectorAll("option[data-en]")) {
    option.textContent = option.dataset[LANG];
  }
}

async function open(choice) {
  const [kind, name] = [choice.slice(0, choice.indexOf(":")), choice.slice(choice.indexOf(":") + 1)];
  state.source = kind === "path" ? { path: name } : { example: name };
  $("model-select").value = choice;
  $("save-path").value = kind === "path" ? name : name + ".yaml";
  const response = await api("api/model?" + new URLSearchParams(state.source));
  const answer = await read(response);
  if (!response.ok) {
    status("failed", { error: answer.error }, "error");
    return;
  }
  state.solution = null;
  state.position = 0;
  state.unsaved = null;
  document.body.dataset.unsaved = "";
  await autosave.open(state.source, answer.text);
}

// Save the editor's text as ``name`` (else the file field's); a new model asks its name.
async function save(name) {
  if (state.unsaved && typeof name !== "string") {
    newModel.ask();
    return;
  }
  const path = typeof name === "string" ? name : $("save-path").value.trim();
  if (!path) {
    status("unsaved", null, "error");
    return;
  }
  status("saving", null);
  const text = $("editor").value;
  const request = { path, text };
  if (state.unsaved) request.template = state.unsaved.template;
  const response = await postJSON("api/save", request);
  const answer = await read(response);
  if (!response.ok) {
    status("failed", { error: answer.error }, "error");
    return;
  }
  await loadList();
  await autosave.saved(state.source, { path: answer.saved }, text);
  state.unsaved = null;
  document.body.dataset.unsaved = "";
  $("save-path").value = answer.saved;
  state.source = { path: answer.saved };
  $("model-select").value = "path:" + answer.saved;
  status("saved", { path: answer.saved }, "ok");
}

// The file name of a download: the model's name with ``suffix``.
function fileName(suffix) {
  const stem = ($("save-path").value.split("/").pop() || "model").replace(/\.[^.]*$/, "");
  return stem + suffix;
}

function saveBlob(blob, name) {
  const link = document.createElement("a");
  link.href = URL.createObjectURL(blob);
  link.download = name;
  document.body.appendChild(link);
  link.click();
  link.remove();
}

// POST the editor's model (with ``extra``) to ``route`` and save the answer as ``name``.
// ``words``: the status keys while it is made and when it is saved.
async function download(route, extra, name, words) {
  status(words.busy, { name });
  const body = Object.assign({ text: $("editor").value }, extra, state.source);
  const response = await postJSON(route, body);
  if (!response.ok) {
    const answer = await read(response);
    status("failed", { error: answer.error }, "error");
    return;
  }
  saveBlob(await response.blob(), name);
  status(words.done, { name }, "ok");
}

async function report() {
  const format = $("report-format").value;
  await download("api/report", { lang: LANG, format }, fileName(`-${LANG}.${format}`),
    { busy: "writing", done: "written" });
}

async function tableFile() {
  const format = $("table-format").value;
  await download("api/table", { format }, fileName("." + format),
    { busy: "downloading", done: "downloaded" });
}

async function figureFile() {
  if (!state.column) return;
  const format = $("figure-format").value;
  await download("api/figure", { names: plotted(), format, lang: LANG },
    fileName(`-${plotted().join("-")}.${format}`), { busy: "downloading", done: "downloaded" });
}

function modelFile() {
  const name = fileName(".yaml");
  saveBlob(new Blob([$("editor").value], { type: "application/x-yaml" }), name);
  status("downloaded", { name }, "ok");
}

// ------------------------------------------------------------------ structure
async function loadStructure(version) {
  const body = Object.assign({ text: $("editor").value }, state.source);
  const response = await postJSON("api/structure", body);
  const answer = await read(response);
  if (version !== state.version) return;
  state.structure = response.ok ? answer : { error: answer.error };
  renderStructure();
}

function renderStructure() {
  const panel = $("structure");
  panel.textContent = "";
  const answer = state.structure && (state.structure.en ? state.structure[LANG]
    : state.structure);  // the solution's structure is in both languages
  if (!answer) return;
  const line = (text, className) => {
    const p = document.createElement("p");
    p.textContent = text;
    if (className) p.className = className;
    panel.appendChild(p);
    return p;
  };
  if (answer.error) {
    line(t("failed", { error: answer.error }), "break");
    return;
  }
  const m = answer.mechanism;
  if (!m) {
    if (!answer.spatial) line(t("noBodies"));  // a spatial model's text says its links
  } else {
    line(`${t("formula")}: ${m.formula}`).id = "structure-formula";
    line(`${t("mechanismClass")}: ${m.class || t("noClass")}`);
    line(`${t("mobility")}: W = 3·${m.n} − 2·${m.p5} − ${m.p4} = ${m.W}; `
      + `${t("inputs")}: ${m.inputs}`).className = m.ok ? "" : "break";
    const table = document.createElement("table");
    table.id = "structure-groups";
    const head = table.createTHead().insertRow();
    for (const word of [t("group"), t("links"), t("pairs"), t("variant")]) {
      const cell = document.createElement("th");
      cell.textContent = word;
      head.appendChild(cell);
    }
    const rows = table.createTBody();
    for (const group of m.groups) {
      const row = rows.insertRow();
      row.dataset.label = group.label;
      const pairs = [...group.external, ...group.internal]
        .map((p) => `${p.name} ${p.kind} ${p.link}–${p.to}`).join(", ");
      for (const text of [group.label, group.links.join(", "), `${group.pairs}: ${pairs}`,
        group.variant === null ? "—" : String(group.variant)]) {
        row.insertCell().textContent = text;
      }
    }
    panel.appendChild(table);
    for (const note of m.notes) line(note);  // the library's words, in the page's language
  }
  const description = document.createElement("pre");
  description.textContent = answer.description;  // the same
  panel.appendChild(description);
}

function setLanguage(lang) {
  LANG = lang;
  localStorage.setItem("mechloop-lang", lang);
  applyWords();
  labelList();
  renderProblems();
  $("play").textContent = t($("play").dataset.i18n);
  status(...lastStatus);
  jobInfo(...job.info);
  loadView();
  if (state.solution) {
    fillPlotChoices();
    fillTraces();
    render();
  }
  renderStructure();
  newModel.fill();
  autosave.show();
  if (window.mechloopForms) window.mechloopForms.draw();
  if (state.problems.length) recheck();
}

// The problems said again in the new language (the server says them in the page's).
async function recheck() {
  const version = state.version;
  const response = await postJSON("api/validate",
    Object.assign({ text: $("editor").value }, state.source));
  const answer = await read(response);
  if (version !== state.version || !response.ok || answer.ok) return;
  state.problems = answer.problems;
  renderProblems();
}

// ------------------------------------------------------------------ start
window.addEventListener("DOMContentLoaded", async () => {
  LANG = query.get("lang") || localStorage.getItem("mechloop-lang") || "en";
  applyWords();
  $("editor").addEventListener("input", edited);
  $("editor").addEventListener("scroll", () => { $("gutter").scrollTop = $("editor").scrollTop; });
  $("editor").addEventListener("keydown", (event) => {
    if (event.key === "Tab") {  // two spaces, as YAML wants
      event.preventDefault();
      document.execCommand("insertText", false, "  ");
    }
  });
  $("slider").addEventListener("input", () => setPosition(Number($("slider").value)));
  $("play").addEventListener("click", togglePlay);
  $("step-back").addEventListener("click", () => stepOnce(-1));
  $("step-forward").addEventListener("click", () => stepOnce(1));
  $("play-speed").addEventListener("change", () => { if (state.timer) startTimer(); });
  $("view-kind").addEventListener("change", loadView);
  $("view-names").addEventListener("change", loadView);
  $("view-joint").addEventListener("change", loadView);
  $("view-op").addEventListener("change", loadView);
  $("view-from").addEventListener("change", loadView);
  $("view-download").addEventListener("click", viewFile);
  $("job-start").addEventListener("click", jobStart);
  $("job-cancel").addEventListener("click", jobCancel);
  $("job-open").addEventListener("click", jobOpen);
  $("plot-select").addEventListener("change", () => {
    state.column = $("plot-select").value;
    state.extra = state.extra.filter((name) => name !== state.column);
    fillExtraCurves();
    render();
  });
  $("overlay").addEventListener("change", render);
  $("trace-add").addEventListener("change", () => {
    if ($("trace-add").value) state.traces.push($("trace-add").value);
    fillTraces();
    render();
  });
  $("plot-add").addEventListener("change", () => {
    const name = $("plot-add").value;
    if (name && state.extra.length < MAX_CURVES - 1) state.extra.push(name);
    fillExtraCurves();
    render();
  });
  $("model-select").addEventListener("change", () => open($("model-select").value));
  $("save").addEventListener("click", save);
  $("report").addEventListener("click", report);
  $("table-download").addEventListener("click", tableFile);
  $("figure-download").addEventListener("click", figureFile);
  $("model-download").addEventListener("click", modelFile);
  for (const button of document.querySelectorAll("button.lang")) {
    button.addEventListener("click", () => setLanguage(button.dataset.lang));
  }
  newModel.list();
  const listed = await loadList();
  const first = query.get("path") ? "path:" + query.get("path")
    : query.get("example") ? "example:" + query.get("example")
    : listed.start ? "path:" + listed.start
    : listed.files.length ? "path:" + listed.files[0]
    : "example:crank_slider";
  await open(first);
});
