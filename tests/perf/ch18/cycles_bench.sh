#!/usr/bin/env bash
# Chapter 18 against Blender's Cycles (make bench): the chapter's Cornell box path traced by
# both, at equal error. Writes BUILD/bench/ch18-cycles.txt.
#
# usage: tests/perf/ch18/cycles_bench.sh BUILD_DIR   (skipped, with a note, without blender)
#
# Each renderer is measured against its own converged picture (raybook at 4096 paths a pixel,
# seed 99; Cycles at 4096 samples, seed 99), at 16, 64 and 256 samples a pixel (seed 1), 160x160,
# 2 threads, the fastest of BENCH_ROUNDS rounds (default 2). Time: raybook's render phase
# (--stats), and Cycles' bpy.ops.render.render (the scene is built and synced before the clock
# starts, as raybook's parse and BVH build are not counted). The time at equal error is read off
# each curve by log-log interpolation at the RMSEs raybook reached; the converged pictures'
# agreement is their mean difference per channel, relative to raybook's mean.
set -euo pipefail
build=$(cd "${1:?usage: cycles_bench.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
out=$build/bench/ch18
mkdir -p "$out"
if ! command -v blender >/dev/null; then
  echo "ch18 cycles: blender is not installed (apt-get install blender); skipped" | tee "$build/bench/ch18-cycles.txt"
  exit 0
fi
python3 "$root/tests/perf/ch18/cycles_bench.py" "$build/rt_ch18" "$root" "$out" "${BENCH_ROUNDS:-2}" |
  tee "$build/bench/ch18-cycles.txt"
