// The model's text: the one way every part of the page changes it, and its undo/redo.
//
//   mechloopEditor.setText(text, {record = true})  replace the text; ``record``: as one
//       undo step (false: no step of its own — e.g. while a drag goes on, after a first
//       recorded setText — so one undo goes back to before the last recorded change)
//   mechloopEditor.getText()                       the text
//   mechloopEditor.undo(), mechloopEditor.redo()   one step back / forward
//   mechloopEditor.load(text)                      a new document: the text, no history
//
// Every change — typed, undone, redone or set — fires the textarea's "input" event, so it
// takes the same path as typing (highlight, validate, solve, autosave, form views).
// Typing is recorded in steps: a pause (STEP_MS), a new line or a change of kind
// (typing / deleting / pasting) starts a new one.
"use strict";

(function () {
  const STEP_MS = 800;
  const LIMIT = 500;  // undo steps kept
  const undoStack = [];
  const redoStack = [];
  let last = { text: "", start: 0, end: 0 };  // the text as last seen, with its selection
  let lastKind = "";
  let lastTime = 0;
  let quiet = false;  // an input event fired by this module itself

  const area = () => document.getElementById("editor");

  function snapshot() {
    const e = area();
    return { text: e.value, start: e.selectionStart, end: e.selectionEnd };
  }

  function push(stack, entry) {
    stack.push(entry);
    if (stack.length > LIMIT) stack.shift();
  }

  function changed() {
    quiet = true;
    try {
      area().dispatchEvent(new Event("input", { bubbles: true }));
    } finally {
      quiet = false;
    }
    buttons();
  }

  function restore(entry) {
    const e = area();
    e.value = entry.text;
    e.setSelectionRange(entry.start, entry.end);
    last = snapshot();
    lastKind = "";
    changed();
  }

  function setText(text, options) {
    const record = !options || options.record === undefined ? true : options.record;
    text = String(text);
    if (text === area().value) return;
    if (record) {
      push(undoStack, last);
      redoStack.length = 0;
    }
    const e = area();
    const scroll = e.scrollTop;
    e.value = text;
    e.scrollTop = scroll;
    last = snapshot();
    lastKind = "";  // the next typing starts a step of its own
    changed();
  }

  function getText() {
    return area().value;
  }

  function undo() {
    if (!undoStack.length) return false;
    push(redoStack, snapshot());
    restore(undoStack.pop());
    return true;
  }

  function redo() {
    if (!redoStack.length) return false;
    push(undoStack, snapshot());
    restore(redoStack.pop());
    return true;
  }

  function load(text) {
    undoStack.length = 0;
    redoStack.length = 0;
    const e = area();
    e.value = String(text);
    e.scrollTop = 0;
    e.setSelectionRange(0, 0);
    last = snapshot();
    lastKind = "";
    changed();
  }

  // A typed change: a new step after a pause, a new line or another kind of edit.
  function typed(event) {
    if (quiet) return;
    const kind = (event.inputType || "insert").startsWith("delete") ? "delete"
      : event.inputType === "insertFromPaste" || event.inputType === "insertFromDrop"
        ? "paste" : "insert";
    const now = Date.now();
    const newLine = event.inputType === "insertLineBreak"
      || (event.data && event.data.includes("\n"));
    if (kind !== lastKind || kind === "paste" || newLine || now - lastTime > STEP_MS) {
      push(undoStack, last);
    }
    redoStack.length = 0;
    lastKind = newLine ? "" : kind;
    lastTime = now;
    last = snapshot();
    buttons();
  }

  function buttons() {
    const u = document.getElementById("undo"), r = document.getElementById("redo");
    if (u) u.disabled = !undoStack.length;
    if (r) r.disabled = !redoStack.length;
  }

  function keys(event) {
    if (!(event.ctrlKey || event.metaKey) || event.altKey) return;
    const key = event.key.toLowerCase();
    if (key === "z" && !event.shiftKey) {
      event.preventDefault();
      undo();
    } else if ((key === "z" && event.shiftKey) || key === "y") {
      event.preventDefault();
      redo();
    }
  }

  window.mechloopEditor = { setText, getText, undo, redo, load };

  window.addEventListener("DOMContentLoaded", () => {
    const e = area();
    e.addEventListener("input", typed);
    e.addEventListener("keydown", keys);
    // the browser's own undo (the context menu) would bypass the history: routed to it
    e.addEventListener("beforeinput", (event) => {
      if (event.inputType === "historyUndo" || event.inputType === "historyRedo") {
        event.preventDefault();
        if (event.inputType === "historyUndo") undo(); else redo();
      }
    });
    // the selection is kept with the text, so an undo puts the caret back
    e.addEventListener("select", () => { if (e.value === last.text) last = snapshot(); });
    e.addEventListener("keyup", () => { if (e.value === last.text) last = snapshot(); });
    e.addEventListener("mouseup", () => { if (e.value === last.text) last = snapshot(); });
    const u = document.getElementById("undo"), r = document.getElementById("redo");
    for (const [button, action] of [[u, undo], [r, redo]]) {
      if (!button) continue;
      button.addEventListener("click", action);
      // the editor keeps the focus (and its keys) when a button is pressed
      button.addEventListener("mousedown", (event) => event.preventDefault());
    }
    buttons();
  });
})();
