// Numbers as the page's language writes them: in Russian the decimal comma and a power of
// ten as ·10⁻⁵ (GOST 2.105 and 8.417), as the library's Russian outputs write them
// (mechloop.views.decimal_mark); in English 1.5 and 1.5e-5.  Numbers typed into the page's
// fields are read with a decimal point or, in Russian, a comma.
"use strict";

(function () {
  const SUPERSCRIPTS = { "0": "⁰", "1": "¹", "2": "²", "3": "³", "4": "⁴", "5": "⁵",
    "6": "⁶", "7": "⁷", "8": "⁸", "9": "⁹", "-": "⁻", "+": "" };
  const PLAIN = Object.fromEntries(Object.entries(SUPERSCRIPTS).filter(([, s]) => s)
    .map(([plain, sup]) => [sup, plain]));

  function language() {
    return typeof LANG === "string" ? LANG : "en";
  }

  // A number already written by JavaScript (``String(x)``, ``toPrecision``, ``toFixed``,
  // ``toExponential``), rewritten for ``lang`` (default: the page's): ``-1.5e-7`` becomes
  // ``-1,5·10⁻⁷`` in Russian; ``field``: for an input field, the exponent kept as
  // ``e-7`` (it can be typed).
  function localText(text, lang, field) {
    if ((lang || language()) !== "ru") return text;
    const match = /^([-+]?[\d.]+)(?:e([-+]?)(\d+))?$/.exec(text);
    if (!match) return text;
    const mantissa = match[1].replace(".", ",");
    if (match[3] === undefined) return mantissa;
    if (field) return `${mantissa}e${match[2] === "-" ? "-" : ""}${match[3]}`;
    const power = (match[2] === "-" ? "-" : "") + String(Number(match[3]));
    return `${mantissa}·10${[...power].map((c) => SUPERSCRIPTS[c]).join("")}`;
  }

  // ``x`` for reading: ``digits`` significant digits (default 6, trailing zeros dropped),
  // in exponent form below 1e-3 and from 1e6; "—" when not a finite number.
  function number(x, digits, lang) {
    if (x === null || x === undefined || !Number.isFinite(x)) return "—";
    if (x === 0) return "0";
    const n = digits || 6;
    const magnitude = Math.abs(x);
    const text = magnitude >= 1e6 || magnitude < 1e-3
      ? x.toExponential(Math.max(n - 2, 0)).replace(/\.?0+e/, "e")
      : String(Number(x.toPrecision(n)));
    return localText(text, lang);
  }

  // A number typed by the user: ``1.5``, ``-2e-3``, and in Russian also ``1,5``,
  // ``1,5e-3`` or ``1,5·10⁻³``; NaN when the text is not one number.
  function parse(text, lang) {
    let s = String(text).trim().replace(/\s+/g, "");
    if ((lang || language()) === "ru") {
      s = s.replace(/[·×*]10([⁻⁺]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)$/,
        (all, power) => "e" + [...power].map((c) => PLAIN[c] || "").join(""));
      if ((s.match(/,/g) || []).length === 1 && !s.includes(".")) s = s.replace(",", ".");
    }
    return /^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(s) ? Number(s) : NaN;
  }

  window.mechloopNumber = number;
  window.mechloopLocalText = localText;
  window.mechloopParseNumber = parse;
})();
