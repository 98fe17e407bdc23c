// The views of mechloop plot drawn by the page from their data (api/view, format data:
// the series read back from the figure the server's SVG shows): stacked panels, several
// y-axes per panel, curves over the positions, the machine motion over the input, x–y
// curves (hodographs), reference lines and tables (the summary).
//
// Interactive as the curve plot (plotzoom.js): the wheel zooms about the pointer, a
// dragged box zooms to it (over x; on an x–y plot over both axes), a double click shows
// everything again, hovering shows the nearest point's name, value, unit and position, a
// click moves the position slider to that point's position.  The current position is
// a vertical cursor on the plots over the cycle and a marker (with the vector from the
// origin on a hodograph) on the x–y curves; the zoomed range follows the slider.
"use strict";

const viewPlot = {
  data: null,    // the answer of api/view with format data
  zoom: null,    // {x: [a, b] | null, y: [c, d] | null}: the zoomed ranges, null: all
  drag: null,    // {frame, x0, y0, x1, y1} in px while a box is dragged
  WIDTH: 560,
  AXIS: 58,      // px of one y-axis with its labels
  DASH_WIDTH: 1.8,
};

function viewFinite(values) {
  return (values || []).filter((v) => known(v));
}

// [low, high] of ``values`` with a margin, never empty.
function viewRange(values, margin = 0.04) {
  if (!values.length) return [0, 1];
  let low = Math.min(...values), high = Math.max(...values);
  if (high - low < 1e-12 * Math.max(1, Math.abs(high))) {
    const pad = Math.max(Math.abs(high) * 0.05, 1e-9);
    return [low - pad, high + pad];
  }
  const pad = (high - low) * margin;
  return [low - pad, high + pad];
}

// The series of a panel a pointer can land on (not the reference lines).
function viewPointSeries(panel) {
  return panel.yaxes.flatMap((axis, a) => axis.series
    .filter((s) => s.kind === "line" || s.kind === "points").map((s) => ({ s, a })));
}

// The index of position ``k`` in a series (-1: not there).
function viewIndex(series, k) {
  return series.positions ? series.positions.indexOf(k) : -1;
}

// The x of position ``k`` on a panel over the cycle (null where it is not drawn).
function viewCursorX(panel, k) {
  for (const { s } of viewPointSeries(panel)) {
    const i = viewIndex(s, k);
    if (i >= 0 && known(s.x[i])) return s.x[i];
  }
  return null;
}

function viewXY(panel) {
  return panel.over === "xy";
}

// The zoomed x range, moved so that the current position stays in it.
function viewFollow(k) {
  const zoom = viewPlot.zoom;
  if (!zoom || !zoom.x || !viewPlot.data) return;
  const panel = viewPlot.data.panels.find((p) => !viewXY(p));
  if (!panel) return;
  const x = viewCursorX(panel, k);
  if (x === null) return;
  let [a, b] = zoom.x;
  if (x < a) [a, b] = [x, x + (b - a)];
  if (x > b) [a, b] = [x - (b - a), x];
  zoom.x = [a, b];
}

// Draw the view's panels on ``svg`` at position ``k``; the frames for the pointer are
// kept as svg.viewFrames.
function drawView(svg, data, k) {
  clear(svg);
  svg.viewFrames = [];
  const panels = data.panels;
  const width = viewPlot.WIDTH;
  const heights = panels.map((p) => (viewXY(p) ? 380 : panels.length > 1 ? 190 : 260));
  const height = heights.reduce((a, b) => a + b, 0);
  svg.setAttribute("width", width);
  svg.setAttribute("height", height);
  svg.setAttribute("viewBox", `0 0 ${width} ${height}`);
  svg.dataset.kind = data.kind;
  svg.dataset.position = k;
  viewFollow(k);
  let offset = 0;
  panels.forEach((panel, p) => {
    svg.viewFrames.push(drawViewPanel(svg, data, panel, p, k, offset, heights[p]));
    offset += heights[p];
  });
}

