// Form views of KDAM's input panels beside the YAML editor: arguments (tables with their
// fill rule, motion laws, intermediate sweeps, CSV files; CSV import), model time,
// vectors and contours, masses (bodies), forces and moments, synthesis settings.
//
// The forms show the plain data of the editor's text (api/data, asked again after every
// change of the text); an edit in a form is made on the server (api/edit: one value, row
// or key changed in place, the user's comments and layout kept) and the new text goes
// into the editor through mechloopEditor.setText (one undo step), so it takes the path of
// typing: validation, solution, plots, autosave and these forms all follow.
"use strict";

(function () {
  // the words of the choices (keys of WORDS, in i18n.js)
  const TABS = { yaml: "tab_yaml", arguments: "tab_arguments", time: "tab_time",
    vectors: "tab_vectors", bodies: "tab_bodies", loads: "tab_loads",
    synthesis: "tab_synthesis" };
  const ROLES = { constant: "formRole_constant", function: "formRole_function",
    argument: "formRole_argument", link: "formRole_link" };
  const LAWS = { constant_speed: "formLaw_constant_speed", harmonic: "formLaw_harmonic",
    cycloidal: "formLaw_cycloidal", poly345: "formLaw_poly345" };
  const KINDS = { table: "formKind_table", law: "formKind_law",
    intermediate: "formKind_intermediate", csv: "formKind_csv" };
  const RULES = { linear: "formRule_linear", spline: "formRule_spline" };
  const TIMES = { none: "formTime_none", rpm: "formTime_rpm", table: "formTime_table" };
  const VARIANTS = { 1: "formVariant_1", 2: "formVariant_2", auto: "formVariant_auto" };
  const LOADS = { body: "formLoad_body", at: "formLoad_at", value: "formLoad_value",
    angle: "formLoad_angle", along: "formLoad_along", name: "formLoad_name" };
  const forms = { data: null, tab: "yaml", pending: null, asked: 0, stale: false,
    queue: Promise.resolve(null) };

  // ---------------------------------------------------------------- the text
  function modelText() {
    return window.mechloopEditor ? window.mechloopEditor.getText() : $("editor").value;
  }

  // Every change of the model's text made here: through the editor (undo/redo covers it)
  // or, without it, into the textarea as typing would.
  function setModelText(text, record) {
    if (window.mechloopEditor) {
      window.mechloopEditor.setText(text, { record: record !== false });
      return;
    }
    const area = $("editor");
    if (area.value === text) return;
    area.value = text;
    area.dispatchEvent(new Event("input"));
  }

  // One change at ``keys`` (``{value}``, ``{delete: true}`` or ``{key}``) of ``text`` (default:
  // the editor's): the new text, or null (the refusal is shown).
  async function editText(keys, change, text) {
    const body = Object.assign({ text: text === undefined ? modelText() : text, keys },
      change, state.source);
    const response = await postJSON("api/edit", body);
    const answer = await read(response);
    if (!response.ok) {
      showProblem(t("editFailed", { error: answer.error })
        + (answer.hint ? ` (${t("fix")}: ${answer.hint})` : ""));
      return null;
    }
    showProblem("");
    forms.asked += 1;  // a reading of the text before this edit, still on its way, is old
    forms.data = answer.data;
    return answer.text;
  }

  // Edits one after another: each starts from the text the one before it left.
  function edit(keys, change) {
    forms.queue = forms.queue.then(async () => {
      const text = await editText(keys, change);
      if (text !== null) setModelText(text, true);
      document.body.dataset.formEdits = String(Number(document.body.dataset.formEdits || 0) + 1);
      return text;
    }).catch((error) => {  // said, and the next edit still runs
      showProblem(t("editFailed", { error: String(error) }));
      return null;
    });
    return forms.queue;
  }

  function showProblem(text) {
    const node = $("form-problem");
    node.textContent = text;
    node.hidden = !text;
  }

  // ---------------------------------------------------------------- after a change
  function changed() {
    clearTimeout(forms.pending);
    forms.pending = setTimeout(refresh, 250);
  }

  async function refresh() {
    const asked = ++forms.asked;
    const body = Object.assign({ text: modelText() }, state.source);
    const response = await postJSON("api/data", body);
    const answer = await read(response);
    if (asked !== forms.asked) return;
    forms.stale = !response.ok;
    if (response.ok) forms.data = answer.data;
    draw();
  }

  // ---------------------------------------------------------------- small builders
  function node(tag, attributes, parent, text) {
    const element = document.createElement(tag);
    for (const [key, value] of Object.entries(attributes || {})) {
      if (key === "dataset") Object.assign(element.dataset, value);
      else element.setAttribute(key, value);
    }
    if (text !== undefined) element.textContent = text;
    if (parent) parent.appendChild(element);
    return element;
  }

  function isScalar(value) {
    return value === null || ["number", "string", "boolean"].includes(typeof value);
  }

  // A value as its field shows it; a number in the page's language (numbers.js: the
  // decimal comma in Russian, where a list's items are then parted by "; ").
  function shown(value) {
    if (value === null || value === undefined) return "";
    if (Array.isArray(value)) return value.map(shown).join(LANG === "ru" ? "; " : ", ");
    if (typeof value === "object") return JSON.stringify(value);
    if (typeof value === "number") return mechloopLocalText(String(value), LANG, true);
    return String(value);
  }

  // A typed text as the value it means: a number (in Russian "0,05" too), true/false, or
  // the text itself.
  function parseScalar(text) {
    const s = text.trim();
    const number = mechloopParseNumber(s);
    if (!Number.isNaN(number)) return number;
    if (s === "true") return true;
    if (s === "false") return false;
    return s;
  }

  // "1, 2, 3" or "1; 2; 3"; in Russian "0,5; 1,5" (a comma inside a number is decimal
  // unless the items are parted by ", " or the text has several commas and no ";").
  function parseList(text) {
    let parts = text.split(/[,;]/);
    if (LANG === "ru" && !/,\s/.test(text) && (text.includes(";")
      || (text.match(/,/g) || []).length === 1)) parts = text.split(";");
    return parts.map((part) => part.trim()).filter(Boolean).map(parseScalar);
  }

  // An input of the value at ``keys``: a change writes it (an empty optional one deletes
  // the key); ``list``: the value is a list written "1, 2, 3".
  function field(parent, keys, value, options) {
    const opts = options || {};
    const input = node("input", { class: "form-field" + (opts.wide ? " wide" : ""),
      spellcheck: "false", size: opts.size || 8,
      dataset: { keys: JSON.stringify(keys) } }, parent);
    input.value = shown(value);
    input.dataset.shown = input.value;
    if (opts.title) input.title = t(opts.title);
    input.addEventListener("change", () => {
      const text = input.value;
      if (!text.trim() && opts.optional) {
        if (value !== undefined) edit(keys, { delete: true });
        return;
      }
      const next = opts.list ? parseList(text) : parseScalar(text);
      if (opts.list ? shown(next) === shown(value) : next === value) return;
      edit(keys, { value: next });
    });
    return input;
  }

  // A choice among the keys of ``words`` (choice -> key of WORDS).
  function select(parent, keys, value, words, onChange) {
    const box = node("select", { class: "form-choice",
      dataset: { keys: JSON.stringify(keys) } }, parent);
    for (const [choice, word] of Object.entries(words)) {
      node("option", { value: choice }, box, t(word));
    }
    box.value = String(value);
    box.addEventListener("change", () => onChange(box.value));
    return box;
  }

  function button(parent, word, onClick, attributes) {
    const b = node("button", Object.assign({ type: "button", class: "form-button" },
      attributes || {}), parent, t(word));
    b.addEventListener("click", onClick);
    return b;
  }

  function remove(parent, keys) {
    return button(parent, "formDelete", () => edit(keys, { delete: true }),
      { title: t("formDeleteTitle"), class: "form-button form-delete" });
  }

  function section(parent, word) {
    const box = node("fieldset", { class: "form-section" }, parent);
    node("legend", {}, box, t(word));
    return box;
  }

  // Any value as nested fields: a scalar as an input, a list of scalars as "a, b", a
  // mapping or a list of mappings as labelled groups.
  function tree(parent, keys, value) {
    if (isScalar(value)) return field(parent, keys, value, { wide: true });
    if (Array.isArray(value) && value.every(isScalar)) {
      return field(parent, keys, value, { list: true, wide: true });
    }
    const list = node("dl", { class: "form-tree" }, parent);
    const entries = Array.isArray(value) ? value.map((v, i) => [i, v]) : Object.entries(value);
    for (const [key, item] of entries) {
      node("dt", {}, list, Array.isArray(value) ? `${Number(key) + 1}.` : key);
      const cell = node("dd", {}, list);
      tree(cell, [...keys, keyOf(key)], item);
    }
    return list;
  }

  function keyOf(key) {
    return typeof key === "string" && /^-?\d+$/.test(key) ? Number(key) : key;
  }

  function numbered(mapping) {
    return Object.keys(mapping || {}).map(Number).filter(Number.isFinite).sort((a, b) => a - b);
  }

  function grid(parent, headers) {
    const table = node("table", { class: "form-table" }, parent);
    const head = table.createTHead().insertRow();
    for (const word of headers) node("th", {}, head, word ? t(word) : "");
    return table.createTBody();
  }

  // ---------------------------------------------------------------- arguments
  function argumentKind(arg) {
    if (!arg || typeof arg !== "object") return "table";
    for (const kind of ["table", "law", "intermediate", "csv"]) if (kind in arg) return kind;
    return "table";
  }

  function lastPosition() {
    const n = Number((forms.data || {}).positions);
    return Number.isFinite(n) && n > 0 ? n : 36;
  }

  function argumentTemplate(kind) {
    const n = lastPosition();
    if (kind === "law") return { law: "constant_speed", start: [0, 0], end: [n, 360] };
    if (kind === "intermediate") return { intermediate: { from: 0, to: 1, count: 5 } };
    if (kind === "csv") return { csv: "argument.csv", column: 1 };
    return { table: { [0]: 0, [n]: 360 } };
  }

  // The rows of a CSV text: (position, value) from the first two numeric columns; a
  // header line and blank lines are skipped, a decimal comma is read when ';' separates.
  function csvRows(text) {
    const rows = {};
    for (const line of text.split(/\r?\n/)) {
      if (!line.trim()) continue;
      const semicolon = line.includes(";");
      const cells = line.split(semicolon ? ";" : /[,\t]/).map((c) =>
        (semicolon ? c.replace(",", ".") : c).trim());
      const numbers = cells.map((c) => parseScalar(c)).filter((v) => typeof v === "number");
      if (numbers.length < 2) continue;
      rows[String(Math.round(numbers[0]))] = numbers[1];
    }
    return rows;
  }

  function drawArguments(panel) {
    const args = (forms.data || {}).arguments || {};
    for (const number of numbered(args)) {
      const arg = args[number];
      const keys = ["arguments", number];
      const box = section(panel, "formArgument");
      box.querySelector("legend").textContent = t("formArgumentN", { n: number });
      box.dataset.argument = number;
      const head = node("div", { class: "form-row" }, box);
      node("span", {}, head, t("formFill"));
      const kind = argumentKind(arg);
      select(head, [...keys, "kind"], kind, KINDS,
        (next) => edit(keys, { value: argumentTemplate(next) }));
      remove(head, keys);
      if (kind === "table") {
        const rule = node("label", {}, head, t("formDerivatives") + " ");
        select(rule, [...keys, "derivatives"], arg.derivatives || "linear", RULES,
          (next) => edit([...keys, "derivatives"], { value: next }));
        const body = grid(box, ["formPosition", "formValue", ""]);
        const table = arg.table || {};
        const positions = numbered(table);
        for (const position of positions) {
          const row = body.insertRow();
          row.dataset.position = position;
          const at = node("input", { class: "form-field form-position", size: 5,
            spellcheck: "false", dataset: { keys: JSON.stringify([...keys, "table", position]),
              role: "position" } }, row.insertCell());
          at.value = String(position);
          at.addEventListener("change", () => {  // a new position renames the row
            const next = parseScalar(at.value);
            if (Number.isInteger(next) && next !== position) {
              edit([...keys, "table", position], { key: next });
            } else {
              at.value = String(position);
            }
          });
          field(row.insertCell(), [...keys, "table", position], table[position]);
          remove(row.insertCell(), [...keys, "table", position]);
        }
        const tools = node("div", { class: "form-row" }, box);
        button(tools, "formAddRow", () => {
          const free = positions.length ? Math.min(lastPosition(),
            positions[positions.length - 1] + 1) : 0;
          const at = positions.includes(free) ? Math.max(...positions) + 1 : free;
          edit([...keys, "table", at], { value: positions.length
            ? table[positions[positions.length - 1]] : 0 });
        });
        const file = node("input", { type: "file", accept: ".csv,.txt,text/csv",
          class: "form-csv", dataset: { keys: JSON.stringify([...keys, "table"]) } });
        const label = node("label", { class: "form-button" }, tools, t("formImportCsv"));
        label.appendChild(file);
        file.addEventListener("change", async () => {
          if (!file.files.length) return;
          const rows = csvRows(await file.files[0].text());
          if (!Object.keys(rows).length) {
            showProblem(t("formCsvEmpty"));
            return;
          }
          edit([...keys, "table"], { value: rows });
        });
      } else if (kind === "law") {
        const row = node("div", { class: "form-row" }, box);
        node("span", {}, row, t("formLaw"));
        select(row, [...keys, "law"], arg.law, LAWS,
          (next) => edit([...keys, "law"], { value: next }));
        for (const end of ["start", "end"]) {
          const line = node("div", { class: "form-row" }, box);
          node("span", {}, line, t(end === "start" ? "formLawStart" : "formLawEnd"));
          const pair = Array.isArray(arg[end]) ? arg[end] : [0, 0];
          field(line, [...keys, end, 0], pair[0], { size: 5, title: "formPosition" });
          field(line, [...keys, end, 1], pair[1], { title: "formValue" });
        }
      } else {
        tree(box, [...keys, kind], arg[kind]);
      }
      if (kind !== "csv") {
        const unit = node("label", { class: "form-row" }, box, t("formUnit") + " ");
        field(unit, [...keys, "unit"], arg.unit, { optional: true, size: 6 });
      }
    }
    button(panel, "formAddArgument", () => {
      const used = numbered(args);
      const next = used.length ? used[used.length - 1] + 1 : 1;
      edit(["arguments", next], { value: argumentTemplate("table") });
    });
  }

  // ---------------------------------------------------------------- time
  function drawTime(panel) {
    const data = forms.data || {};
    const box = section(panel, "formPositions");
    const row = node("label", { class: "form-row" }, box, t("formPositionsN") + " ");
    field(row, ["positions"], data.positions, { size: 6 });
    const time = section(panel, "formTime");
    const kind = !data.time ? "none" : "rpm" in data.time ? "rpm" : "table";
    const head = node("div", { class: "form-row" }, time);
    select(head, ["time", "kind"], kind, TIMES, (next) => {
      if (next === "none") edit(["time"], { delete: true });
      else if (next === "rpm") edit(["time"], { value: { rpm: 60 } });
      else edit(["time"], { value: { table: { [0]: 0, [lastPosition()]: 1 } } });
    });
    if (kind === "rpm") {
      const line = node("div", { class: "form-row" }, time);
      node("span", {}, line, t("formRpm"));
      field(line, ["time", "rpm"], data.time.rpm, { size: 7 });
      node("span", {}, line, t("formTurns"));
      field(line, ["time", "turns"], data.time.turns, { size: 4, optional: true });
    } else if (kind === "table") {
      tree(time, ["time"], data.time);
    }
  }

  // ---------------------------------------------------------------- vectors, contours
  function roleOf(value) {
    if (value === "function") return "function";
    if (value && typeof value === "object") return "link" in value ? "link" : "argument";
    return "constant";
  }

  function roleTemplate(role, letter) {
    if (role === "function") return "function";
    if (role === "argument") return { argument: 1 };
    if (role === "link") return { link: letter === "a" ? "a1" : "r1" };
    return letter === "a" ? 0 : 1;
  }

  function parameterCell(cell, keys, value, letter) {
    const role = roleOf(value);
    cell.className = "form-parameter";
    select(cell, [...keys, "role"], role, ROLES,
      (next) => edit(keys, { value: roleTemplate(next, letter) }));
    if (role === "constant") field(cell, keys, value, { size: 7 });
    if (role === "argument") {
      field(cell, [...keys, "argument"], value.argument, { size: 2, title: "formArgNumber" });
      field(cell, [...keys, "offset"], value.offset, { size: 5, optional: true,
        title: "formOffset" });
    }
    if (role === "link") {
      field(cell, [...keys, "link"], value.link, { size: 3, title: "formLinkTo" });
      field(cell, [...keys, "ratio"], value.ratio, { size: 4, optional: true,
        title: "formRatio" });
      field(cell, [...keys, "delta"], value.delta, { size: 4, optional: true,
        title: "formDelta" });
    }
  }

  function drawVectors(panel) {
    const data = forms.data || {};
    const vectors = data.vectors || {};
    const box = section(panel, "formVectors");
    const body = grid(box, ["formNumber", "formLength", "formAngle", "formName", ""]);
    for (const number of numbered(vectors)) {
      const vector = vectors[number] || {};
      const keys = ["vectors", number];
      const row = body.insertRow();
      row.dataset.vector = number;
      row.insertCell().textContent = number;
      parameterCell(row.insertCell(), [...keys, "r"], vector.r, "r");
      parameterCell(row.insertCell(), [...keys, "a"], vector.a, "a");
      field(row.insertCell(), [...keys, "name"], vector.name, { optional: true, size: 12 });
      remove(row.insertCell(), keys);
    }
    button(box, "formAddVector", () => {
      const used = numbered(vectors);
      edit(["vectors", used.length ? used[used.length - 1] + 1 : 1],
        { value: { r: 1, a: 0 } });
    });
    const loops = section(panel, "formContours");
    const rows = grid(loops, ["formNumber", "formContourVectors", "formVariant", "formName",
      ""]);
    (data.contours || []).forEach((contour, i) => {
      const keys = ["contours", i];
      const row = rows.insertRow();
      row.dataset.contour = i + 1;
      row.insertCell().textContent = i + 1;
      field(row.insertCell(), [...keys, "vectors"], contour.vectors, { list: true, size: 12 });
      const variant = contour.variant === undefined ? "1" : String(contour.variant);
      select(row.insertCell(), [...keys, "variant"], variant, VARIANTS,
        (next) => edit([...keys, "variant"], { value: parseScalar(next) }));
      field(row.insertCell(), [...keys, "name"], contour.name, { optional: true, size: 10 });
      remove(row.insertCell(), keys);
    });
    button(loops, "formAddContour", () => edit(["contours", (data.contours || []).length],
      { value: { vectors: numbered(vectors).slice(0, 2) } }));
  }

  // ---------------------------------------------------------------- bodies, loads
  function drawBodies(panel) {
    const data = forms.data || {};
    const bodies = data.bodies || {};
    const box = section(panel, "formBodies");
    const body = grid(box, ["formNumber", "formName", "formBodyVectors", "formMass",
      "formInertia", "formCenter", ""]);
    for (const number of numbered(bodies)) {
      const item = bodies[number] || {};
      const keys = ["bodies", number];
      const row = body.insertRow();
      row.dataset.body = number;
      row.insertCell().textContent = number;
      field(row.insertCell(), [...keys, "name"], item.name, { optional: true, size: 10 });
      field(row.insertCell(), [...keys, "vectors"], item.vectors, { list: true, size: 6 });
      field(row.insertCell(), [...keys, "mass"], item.mass, { optional: true, size: 6 });
      field(row.insertCell(), [...keys, "inertia"], item.inertia, { optional: true, size: 6 });
      const center = row.insertCell();
      if (item.center && typeof item.center === "object") tree(center, [...keys, "center"],
        item.center);
      remove(row.insertCell(), keys);
    }
    button(box, "formAddBody", () => {
      const used = numbered(bodies);
      const vector = numbered(data.vectors)[0] || 1;
      edit(["bodies", used.length ? used[used.length - 1] + 1 : 1],
        { value: { vectors: [vector] } });
    });
    // the other sections of the masses panel, as they are written
    for (const [name, word] of [["joints", "formJoints"], ["gravity", "formGravity"],
      ["friction", "formFriction"]]) {
      if (data[name] && typeof data[name] === "object") tree(section(panel, word), [name],
        data[name]);
    }
  }

  function drawLoads(panel) {
    const data = forms.data || {};
    for (const [name, word, columns] of [
      ["forces", "formForces", ["body", "at", "value", "angle", "along", "name"]],
      ["moments", "formMoments", ["body", "value", "name"]]]) {
      const box = section(panel, word);
      const body = grid(box, ["formNumber", ...columns.map((c) => LOADS[c]), ""]);
      (data[name] || []).forEach((load, i) => {
        const row = body.insertRow();
        row.dataset[name === "forces" ? "force" : "moment"] = i + 1;
        row.insertCell().textContent = i + 1;
        for (const column of columns) {
          const cell = row.insertCell();
          const value = load[column];
          if (value !== undefined && !isScalar(value)) tree(cell, [name, i, column], value);
          else field(cell, [name, i, column], value, { optional: column !== "body"
            && column !== "value", size: column === "name" ? 10 : 6 });
        }
        remove(row.insertCell(), [name, i]);
      });
      button(box, name === "forces" ? "formAddForce" : "formAddMoment", () => {
        const first = numbered(data.bodies)[0] || 1;
        const vector = ((data.bodies || {})[first] || {}).vectors || [1];
        const value = name === "forces" ? { body: first, at: { head: vector[0] }, value: 0 }
          : { body: first, value: 0 };
        edit([name, (data[name] || []).length], { value });
      });
    }
    for (const [name, word] of [["springs", "formSprings"], ["dampers", "formDampers"]]) {
      if (Array.isArray(data[name]) && data[name].length) tree(section(panel, word), [name],
        data[name]);
    }
  }

  function drawSynthesis(panel) {
    const data = forms.data || {};
    const box = section(panel, "formSynthesis");
    if (!data.synthesis) {
      node("p", { class: "form-note" }, box, t("formNoSynthesis"));
      return;
    }
    tree(box, ["synthesis"], data.synthesis);
  }

  // ---------------------------------------------------------------- the tabs
  const DRAW = { arguments: drawArguments, time: drawTime, vectors: drawVectors,
    bodies: drawBodies, loads: drawLoads, synthesis: drawSynthesis };

  function draw() {
    const panel = $("forms");
    for (const button of document.querySelectorAll("#form-tabs button")) {
      button.classList.toggle("active", button.dataset.tab === forms.tab);
    }
    const yaml = forms.tab === "yaml";
    document.querySelector(".editor").hidden = !yaml;
    panel.hidden = yaml;
    if (yaml) return;
    const scroll = panel.scrollTop;
    // the field that has the focus (the user tabbed on after a change) keeps it
    const active = document.activeElement;
    const focused = active && panel.contains(active) && active.dataset.keys
      ? [active.tagName, active.className, active.dataset.keys] : null;
    const typed = focused && active.tagName === "INPUT" && active.dataset.shown !== undefined
      && active.value !== active.dataset.shown ? active.value : null;  // not yet changed
    panel.textContent = "";
    if (forms.stale) node("p", { class: "form-note break" }, panel, t("formStale"));
    if (!forms.data) return;
    DRAW[forms.tab](panel);
    panel.scrollTop = scroll;
    if (focused) {
      const again = [...panel.querySelectorAll("[data-keys]")].find((e) =>
        e.tagName === focused[0] && e.className === focused[1] && e.dataset.keys === focused[2]);
      if (again && typed !== null) again.value = typed;
      if (again) again.focus();
    }
    panel.dataset.drawn = String(Number(panel.dataset.drawn || 0) + 1);
  }

  // A tab drawn by another module (units.js), registered before the page is loaded: its
  // name, its word (a key of WORDS) and the function that draws it into the panel.
  function register(tab, word, drawTab) {
    TABS[tab] = word;
    DRAW[tab] = drawTab;
  }

  function showTab(tab) {
    forms.tab = tab in TABS ? tab : "yaml";
    draw();
  }

  window.addEventListener("DOMContentLoaded", () => {
    const tabs = $("form-tabs");
    for (const [tab, word] of Object.entries(TABS)) {
      const b = node("button", { type: "button", class: "form-tab", "data-tab": tab,
        "data-i18n": word }, tabs, t(word));
      b.addEventListener("click", () => showTab(tab));
    }
    draw();
  });

  window.mechloopForms = {
    changed, draw, showTab, editText, setModelText,
    register, edit, node, field, select, section,
    data: () => forms.data,
  };
})();
