// The interactive 3-D view of a spatial model (issue 17): every vector of the solved model
// as an arrow from its tail to its head, the joints (vector ends), the ground at the fixed
// points, the trajectories of chosen points and the X/Y/Z triad, drawn as SVG in an
// orthographic projection.  Drag (mouse or touch) turns it, the wheel or the +/− buttons
// zoom, "3-D" goes back to the viewing angles it was opened with, XY/ZY/XZ show the three
// projections.  Used by the page of `mechloop serve` (app.js) and by the self-contained
// HTML file of `mechloop animate MODEL -o x.html` (with the player below).
//
// The viewing angles are those of mechloop.views.spatial_plan (matplotlib's elev/azim with
// the model's Y axis up): the eye looks from w = (cos e sin a, sin e, cos e cos a), the
// screen's right is u = (cos a, 0, −sin a) and its up v = w × u (matplotlib's _view_axes
// with V = Y); a point p is drawn at (u·p, v·p), nearer the eye the larger w·p.
// Every drawn joint carries its coordinates (data-x, data-y, data-z) and the view its
// angles (data-elev, data-azim), so what is drawn can be checked against the library.
// The strings come from i18n.js (t, unitText).
"use strict";

(function () {
  const NS = "http://www.w3.org/2000/svg";
  //: the projections: [elev, azim] giving the panels of the static figure (x→, y↑;
  //: z→, y↑; x→, z↑)
  const PROJECTIONS = { xy: [0, 0], zy: [0, -90], xz: [-90, 0] };
  const TRACE_COLORS = ["#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e", "#e6ab02"];
  const ZOOM_MIN = 0.2, ZOOM_MAX = 25;

  function node(name, attributes, parent) {
    const element = document.createElementNS(NS, name);
    for (const [key, value] of Object.entries(attributes || {})) element.setAttribute(key, value);
    if (parent) parent.appendChild(element);
    return element;
  }

  function finite(...values) {
    return values.every((v) => typeof v === "number" && Number.isFinite(v));
  }

  // matplotlib's _norm_angle: into [-180, 180).
  function normAngle(a) {
    return ((a + 180) % 360 + 360) % 360 - 180;
  }

  // The unit axes of the screen (right u, up v, out w) for the angles in degrees.
  function viewAxes(elev, azim) {
    const e = elev * Math.PI / 180, a = azim * Math.PI / 180;
    const w = [Math.cos(e) * Math.sin(a), Math.sin(e), Math.cos(e) * Math.cos(a)];
    const u = [Math.cos(a), 0, -Math.sin(a)];
    const v = [w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0]];
    return { u, v, w };
  }

  function dot(a, p) {
    return a[0] * p[0] + a[1] * p[1] + a[2] * p[2];
  }

  // The point of ``end`` ({x, y, z} arrays) at position k, or null where it is unknown.
  function at(end, k) {
    const p = [end.x[k], end.y[k], end.z[k]];
    return finite(...p) ? p : null;
  }

  class View3d {
    // ``root``: an element the view is built in (its toolbar and its SVG); ``options``:
    // width, height (px).
    constructor(root, options) {
      const o = Object.assign({ width: 560, height: 380 }, options || {});
      this.root = root;
      this.width = o.width;
      this.height = o.height;
      this.data = null;
      this.position = 0;
      this.overlay = false;
      this.traces = [];
      this.elev = 20;
      this.azim = 30;
      this.zoom = 1;
      this.pan = [0, 0];
      root.classList.add("view3d");
      const bar = document.createElement("div");
      bar.className = "view3d-bar";
      const button = (key, action) => {
        const b = document.createElement("button");
        b.type = "button";
        b.dataset.view3d = key;
        b.addEventListener("click", action);
        bar.appendChild(b);
        return b;
      };
      this.buttons = {
        reset: button("reset", () => this.reset()),
        xy: button("xy", () => this.setView(...PROJECTIONS.xy)),
        zy: button("zy", () => this.setView(...PROJECTIONS.zy)),
        xz: button("xz", () => this.setView(...PROJECTIONS.xz)),
        zoomIn: button("zoom-in", () => this.zoomBy(1.25)),
        zoomOut: button("zoom-out", () => this.zoomBy(0.8)),
      };
      this.buttons.xy.textContent = "XY";
      this.buttons.zy.textContent = "ZY";
      this.buttons.xz.textContent = "XZ";
      this.buttons.zoomIn.textContent = "+";
      this.buttons.zoomOut.textContent = "−";
      this.angles = document.createElement("span");
      this.angles.className = "view3d-angles";
      bar.appendChild(this.angles);
      root.appendChild(bar);
      this.svg = node("svg", { width: this.width, height: this.height,
        viewBox: `0 0 ${this.width} ${this.height}`, class: "view3d-svg" }, root);
      this.svg.style.touchAction = "none";  // a touch drag turns the view, not the page
      this.help = document.createElement("p");
      this.help.className = "view3d-help";
      root.appendChild(this.help);
      this.listen();
      this.words();
    }

    // The strings in the page's language (again when it changes).
    words() {
      const b = this.buttons;
      b.reset.textContent = t("view3dReset");
      b.reset.title = t("view3dResetTitle");
      b.xy.title = t("view3dXyTitle");
      b.zy.title = t("view3dZyTitle");
      b.xz.title = t("view3dXzTitle");
      b.zoomIn.title = t("view3dZoomInTitle");
      b.zoomOut.title = t("view3dZoomOutTitle");
      this.help.textContent = t("view3dHelp");
      this.draw();
    }

    listen() {
      let drag = null;
      const touches = new Map();  // the pointers down: two of them pinch (zoom)
      const spread = () => {
        const [a, b] = [...touches.values()];
        return Math.hypot(a.x - b.x, a.y - b.y) || 1;
      };
      this.svg.addEventListener("pointerdown", (event) => {
        touches.set(event.pointerId, { x: event.clientX, y: event.clientY });
        drag = touches.size === 1
          ? { x: event.clientX, y: event.clientY, elev: this.elev, azim: this.azim }
          : { pinch: spread(), zoom: this.zoom };
        try {
          this.svg.setPointerCapture(event.pointerId);
        } catch (error) {  // a pointer the browser does not track (a synthetic event)
        }
        event.preventDefault();
      });
      this.svg.addEventListener("pointermove", (event) => {
        if (!drag || !touches.has(event.pointerId)) return;
        touches.set(event.pointerId, { x: event.clientX, y: event.clientY });
        if (drag.pinch) {
          if (touches.size === 2) this.zoomBy(drag.zoom * spread() / drag.pinch / this.zoom);
          return;
        }
        // as matplotlib's mouse rotation: across the width 180° of azimuth, up the height
        // 180° of elevation (kept within ±90°: Y stays up)
        const elev = drag.elev + (event.clientY - drag.y) / this.height * 180;
        const azim = drag.azim - (event.clientX - drag.x) / this.width * 180;
        this.elev = Math.max(-90, Math.min(90, elev));  // the scale kept while it turns
        this.azim = normAngle(azim);
        this.draw();
      });
      const end = (event) => {
        touches.delete(event.pointerId);
        drag = null;
      };
      this.svg.addEventListener("pointerup", end);
      this.svg.addEventListener("pointercancel", end);
      this.svg.addEventListener("wheel", (event) => {
        event.preventDefault();
        this.zoomBy(Math.exp(-event.deltaY * 0.0015));
      }, { passive: false });
      this.svg.addEventListener("dblclick", () => this.reset());
    }

    // The solved model: {unit, vectors: [{number, color, name, tail: {x, y, z},
    // head: {x, y, z}}], ground: {x, y, z}, broken, elev, azim} (display units, null
    // where the chain breaks).  The angles are kept when the same view is given a new
    // solution (an edit), and set from the data the first time.
    setData(data) {
      const first = !this.data;
      this.data = data;
      this.position = Math.min(this.position, (data.broken || [0]).length - 1);
      this.measure();
      if (first) this.reset(); else this.setView(this.elev, this.azim);
    }

    // The centre and radius of everything drawn (every position): the scale does not
    // change while the mechanism moves or the view turns.
    measure() {
      const points = [];
      const add = (end) => end.x.forEach((x, i) => {
        if (finite(x, end.y[i], end.z[i])) points.push([x, end.y[i], end.z[i]]);
      });
      for (const v of this.data.vectors) { add(v.tail); add(v.head); }
      if (this.data.ground) add(this.data.ground);
      this.points = points;
      const low = [Infinity, Infinity, Infinity], high = [-Infinity, -Infinity, -Infinity];
      for (const p of points) {
        for (const j of [0, 1, 2]) {
          low[j] = Math.min(low[j], p[j]);
          high[j] = Math.max(high[j], p[j]);
        }
      }
      this.center = points.length ? low.map((l, j) => (l + high[j]) / 2) : [0, 0, 0];
      let radius = 0;
      for (const p of points) radius = Math.max(radius, Math.hypot(...p.map((c, j) => c - this.center[j])));
      this.radius = radius > 0 ? radius : 1;
    }

    reset() {
      this.zoom = 1;
      const d = this.data || {};
      this.setView(finite(d.elev) ? d.elev : 20, finite(d.azim) ? d.azim : 30);
    }

    // Look from ``elev``, ``azim`` (deg), every position filling the view at zoom 1.
    setView(elev, azim) {
      this.elev = elev;
      this.azim = azim;
      this.fit();
      this.draw();
    }

    // The scale at zoom 1 (pixels per model unit): every point of every position inside
    // the view at the current angles.
    fit() {
      const { u, v } = viewAxes(this.elev, this.azim);
      const low = [Infinity, Infinity], high = [-Infinity, -Infinity];
      for (const p of this.points || []) {
        const d = p.map((c, j) => c - this.center[j]);
        const seen = [dot(u, d), dot(v, d)];
        for (const j of [0, 1]) {
          low[j] = Math.min(low[j], seen[j]);
          high[j] = Math.max(high[j], seen[j]);
        }
      }
      const known = low[0] <= high[0];
      // the middle of what is seen, drawn in the middle of the view
      this.middle = known ? [0, 1].map((j) => (low[j] + high[j]) / 2) : [0, 0];
      const right = known ? (high[0] - low[0]) / 2 : 0, up = known ? (high[1] - low[1]) / 2 : 0;
      const w = (this.width / 2 - 14) / (right || this.radius);
      const h = ((this.height - 24) / 2 - 22) / (up || this.radius);
      this.fitted = Math.min(w, h, 4 * Math.min(this.width, this.height) / this.radius);
    }

    zoomBy(factor) {
      this.zoom = Math.max(ZOOM_MIN, Math.min(ZOOM_MAX, this.zoom * factor));
      this.draw();
    }

    view() {
      return { elev: this.elev, azim: this.azim, zoom: this.zoom };
    }

    // Pixels per model unit.
    scale() {
      if (!this.fitted) this.fit();
      return this.zoom * this.fitted;
    }

    // ``p`` = [x, y, z] (model units): {right, up, depth} on the screen's axes (model units,
    // about the origin) and {px, py}, the SVG's pixels.
    project(p) {
      const { u, v, w } = viewAxes(this.elev, this.azim);
      const right = dot(u, p), up = dot(v, p), depth = dot(w, p);
      const s = this.scale(), c = this.center, m = this.middle;
      const px = this.width / 2 + s * (right - dot(u, c) - m[0]);
      const py = (this.height + 24) / 2 - s * (up - dot(v, c) - m[1]);
      return { right, up, depth, px, py };
    }

    // Draw position ``k`` with the overlay of every position (``overlay``) and the
    // trajectories of ``traces`` (keys "head:2", "tail:2").
    show(k, overlay, traces) {
      this.position = k;
      this.overlay = !!overlay;
      this.traces = traces || [];
      this.draw();
    }

    draw() {
      const svg = this.svg;
      while (svg.firstChild) svg.removeChild(svg.firstChild);
      this.angles.textContent = t("view3dAngles", {
        elev: Number(this.elev.toFixed(1)), azim: Number(this.azim.toFixed(1)) });
      svg.dataset.elev = this.elev;
      svg.dataset.azim = this.azim;
      svg.dataset.position = this.position;
      const data = this.data;
      if (!data) return;
      const k = this.position;
      const { w } = viewAxes(this.elev, this.azim);
      const depthOf = (p) => (dot(w, p) - dot(w, this.center)) / this.radius;  // -1..1
      this.drawTriad();
      const defs = node("defs", {}, svg);
      for (const v of data.vectors) {
        const marker = node("marker", { id: `v3-arrow-${v.number}`, viewBox: "0 0 10 10",
          refX: "10", refY: "5", markerWidth: 9, markerHeight: 9,
          markerUnits: "userSpaceOnUse", orient: "auto-start-reverse" }, defs);
        node("path", { d: "M0,1 L10,5 L0,9 z", fill: v.color }, marker);
      }
      // the ground: a support triangle on a hatched base under every fixed point
      const ground = node("g", { class: "ground" }, svg);
      if (data.ground) {
        data.ground.x.forEach((x, i) => {
          const p = [x, data.ground.y[i], data.ground.z[i]];
          if (!finite(...p)) return;
          const { px, py } = this.project(p);
          node("path", { d: `M${px},${py} l-7,11 h14 z`, fill: "white", stroke: "#333",
            "stroke-width": 1 }, ground);
          for (let h = -8; h <= 6; h += 4) {
            node("line", { x1: px + h, y1: py + 15, x2: px + h + 4, y2: py + 11,
              stroke: "#333", "stroke-width": 1 }, ground);
          }
        });
      }
      this.drawHistory();
      // the vectors, farthest first, nearer ones thicker (the depth cue)
      const drawn = [];
      for (const v of data.vectors) {
        const a = at(v.tail, k), b = at(v.head, k);
        if (!a || !b) continue;
        const middle = a.map((c, j) => (c + b[j]) / 2);
        drawn.push({ v, a, b, depth: depthOf(middle) });
      }
      drawn.sort((p, q) => p.depth - q.depth);
      const vectors = node("g", { class: "vectors" }, svg);
      for (const { v, a, b, depth } of drawn) {
        const pa = this.project(a), pb = this.project(b);
        node("line", { id: "v3-vector-" + v.number, class: "vector3d", x1: pa.px,
          y1: pa.py, x2: pb.px, y2: pb.py, stroke: v.color,
          "stroke-width": (2.1 + 0.9 * depth).toFixed(2),
          "marker-end": `url(#v3-arrow-${v.number})`, "data-vector": v.number }, vectors);
      }
      // the joints: the distinct vector ends
      const joints = node("g", { class: "joints" }, svg);
      const seen = [];
      const same = 1e-9 * this.radius;
      for (const { a, b } of drawn) {
        for (const p of [a, b]) {
          if (seen.some((q) => Math.max(...q.map((c, j) => Math.abs(c - p[j]))) <= same)) continue;
          seen.push(p);
        }
      }
      seen.sort((p, q) => depthOf(p) - depthOf(q));
      for (const p of seen) {
        const { px, py } = this.project(p);
        node("circle", { cx: px, cy: py, r: 3.4, fill: "#bbb", stroke: "black",
          "stroke-width": 0.8, class: "joint3d", "data-x": p[0], "data-y": p[1],
          "data-z": p[2] }, joints);
      }
      // the numbers at the middles
      const labels = node("g", { class: "labels" }, svg);
      for (const { v, a, b } of drawn) {
        const pa = this.project(a), pb = this.project(b);
        const cx = (pa.px + pb.px) / 2, cy = (pa.py + pb.py) / 2;
        const label = node("g", { class: "number" }, labels);
        node("rect", { x: cx - 7, y: cy - 7, width: 14, height: 14, rx: 3, fill: "white",
          stroke: v.color }, label);
        node("text", { x: cx, y: cy + 4, "text-anchor": "middle", "font-size": 10 }, label)
          .textContent = v.number;
      }
      node("text", { x: this.width - 6, y: this.height - 6, "text-anchor": "end",
        "font-size": 10, fill: "#555", class: "unit" }, svg).textContent = unitText(data.unit);
      if (data.broken && data.broken[k]) {
        node("text", { x: this.width / 2, y: 36, "text-anchor": "middle", "font-size": 12,
          fill: "#d62728", class: "break3d" }, svg).textContent = t("broken", { k });
      }
    }

    // The axes X, Y, Z as seen, in the lower left corner.
    drawTriad() {
      const { u, v, w } = viewAxes(this.elev, this.azim);
      const group = node("g", { class: "triad" }, this.svg);
      const ox = 34, oy = this.height - 34, length = 24;
      const axes = [["X", [1, 0, 0], "#d62728"], ["Y", [0, 1, 0], "#2ca02c"],
        ["Z", [0, 0, 1], "#1f77b4"]].sort((p, q) => dot(w, p[1]) - dot(w, q[1]));
      for (const [name, e, color] of axes) {
        const x = ox + length * dot(u, e), y = oy - length * dot(v, e);
        node("line", { x1: ox, y1: oy, x2: x, y2: y, stroke: color, "stroke-width": 1.6 },
          group);
        node("text", { x: ox + 1.35 * length * dot(u, e) - 3, y: oy - 1.35 * length * dot(v, e) + 4,
          "font-size": 10, fill: color, class: "axis-" + name.toLowerCase() }, group)
          .textContent = name;
      }
    }

    // Every position faintly, and the trajectories (with gaps where the chain breaks).
    drawHistory() {
      const data = this.data;
      const count = data.vectors.length ? data.vectors[0].tail.x.length : 0;
      if (this.overlay) {
        const group = node("g", { class: "overlay", opacity: 0.2 }, this.svg);
        for (const v of data.vectors) {
          let d = "";
          for (let i = 0; i < count; i++) {
            const a = at(v.tail, i), b = at(v.head, i);
            if (!a || !b) continue;
            const pa = this.project(a), pb = this.project(b);
            d += `M${pa.px},${pa.py} L${pb.px},${pb.py} `;
          }
          node("path", { d, fill: "none", stroke: v.color, "stroke-width": 1 }, group);
        }
      }
      this.traces.forEach((key, j) => {
        const [end, number] = key.split(":");
        const vector = data.vectors.find((v) => String(v.number) === number);
        if (!vector || (end !== "head" && end !== "tail")) return;
        let d = "", pen = false, points = 0;
        for (let i = 0; i < count; i++) {
          const p = at(vector[end], i);
          if (!p) { pen = false; continue; }
          const { px, py } = this.project(p);
          d += `${pen ? "L" : "M"}${px},${py} `;
          pen = true;
          points += 1;
        }
        node("path", { d, fill: "none", stroke: TRACE_COLORS[j % TRACE_COLORS.length],
          "stroke-width": 1.4, "stroke-dasharray": "5 3", class: "trajectory3d",
          "data-key": key, "data-points": points }, this.svg);
      });
    }
  }

  // The self-contained HTML file's player: the position slider, play/pause, one position
  // back or forward, the overlay and the trajectories, over ``data`` (see setData; and
  // frames, the positions played in a loop, interval, ms a frame, time, breaks, name).
  function player(root, data) {
    const $ = (id) => document.getElementById(id);
    const view = new View3d(root, { width: 720, height: 480 });
    view.setData(data);
    const n = data.broken.length - 1;
    const slider = $("slider");
    slider.max = n;
    let timer = null;
    const traces = () => ($("traces").checked ? data.traced : []);
    const show = (k) => {
      $("traces-label").textContent = t("view3dTraces");
      slider.value = k;
      view.show(k, $("overlay").checked, traces());
      let label = t("position", { k, n });
      if (data.time) {  // the decimal comma in Russian (numbers.js, inlined by the file)
        const time = Number(data.time[k].toPrecision(4));
        label += ", " + t("time", { t: window.mechloopLocalText
          ? window.mechloopLocalText(String(time)) : time });
      }
      $("position-label").textContent = label;
      const note = $("break-note");
      if (data.broken[k]) {
        const reasons = data.breaks.filter((b) => b.positions.includes(k))
          .map((b) => t("breakReason", Object.assign({}, b,
            LANG === "ru" && b.reason_ru ? { reason: b.reason_ru } : {})));
        note.textContent = [t("broken", { k }), ...reasons].join("; ");
        note.hidden = false;
      } else {
        note.hidden = true;
      }
    };
    const step = (direction) => {
      const i = data.frames.indexOf(view.position);
      const next = i < 0 ? data.frames.findIndex((f) => f > view.position)
        : (i + direction + data.frames.length) % data.frames.length;
      show(data.frames[Math.max(0, next)]);
    };
    const play = () => {
      if (timer) { clearInterval(timer); timer = null; } else {
        timer = setInterval(() => step(1), data.interval);
      }
      $("play").dataset.i18n = timer ? "pause" : "play";
      $("play").textContent = t($("play").dataset.i18n);
    };
    slider.addEventListener("input", () => show(Number(slider.value)));
    $("play").addEventListener("click", play);
    $("step-back").addEventListener("click", () => { if (timer) play(); step(-1); });
    $("step-forward").addEventListener("click", () => { if (timer) play(); step(1); });
    $("overlay").addEventListener("change", () => show(view.position));
    $("traces").addEventListener("change", () => show(view.position));
    show(data.frames[0] || 0);
    window.mechloopView3d = view;  // the tests' hook: view(), setView(), project(), show()
    window.mechloopPlayer = { show, play, step };
    return view;
  }

  window.View3d = View3d;
  window.view3dPlayer = player;
  window.view3dAxes = viewAxes;
})();