function drawViewPanel(svg, data, panel, p, k, offset, height) {
  const width = viewPlot.WIDTH, AXIS = viewPlot.AXIS;
  const xy = viewXY(panel);
  const zoom = viewPlot.zoom || {};
  const labelled = panel.yaxes.flatMap((axis) => axis.series.filter((s) => s.label));
  // two legend columns, one when a label is long (the machine motion's δ and J)
  const columns = labelled.some((s) => s.label.length > 30) ? 1 : 2;
  const legendRows = Math.ceil(labelled.length / columns);
  const titleRows = panel.title ? panel.title.split("\n").length : 0;
  const top = offset + 8 + 13 * titleRows + 14 * legendRows;
  const bottom = panel.xlabel ? 34 : 18;
  const rights = Math.max(0, panel.yaxes.length - 1);
  const left = AXIS + 6, right = rights ? AXIS * rights + 6 : 14;
  const plotW = width - left - right, plotH = offset + height - bottom - top;
  // the x range: every series, the vertical lines; zoomed
  const allX = panel.yaxes.flatMap((axis) => axis.series.flatMap((s) => viewFinite(s.x)));
  let xr = viewRange(allX, xy ? 0.06 : 0);
  if (zoom.x && (xy ? zoom.panel === p : true)) xr = zoom.x.slice();
  const inX = (x) => x >= xr[0] - 1e-9 * Math.abs(xr[1] - xr[0])
    && x <= xr[1] + 1e-9 * Math.abs(xr[1] - xr[0]);
  const yrs = panel.yaxes.map((axis) => {
    const ys = axis.series.flatMap((s) => (s.kind === "hline" ? viewFinite(s.y)
      : s.y.filter((v, i) => known(v) && (s.kind === "vline" || inX(s.x[i])))));
    return viewRange(ys, 0.06);
  });
  if (xy && zoom.y && zoom.panel === p) yrs[0] = zoom.y.slice();
  if (panel.equal && xy) {  // one scale on both axes, as matplotlib's equal aspect
    const scale = Math.min(plotW / (xr[1] - xr[0]), plotH / (yrs[0][1] - yrs[0][0]));
    const cx = (xr[0] + xr[1]) / 2, cy = (yrs[0][0] + yrs[0][1]) / 2;
    xr = [cx - plotW / scale / 2, cx + plotW / scale / 2];
    yrs[0] = [cy - plotH / scale / 2, cy + plotH / scale / 2];
  }
  const x = (v) => left + (v - xr[0]) / (xr[1] - xr[0]) * plotW;
  const ys = yrs.map((yr) => (v) => top + (yr[1] - v) / (yr[1] - yr[0]) * plotH);
  const group = el("g", { class: "view-panel", "data-panel": p, "data-x0": xr[0],
    "data-x1": xr[1], "data-y0": yrs[0][0], "data-y1": yrs[0][1] }, svg);
  const axes = el("g", { class: "axes", "font-size": 10, fill: "#333" }, group);
  if (panel.title) {
    panel.title.split("\n").forEach((line, j) => {
      el("text", { x: left + plotW / 2, y: offset + 12 + 13 * j, "text-anchor": "middle",
        "font-size": 11, "font-weight": "bold", class: "view-title" }, axes).textContent = line;
    });
  }
  for (const v of ticks(xr[0], xr[1], 8)) {
    el("line", { x1: x(v), x2: x(v), y1: top, y2: top + plotH, stroke: "#e3e3e3" }, axes);
    el("text", { x: x(v), y: top + plotH + 13, "text-anchor": "middle" }, axes)
      .textContent = format(v);
  }
  if (panel.xlabel) {
    el("text", { x: left + plotW / 2, y: top + plotH + 28, "text-anchor": "middle",
      class: "view-xlabel" }, axes).textContent = panel.xlabel;
  }
  panel.yaxes.forEach((axis, j) => {
    const y = ys[j], yr = yrs[j];
    const at = j === 0 ? left : width - right + (j - 1) * AXIS;
    const sign = j === 0 ? -1 : 1;
    const lone = axis.series.filter((s) => s.kind === "line").length === 1
      && panel.yaxes.length > 1;
    const color = lone ? axis.series.find((s) => s.kind === "line").color : "#333";
    const g = el("g", { class: "y-axis", "data-unit": axis.unit, fill: color }, axes);
    el("line", { x1: at, x2: at, y1: top, y2: top + plotH, stroke: color }, g);
    for (const v of ticks(yr[0], yr[1], 5)) {
      if (j === 0) {
        el("line", { x1: left, x2: left + plotW, y1: y(v), y2: y(v), stroke: "#e3e3e3" },
          axes);
      }
      el("line", { x1: at, x2: at + 3 * sign, y1: y(v), y2: y(v), stroke: color }, g);
      el("text", { x: at + 5 * sign, y: y(v) + 3, "text-anchor": j === 0 ? "end" : "start" },
        g).textContent = format(v);
    }
    const middle = top + plotH / 2, lx = at + (AXIS - 6) * sign;
    el("text", { x: lx, y: middle, "text-anchor": "middle", class: "view-ylabel",
      transform: `rotate(-90 ${lx} ${middle})` }, g).textContent = axis.label;
  });
  el("rect", { x: left, y: top, width: plotW, height: plotH, fill: "none", stroke: "#888" },
    axes);
  const clipId = `${svg.id}-clip-${p}`;
  const clip = el("clipPath", { id: clipId }, el("defs", {}, group));
  el("rect", { x: left, y: top - 4, width: plotW, height: plotH + 8 }, clip);
  const inside = el("g", { "clip-path": `url(#${clipId})` }, group);
  const legend = el("g", { class: "view-legend", "font-size": 11 }, group);
  let item = 0;
  const markers = [];
  panel.yaxes.forEach((axis, j) => {
    const y = ys[j];
    for (const s of axis.series) {
      const attrs = { stroke: s.color, "stroke-width": s.kind === "line" ? viewPlot.DASH_WIDTH : 1,
        fill: "none", "data-name": s.name, "data-kind": s.kind };
      if (s.dash) attrs["stroke-dasharray"] = s.dash;
      if (s.kind === "hline") {
        el("line", Object.assign({ x1: left, x2: left + plotW, y1: y(s.y[0]), y2: y(s.y[0]),
          class: "view-line" }, attrs), inside);
      } else if (s.kind === "vline") {
        el("line", Object.assign({ x1: x(s.x[0]), x2: x(s.x[0]), y1: top, y2: top + plotH,
          class: "view-line" }, attrs), inside);
      } else if (s.kind === "line") {
        let d = "", pen = false, n = 0;
        s.x.forEach((xv, i) => {
          const yv = s.y[i];
          if (known(xv, yv)) {
            d += `${pen ? "L" : "M"}${x(xv).toFixed(2)},${y(yv).toFixed(2)} `;
            pen = true;
            n += 1;
          } else {
            pen = false;
          }
        });
        attrs["data-points"] = n;
        el("path", Object.assign({ d, class: "view-curve" }, attrs), inside);
      } else {
        const g = el("g", Object.assign({ class: "view-points" }, attrs), inside);
        s.x.forEach((xv, i) => {
          const yv = s.y[i];
          if (!known(xv, yv)) return;
          const px = x(xv), py = y(yv);
          if (s.marker === "+" || s.marker === "x") {
            el("path", { d: `M${px - 6},${py} h12 M${px},${py - 6} v12` }, g);
          } else {
            el("circle", { cx: px, cy: py, r: 3.5, fill: s.color }, g);
          }
        });
      }
      // the value at the current position
      const i = viewIndex(s, k);
      const v = i >= 0 ? s.y[i] : null;
      if (i >= 0 && known(s.x[i], v)) markers.push({ s, i, j, px: x(s.x[i]), py: y(v) });
      if (s.label) {
        const col = item % columns, row = Math.floor(item / columns);
        const text = el("text", { x: left + col * plotW / columns, class: "view-legend-item",
          y: offset + 8 + 13 * titleRows + 14 * row + 8, fill: s.color,
          "data-name": s.name }, legend);
        let said = s.label;
        const equals = s.name.includes("=") ? ":" : " =";  // a label with its own '='
        if (i >= 0 && !xy) said = `${s.name}${equals} ${format(known(v) ? v : NaN)} ${s.unit}`.trim();
        if (i >= 0 && xy) {
          said = `${s.name} (${format(known(s.x[i]) ? s.x[i] : NaN)}; `
            + `${format(known(v) ? v : NaN)}) ${s.unit}`.trim();
        }
        const room = columns === 1 ? 90 : 44;
        text.textContent = said.length > room ? said.slice(0, room - 1) + "…" : said;
        const title = el("title", {}, text);
        title.textContent = s.label;
        item += 1;
      }
    }
  });
  // the cursor: a vertical line at the position over the cycle, markers on the curves
  if (!xy) {
    const cx = viewCursorX(panel, k);
    if (cx !== null && inX(cx)) {
      el("line", { x1: x(cx), x2: x(cx), y1: top, y2: top + plotH, stroke: "#d62728",
        "stroke-dasharray": "4 3", class: "view-cursor", "data-x": cx,
        "data-position": k }, inside);
    }
  } else if (data.kind === "hodograph" && markers.length) {
    const m = markers[0];
    el("line", { x1: x(0), y1: ys[m.j](0), x2: m.px, y2: m.py, stroke: "#d62728",
      "stroke-width": 1.6, class: "view-vector" }, inside);
  }
  for (const m of markers) {
    el("circle", { cx: m.px, cy: m.py, r: 4.5, fill: m.s.color, stroke: "#d62728",
      "stroke-width": 1.5, class: "view-marker", "data-name": m.s.name, "data-position": k,
      "data-x": m.s.x[m.i], "data-value": m.s.y[m.i] }, inside);
  }
  return { panel, p, left, top, plotW, plotH, xr, yrs, x, ys, xy };
}

