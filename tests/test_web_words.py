"""Every string of the web application's interface exists in English and Russian
(``static/i18n.js``), every key the page and its scripts ask for is there (and no other),
and the Russian words hold no English word (issue 16: the whole interface in both languages)."""

from __future__ import annotations

import json
import re

from helpers.latin import latin_words

from mechloop.web.app import STATIC

I18N = (STATIC / "i18n.js").read_text(encoding="utf-8")


def _words(lang: str) -> dict[str, str]:
    """The WORDS[lang] table of i18n.js, read as JSON (its keys are bare names)."""
    block = re.search(rf"\n  {lang}: \{{\n(.*?)\n  }},", I18N, flags=re.S).group(1)
    text = re.sub(r"(?m)(^|\s|,)(\w+):", r'\1"\2":', block).rstrip().rstrip(",")
    return json.loads("{" + text + "}")


def _asked_keys() -> set[str]:
    """Every key the page (data-i18n, data-i18n-title, data-i18n-label) and the scripts
    (t(...), status(...), jobInfo(...)) ask for."""
    page = (STATIC / "index.html").read_text(encoding="utf-8")
    keys = set(re.findall(r'data-i18n(?:-title)?="(\w+)"', page))
    for path in sorted(STATIC.glob("*.js")):
        script = path.read_text(encoding="utf-8")
        keys |= set(re.findall(r'\bt\("(\w+)"', script))
        keys |= set(re.findall(r'\b(?:status|jobInfo)\("(\w+)"', script))
        keys |= set(re.findall(r'i18nLabel = "(\w+)"', script))
        keys |= set(re.findall(r'\b(?:busy|done|word): "(\w+)"', script))
        for pair in re.findall(r'state\.timer \? "(\w+)" : "(\w+)"', script):
            keys |= set(pair)
    script = (STATIC / "work.js").read_text(encoding="utf-8")  # the background work
    keys |= set(re.findall(r'\b(?:t|status)\("(\w+)"', script))
    keys |= set(re.findall(r'"((?:work|anim|sweep|sim)[A-Z]\w*)"', script))
    for name in ("forms.js", "drag.js", "units.js"):  # their words: literal keys of WORDS
        script = (STATIC / name).read_text(encoding="utf-8")
        keys |= set(re.findall(r'\bt\("(\w+)"', script))
        keys |= set(re.findall(r'"((?:form|drag)[A-Z]\w*|tab_\w+)"', script))
    return keys


def test_both_languages_have_every_key_the_page_asks_for():
    en, ru = _words("en"), _words("ru")
    assert set(en) == set(ru)
    asked = _asked_keys()
    assert {"play", "pause", "files", "examples", "solved", "broken"} <= asked
    assert asked == set(en), (asked - set(en), set(en) - asked)  # none missing or unused


def test_the_russian_words_are_russian():
    en, ru = _words("en"), _words("ru")
    for key, text in ru.items():
        plain = re.sub(r"\{\w+\}", "", text)
        assert not latin_words(plain, ["PDF", "YAML", "Ctrl", "Shift"]), (key, text)
        assert text != en[key] or not re.search("[A-Za-z]{4,}", text), key
