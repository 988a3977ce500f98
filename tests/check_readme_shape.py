#!/usr/bin/env python3
"""Checks the README's table of the model's distance to t^n ("### Against t^n"):

- its lines are the output of `kutlog-curves --figure shape-table --format markdown`, line for
  line, so that the README cannot drift from the tool;
- every cell ("gap at angle") agrees with a recomputation here, independent of kutlog's
  reference: F = cos^k(c x) up to the cut-off, t^n = cos^n(x), |F - t^n| on a dense grid of
  angles, within the printed digits;
- at n = 32, k = 3, Q = 0.5, the gap at t = 0.9 (0.031) is at most the maximum reported.

Usage: check_readme_shape.py KUTLOG_CURVES README.md
"""
import math
import re
import subprocess
import sys

SECTION = "### Against t^n"
CELL = re.compile(r"^(\d+\.\d{3}) at (\d+\.\d)°$")
GRID = 20000


def section_table(readme):
    """The table lines of the section, in order."""
    lines, inside = [], False
    for line in readme.splitlines():
        if line.startswith("#"):
            inside = line.strip() == SECTION
        elif inside and line.startswith("|"):
            lines.append(line)
    return lines


def gap(n, k, Q, x):
    c = math.acos(Q ** (1 / k)) / math.acos(Q ** (1 / n))
    kutlog = math.cos(c * x) ** k if c * x < math.pi / 2 else 0.0
    return abs(kutlog - math.cos(x) ** n)


def largest_gap(n, k, Q):
    """(gap, angle in degrees): the best of a grid of angles from 0 to past both lobes (F's
    cut-off, and 8 / sqrt(n), where t^n < e^-32), or to pi/2."""
    c = math.acos(Q ** (1 / k)) / math.acos(Q ** (1 / n))
    end = min(math.pi / 2, max(math.pi / (2 * c), 8 / math.sqrt(n)))
    best = max((gap(n, k, Q, end * i / GRID), end * i / GRID) for i in range(GRID + 1))
    return best[0], math.degrees(best[1])


def check_cells(header, rows):
    """Failures of the cells against the recomputation, within half a printed unit."""
    columns = [float(name.split("=")[1]) for name in header[2:]]
    failures = []
    for row in rows:
        Q, k = float(row[0]), int(row[1])
        for n, cell in zip(columns, row[2:]):
            match = CELL.match(cell)
            if not match:
                failures.append(f"Q = {Q}, k = {k}, n = {n:g}: '{cell}' is not 'gap at angle°'")
                continue
            value, angle = largest_gap(n, k, Q)
            if abs(float(match[1]) - value) > 0.0005 + 1e-9 or abs(float(match[2]) - angle) > 0.1:
                failures.append(f"Q = {Q}, k = {k}, n = {n:g}: '{cell}', recomputed "
                                f"{value:.6f} at {angle:.3f}°")
    return failures


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    tool, readme_path = sys.argv[1:]
    run = subprocess.run([tool, "--figure", "shape-table", "--format", "markdown"],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"{tool} exited {run.returncode}: {run.stderr}")
    printed = run.stdout.splitlines()
    with open(readme_path, encoding="utf-8") as readme:
        quoted = section_table(readme.read())
    failures = []
    if quoted != printed:
        failures.append(f"the table of '{SECTION}' is not the tool's output; paste it again:\n" +
                        "\n".join(printed))
    cells = [[cell.strip() for cell in line.strip("|").split("|")] for line in printed]
    header, rows = cells[0], cells[2:]
    failures += check_cells(header, rows)
    t = 0.9
    at_t = gap(32, 3, 0.5, math.acos(t))
    reported = next(float(CELL.match(row[header.index("n = 32")])[1]) for row in rows
                    if row[0] == "0.5" and row[1] == "3")
    if not 0.030 < at_t <= reported:
        failures.append(f"n = 32, k = 3, Q = 0.5: the gap at t = {t} is {at_t:.6f}, the largest "
                        f"reported {reported}")
    for failure in failures:
        print("FAIL:", failure)
    if failures:
        sys.exit(f"{len(failures)} failure(s)")
    print(f"{len(rows)} rows of '{SECTION}', the tool's output, every cell recomputed; "
          f"n = 32, k = 3, Q = 0.5: gap {at_t:.4f} at t = {t}, largest {reported}")


if __name__ == "__main__":
    main()
