// The vector diagram and the plot, drawn as SVG from the solution the API sends.
// Every drawn vector and the plot's marker carry their numbers (data-x1 ... data-value) in
// the units of the solution, so what is drawn can be checked against the API.
"use strict";

const SVG = "http://www.w3.org/2000/svg";

function el(name, attributes, parent) {
  const node = document.createElementNS(SVG, name);
  for (const [key, value] of Object.entries(attributes || {})) node.setAttribute(key, value);
  if (parent) parent.appendChild(node);
  return node;
}

function clear(svg) {
  while (svg.firstChild) svg.removeChild(svg.firstChild);
}

function known(...values) {
  return values.every((v) => v !== null && v !== undefined && Number.isFinite(v));
}

// A map from the solution's plane (y up) to the SVG's pixels, one scale on both axes.
function planeMap(limits, width, height, pad) {
  const [x0, x1, y0, y1] = limits;
  const scale = Math.min((width - 2 * pad) / (x1 - x0), (height - 2 * pad) / (y1 - y0));
  const dx = (width - scale * (x1 - x0)) / 2;
  const dy = (height - scale * (y1 - y0)) / 2;
  return {
    scale,
    x: (x) => dx + (x - x0) * scale,
    y: (y) => height - dy - (y - y0) * scale,
  };
}

// The points a trajectory can follow: "head:2", "tail:2" (of a vector), "center:S2",
// "joint:A"; each {key, x, y} over every position (null where the chain breaks).
function tracePoints(diagram) {
  const points = [];
  for (const v of diagram.vectors) {
    points.push({ key: `head:${v.number}`, word: "pointHead", n: v.number, ...v.head });
    points.push({ key: `tail:${v.number}`, word: "pointTail", n: v.number, ...v.tail });
  }
  for (const c of diagram.centers) {
    points.push({ key: `center:${c.name}`, word: "pointCenter", n: c.name, x: c.x, y: c.y });
  }
  for (const j of diagram.joints) {
    points.push({ key: `joint:${j.name}`, word: "pointJoint", n: j.name, x: j.x, y: j.y });
  }
  return points;
}

// Every position faintly (the photo overlay) and the trajectories of the points ``traces``
// (keys of tracePoints), drawn under the mechanism; a trajectory is broken where the
// chain breaks.
function drawHistory(svg, diagram, map, overlay, traces) {
  if (overlay) {
    const group = el("g", { id: "overlay", opacity: 0.2 }, svg);
    for (const vector of diagram.vectors) {
      let d = "";
      vector.tail.x.forEach((x1, i) => {
        const y1 = vector.tail.y[i], x2 = vector.head.x[i], y2 = vector.head.y[i];
        if (known(x1, y1, x2, y2)) d += `M${map.x(x1)},${map.y(y1)} L${map.x(x2)},${map.y(y2)} `;
      });
      el("path", { d, fill: "none", stroke: vector.color, "stroke-width": 1,
        class: "overlay", "data-vector": vector.number }, group);
    }
  }
  const points = tracePoints(diagram);
  traces.forEach((key, j) => {
    const point = points.find((p) => p.key === key);
    if (!point) return;
    let d = "", pen = false, count = 0;
    point.x.forEach((x, i) => {
      const y = point.y[i];
      if (known(x, y)) {
        d += `${pen ? "L" : "M"}${map.x(x)},${map.y(y)} `;
        pen = true;
        count += 1;
      } else {
        pen = false;
      }
    });
    el("path", { d, fill: "none", stroke: CURVE_COLORS[j % CURVE_COLORS.length],
      "stroke-width": 1.4, "stroke-dasharray": "5 3", class: "trajectory",
      id: "trajectory-" + key.replace(":", "-"), "data-points": count }, svg);
  });
}

