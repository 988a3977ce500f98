#!/usr/bin/env bash
# The main job: install what is needed, build, and write everything kutlog shows into one
# output folder (default out/): the article's tables, the ULP table, a benchmark summary and
# its page (docs/benchmarks.md), the figures, the model's distance to t^n (docs/shape.md), the
# renders, the white-furnace plot, the path-traced sampling comparison and a frame of the
# example rasterizer.
# About 10 minutes on 2 cores, most of it the ULP sweep over every float.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup-debian.sh
bash scripts/build.sh >/dev/null
build_dir=${KUTLOG_BUILD_DIR:-build}
out=${KUTLOG_OUT_DIR:-out}
mkdir -p "$out"
tools="$build_dir/tools"

section() { printf '\n== %s\n' "$*"; }

for table in 1 2 fig4; do
  section "kutlog-tables --table $table"
  "$tools/kutlog-tables" --table "$table" | tee "$out/table-$table.txt"
  "$tools/kutlog-tables" --table "$table" --format csv >"$out/table-$table.csv"
done

section "kutlog-ulp: every float of each kernel's domain, on the dispatched arch"
"$tools/kutlog-ulp" --arch active --summary --format markdown | tee "$out/ulp.md"

section "kutlog-bench: lobes at n = 1000 against pow (xsimd), every arch, median of 5"
"$build_dir/bench/kutlog-bench" --benchmark_filter='lobe/.*n:1000/' --benchmark_repetitions=5 \
  --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true \
  --benchmark_out="$out/bench.json" --benchmark_out_format=json >/dev/null 2>"$out/bench.log" ||
  { cat "$out/bench.log"; exit 1; }
"$build_dir/bench/kutlog-bench" --kutlog_ratios_from="$out/bench.json" | tee "$out/bench.md"
"$build_dir/bench/kutlog-bench" --kutlog_ratios_from="$out/bench.json" --kutlog_page="$out/benchmarks"

section "figures (kutlog-curves CSV, drawn by matplotlib), white furnace, distance to t^n, renders"
# Debian's Python, where python3-matplotlib is installed (a python3 earlier on PATH may lack it).
python=${KUTLOG_PYTHON:-/usr/bin/python3}
draw() {  # draw FIGURE NAME: out/NAME.csv -> out/NAME.png
  "$python" tools/plot/kutlog_figures.py --figure "$1" --data "$out/$2.csv" --output "$out/$2.png"
}
for figure in 2 3 9; do
  "$tools/kutlog-curves" --figure "$figure" --format csv >"$out/figure-$figure.csv"
  draw "$figure" "figure-$figure"
done
"$tools/kutlog-curves" --figure albedo --n 100 --k 5 --q 0.5 --format csv >"$out/albedo.csv"
draw albedo albedo
# The model against t^n: the README's table (docs/shape.md) and the sweep over n behind it.
"$tools/kutlog-curves" --figure shape-table --format markdown | tee "$out/shape.md"
"$tools/kutlog-curves" --figure shape --format csv >"$out/shape.csv"
draw shape shape
"$tools/kutlog-render" --object sphere --n 100 --k 3 --output "$out/spheres"
"$tools/kutlog-render" --object teapot --n 100 --k 3 --output "$out/teapot"

section "kutlog-pathtrace: lobe against uniform sampling, RMSE against a 4096-spp reference"
# About 80 s of CPU (40 s on 2 idle cores; 2 min 47 s measured on 2 cores shared at load 8):
# the 4096-spp reference is most of it.
"$tools/kutlog-pathtrace" --output "$out/pathtrace" --format csv >"$out/pathtrace-rmse.csv"
draw rmse pathtrace-rmse

section "example rasterizer, built against the installed package"
prefix="$(cd "$build_dir" && pwd)/install"
cmake --install "$build_dir" --prefix "$prefix" >/dev/null
cmake -S examples/rasterizer -B "$build_dir/rasterizer" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$build_dir/rasterizer" -j "${KUTLOG_JOBS:-2}" >/dev/null
"$build_dir/rasterizer/kutlog-rasterizer" 1920 1080 7 "$out/rasterizer.png" | tee "$out/rasterizer.txt"

echo
echo "kutlog: results written to $(cd "$out" && pwd)"
ls "$out"
