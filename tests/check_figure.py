#!/usr/bin/python3
"""Draws a figure with tools/plot/kutlog_figures.py from a tool's CSV and checks the result: the
script exits 0 and writes a PNG of the figure's size (1200 x 800).

Usage: check_figure.py FIGURE PNG COMMAND [ARGUMENT...]   the CSV from COMMAND's standard output
       check_figure.py FIGURE PNG --data CSV              a CSV file
Run with the Python that has matplotlib (Debian: /usr/bin/python3 and python3-matplotlib).
"""
import os
import struct
import subprocess
import sys
import tempfile

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "tools", "plot",
                      "kutlog_figures.py")
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
EXPECTED_SIZE = (1200, 800)


def png_size(path):
    """(width, height) from the PNG's IHDR chunk, which comes first."""
    with open(path, "rb") as stream:
        head = stream.read(24)
    if len(head) < 24 or head[:8] != PNG_SIGNATURE or head[12:16] != b"IHDR":
        sys.exit(f"{path} is not a PNG")
    return struct.unpack(">II", head[16:24])


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    figure, png, source = sys.argv[1], sys.argv[2], sys.argv[3:]
    with tempfile.TemporaryDirectory() as scratch:
        if source[0] == "--data":
            data = source[1]
        else:
            data = os.path.join(scratch, "data.csv")
            with open(data, "wb") as stream:
                run = subprocess.run(source, stdout=stream)
            if run.returncode != 0:
                sys.exit(f"exit status {run.returncode}: {' '.join(source)}")
        if os.path.exists(png):
            os.remove(png)
        draw = [sys.executable, SCRIPT, "--figure", figure, "--data", data, "--output", png]
        if subprocess.run(draw).returncode != 0:
            sys.exit(f"failed: {' '.join(draw)}")
    size = png_size(png)
    if size != EXPECTED_SIZE:
        sys.exit(f"{png} is {size[0]} x {size[1]} pixels, expected {EXPECTED_SIZE}")
    print(f"figure {figure}: {png}, {size[0]} x {size[1]}, {os.path.getsize(png)} bytes")


if __name__ == "__main__":
    main()
