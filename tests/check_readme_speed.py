#!/usr/bin/env python3
"""Checks that the README's headline speed table is copied from one benchmark page: every table
row of its "## Speed" section, header included, must be a line of the docs/benchmarks/ page
that the section links to, so that the README quotes one run and cannot drift from it.

Usage: check_readme_speed.py README.md
"""
import os
import re
import sys

PAGE_LINK = re.compile(r"\]\((docs/benchmarks/[^)\s#]+\.md)\)")


def speed_section(readme):
    section, inside = [], False
    for line in readme.splitlines():
        if line.startswith("## "):
            inside = line.strip() == "## Speed"
        elif inside:
            section.append(line)
    return section


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    readme_path = sys.argv[1]
    with open(readme_path, encoding="utf-8") as readme:
        section = speed_section(readme.read())
    pages = sorted({m for line in section for m in PAGE_LINK.findall(line)})
    if len(pages) != 1:
        sys.exit(f"the Speed section must link to one benchmark page, it links to {pages}")
    page_path = os.path.join(os.path.dirname(os.path.abspath(readme_path)), pages[0])
    with open(page_path, encoding="utf-8") as page:
        page_lines = set(page.read().splitlines())
    rows = [line for line in section if line.startswith("|")]
    if not rows:
        sys.exit("the Speed section has no table")
    missing = [row for row in rows if row not in page_lines]
    for row in missing:
        print(f"not on {pages[0]}: {row}")
    if missing:
        sys.exit(f"{len(missing)} row(s) of the README's speed table are not on {pages[0]}")
    print(f"{len(rows)} rows of the README's speed table, all from {pages[0]}")


if __name__ == "__main__":
    main()
