// The page's other background work (api/jobs, mechloop.web.work): the animation of the
// motion (GIF, MP4, HTML) downloaded when made, a parametric sweep with its table and plot,
// a simulation of the model's simulate: section with its curves — each with a progress
// bar and a cancel button.  Uses app.js's api, postJSON, read, status, t, fileName and
// saveBlob, and the editor's text.
"use strict";

// One kind of work on the page: its elements and what it shows when done.
const WORK = {
  animation: { bar: "anim-bar", start: "anim-download", cancel: "anim-cancel", info: null },
  sweep: { bar: "sweep-bar", start: "sweep-start", cancel: "sweep-cancel", info: "sweep-info" },
  simulation: { bar: "sim-bar", start: "sim-start", cancel: "sim-cancel", info: "sim-info" },
};
const works = {};  // kind -> {id, poll, result, info: [key, values]}

// The line of a kind's work, kept as a key of WORDS (re-said when the language changes).
function workInfo(kind, key, values) {
  const run = works[kind];
  run.info = [key, values];
  const node = WORK[kind].info ? $(WORK[kind].info) : null;
  if (kind === "animation") {
    if (key) status(key, values, key === "workFailed" ? "error" : "");
  } else if (node) {
    node.textContent = key ? t(key, values && Object.fromEntries(Object.entries(values)
      .map(([name, v]) => [name, typeof v === "number" ? format(v) : v]))) : "";
  }
}

function workOptions(kind) {
  if (kind === "animation") return { format: $("anim-format").value };
  if (kind === "sweep") {
    const vary = [$("sweep-vary").value, $("sweep-vary2").value].map((s) => s.trim())
      .filter((s) => s).map(varySpec);
    const collect = $("sweep-collect").value.split(/[,;\s]+/).filter((s) => s);
    return { vary, collect, lang: LANG };
  }
  const options = { lang: LANG };
  const duration = mechloopParseNumber($("sim-duration").value);  // "0,5" in Russian
  if ($("sim-duration").value.trim()) options.duration = duration;
  return options;
}

// A sweep's PATH=VALUES as the server reads it (points): in Russian the values may be
// written with decimal commas, a range "0,1:0,3:5" or a list parted by ";" ("0,1; 0,2").
function varySpec(text) {
  const at = text.indexOf("=");
  if (LANG !== "ru" || at < 0) return text;
  const values = text.slice(at + 1);
  const decimal = (part) => part.trim().replace(/(\d),(\d)/g, "$1.$2");
  if (values.includes(";")) return text.slice(0, at + 1) + values.split(";").map(decimal).join(",");
  if (values.includes(":")) return text.slice(0, at + 1) + decimal(values);
  return text;
}

async function workStart(kind) {
  const run = works[kind] || (works[kind] = { id: null, poll: null, result: null, info: ["", null] });
  const parts = WORK[kind];
  run.result = null;
  clearTimeout(run.poll);
  workShow(kind, null);
  const body = Object.assign({ text: $("editor").value, kind }, workOptions(kind), state.source);
  workInfo(kind, "workStarting");
  const response = await postJSON("api/jobs", body);
  const answer = await read(response);
  if (!response.ok) {
    workInfo(kind, "workFailed", { error: answer.error + (answer.hint ? ` (${answer.hint})` : "") });
    return;
  }
  run.id = answer.id;
  $(parts.start).disabled = true;
  $(parts.cancel).disabled = false;
  $(parts.cancel).hidden = false;
  $(parts.bar).hidden = false;
  $(parts.bar).value = 0;
  run.poll = setTimeout(() => workPoll(kind), 150);
}

async function workPoll(kind) {
  const run = works[kind];
  const parts = WORK[kind];
  const response = await api("api/jobs/" + run.id);
  const answer = await read(response);
  if (!response.ok) {
    workDone(kind);
    workInfo(kind, "workFailed", { error: answer.error });
    return;
  }
  const p = answer.progress;
  if (p.total) $(parts.bar).value = p.done / p.total;
  if (answer.state === "running" || answer.state === "stopping") {
    if (answer.state === "stopping") workInfo(kind, "workStopping");
    else if (p.total) {
      workInfo(kind, kind === "animation" ? "animProgress" : kind === "sweep"
        ? "sweepProgress" : "simProgress", { k: format(p.done), n: format(p.total) });
    }
    run.poll = setTimeout(() => workPoll(kind), 200);
    return;
  }
  workDone(kind);
  if (answer.state === "failed") {
    const first = answer.problems[0] || {};
    workInfo(kind, answer.cancelled ? "workCancelled" : "workFailed",
      { error: (first.line ? t("line", { n: first.line }) + ": " : "") + first.message });
    return;
  }
  run.result = answer.result;
  await workShow(kind, answer.result);
}