// The point of a mouse event in the view's coordinates, and the frame it is in.
function viewAt(svg, event) {
  const p = plotPoint(svg, event);
  const frame = (svg.viewFrames || []).find((f) => p.x >= f.left - 2
    && p.x <= f.left + f.plotW + 2 && p.y >= f.top - 4 && p.y <= f.top + f.plotH + 4);
  return { p, frame };
}

// The point of the panel nearest to the pointer: on a plot over the cycle the nearest x
// first (one position), then the nearest curve; on an x–y plot the nearest in the plane.
function viewNearest(frame, p) {
  let best = null;
  for (const { s, a } of viewPointSeries(frame.panel)) {
    const y = frame.ys[a];
    s.x.forEach((xv, i) => {
      const yv = s.y[i];
      if (!known(xv, yv) || xv < frame.xr[0] || xv > frame.xr[1]) return;
      const dx = Math.abs(frame.x(xv) - p.x), dy = Math.abs(y(yv) - p.y);
      const key = frame.xy ? [Math.hypot(dx, dy), 0] : [Math.round(dx * 2), dy];
      if (!best || key[0] < best.key[0] || (key[0] === best.key[0] && key[1] < best.key[1])) {
        best = { key, s, i, a, px: frame.x(xv), py: y(yv) };
      }
    });
  }
  return best;
}

