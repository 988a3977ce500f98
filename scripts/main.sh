#!/usr/bin/env bash
# The main job: install what is needed, build, and write everything kutlog shows into one
# output folder (default out/), printing the tables on the way.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup-debian.sh
bash scripts/build.sh >/dev/null
build_dir=${KUTLOG_BUILD_DIR:-build}
out=${KUTLOG_OUT_DIR:-out}
mkdir -p "$out"
tables="$build_dir/tools/kutlog-tables"

for table in 1 2 fig4; do
  echo
  echo "== kutlog-tables --table $table"
  "$tables" --table "$table" | tee "$out/table-$table.txt"
  "$tables" --table "$table" --format csv >"$out/table-$table.csv"
done

plot="$build_dir/tools/kutlog-plot"
for figure in 2 3 9; do
  "$plot" --figure "$figure" --output "$out/figure-$figure.png"
done
"$plot" --figure albedo --n 100 --k 5 --q 0.5 --output "$out/albedo.png"
"$build_dir/tools/kutlog-render" --n 100 --k 3 --output "$out/spheres"

echo
echo "kutlog: results written to $(cd "$out" && pwd)"
