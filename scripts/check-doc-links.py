#!/usr/bin/env python3
"""Checks the relative links of the project's Markdown documents.

Every link [text](target) whose target is not a URL must name a file or folder
that exists (relative to the document), and a #fragment must name a heading of
the target document, spelled as GitHub spells heading anchors. Links inside
code (fenced blocks and `inline code`) are not links and are skipped, and so
are links out of the repository (../shared beside it): whether those exist
depends on where the clone sits, not on the documents.

  scripts/check-doc-links.py [FILE.md ...]   # default: README.md and docs/*.md

Prints one line per broken link, `FILE:LINE: what is wrong`, and exits 1 if
there is any (0 otherwise). tests/scripts/test_doc_links.py runs it in ctest.
"""

import glob
import os
import re
import sys
import unicodedata

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# [text](target) or [text](target "title"); the text may hold `code` and
# brackets one level deep.
LINK = re.compile(r"\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
HTML_ANCHOR = re.compile(r"<a\s+(?:id|name)=\"([^\"]+)\"")


def slug(heading):
    """GitHub's anchor of a heading (github-slugger): lower case; every
    character but letters, marks, numbers, connector punctuation, spaces and
    hyphens removed; each space a hyphen. Markdown emphasis and code marks go
    first, and a link keeps only its text."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)
    text = text.replace("`", "").replace("*", "")
    out = []
    for ch in text.lower():
        cat = unicodedata.category(ch)
        if ch in " -" or cat[0] in "LMN" or cat == "Pc":
            out.append(ch)
    return "".join(out).replace(" ", "-")


def outside_fences(lines):
    """(line number from 1, line) of every line outside fenced code blocks."""
    fenced = False
    for number, line in enumerate(lines, 1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
        elif not fenced:
            yield number, line


_anchor_cache = {}


def anchors(path):
    """Every anchor a document defines: its headings' (repeats numbered -1,
    -2, ... as GitHub numbers them) and explicit <a id/name> ones."""
    if path not in _anchor_cache:
        seen = {}
        found = set()
        with open(path, encoding="utf-8") as f:
            lines = f.read().split("\n")
        for _, line in outside_fences(lines):
            found.update(HTML_ANCHOR.findall(line))
            m = HEADING.match(line)
            if not m:
                continue
            base = slug(m.group(2))
            n = seen.get(base, 0)
            seen[base] = n + 1
            found.add(base if n == 0 else f"{base}-{n}")
        _anchor_cache[path] = found
    return _anchor_cache[path]


def check(path, root=TOP):
    """The broken links of one document, as messages; targets outside the
    folder `root` are not checked."""
    problems = []
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    here = os.path.dirname(path)
    for number, line in outside_fences(lines):
        for target in LINK.findall(re.sub(r"`[^`]*`", "", line)):  # inline code holds no links
            if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.I):  # http:, https:, mailto:
                continue
            file_part, _, fragment = target.partition("#")
            target_path = os.path.normpath(os.path.join(here, file_part)) if file_part else path
            if os.path.commonpath([target_path, root]) != root:
                continue
            where = f"{os.path.relpath(path, TOP)}:{number}"
            if not os.path.exists(target_path):
                problems.append(f"{where}: link to a missing file: {target}")
                continue
            if fragment and target_path.endswith(".md"):
                if fragment not in anchors(target_path):
                    problems.append(f"{where}: no heading or anchor '#{fragment}' in "
                                    f"{os.path.relpath(target_path, TOP)}")
    return problems


def main(argv, root=TOP):
    files = argv[1:] or [os.path.join(TOP, "README.md")] + sorted(
        glob.glob(os.path.join(TOP, "docs", "*.md")))
    problems = []
    for path in files:
        if not os.path.isfile(path):
            print(f"check-doc-links: error: {path}: no such file", file=sys.stderr)
            return 2
        problems += check(os.path.abspath(path), root)
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