function workDone(kind) {
  const parts = WORK[kind];
  clearTimeout(works[kind].poll);
  $(parts.start).disabled = false;
  $(parts.cancel).disabled = true;
  if (kind === "animation") {
    $(parts.cancel).hidden = true;
    $(parts.bar).hidden = true;
  }
  document.body.dataset[kind] = works[kind].id || "";
}

async function workCancel(kind) {
  const run = works[kind];
  if (!run || !run.id) return;
  $(WORK[kind].cancel).disabled = true;
  workInfo(kind, "workStopping");
  await postJSON("api/jobs/" + run.id + "/cancel", {});
}

// The file of a finished job, saved as ``name``.
async function workFile(kind, name) {
  const run = works[kind];
  const response = await api("api/jobs/" + run.id + "/file");
  if (!response.ok) {
    const answer = await read(response);
    status("failed", { error: answer.error }, "error");
    return false;
  }
  saveBlob(await response.blob(), name);
  return true;
}

function svgSource(svg) {
  return "data:image/svg+xml;charset=utf-8," + encodeURIComponent(svg);
}

// What a finished job shows (``result`` null: nothing yet).
async function workShow(kind, result) {
  if (kind === "animation") {
    if (!result) return;
    const name = fileName("." + result.format);
    if (await workFile(kind, name)) {
      workInfo(kind, "animDone", { name, n: result.frames });
      status("animDone", { name, n: result.frames }, "ok");
    }
    return;
  }
  const prefix = kind === "sweep" ? "sweep" : "sim";
  $(prefix + "-result").hidden = !result;
  $(prefix + "-file").hidden = !result;
  if (!result) return;
  $(prefix + "-plot").src = svgSource(result.svg);
  if (kind === "sweep") {
    sweepTable(result);
    const broken = result.rows.filter((row) => row[row.length - 2] > 0 || row[row.length - 1])
      .length;
    workInfo(kind, "sweepDone", { n: result.rows.length, broken });
  } else {
    simSummary(result.summary);
    workInfo(kind, "simDone", { t: result.summary.end, n: result.summary.rows });
  }
}

function sweepTable(result) {
  const table = $("sweep-table");
  table.textContent = "";
  const head = table.createTHead().insertRow();
  const shown = result.columns.map((name, i) => [name, i]).filter(([name]) => name !== "note");
  for (const [name] of shown) {
    const cell = document.createElement("th");
    cell.textContent = name === "broken" ? t("sweepBroken") : name;
    head.appendChild(cell);
  }
  const body = table.createTBody();
  for (const row of result.rows) {
    const line = body.insertRow();
    for (const [, i] of shown) {
      const cell = line.insertCell();
      const value = row[i];
      cell.textContent = typeof value === "number" ? format(value) : value === null ? "—" : value;
      cell.className = "number";
    }
  }
}

function simSummary(summary) {
  const node = $("sim-summary");
  node.textContent = "";
  const lines = summary.lines ? summary.lines.slice() : [
    t("simCycles", { n: summary.cycles }),
    summary.speed === null ? "" : t("simSpeed", { n: format(summary.speed) }),
    summary.steady === null ? t("simNotSteady") : t("simSteady", { t: format(summary.steady) }),
    ...summary.events,
  ];
  for (const text of lines.filter((s) => s)) {
    const item = document.createElement("li");
    item.textContent = text;
    node.appendChild(item);
  }
}

function workLanguage() {
  for (const kind of Object.keys(works)) {
    if (kind !== "animation") workInfo(kind, ...works[kind].info);
    const result = works[kind].result;
    if (kind === "simulation" && result) simSummary(result.summary);
    if (kind === "sweep" && result) sweepTable(result);
  }
}

window.addEventListener("DOMContentLoaded", () => {
  for (const kind of Object.keys(WORK)) {
    works[kind] = { id: null, poll: null, result: null, info: ["", null] };
    $(WORK[kind].start).addEventListener("click", () => workStart(kind));
    $(WORK[kind].cancel).addEventListener("click", () => workCancel(kind));
  }
  $("sweep-file").addEventListener("click", () => workFile("sweep", fileName("-sweep.csv")));
  $("sim-file").addEventListener("click", () => workFile("simulation",
    fileName("-simulation.csv")));
  for (const button of document.querySelectorAll("button.lang")) {
    button.addEventListener("click", workLanguage);  // after app.js's, which sets LANG
  }
});