function drawDiagram(svg, solution, k, overlay = false, traces = [], prefix = "") {
  clear(svg);
  const width = Number(svg.getAttribute("width"));
  const height = Number(svg.getAttribute("height"));
  const diagram = solution.diagram;
  const map = planeMap(diagram.limits, width, height, 16);
  const defs = el("defs", {}, svg);
  const size = 10;
  for (const vector of diagram.vectors) {
    const marker = el("marker", {
      id: prefix + "arrow-" + vector.number, viewBox: "0 0 10 10", refX: "10", refY: "5",
      markerWidth: size, markerHeight: size, markerUnits: "userSpaceOnUse",
      orient: "auto-start-reverse",
    }, defs);
    el("path", { d: "M0,1 L10,5 L0,9 z", fill: vector.color }, marker);
  }
  // the ground: a hatched base under every fixed point
  const ground = el("g", { class: "ground" }, svg);
  diagram.ground.x.forEach((gx, i) => {
    const px = map.x(gx), py = map.y(diagram.ground.y[i]);
    el("path", { d: `M${px},${py} l-7,11 h14 z`, fill: "none", stroke: "#333",
      "stroke-width": 1 }, ground);
    for (let h = -8; h <= 6; h += 4) {
      el("line", { x1: px + h, y1: py + 15, x2: px + h + 4, y2: py + 11, stroke: "#333",
        "stroke-width": 1 }, ground);
    }
  });
  drawHistory(svg, diagram, map, overlay, traces);
  const vectors = el("g", { class: "vectors" }, svg);
  const labels = el("g", { class: "labels" }, svg);
  for (const vector of diagram.vectors) {
    const x1 = vector.tail.x[k], y1 = vector.tail.y[k];
    const x2 = vector.head.x[k], y2 = vector.head.y[k];
    if (!known(x1, y1, x2, y2)) continue;
    const a = [map.x(x1), map.y(y1)], b = [map.x(x2), map.y(y2)];
    el("line", {
      id: prefix + "vector-" + vector.number, class: "vector", x1: a[0], y1: a[1], x2: b[0],
      y2: b[1], stroke: vector.color, "stroke-width": 2.2,
      "marker-end": "url(#" + prefix + "arrow-" + vector.number + ")",
      "data-x1": x1, "data-y1": y1, "data-x2": x2, "data-y2": y2,
    }, vectors);
    for (const [letter, role] of Object.entries(vector.marks)) {
      const f = letter === "a" ? 0.25 : 0.75;
      const mx = a[0] + f * (b[0] - a[0]), my = a[1] + f * (b[1] - a[1]);
      if (role === "function") {
        el("circle", { cx: mx, cy: my, r: 4, fill: "white", stroke: "black",
          class: "mark-function" }, vectors);
      } else {
        const angle = Math.atan2(b[1] - a[1], b[0] - a[0]) * 180 / Math.PI;
        el("path", { d: "M6,0 L-4,5 L-4,-5 z", fill: vector.color, stroke: "black",
          "stroke-width": 0.8, class: "mark-argument",
          transform: `translate(${mx},${my}) rotate(${angle})` }, vectors);
      }
    }
    const label = el("g", { class: "number" }, labels);
    const cx = (a[0] + b[0]) / 2, cy = (a[1] + b[1]) / 2;
    el("rect", { x: cx - 7, y: cy - 7, width: 14, height: 14, rx: 3, fill: "white",
      stroke: vector.color }, label);
    el("text", { x: cx, y: cy + 4, "text-anchor": "middle", "font-size": 10 }, label)
      .textContent = vector.number;
  }
  for (const joint of diagram.joints) {
    const x = joint.x[k], y = joint.y[k];
    if (!known(x, y)) continue;
    if (joint.kind === "revolute") {
      el("circle", { cx: map.x(x), cy: map.y(y), r: 3.5, fill: "#bbb", stroke: "black",
        class: "joint" }, labels);
    }
    el("text", { x: map.x(x) + 5, y: map.y(y) - 5, "font-size": 10, "font-weight": "bold" },
      labels).textContent = joint.name;
  }
  for (const center of diagram.centers) {
    const x = center.x[k], y = center.y[k];
    if (!known(x, y)) continue;
    const px = map.x(x), py = map.y(y);
    el("circle", { cx: px, cy: py, r: 5, fill: "white", stroke: "black", class: "center" },
      labels);
    el("path", { d: `M${px},${py} v-5 a5,5 0 0,1 5,5 z M${px},${py} v5 a5,5 0 0,1 -5,-5 z`,
      fill: "black" }, labels);
    el("text", { x: px + 6, y: py + 12, "font-size": 9 }, labels).textContent = center.name;
  }
  el("text", { x: 6, y: height - 6, "font-size": 10, fill: "#555", class: "unit" }, svg)
    .textContent = unitText(diagram.unit);
}

