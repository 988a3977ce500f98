#!/usr/bin/env python3
"""Below C++20, including any public header of kutlog fails with one error: api.hpp's #error
naming C++20, and no cascade after it (issue 49).

  check_cxx17_error.py <compiler> <include dir> <generated include dir>
"""
import pathlib
import subprocess
import sys

# Preprocessor lists, valid in any language and standard (kutlog/kutlog.h includes them in C).
ANY_STANDARD = {"kutlog/detail/math_functions.hpp"}


def main(compiler, include, generated):
    headers = sorted(str(p.relative_to(include)) for p in pathlib.Path(include).rglob("*.hpp"))
    failures = 0
    for header in headers:
        if header in ANY_STANDARD:
            continue
        run = subprocess.run([compiler, "-std=c++17", "-fsyntax-only", "-x", "c++", "-I", include,
                              "-I", generated, "-"], input=f"#include <{header}>\n",
                             capture_output=True, text=True)
        errors = [line for line in run.stderr.splitlines() if " error: " in line]
        if run.returncode == 0 or len(errors) != 1 or "C++20" not in errors[0]:
            failures += 1
            print(f"{header}: {len(errors)} errors, exit {run.returncode}; first lines:")
            print("\n".join(run.stderr.splitlines()[:6]))
    print(f"{len(headers) - len(ANY_STANDARD)} headers below C++20: {failures} without the one "
          "#error")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
