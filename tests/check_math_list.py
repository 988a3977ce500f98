#!/usr/bin/env python3
"""The one list of math kernels (include/kutlog/detail/math_functions.hpp) drives the docs'
tables: README's accuracy table and docs/accuracy.md's aarch64 table have a row for every
listed kernel, with its measured bound as the list gives it, and no row for another; README's
domain of each is the list's, the domain its bound was measured on.

  check_math_list.py <source dir>
"""
import pathlib
import re
import sys


def listed(root):
    text = (root / "include/kutlog/detail/math_functions.hpp").read_text().replace("\\\n", " ")
    # X(function, kernel, promised, x86_64, aarch64, ...
    pattern = r'X\(\s*\w+,\s*(\w+),\s*[\d.]+,\s*([\d.]+),\s*([\d.]+),\s*"([^"]*)"'
    return {kernel: (float(x86_64), float(aarch64), domain)
            for kernel, x86_64, aarch64, domain in re.findall(pattern, text)}


def table_rows(text, header_word):
    """Rows of the markdown table whose header line contains header_word: {first cell: cells}."""
    rows, inside = {}, False
    for line in text.splitlines():
        if line.startswith("|") and header_word in line:
            inside = True
            continue
        if inside and line.startswith("|"):
            cells = [c.strip() for c in line.strip("|").split("|")]
            if not set(cells[0]) <= set("- "):
                rows[cells[0]] = cells
        elif inside:
            break
    return rows


def main(root):
    root = pathlib.Path(root)
    kernels = listed(root)
    failures = []
    readme = table_rows((root / "README.md").read_text(), "measured_max_ulp")
    aarch64 = table_rows((root / "docs/accuracy.md").read_text(), "bound_ulp (aarch64)")
    for name, rows, column, which in (("README.md accuracy table", readme, 3, 0),
                                      ("docs/accuracy.md aarch64 table", aarch64, 2, 1)):
        if set(rows) != set(kernels):
            failures.append(f"{name}: rows {sorted(rows)} but the list has {sorted(kernels)}")
            continue
        for kernel, bounds in kernels.items():
            if float(rows[kernel][column]) != bounds[which]:
                failures.append(f"{name}: {kernel}'s bound {rows[kernel][column]}, the list's "
                                f"{bounds[which]}")
    for kernel, (_, _, domain) in kernels.items():
        if kernel in readme and readme[kernel][1] != domain:
            failures.append(f"README.md accuracy table: {kernel}'s domain '{readme[kernel][1]}', "
                            f"the list's '{domain}'")
    print(f"{len(kernels)} listed kernels: {' '.join(kernels)}")
    for failure in failures:
        print("FAIL:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
