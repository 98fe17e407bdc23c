// Drag editing on the mechanism diagram: the head of every vector whose length is a
// constant number carries a handle; dragging it sets the length (and, when the angle is a
// constant number too — a ground point of the frame — the angle) in the model's text.
// While the drag goes on, the text changes every DRAG_MS (api/edit, then the page solves
// it: the diagram, the breaks and the plots follow); on release the value is written
// rounded to three significant digits (angles to 0.1 deg), as one undo step.
"use strict";

(function () {
  const DRAG_MS = 200;
  const drag = { active: null, timer: null, sent: null, recorded: false };

  function number(value) {
    return typeof value === "number" && Number.isFinite(value);
  }

  // The angle unit of the model as a factor from radians (deg by default).
  function angleFactor(data) {
    const unit = ((data && data.units) || {}).angle || "deg";
    if (unit === "rad") return 1;
    if (unit === "grad") return 200 / Math.PI;
    return 180 / Math.PI;
  }

  // ``value`` rounded to ``digits`` significant digits (a sensible step in any unit).
  function rounded(value, digits) {
    if (value === 0) return 0;
    const step = Math.pow(10, Math.floor(Math.log10(Math.abs(value))) - digits + 1);
    return Number((Math.round(value / step) * step).toPrecision(digits + 1));
  }

  function roundedAngle(value, data) {
    const unit = ((data && data.units) || {}).angle || "deg";
    const step = unit === "rad" ? 1e-3 : 0.1;
    return Number((Math.round(value / step) * step).toFixed(unit === "rad" ? 3 : 1));
  }

  // The point of the plane (the diagram's units) under the pointer.
  function planePoint(svg, map, event) {
    const point = svg.createSVGPoint();
    point.x = event.clientX;
    point.y = event.clientY;
    const local = point.matrixTransform(svg.getScreenCTM().inverse());
    return { x: (local.x - map.x(0)) / map.scale, y: (map.y(0) - local.y) / map.scale };
  }

  // The draggable vectors at position k: [{number, tail, head, r, a, ground, factor}].
  function draggable(solution, data, k) {
    const vectors = (data && data.vectors) || {};
    const out = [];
    for (const v of solution.diagram.vectors) {
      const entry = vectors[String(v.number)];
      if (!entry || !number(entry.r) || entry.r <= 0) continue;
      const tail = { x: v.tail.x[k], y: v.tail.y[k] }, head = { x: v.head.x[k], y: v.head.y[k] };
      if (![tail.x, tail.y, head.x, head.y].every(number)) continue;
      const drawn = Math.hypot(head.x - tail.x, head.y - tail.y);
      if (!(drawn > 0)) continue;
      out.push({ number: v.number, tail, head, r: entry.r, ground: number(entry.a),
        factor: drawn / entry.r, color: v.color });
    }
    return out;
  }

  // The handles, drawn after the diagram (app.js's render calls this).
  function render() {
    const svg = $("diagram");
    const solution = state.solution;
    const data = window.mechloopForms ? window.mechloopForms.data() : null;
    if (!solution || !data) return;
    const width = Number(svg.getAttribute("width")), height = Number(svg.getAttribute("height"));
    const map = planeMap(solution.diagram.limits, width, height, 16);
    const group = el("g", { class: "drag-handles" }, svg);
    const shown = Number(svg.dataset.shown ?? state.position);  // faded at a break
    for (const item of draggable(solution, data, shown)) {
      const handle = el("circle", { cx: map.x(item.head.x), cy: map.y(item.head.y), r: 6,
        class: "drag-handle" + (item.ground ? " ground" : ""), "data-vector": item.number,
        fill: item.ground ? "#ffd866" : "white", stroke: item.color, "stroke-width": 2 },
      group);
      const title = el("title", {}, handle);
      title.textContent = t(item.ground ? "dragGround" : "dragLength", { n: item.number });
      handle.addEventListener("pointerdown", (event) => start(event, item, map));
    }
    if (drag.active) preview();
  }

  function start(event, item, map) {
    event.preventDefault();
    const data = window.mechloopForms.data();
    drag.active = { item, map, data, point: null, value: null, text: modelTextNow() };
    drag.recorded = false;
    drag.sent = null;
    document.body.dataset.dragging = String(item.number);
    window.addEventListener("pointermove", move);
    window.addEventListener("pointerup", end, { once: true });
  }

  function modelTextNow() {
    return window.mechloopEditor ? window.mechloopEditor.getText() : $("editor").value;
  }

  // The values the pointer asks: {r} or {r, a} in the model's units.
  function valuesAt(point) {
    const { item, data } = drag.active;
    const dx = point.x - item.tail.x, dy = point.y - item.tail.y;
    const values = { r: Math.hypot(dx, dy) / item.factor };
    if (item.ground) values.a = Math.atan2(dy, dx) * angleFactor(data);
    return values;
  }

  function move(event) {
    const active = drag.active;
    if (!active) return;
    active.point = planePoint($("diagram"), active.map, event);
    active.value = valuesAt(active.point);
    preview();
    if (!drag.timer) drag.timer = setTimeout(() => { drag.timer = null; send(false); }, DRAG_MS);
  }

  // A dashed line from the tail to the pointer while the solution follows.
  function preview() {
    const active = drag.active;
    const svg = $("diagram");
    const old = svg.querySelector(".drag-preview");
    if (old) old.remove();
    if (!active.point) return;
    const { map, item } = active;
    el("line", { class: "drag-preview", x1: map.x(item.tail.x), y1: map.y(item.tail.y),
      x2: map.x(active.point.x), y2: map.y(active.point.y), stroke: "#d62728",
      "stroke-dasharray": "4 3", "stroke-width": 1.5 }, svg);
  }

  // Write the asked values into the text (``final``: rounded, and the drag ends).
  async function send(final) {
    const active = drag.active;
    if (!active || !active.value) return;
    const forms = window.mechloopForms;
    const number = active.item.number;
    const value = final ? { r: rounded(active.value.r, 3),
      a: active.value.a === undefined ? undefined : roundedAngle(active.value.a, active.data) }
      : active.value;
    const key = JSON.stringify(value);
    if (key === drag.sent) {
      if (final) document.body.dataset.dragged = `${number}:${value.r}`;
      return;
    }
    drag.sent = key;
    let text = await forms.editText(["vectors", number, "r"], { value: value.r },
      active.text);
    if (text !== null && value.a !== undefined) {
      text = await forms.editText(["vectors", number, "a"], { value: value.a }, text);
    }
    if (text === null) return;
    forms.setModelText(text, !drag.recorded);  // one undo step for the whole drag
    drag.recorded = true;
    if (final) document.body.dataset.dragged = `${number}:${value.r}`;
  }

  async function end() {
    window.removeEventListener("pointermove", move);
    clearTimeout(drag.timer);
    drag.timer = null;
    await send(true);
    drag.active = null;
    delete document.body.dataset.dragging;
    const old = $("diagram").querySelector(".drag-preview");
    if (old) old.remove();
  }

  window.mechloopDrag = { render, rounded };
})();