// Round tick values covering [low, high].
function ticks(low, high, count) {
  if (!(high > low)) return [low];
  const raw = (high - low) / count;
  const power = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 5, 10].map((m) => m * power).find((s) => s >= raw);
  const out = [];
  for (let v = Math.ceil(low / step) * step; v <= high + 1e-9 * step; v += step) {
    out.push(Math.abs(v) < 1e-12 * step ? 0 : v);
  }
  return out;
}

// A number for reading, in the page's language (numbers.js: the decimal comma in Russian).
function format(value) {
  return mechloopNumber(value);
}

// A number of the results table with the model's precision (the API's ``precision``:
// ``{digits}`` significant digits or ``{decimals}`` after the point; the value comes
// rounded by the library, this only prints it, trailing zeros kept); else as format().
function formatPrecise(value, precision) {
  if (!Number.isFinite(value) || !precision) return format(value);
  if (precision.digits) return mechloopLocalText(value.toPrecision(precision.digits));
  if (precision.decimals !== undefined) {
    return mechloopLocalText(value.toFixed(precision.decimals));
  }
  return format(value);
}

// The colours of the curves (matplotlib's first six).
const CURVE_COLORS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b", "#e377c2"];
const AXIS_WIDTH = 58;  // px of one y-axis with its labels

