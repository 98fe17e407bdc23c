// The working copy of the model: every change is kept (after a short pause) in the
// browser's localStorage and on the server (api/autosave, a file in the served folder's
// .mechloop/autosave/), so a browser crash or a bad edit loses nothing.  When a model is
// opened and a working copy of it differs from the file, the page offers it back (the
// newer of the two copies); saving the model clears them.
"use strict";

const autosave = {
  DELAY_MS: 600,
  source: null,     // {path} or {example}: whose working copy
  disk: null,       // the text of the file as opened or saved
  timer: null,
  loading: false,   // the editor is being filled with the file: not a change
  offer: null,      // the working copy offered back: {text, time}
  written: 0,       // working copies sent to the server (for the tests)

  key(source) {
    const s = source || this.source;
    return "mechloop-autosave:" + (s.path ? "path:" + s.path : "example:" + s.example);
  },

  local(source) {
    try {
      const found = JSON.parse(localStorage.getItem(this.key(source)) || "null");
      return found && typeof found.text === "string" ? found : null;
    } catch (error) {
      return null;
    }
  },

  // A model was opened: ``text``, its file's; fill the editor, then offer a working copy.
  async open(source, text) {
    clearTimeout(this.timer);
    this.source = source;
    this.disk = text;
    this.hide();
    this.loading = true;
    try {
      mechloopEditor.load(text);
    } finally {
      this.loading = false;
    }
    const response = await api("api/autosave?" + new URLSearchParams(source));
    const remote = response.ok ? await read(response) : { text: null };
    if (this.source !== source) return;  // another model opened meanwhile
    const copies = [this.local(source), remote.text === null ? null : remote]
      .filter((c) => c && c.text !== text);
    if (!copies.length) return;
    copies.sort((a, b) => (b.time || 0) - (a.time || 0));
    this.offer = copies[0];
    this.show();
  },

  show() {
    if (!this.offer) return;
    const when = new Date(this.offer.time * 1000)
      .toLocaleString(LANG === "ru" ? "ru-RU" : "en-GB");
    $("restore-text").textContent = t("restoreOffer", { time: when });
    $("restore-bar").hidden = false;
  },

  hide() {
    this.offer = null;
    $("restore-bar").hidden = true;
  },

  restore() {
    const offer = this.offer;
    this.hide();
    if (offer) mechloopEditor.setText(offer.text);  // one undo goes back to the file
    $("editor").focus();
    status("restored", null, "ok");
  },

  discard() {
    this.hide();
    this.clear(this.source);
  },

  // The editor's text changed: keep it, after a pause.
  changed() {
    if (this.loading || !this.source) return;
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.keep(), this.DELAY_MS);
  },

  async keep() {
    const source = this.source, text = mechloopEditor.getText();
    try {
      if (text === this.disk) localStorage.removeItem(this.key(source));
      else localStorage.setItem(this.key(source), JSON.stringify({ text, time: Date.now() / 1000 }));
    } catch (error) { /* a full or refused localStorage: the server's copy remains */ }
    const response = await postJSON("api/autosave", Object.assign({ text }, source));
    if (response.ok) {
      this.written += 1;
      document.body.dataset.autosaved = String(this.written);
    }
  },

  // Forget the working copy of ``source``, here and on the server.
  async clear(source) {
    try {
      localStorage.removeItem(this.key(source));
    } catch (error) { /* nothing kept */ }
    await postJSON("api/autosave/clear", Object.assign({}, source));
  },

  // The model was saved as ``source`` (from ``before``) with ``text``.
  async saved(before, source, text) {
    clearTimeout(this.timer);
    this.source = source;
    this.disk = text;
    this.hide();
    try {
      localStorage.removeItem(this.key(source));
    } catch (error) { /* nothing kept */ }
    if (before && this.key(before) !== this.key(source)) await this.clear(before);
  },
};

window.addEventListener("DOMContentLoaded", () => {
  $("editor").addEventListener("input", () => autosave.changed());
  $("restore").addEventListener("click", () => autosave.restore());
  $("discard").addEventListener("click", () => autosave.discard());
});