function viewHideTip() {
  const tip = document.getElementById("view-tip");
  if (tip) tip.hidden = true;
  const mark = document.getElementById("view-hover");
  if (mark) mark.remove();
}

function viewShowTip(svg, event) {
  const { p, frame } = viewAt(svg, event);
  const best = frame && viewNearest(frame, p);
  if (!best) {
    viewHideTip();
    return;
  }
  const { s, i } = best;
  let mark = document.getElementById("view-hover");
  if (!mark) mark = el("circle", { id: "view-hover", r: 5, fill: "none", "stroke-width": 2 }, svg);
  mark.setAttribute("cx", best.px);
  mark.setAttribute("cy", best.py);
  mark.setAttribute("stroke", s.color);
  const tip = document.getElementById("view-tip");
  tip.textContent = "";
  const head = document.createElement("strong");
  head.style.color = s.color;
  const name = s.name || frame.panel.yaxes[best.a].label;
  head.textContent = frame.xy
    ? `${name}: ${format(s.x[i])}; ${format(s.y[i])} ${s.unit}`
    : `${name} = ${format(s.y[i])} ${s.unit}`;
  tip.append(head);
  const k = s.positions ? s.positions[i] : null;
  const lines = [];
  if (known(k)) {
    const solution = state.solution;
    let where = t("position", { k, n: viewPlot.data.count - 1 });
    if (solution && solution.time && known(solution.time[k])) {
      where += ", " + t("time", { t: format(solution.time[k]) });
    }
    lines.push(where);
  }
  if (frame.panel.over === "cycle") lines.push(`${frame.panel.xlabel} = ${format(s.x[i])}`);
  for (const line of lines) {
    const div = document.createElement("div");
    div.textContent = line;
    tip.append(div);
  }
  tip.dataset.name = s.name;
  tip.dataset.value = s.y[i];
  tip.dataset.x = s.x[i];
  tip.dataset.unit = s.unit;
  tip.dataset.position = known(k) ? k : "";
  const box = svg.getBoundingClientRect();
  const scale = box.width / viewPlot.WIDTH;
  const px = best.px * scale, py = best.py * scale;
  tip.hidden = false;
  const right = px + 12 + tip.offsetWidth > box.width;
  tip.style.left = `${right ? px - 12 - tip.offsetWidth : px + 12}px`;
  tip.style.top = `${Math.max(0, py - tip.offsetHeight - 8)}px`;
}