// Up to six columns over the positions, one y-axis per unit (the first unit's axis on the
// left, the next on the right, and so on outwards), the slider's position marked on every
// curve; the first curve's marker is #plot-marker, every marker carries its value.
// ``range``: the positions shown [from, to] (zoomed; all when not given); the frame of the
// plot is kept as svg.plotFrame for the hover values (plotzoom.js).
function drawPlot(svg, solution, columns, k, range) {
  clear(svg);
  columns = columns.filter(Boolean);
  if (!columns.length) return;
  const width = Number(svg.getAttribute("width"));
  const height = Number(svg.getAttribute("height"));
  const units = [...new Set(columns.map((c) => c.unit))];
  const sides = units.map((u, j) => (j % 2 === 0 ? "left" : "right"));
  const count = (side) => sides.filter((s) => s === side).length;
  const left = AXIS_WIDTH * count("left") + 6, right = AXIS_WIDTH * count("right") + 12;
  const top = 12 + 14 * Math.ceil(columns.length / 3), bottom = 34;
  const n = solution.count - 1;
  const [i0, i1] = range || [0, n];
  const x = (i) => left + (i1 > i0 ? (i - i0) / (i1 - i0) : 0) * (width - left - right);
  svg.dataset.from = i0;
  svg.dataset.to = i1;
  const shown = (i) => i >= Math.floor(i0) && i <= Math.ceil(i1);
  const axes = el("g", { class: "axes", "font-size": 10, fill: "#333" }, svg);
  for (const i of ticks(i0, i1, 8)) {
    el("line", { x1: x(i), x2: x(i), y1: top, y2: height - bottom, stroke: "#e3e3e3" }, axes);
    el("text", { x: x(i), y: height - bottom + 13, "text-anchor": "middle" }, axes)
      .textContent = format(i);
  }
  el("text", { x: (left + width - right) / 2, y: height - 4, "text-anchor": "middle" }, axes)
    .textContent = t("axisPosition");
  const scales = {};
  units.forEach((unit, j) => {
    const finite = columns.filter((c) => c.unit === unit)
      .flatMap((c) => c.values.filter((v, i) => known(v) && shown(i)));
    let low = finite.length ? Math.min(...finite) : 0;
    let high = finite.length ? Math.max(...finite) : 1;
    if (high - low < 1e-12 * Math.max(1, Math.abs(high))) { low -= 1; high += 1; }
    const y = (v) => top + (high - v) / (high - low) * (height - top - bottom);
    scales[unit] = y;
    const side = sides[j], outward = Math.floor(j / 2);
    const at = side === "left" ? left - outward * AXIS_WIDTH : width - right + outward * AXIS_WIDTH;
    const sign = side === "left" ? -1 : 1;
    const first = columns.findIndex((c) => c.unit === unit);
    const color = units.length > 1 ? CURVE_COLORS[first] : "#333";
    const axis = el("g", { class: "y-axis", "data-unit": unit, fill: color }, axes);
    el("line", { x1: at, x2: at, y1: top, y2: height - bottom, stroke: color }, axis);
    for (const v of ticks(low, high, 5)) {
      if (j === 0) {
        el("line", { x1: left, x2: width - right, y1: y(v), y2: y(v), stroke: "#e3e3e3" },
          axes);
      }
      el("line", { x1: at, x2: at + 3 * sign, y1: y(v), y2: y(v), stroke: color }, axis);
      el("text", { x: at + 5 * sign, y: y(v) + 3,
        "text-anchor": side === "left" ? "end" : "start" }, axis).textContent = format(v);
    }
    const middle = top + (height - top - bottom) / 2, lx = at + (AXIS_WIDTH - 8) * sign;
    const names = columns.filter((c) => c.unit === unit).map((c) => columnText(c.name));
    el("text", { x: lx, y: middle, "text-anchor": "middle",
      transform: `rotate(-90 ${lx} ${middle})` }, axis)
      .textContent = `${names.join(", ")}, ${unitText(unit)}`;
  });
  el("rect", { x: left, y: top, width: width - left - right, height: height - top - bottom,
    fill: "none", stroke: "#888" }, axes);
  const clip = el("clipPath", { id: svg.id + "-clip" }, el("defs", {}, svg));
  el("rect", { x: left, y: top - 5, width: width - left - right,
    height: height - top - bottom + 10 }, clip);
  const inside = el("g", { "clip-path": `url(#${svg.id}-clip)` }, svg);
  svg.plotFrame = { left, right, top, bottom, width, height, i0, i1, n, x, scales, columns };
  if (shown(k)) {
    el("line", { x1: x(k), x2: x(k), y1: top, y2: height - bottom, stroke: "#d62728",
      "stroke-dasharray": "4 3", class: "cursor" }, inside);
  }
  columns.forEach((column, j) => {
    const y = scales[column.unit], color = CURVE_COLORS[j];
    // the curve, broken where a value is unknown
    let path = "", pen = false;
    column.values.forEach((v, i) => {
      if (known(v) && shown(i)) {
        path += `${pen ? "L" : "M"}${x(i).toFixed(2)},${y(v).toFixed(2)} `;
        pen = true;
      } else {
        pen = false;
      }
    });
    el("path", { d: path, fill: "none", stroke: color, "stroke-width": 1.8,
      class: "curve", "data-name": column.name }, inside);
    const v = column.values[k];
    const legend = el("text", { x: 8 + (j % 3) * ((width - 16) / 3),
      y: 11 + 14 * Math.floor(j / 3), "font-size": 11, fill: color, class: "legend",
      "data-name": column.name }, svg);
    legend.textContent = `${columnText(column.name)} = ${format(v === null ? NaN : v)} `
      + unitText(column.unit);
    if (known(v) && shown(k)) {
      const marker = el("circle", { cx: x(k), cy: y(v), r: 4.5, fill: color,
        stroke: "#d62728", class: "marker", "data-name": column.name, "data-position": k,
        "data-value": v }, svg);
      if (j === 0) marker.id = "plot-marker";
    }
  });
}
