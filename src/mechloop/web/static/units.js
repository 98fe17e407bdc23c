// The Units tab of the forms (KDAM's units and tolerances panels): the model's
// ``display:`` section, a unit for each kind of quantity and the precision of the numbers.
//
// The kinds and the units offered come from the library (api/units, mechloop.web.units);
// "default" means the kind's key is absent.  Every change is one edit of the text through
// the forms (api/edit, then the editor: one undo step), the section added when absent and
// removed with its last key; the results table, the plots' axes and the downloads follow
// from the model as they do for a section typed in the editor.
"use strict";

(function () {
  // the words of the kinds (keys of WORDS, in i18n.js)
  const KINDS = { length: "formUnitLength", angle: "formUnitAngle", time: "formUnitTime",
    velocity: "formUnitVelocity", acceleration: "formUnitAcceleration",
    angular_velocity: "formUnitAngularVelocity",
    angular_acceleration: "formUnitAngularAcceleration", mass: "formUnitMass",
    inertia: "formUnitInertia", force: "formUnitForce", moment: "formUnitMoment",
    energy: "formUnitEnergy", power: "formUnitPower" };
  const MODES = { "": "formPrecisionAll", digits: "formPrecisionDigits",
    decimals: "formPrecisionDecimals" };
  const START = { digits: 6, decimals: 3 };  // the count a newly chosen mode starts with
  const units = { choices: null, asked: null, chain: Promise.resolve(null) };

  function forms() {
    return window.mechloopForms;
  }

  // The choices, asked once; the tab is drawn again when they come.
  function load() {
    if (units.asked) return;
    units.asked = api("api/units").then(async (response) => {
      const answer = await read(response);
      if (!response.ok) {
        units.asked = null;  // asked again at the next drawing
        return;
      }
      units.choices = answer;
      forms().draw();
    });
  }

  function display() {
    const section = (forms().data() || {}).display;
    return section && typeof section === "object" && !Array.isArray(section) ? section : null;
  }

  // The edits of this tab, one after another, each deciding what to change from the data
  // the one before it left (two quick choices on a model without the section: one
  // section with both).
  function later(step) {
    units.chain = units.chain.then(step).catch(() => null);
    return units.chain;
  }

  // Sets ``key`` of the section to ``value``, adding the section when it is not there.
  function set(key, value) {
    return later(() => (display() ? forms().edit(["display", key], { value })
      : forms().edit(["display"], { value: { [key]: value } })));
  }

  // Removes ``key``; the section goes with its last key.
  function unset(key) {
    return later(() => {
      const section = display();
      if (!section || !(key in section)) return null;
      const others = Object.keys(section).filter((k) => k !== key);
      return forms().edit(others.length ? ["display", key] : ["display"], { delete: true });
    });
  }

  function option(box, value, text) {
    const item = document.createElement("option");
    item.value = value;
    item.textContent = text;
    box.appendChild(item);
  }

  function drawUnits(panel) {
    const { node, section, select } = forms();
    if (!units.choices) {
      load();
      node("p", { class: "form-note" }, panel, t("formUnitsLoading"));
      return;
    }
    const current = display() || {};
    const box = section(panel, "formUnits");
    const body = node("table", { class: "form-table" }, box).createTBody();
    for (const { kind, default: standard, units: offered } of units.choices.kinds) {
      const row = body.insertRow();
      row.dataset.kind = kind;
      row.insertCell().textContent = KINDS[kind] ? t(KINDS[kind]) : kind;
      const choice = node("select", { class: "form-choice form-unit",
        dataset: { keys: JSON.stringify(["display", kind]) } }, row.insertCell());
      option(choice, "", t("formUnitDefault", { unit: unitText(standard) }));
      const named = current[kind] === undefined || current[kind] === null
        ? "" : String(current[kind]);
      for (const unit of offered) option(choice, unit, unitText(unit));
      if (named && !offered.includes(named)) option(choice, named, named);  // typed in
      choice.value = named;
      choice.addEventListener("change", () => {
        if (choice.value) set(kind, choice.value);
        else unset(kind);
      });
    }
    const exact = section(panel, "formPrecision");
    const row = node("div", { class: "form-row" }, exact);
    const mode = current.digits !== undefined && current.digits !== null ? "digits"
      : current.decimals !== undefined && current.decimals !== null ? "decimals" : "";
    select(row, ["display", "precision"], mode, MODES, (next) => {
      if (mode) unset(mode);  // the section may go with it: set() then adds it again
      if (next) set(next, START[next]);
    });
    if (mode) {
      const [low, high] = units.choices[mode];
      const count = node("select", { class: "form-choice form-count",
        dataset: { keys: JSON.stringify(["display", mode]) } }, row);
      for (let n = low; n <= high; n += 1) option(count, String(n), String(n));
      if (!(current[mode] >= low && current[mode] <= high)) {  // typed in, out of range
        option(count, String(current[mode]), String(current[mode]));
      }
      count.value = String(current[mode]);
      count.addEventListener("change", () => set(mode, Number(count.value)));
    }
    node("p", { class: "form-note" }, panel, t("formUnitsNote"));
  }

  forms().register("units", "tab_units", drawUnits);
})();
