#!/usr/bin/env python3
"""Runs a command that writes CSV to stdout and reads the output back with Python's csv module,
as a program consuming it would: there must be a header and at least one data row, and every
row must have as many fields as the header.

Usage: check_csv.py COMMAND [ARGUMENT...]
"""
import csv
import io
import subprocess
import sys


def main():
    command = sys.argv[1:]
    if not command:
        sys.exit(__doc__)
    run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    if run.returncode != 0:
        sys.stderr.write(run.stderr.decode(errors="replace"))
        sys.exit(f"exit status {run.returncode}: {' '.join(command)}")
    # newline="" as the csv module asks: a quoted field may hold a line break of its own.
    rows = list(csv.reader(io.StringIO(run.stdout.decode(), newline="")))
    if len(rows) < 2:
        sys.exit(f"expected a header and at least one data row, read {len(rows)} row(s):\n"
                 f"{run.stdout.decode()}")
    header = rows[0]
    uneven = [(line, row) for line, row in enumerate(rows[1:], start=2) if len(row) != len(header)]
    for line, row in uneven:
        print(f"row {line} has {len(row)} fields, the header {len(header)}: {row}")
    if uneven:
        sys.exit(f"{len(uneven)} of {len(rows) - 1} data rows are not as wide as the header "
                 f"{header}")
    print(f"{len(rows) - 1} rows of {len(header)} fields: {header}")


if __name__ == "__main__":
    main()
