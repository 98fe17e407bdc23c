"""The documentation's links hold: every relative link and image of README.md and the pages
of docs/ points to a file that exists, every ``#anchor`` to a heading of the page it names
(GitHub's anchors), every page starts with what it covers and a link back to the README,
the README's table of contents lists every page, and the examples' table lists every
bundled example.  No network: links to other sites are not followed."""

from __future__ import annotations

import re
from pathlib import PurePosixPath
from urllib.parse import unquote, urlsplit

import pytest
from helpers.docs import PAGES, ROOT, page_text
from markdown_it import MarkdownIt

PARSER = MarkdownIt("commonmark").enable("table")


def _slug(heading: str) -> str:
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def _parsed(page: str) -> tuple[list[str], set[str]]:
    """The link targets (links and images) of a page and its headings' anchors."""
    tokens = PARSER.parse(page_text(page))
    targets, anchors, seen = [], set(), {}
    for i, token in enumerate(tokens):
        if token.type == "heading_open":
            text = "".join(c.content for c in tokens[i + 1].children
                           if c.type in ("text", "code_inline"))
            slug = _slug(text)
            anchors.add(slug if slug not in seen else f"{slug}-{seen[slug]}")
            seen[slug] = seen.get(slug, 0) + 1
        if token.type == "inline":
            for child in token.children:
                if child.type == "link_open":
                    targets.append(child.attrs["href"])
                elif child.type == "image":
                    targets.append(child.attrs["src"])
    return targets, anchors


PARSED = {page: _parsed(page) for page in PAGES}


def test_slug_is_githubs():
    assert _slug("Cam design (course sheet 4)") == "cam-design-course-sheet-4"
    assert _slug("Output files, columns and units") == "output-files-columns-and-units"
    assert _slug("Roof-support synthesis (seed 001)") == "roof-support-synthesis-seed-001"


@pytest.mark.parametrize("page", PAGES)
def test_every_relative_link_and_anchor_exists(page):
    targets, _ = PARSED[page]
    assert targets or page != "README.md"
    broken = []
    for target in targets:
        parts = urlsplit(target)
        if parts.scheme or parts.netloc:  # another site: not followed here
            continue
        path = PurePosixPath(page).parent / unquote(parts.path) if parts.path else \
            PurePosixPath(page)
        file = (ROOT / path).resolve()
        if not file.exists() or ROOT not in [file, *file.parents]:
            broken.append(f"{target}: no file {path}")
            continue
        if parts.fragment:
            linked = file.relative_to(ROOT).as_posix()
            if linked not in PARSED:
                broken.append(f"{target}: an anchor into {linked}, not a documentation page")
            elif parts.fragment not in PARSED[linked][1]:
                broken.append(f"{target}: {linked} has no heading #{parts.fragment}")
    assert not broken, f"{page}:\n" + "\n".join(broken)


@pytest.mark.parametrize("page", [p for p in PAGES if p != "README.md"])
def test_every_page_says_what_it_covers_and_links_back(page):
    lines = page_text(page).split("\n\n")
    assert lines[0].startswith("# ") and "\n" not in lines[0], "a page starts with its title"
    assert "](../README.md)" in lines[1], "then what it covers and a link back to the README"


def test_the_readme_lists_every_page():
    listed = {t for t in PARSED["README.md"][0] if t.startswith("docs/") and t.endswith(".md")}
    assert listed == {p for p in PAGES if p != "README.md"}


def test_the_examples_table_lists_every_example():
    """docs/examples.md has a row for every file of examples/ (a folder's row covers its
    files), and every row names a file or folder that exists."""
    text = page_text("docs/examples.md")
    listed = set(re.findall(r"^\| `(examples/[^`]+)` \|", text, flags=re.M))
    files = {p.relative_to(ROOT).as_posix() for p in (ROOT / "examples").rglob("*")
             if p.is_file() and "__pycache__" not in p.parts}
    folders = {row for row in listed if row.endswith("/")}
    assert not {f for f in files if f not in listed
                and not any(f.startswith(d) for d in folders)}, "add a row to docs/examples.md"
    assert all((ROOT / row).exists() for row in listed)
