#!/usr/bin/env python3
"""The public core stays small: the headers a renderer includes declare at most MAX_TYPES
types and MAX_FUNCTIONS functions, as universal-ctags counts them (types: classes, structs and
enums in namespace kutlog; functions: public functions and members of kutlog and its classes;
the detail and ref scopes left out), and nothing a detail header declares lives in namespace
kutlog itself. The headers outside the core: inspect, baselines, reference*, accuracy.

  check_public_api.py <include/kutlog>
"""
import json
import pathlib
import subprocess
import sys

MAX_TYPES, MAX_FUNCTIONS = 15, 40
OUTSIDE_CORE = ("inspect.hpp", "baselines.hpp", "reference.hpp", "sampling_reference.hpp",
                "accuracy.hpp")


def tags(paths):
    out = subprocess.run(["ctags", "--output-format=json", "--fields=+neaKZ", "--c++-kinds=+p",
                          "--language-force=C++", "-f", "-", *map(str, paths)],
                         check=True, capture_output=True, text=True).stdout
    return [json.loads(line) for line in out.splitlines() if line.startswith("{")]


def in_core_scope(scope):
    parts = (scope or "").split("::")
    return parts[0] == "kutlog" and "detail" not in parts and "ref" not in parts


def main(include_dir):
    root = pathlib.Path(include_dir)
    core = sorted(p for p in root.glob("*.hpp") if p.name not in OUTSIDE_CORE)
    rows = tags(core)
    types = [r for r in rows if r["kind"] in ("class", "struct", "enum") and r.get("scope") == "kutlog"]
    functions = [r for r in rows if r["kind"] in ("function", "prototype")
                 and in_core_scope(r.get("scope")) and r.get("access", "public") == "public"]
    print(f"core headers: {', '.join(p.name for p in core)}")
    print(f"{len(types)} types (at most {MAX_TYPES}): {' '.join(r['name'] for r in types)}")
    print(f"{len(functions)} functions (at most {MAX_FUNCTIONS})")
    failures = []
    if len(types) > MAX_TYPES:
        failures.append(f"{len(types)} public types, more than {MAX_TYPES}")
    if len(functions) > MAX_FUNCTIONS:
        failures.append(f"{len(functions)} public functions, more than {MAX_FUNCTIONS}: " +
                        ", ".join(f"{r['scope']}::{r['name']}" for r in functions))
    detail = sorted((root / "detail").glob("*.hpp"))
    leaked = [r for r in tags(detail) if r["kind"] in ("class", "struct", "enum", "function",
                                                       "prototype", "typedef", "variable")
              and in_core_scope(r.get("scope")) and r.get("scope") == "kutlog"]
    for r in leaked:
        failures.append(f"{pathlib.Path(r['path']).name}:{r['line']} declares kutlog::{r['name']}"
                        " (detail headers declare in kutlog::detail)")
    for failure in failures:
        print("FAIL:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