// The view at the current position (app.js calls it on every position and new data).
function drawViewPlot() {
  const svg = document.getElementById("view-plot");
  if (!svg || !viewPlot.data) return;
  if (viewPlot.data.panels.length) drawView(svg, viewPlot.data, state.position);
}

// New data: the tables drawn, the zoom reset, the plot drawn.
function showViewData(data) {
  viewPlot.data = data;
  viewPlot.zoom = null;
  const svg = document.getElementById("view-plot");
  clear(svg);
  if (data.panels.length) svg.removeAttribute("hidden");
  else svg.setAttribute("hidden", "");
  const tables = document.getElementById("view-tables");
  tables.textContent = "";
  for (const table of data.tables) {
    const node = document.createElement("table");
    node.className = "view-table";
    table.rows.forEach((row, r) => {
      const line = (r === 0 && table.header ? node.createTHead() : node.tBodies[0]
        || node.createTBody()).insertRow();
      for (const text of row) {
        const cell = document.createElement(r === 0 && table.header ? "th" : "td");
        cell.textContent = text;
        line.appendChild(cell);
      }
    });
    tables.appendChild(node);
  }
  tables.hidden = !data.tables.length;
  viewHideTip();
  drawViewPlot();
}

function hideViewData() {
  viewPlot.data = null;
  clear(document.getElementById("view-plot"));
  document.getElementById("view-plot").setAttribute("hidden", "");
  document.getElementById("view-tables").hidden = true;
  viewHideTip();
}

function viewZoomTo(frame, xr, yr) {
  if (!(xr[1] > xr[0])) return;
  viewPlot.zoom = frame.xy ? { x: xr, y: yr, panel: frame.p } : { x: xr, y: null };
  drawViewPlot();
}

