// New models: the "New…" menu lists the course tasks and the bundled examples
// (api/templates); the one chosen opens unsaved, and Save asks for its file name in the
// folder (the server copies the files it names from beside the template).
"use strict";

const newModel = {
  templates: [],

  async list() {
    const response = await api("api/templates");
    if (!response.ok) return;
    this.templates = (await read(response)).templates;
    this.fill();
  },

  fill() {
    const select = $("new-model");
    select.textContent = "";
    const prompt = document.createElement("option");
    prompt.value = "";
    prompt.textContent = t("newModel");
    select.appendChild(prompt);
    for (const [group, label] of [["course", t("courseTasks")], ["example", t("examples")]]) {
      const optgroup = document.createElement("optgroup");
      optgroup.label = label;
      for (const item of this.templates.filter((x) => x.group === group)) {
        const option = document.createElement("option");
        option.value = item.id;
        const title = LANG === "ru" ? item.title_ru : item.title;
        option.textContent = (item.number ? `${item.number}. ` : `${item.id} — `) + title;
        optgroup.appendChild(option);
      }
      select.appendChild(optgroup);
    }
    select.value = "";
  },

  // Open the template ``name`` as a new, unsaved model.
  async create(name) {
    $("new-model").value = "";
    if (!name) return;
    const response = await api("api/template?" + new URLSearchParams({ name }));
    const answer = await read(response);
    if (!response.ok) {
      status("failed", { error: answer.error }, "error");
      return;
    }
    state.source = { example: answer.id };
    state.unsaved = { template: answer.id, file: answer.file };
    state.solution = null;
    state.position = 0;
    $("model-select").value = "";
    $("save-path").value = "";
    document.body.dataset.unsaved = "1";
    await autosave.open(state.source, answer.text);
    status("newOpened", { name: answer.file }, "ok");
  },

  // Save asks for the new model's file name.
  ask() {
    $("save-as-name").value = state.unsaved ? state.unsaved.file : $("save-path").value;
    $("save-as").hidden = false;
    $("save-as-name").focus();
    $("save-as-name").select();
  },

  async answer(ok) {
    $("save-as").hidden = true;
    const name = $("save-as-name").value.trim();
    if (ok && name) await save(name);
  },
};

window.addEventListener("DOMContentLoaded", () => {
  $("new-model").addEventListener("change", () => newModel.create($("new-model").value));
  $("save-as-ok").addEventListener("click", () => newModel.answer(true));
  $("save-as-cancel").addEventListener("click", () => newModel.answer(false));
  $("save-as-name").addEventListener("keydown", (event) => {
    if (event.key === "Enter") newModel.answer(true);
    if (event.key === "Escape") newModel.answer(false);
  });
});
