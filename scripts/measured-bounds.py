#!/usr/bin/env python3
"""Prints the largest error each measured column of kutlog/accuracy.hpp needs, read from the
gtest XML files that the exhaustive tests wrote (GTEST_OUTPUT=xml:<dir>/; the properties that
tests/record_measured.hpp records), one `name max` line each, names sorted.

  KUTLOG_JOBS=1 GTEST_OUTPUT=xml:$PWD/build-aarch64/measured/ \
    bash scripts/test-aarch64.sh -L exhaustive
  python3 scripts/measured-bounds.py build-aarch64/measured

One test at a time (KUTLOG_JOBS=1): gtest picks a free file name in <dir>/ when a test program
starts, so two starting together write the same file and the first one's errors are lost.
"""
import pathlib
import sys
import xml.etree.ElementTree as ElementTree


def main(directory):
    maxima = {}
    for path in sorted(pathlib.Path(directory).glob("*.xml")):
        for testcase in ElementTree.parse(path).iter("testcase"):
            for prop in testcase.iter("property"):
                name, value = prop.get("name"), float(prop.get("value"))
                maxima[name] = max(value, maxima.get(name, value))
    if not maxima:
        sys.exit(f"measured-bounds: no recorded errors in {directory}/*.xml")
    for name in sorted(maxima):
        print(f"{name} {maxima[name]:.9g}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
