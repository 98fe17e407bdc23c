// YAML syntax highlighting of the editor: a <pre> under the transparent textarea shows the
// same text in colour — keys, comments, strings, numbers, units and words of the model
// (function, argument, ...) — redrawn on every change and moved with the textarea's scroll.
// The line of every problem is marked in it too.
"use strict";

// The units the model files write (units: {length: mm, ...}, rpm, ...).
const YAML_UNITS = new Set(["m", "mm", "cm", "km", "deg", "rad", "rev", "s", "ms", "min",
  "h", "kg", "g", "t", "N", "kN", "MN", "N*m", "kN*m", "J", "kJ", "W", "kW", "Pa", "kPa",
  "MPa", "bar", "rpm", "Hz", "rad/s", "deg/s", "m/s", "mm/s", "m/s^2", "mm/s^2",
  "rad/s^2", "kg*m^2", "kg*mm^2"]);
// The model's own words as values.
const YAML_WORDS = new Set(["function", "argument", "true", "false", "null", "yes", "no",
  "on", "off", "~"]);

function escapeHTML(text) {
  return text.replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;");
}

function span(kind, text) {
  return `<span class="y-${kind}">${escapeHTML(text)}</span>`;
}

// One value word: a number, a unit, a word of the model, or plain.
function word(text) {
  if (/^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(text) || /^[-+]?\.(inf|nan)$/i.test(text)) {
    return span("number", text);
  }
  if (YAML_UNITS.has(text)) return span("unit", text);
  if (YAML_WORDS.has(text.toLowerCase())) return span("word", text);
  return escapeHTML(text);
}

// One line of YAML as HTML: block keys and flow keys ({r: 0.2, a: 30}), quoted strings,
// comments (a # at the start or after a space, outside quotes), numbers, units.
function highlightLine(line) {
  let out = "";
  let i = 0;
  const block = /^(\s*(?:-\s+)*)([^\s#'"{}[\],:][^#{}[\],:]*?|"[^"]*"|'[^']*')(\s*)(:)(?=\s|$)/
    .exec(line);
  if (block) {
    out += escapeHTML(block[1]) + span("key", block[2]) + block[3] + span("punct", ":");
    i = block[0].length;
  } else if (/^---|^\.\.\./.test(line)) {
    return span("punct", line);
  }
  let afterOpen = false;  // just after { or , (a flow key may follow)
  while (i < line.length) {
    const rest = line.slice(i);
    const c = line[i];
    if (c === "#" && (i === 0 || /\s/.test(line[i - 1]))) {
      out += span("comment", rest);
      break;
    }
    if (c === '"' || c === "'") {
      const close = c === '"' ? /^"(?:[^"\\]|\\.)*("|$)/ : /^'(?:[^']|'')*('|$)/;
      const quoted = close.exec(rest)[0];
      const isKey = afterOpen && /^\s*:(\s|$)/.test(line.slice(i + quoted.length));
      out += span(isKey ? "key" : "string", quoted);
      i += quoted.length;
      afterOpen = false;
      continue;
    }
    if ("{}[],:".includes(c) || (c === "-" && /^-(\s|$)/.test(rest))) {
      out += span("punct", c);
      afterOpen = c === "{" || c === ",";
      i += 1;
      continue;
    }
    if (/\s/.test(c)) {
      const blank = /^\s+/.exec(rest)[0];
      out += blank;
      i += blank.length;
      continue;
    }
    const token = /^[^\s{}[\],#]+?(?=\s*[{}[\],]|:\s|:$|\s|$)/.exec(rest);
    const text = token ? token[0] : rest;
    const isKey = afterOpen && /^\s*:(\s|$)/.test(line.slice(i + text.length));
    out += isKey ? span("key", text) : word(text);
    i += text.length;
    afterOpen = false;
  }
  return out;
}

// The highlighted HTML of the whole text; ``bad``: the set of lines (1-based) with a
// problem.
function highlightYAML(text, bad) {
  return text.split("\n").map((line, n) => {
    const html = highlightLine(line);
    return bad && bad.has(n + 1) ? `<span class="y-bad">${html}</span>` : html;
  }).join("\n") + "\n ";
}

// The layer under the editor, kept in step with its text and scroll.
const highlighter = {
  bad: new Set(),
  render() {
    const editor = document.getElementById("editor");
    const code = document.getElementById("highlight-code");
    if (!editor || !code) return;
    code.innerHTML = highlightYAML(editor.value, this.bad);
    this.scroll();
  },
  scroll() {
    const editor = document.getElementById("editor");
    const code = document.getElementById("highlight-code");
    code.style.transform = `translate(${-editor.scrollLeft}px, ${-editor.scrollTop}px)`;
  },
  mark(lines) {  // the lines with a problem
    const next = new Set(lines.filter((n) => n));
    if (next.size === this.bad.size && [...next].every((n) => this.bad.has(n))) return;
    this.bad = next;
    this.render();
  },
};

window.addEventListener("DOMContentLoaded", () => {
  const editor = document.getElementById("editor");
  editor.addEventListener("input", () => highlighter.render());
  editor.addEventListener("scroll", () => highlighter.scroll());
  highlighter.render();
});
