// Zoom and hover values on the curve plot (#plot): the wheel zooms about the pointer,
// dragging a box zooms to its positions, a double click shows every position again; a
// click moves the position slider there.  Hovering shows the nearest curve's name, the
// position (and time) and the value with its unit.  The zoomed range follows the slider:
// a position outside it moves the range to it.
"use strict";

const plotZoom = {
  range: null,     // [from, to] in positions, or null: all
  count: null,     // the positions of the solution the range belongs to
  drag: null,      // {x0, x1} px while a box is dragged
  MIN_SPAN: 2,     // positions: the narrowest range

  // The positions to draw for a solution of n + 1 positions at position k.
  rangeFor(n, k) {
    if (this.count !== n) {  // another model: every position
      this.count = n;
      this.range = null;
    }
    if (!this.range) return [0, n];
    let [a, b] = this.range;
    if (k < a) [a, b] = [k, k + (b - a)];
    if (k > b) [a, b] = [k - (b - a), k];
    this.range = this.clamp(a, b, n);
    return this.range;
  },

  clamp(a, b, n) {
    let span = Math.min(Math.max(b - a, this.MIN_SPAN), n);
    a = Math.max(0, Math.min(a, n - span));
    return [a, a + span];
  },

  set(a, b) {
    const n = this.count;
    if (n === null) return;
    this.range = a <= 0 && b >= n ? null : this.clamp(a, b, n);
    render();
  },

  reset() {
    this.range = null;
    render();
  },
};

// The point of a mouse event in the plot's own coordinates.
function plotPoint(svg, event) {
  const point = svg.createSVGPoint();
  point.x = event.clientX;
  point.y = event.clientY;
  return point.matrixTransform(svg.getScreenCTM().inverse());
}

// The position under the x coordinate ``px`` (unrounded).
function plotPosition(frame, px) {
  const w = frame.width - frame.left - frame.right;
  return frame.i0 + (px - frame.left) / w * (frame.i1 - frame.i0);
}

function inFrame(frame, p) {
  return frame && p.x >= frame.left && p.x <= frame.width - frame.right
    && p.y >= frame.top - 4 && p.y <= frame.height - frame.bottom + 4;
}

function hideTip() {
  const tip = document.getElementById("plot-tip");
  if (tip) tip.hidden = true;
  const mark = document.getElementById("plot-hover");
  if (mark) mark.remove();
}

// The tooltip at the pointer: the curve nearest to it at the nearest position.
function showTip(svg, event) {
  const frame = svg.plotFrame;
  const p = plotPoint(svg, event);
  if (!inFrame(frame, p) || !state.solution) {
    hideTip();
    return;
  }
  const i = Math.max(0, Math.min(frame.n, Math.round(plotPosition(frame, p.x))));
  let best = null;
  for (const column of frame.columns) {
    const v = column.values[i];
    if (!known(v)) continue;
    const distance = Math.abs(frame.scales[column.unit](v) - p.y);
    if (!best || distance < best.distance) best = { column, v, distance };
  }
  if (!best) {
    hideTip();
    return;
  }
  const y = frame.scales[best.column.unit](best.v);
  const color = CURVE_COLORS[frame.columns.indexOf(best.column) % CURVE_COLORS.length];
  let mark = document.getElementById("plot-hover");
  if (!mark) mark = el("circle", { id: "plot-hover", r: 5, fill: "none", "stroke-width": 2 }, svg);
  mark.setAttribute("cx", frame.x(i));
  mark.setAttribute("cy", y);
  mark.setAttribute("stroke", color);
  const tip = document.getElementById("plot-tip");
  tip.textContent = "";
  const head = document.createElement("strong");
  head.style.color = color;
  head.textContent = `${columnText(best.column.name)} = ${format(best.v)} `
    + unitText(best.column.unit);
  const where = document.createElement("div");
  where.textContent = t("position", { k: i, n: frame.n })
    + (state.solution.time ? ", " + t("time", { t: format(state.solution.time[i]) }) : "");
  tip.append(head, where);
  tip.dataset.name = best.column.name;
  tip.dataset.position = i;
  tip.dataset.value = best.v;
  tip.dataset.unit = best.column.unit;
  const box = svg.getBoundingClientRect();
  const scale = box.width / frame.width;
  const px = frame.x(i) * scale, py = y * scale;
  tip.hidden = false;
  const right = px + 12 + tip.offsetWidth > box.width;
  tip.style.left = `${right ? px - 12 - tip.offsetWidth : px + 12}px`;
  tip.style.top = `${Math.max(0, py - tip.offsetHeight - 8)}px`;
}

function drawBox(svg) {
  const frame = svg.plotFrame;
  let box = document.getElementById("zoom-box");
  if (!box) {
    box = el("rect", { id: "zoom-box", fill: "rgba(31,119,180,0.12)", stroke: "#1f77b4",
      "stroke-dasharray": "3 2" }, svg);
  }
  const a = Math.min(plotZoom.drag.x0, plotZoom.drag.x1);
  box.setAttribute("x", a);
  box.setAttribute("y", frame.top);
  box.setAttribute("width", Math.abs(plotZoom.drag.x1 - plotZoom.drag.x0));
  box.setAttribute("height", frame.height - frame.top - frame.bottom);
}

window.addEventListener("DOMContentLoaded", () => {
  const svg = document.getElementById("plot");
  svg.addEventListener("wheel", (event) => {
    const frame = svg.plotFrame;
    const p = plotPoint(svg, event);
    if (!inFrame(frame, p)) return;
    event.preventDefault();
    const at = plotPosition(frame, p.x);
    const factor = event.deltaY < 0 ? 0.8 : 1.25;
    plotZoom.set(at - (at - frame.i0) * factor, at + (frame.i1 - at) * factor);
  }, { passive: false });
  svg.addEventListener("mousedown", (event) => {
    const p = plotPoint(svg, event);
    if (event.button !== 0 || !inFrame(svg.plotFrame, p)) return;
    event.preventDefault();
    plotZoom.drag = { x0: p.x, x1: p.x };
  });
  svg.addEventListener("mousemove", (event) => {
    if (plotZoom.drag) {
      const frame = svg.plotFrame;
      plotZoom.drag.x1 = Math.max(frame.left, Math.min(frame.width - frame.right,
        plotPoint(svg, event).x));
      drawBox(svg);
    }
    showTip(svg, event);
  });
  window.addEventListener("mouseup", (event) => {
    const drag = plotZoom.drag;
    if (!drag) return;
    plotZoom.drag = null;
    const box = document.getElementById("zoom-box");
    if (box) box.remove();
    const frame = svg.plotFrame;
    const a = plotPosition(frame, Math.min(drag.x0, drag.x1));
    const b = plotPosition(frame, Math.max(drag.x0, drag.x1));
    if (Math.abs(drag.x1 - drag.x0) > 6) {
      plotZoom.set(a, b);
    } else if (state.solution) {  // a click: the slider goes there
      setPosition(Math.max(0, Math.min(frame.n, Math.round(a))));
    }
    showTip(svg, event);
  });
  svg.addEventListener("mouseleave", () => { if (!plotZoom.drag) hideTip(); });
  svg.addEventListener("dblclick", (event) => {
    event.preventDefault();
    plotZoom.reset();
  });
});
