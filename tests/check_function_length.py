#!/usr/bin/env python3
"""No function in the given trees is longer than MAX_LINES lines, as universal-ctags sees them
(kind function, from its line to its end, both counted), issue 48's measure: a long function is
split into named steps.

  check_function_length.py <dir or file>...
"""
import json
import subprocess
import sys

MAX_LINES = 60


def functions(paths):
    out = subprocess.run(["ctags", "--output-format=json", "--fields=+neK", "-f", "-", "-R",
                          *paths], check=True, capture_output=True, text=True).stdout
    rows = (json.loads(line) for line in out.splitlines() if line.startswith("{"))
    return [r for r in rows if r.get("kind") == "function" and "end" in r]


def main(paths):
    rows = functions(paths)
    long = sorted((r["end"] - r["line"] + 1, r["path"], r["line"], r.get("scope", ""), r["name"])
                  for r in rows if r["end"] - r["line"] + 1 > MAX_LINES)
    longest = max((r["end"] - r["line"] + 1 for r in rows), default=0)
    print(f"{len(rows)} functions, the longest {longest} lines (at most {MAX_LINES})")
    for length, path, line, scope, name in long:
        print(f"{path}:{line}: {scope + '::' if scope else ''}{name} is {length} lines")
    return 1 if long else 0


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1:]))
