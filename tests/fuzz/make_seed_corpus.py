#!/usr/bin/env python3
"""Writes the seed corpus of the fuzz targets: corpus/<target>/seed-<i>, a few byte strings of
1 to 8 KiB from a fixed random seed. The targets decode every choice (API, parameters, counts,
offsets, floats) from the bytes, so random bytes reach every API; the fuzzer does the rest.
Run from anywhere: python3 tests/fuzz/make_seed_corpus.py"""
import pathlib
import random

TARGETS = ("math", "lobe", "shade")
SIZES = (1024, 2048, 3072, 4096, 6144, 8192)

here = pathlib.Path(__file__).resolve().parent
for target in TARGETS:
    directory = here / "corpus" / target
    directory.mkdir(parents=True, exist_ok=True)
    for index, size in enumerate(SIZES):
        rng = random.Random(f"{target}-{index}")
        (directory / f"seed-{index}").write_bytes(bytes(rng.randrange(256) for _ in range(size)))
