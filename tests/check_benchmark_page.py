#!/usr/bin/env python3
"""Runs the benchmark page generator on a saved run and compares the page it writes, byte for
byte, with the expected one: the file name (the machine's slug) and the content.

Usage: check_benchmark_page.py KUTLOG_BENCH RUN_JSON EXPECTED_PAGE
"""
import difflib
import os
import subprocess
import sys
import tempfile


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    bench, run_json, expected_path = sys.argv[1:]
    with tempfile.TemporaryDirectory() as pages:
        command = [bench, f"--kutlog_ratios_from={run_json}", f"--kutlog_page={pages}"]
        run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        if run.returncode != 0:
            sys.stderr.write(run.stderr.decode(errors="replace"))
            sys.exit(f"exit status {run.returncode}: {' '.join(command)}")
        written = os.listdir(pages)
        expected_name = os.path.basename(expected_path)
        if written != [expected_name]:
            sys.exit(f"expected the page {expected_name}, the generator wrote {written}")
        with open(os.path.join(pages, expected_name), "rb") as page:
            actual = page.read()
    with open(expected_path, "rb") as page:
        expected = page.read()
    if actual != expected:
        diff = difflib.unified_diff(expected.decode().splitlines(keepends=True),
                                    actual.decode().splitlines(keepends=True),
                                    expected_path, "generated")
        sys.stdout.writelines(diff)
        sys.exit("the generated page differs from the expected one (regenerate the expected page "
                 "only if the change is meant: see the test's comment in tests/CMakeLists.txt)")
    print(f"{expected_name}: as expected")


if __name__ == "__main__":
    main()
