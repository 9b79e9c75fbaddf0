#!/usr/bin/env bash
# Run every benchmark in bench/ and collect their markdown tables in bench/RESULTS.md.
set -eo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
source "$here/scripts/python-env.sh"
source "$here/catkin_ws/devel/setup.bash"
cd "$here"
out=bench/RESULTS.md
tmp=$(mktemp)
echo "# Benchmarks ($(date -u +%Y-%m-%d), $(nproc) cores)" >"$tmp"
shopt -s nullglob
for bench in bench/bench_*; do
  [ -x "$bench" ] || continue
  echo "bench: $bench" >&2
  "$bench" >>"$tmp"
  echo >>"$tmp"
done
mv "$tmp" "$out"
cat "$out"
