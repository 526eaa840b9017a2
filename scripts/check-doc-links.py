#!/usr/bin/env python3
"""Checks every local link of the repository's Markdown documentation.

Scans README.md, CONTRIBUTING.md, CHANGELOG.md and docs/**/*.md for Markdown links and images
([text](target), ![alt](target)) and HTML src/href attributes. A target without a scheme must name an
existing file or folder relative to the page; with a #fragment into a Markdown file, that file must
have a heading whose GitHub-style anchor is the fragment. Code blocks and code spans are skipped.
External links (http:, https:, mailto:) are not fetched (the build is offline). README.md is the
front page: at most README_MAX_LINES lines (issue 42), the manual lives in docs/. The pages and the
README are reference text: a calendar date (2026-11-28) in them is reported too — measurement logs
and history go to CHANGELOG.md and commit messages.
Usage: check-doc-links.py REPO_ROOT; prints one line per problem, exits 1 if any.
"""
import pathlib
import re
import sys

LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^()\s>]+(?:\([^()\s]*\))?[^()\s>]*)>?(?:\s+\"[^\"]*\")?\s*\)")
HTML = re.compile(r"""(?:src|href)\s*=\s*["']([^"']+)["']""")
FENCE = re.compile(r"^\s*(```|~~~)")
CODE_SPAN = re.compile(r"(`+)(?:(?!\1).)+?\1")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
README_MAX_LINES = 300
DATE = re.compile(r"\b20\d\d-[01]\d-[0-3]\d\b")


def slug(heading):
    """GitHub's (and MyST's myst_heading_anchors) anchor of a heading text."""
    text = re.sub(r"`([^`]*)`", r"\1", heading)
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)
    text = text.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def prose_lines(path):
    """(line number, text) of the lines outside fenced code."""
    fenced = False
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if FENCE.match(line):
            fenced = not fenced
            continue
        if not fenced:
            yield number, line


def anchors(path):
    return {slug(m.group(2)) for _, line in prose_lines(path) if (m := HEADING.match(line))}


def broken_links(page, root):
    for number, line in prose_lines(page):
        line = CODE_SPAN.sub("", line)
        targets = [m.group(1) for m in LINK.finditer(line)] + [m.group(1) for m in HTML.finditer(line)]
        for target in targets:
            if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.I):
                continue  # external: http(s), mailto
            file_part, _, fragment = target.partition("#")
            dest = (page.parent / file_part).resolve() if file_part else page
            where = f"{page.relative_to(root)}:{number}: {target}"
            if not dest.exists():
                yield f"{where}: no such file"
            elif fragment and dest.suffix == ".md" and fragment not in anchors(dest):
                yield f"{where}: no heading with anchor '{fragment}' in {dest.relative_to(root)}"


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    pages = [root / name for name in ("README.md", "CONTRIBUTING.md", "CHANGELOG.md") if (root / name).exists()]
    pages += sorted((root / "docs").rglob("*.md"))
    problems = [p for page in pages for p in broken_links(page, root)]
    for page in pages:
        if page.name == "CHANGELOG.md":
            continue
        for number, line in prose_lines(page):
            if DATE.search(line):
                problems.append(f"{page.relative_to(root)}:{number}: a date ({DATE.search(line).group(0)}): "
                                "history belongs in CHANGELOG.md")
    readme = root / "README.md"
    if readme.exists():
        lines = len(readme.read_text(encoding="utf-8").splitlines())
        if lines > README_MAX_LINES:
            problems.append(f"README.md: {lines} lines, more than {README_MAX_LINES}: move the detail to a page under docs/")
    for p in problems:
        print(f"check-doc-links: {p}")
    print(f"check-doc-links: {len(pages)} pages, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
