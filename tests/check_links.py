#!/usr/bin/env python3
"""Checks the relative links of markdown files: each must name a file or directory that exists
and, after '#', a heading of that markdown file (GitHub's anchors: lowercase, punctuation
dropped, spaces as '-'). Links with a scheme (https:, mailto:) are not followed.

Usage: check_links.py FILE.md|DIRECTORY... (a directory: every .md file under it)
"""
import os
import re
import sys

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
HEADING = re.compile(r"^#{1,6}\s+(.*?)\s*#*\s*$")
FENCE = re.compile(r"^\s*(```|~~~)")


def lines_outside_code(path):
    inside = False
    with open(path, encoding="utf-8") as markdown:
        for line in markdown:
            if FENCE.match(line):
                inside = not inside
                continue
            if not inside:
                yield line


def anchors(path):
    found = set()
    for line in lines_outside_code(path):
        heading = HEADING.match(line)
        if heading:
            slug = re.sub(r"[^\w\- ]", "", heading.group(1).lower()).replace(" ", "-")
            found.add(slug)
    return found


def broken_links(path):
    for line in lines_outside_code(path):
        for target in LINK.findall(re.sub(r"`[^`]*`", "", line)):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):
                continue
            file_part, _, anchor = target.partition("#")
            linked = os.path.normpath(os.path.join(os.path.dirname(path), file_part)) if file_part else path
            if not os.path.exists(linked):
                yield f"{path}: {target}: no such file"
            elif anchor and linked.endswith(".md") and anchor not in anchors(linked):
                yield f"{path}: {target}: no heading with the anchor #{anchor}"


def markdown_files(paths):
    for path in paths:
        if not os.path.isdir(path):
            yield path
            continue
        for directory, _, names in sorted(os.walk(path)):
            yield from (os.path.join(directory, name) for name in sorted(names) if name.endswith(".md"))


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    files = list(markdown_files(sys.argv[1:]))
    broken = [problem for path in files for problem in broken_links(path)]
    for problem in broken:
        print(problem, flush=True)
    if broken:
        sys.exit(f"{len(broken)} broken link(s)")
    print(f"{len(files)} files, every relative link resolves")


if __name__ == "__main__":
    main()