function viewDrawBox(svg) {
  const d = viewPlot.drag, f = d.frame;
  let box = document.getElementById("view-zoom-box");
  if (!box) {
    box = el("rect", { id: "view-zoom-box", fill: "rgba(31,119,180,0.12)", stroke: "#1f77b4",
      "stroke-dasharray": "3 2" }, svg);
  }
  const y0 = f.xy ? Math.min(d.y0, d.y1) : f.top;
  box.setAttribute("x", Math.min(d.x0, d.x1));
  box.setAttribute("y", y0);
  box.setAttribute("width", Math.abs(d.x1 - d.x0));
  box.setAttribute("height", f.xy ? Math.abs(d.y1 - d.y0) : f.plotH);
}

// The plot values under the px ``px``, ``py`` of a frame.
function viewValue(f, px, py) {
  return [f.xr[0] + (px - f.left) / f.plotW * (f.xr[1] - f.xr[0]),
    f.yrs[0][1] - (py - f.top) / f.plotH * (f.yrs[0][1] - f.yrs[0][0])];
}

window.addEventListener("DOMContentLoaded", () => {
  const svg = document.getElementById("view-plot");
  svg.addEventListener("wheel", (event) => {
    const { p, frame } = viewAt(svg, event);
    if (!frame) return;
    event.preventDefault();
    const factor = event.deltaY < 0 ? 0.8 : 1.25;
    const [ax, ay] = viewValue(frame, p.x, p.y);
    const xr = [ax - (ax - frame.xr[0]) * factor, ax + (frame.xr[1] - ax) * factor];
    const yr = [ay - (ay - frame.yrs[0][0]) * factor, ay + (frame.yrs[0][1] - ay) * factor];
    viewZoomTo(frame, xr, yr);
  }, { passive: false });
  svg.addEventListener("mousedown", (event) => {
    const { p, frame } = viewAt(svg, event);
    if (event.button !== 0 || !frame) return;
    event.preventDefault();
    viewPlot.drag = { frame, x0: p.x, y0: p.y, x1: p.x, y1: p.y };
  });
  svg.addEventListener("mousemove", (event) => {
    const d = viewPlot.drag;
    if (d) {
      const p = plotPoint(svg, event), f = d.frame;
      d.x1 = Math.max(f.left, Math.min(f.left + f.plotW, p.x));
      d.y1 = Math.max(f.top, Math.min(f.top + f.plotH, p.y));
      viewDrawBox(svg);
    }
    viewShowTip(svg, event);
  });
  window.addEventListener("mouseup", (event) => {
    const d = viewPlot.drag;
    if (!d) return;
    viewPlot.drag = null;
    const box = document.getElementById("view-zoom-box");
    if (box) box.remove();
    const f = d.frame;
    const moved = f.xy ? Math.max(Math.abs(d.x1 - d.x0), Math.abs(d.y1 - d.y0))
      : Math.abs(d.x1 - d.x0);
    if (moved > 6) {
      const [a, c] = viewValue(f, Math.min(d.x0, d.x1), Math.max(d.y0, d.y1));
      const [b, e] = viewValue(f, Math.max(d.x0, d.x1), Math.min(d.y0, d.y1));
      viewZoomTo(f, [a, b], [c, e]);
    } else {  // a click: the slider goes to the nearest point's position
      const best = viewNearest(f, { x: d.x0, y: d.y0 });
      const k = best && best.s.positions ? best.s.positions[best.i] : null;
      if (known(k) && state.solution) setPosition(k);
    }
    viewShowTip(svg, event);
  });
  svg.addEventListener("mouseleave", () => { if (!viewPlot.drag) viewHideTip(); });
  svg.addEventListener("dblclick", (event) => {
    event.preventDefault();
    viewPlot.zoom = null;
    drawViewPlot();
  });
});
