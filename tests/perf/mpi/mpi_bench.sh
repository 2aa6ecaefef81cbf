#!/usr/bin/env bash
# make bench: rendering on many processes (issue 23), on this machine's cores, oversubscribed
# where it needs more ranks than cores. A benchmark, not a test: nothing here gates CI.
#
# usage: mpi_bench.sh BUILD_DIR
#   BENCH_RUNS=N   runs of each measurement (default 5); each figure is the median
#
# 1. Overhead at equal cores: the showcase (every chapter, cheap sampling, 320x200) on 1 rank
#    x 2 threads (rt alone) and on 2 ranks x 1 thread, alternating. Time = the render phase of
#    --stats (photon passes and tiles; rank 0's clock, so it includes collecting the tiles).
#    Target: 2 ranks reach >= 95% of one process's throughput.
# 2. Bytes per frame: what the tile exchange sent (leases, tiles, reports; --stats "mpi sent")
#    against the film's size (width x height x 3 floats), at 2 and 4 ranks; the photon join
#    (every rank gets every other rank's photons) is printed beside it. Target <= 1.1x.
# 3. Startup: the wall time of a 16x16 render of the showcase under mpirun at 4 ranks against
#    1 rank (MPI start, Lua, BVH, photons and 1 tile: all fixed costs). Target <= 1.1x.
# 4. Balance: tests/perf/mpi/half_glass.lua (glass over the top half) at 4 ranks x 1 thread,
#    --spp 16, with dynamic leases and with a static split into bands of rows. Each rank's busy
#    time is the thread CPU time spent inside its tiles; spread = the largest distance of a
#    rank's from the mean, over the mean. Target: dynamic <= 10%.
# Prints "target NAME VALUE" lines for bench.sh's summary.
set -uo pipefail
build=$(cd "${1:?usage: mpi_bench.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
runs=${BENCH_RUNS:-5}
rt=$(ls "$build"/rt_ch[0-9]* | sort -V | tail -1)
command -v mpirun >/dev/null || { echo "mpi bench: mpirun not found (make mpi installs Open MPI)"; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi=(mpirun -q --oversubscribe)
tmp=$(mktemp -d /tmp/raybook-mpi-bench.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
showcase=(--quiet --stats --preview --aa=jittered --light-samples=3 --glossy-samples=2
          --dof-samples=4 --photon-passes=2 --photons=20000 --size 320x200
          "$root/scenes/showcase.lua")

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
render_s() { sed -n 's/.*render \([0-9.]*\) s.*/\1/p' "$1"; }
wall() { local t0=$EPOCHREALTIME; "$@" >/dev/null 2>&1; awk -v a="$t0" -v b="$EPOCHREALTIME" 'BEGIN { print b - a }'; }

echo "Rendering on many processes (issue 23), $(date -u '+%F %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
echo "$(basename "$rt"), $(mpirun --version | head -1), $runs runs each, medians"

# ---- 1. Overhead at equal cores --------------------------------------------------------------
: >"$tmp/one.txt"
: >"$tmp/two.txt"
for ((i = 0; i < runs; i++)); do
    "$rt" "${showcase[@]}" --threads 2 --output "$tmp/one.png" 2>"$tmp/s.txt"
    render_s "$tmp/s.txt" >>"$tmp/one.txt"
    "${mpi[@]}" -np 2 "$rt" "${showcase[@]}" --threads 1 --output "$tmp/two.png" 2>"$tmp/s2.txt"
    render_s "$tmp/s2.txt" >>"$tmp/two.txt"
done
cmp -s "$tmp/one.png" "$tmp/two.png" || echo "WARNING: the two renders differ"
one=$(median <"$tmp/one.txt")
two=$(median <"$tmp/two.txt")
throughput=$(awk -v a="$one" -v b="$two" 'BEGIN { printf "%.3f", a / b }')
echo
echo "1. overhead: showcase 320x200, render phase: 1 rank x 2 threads ${one} s ($(tr '\n' ' ' <"$tmp/one.txt")),"
echo "   2 ranks x 1 thread ${two} s ($(tr '\n' ' ' <"$tmp/two.txt")): throughput ${throughput}x of one process's"
echo "target mpi_throughput_2x1 $throughput"

# ---- 2. Bytes per frame ------------------------------------------------------------------------
echo
for ranks in 2 4; do
    "${mpi[@]}" -np $ranks "$rt" "${showcase[@]}" --threads 1 --output "$tmp/b.png" 2>"$tmp/b.txt"
    line=$(grep 'mpi *sent' "$tmp/b.txt")
    sent=$(sed -n 's/.*sent \([0-9]*\) bytes.*/\1/p' <<<"$line")
    film=$(sed -n 's/.*film of \([0-9]*\).*/\1/p' <<<"$line")
    joins=$(sed -n 's/.*joins \([0-9]*\).*/\1/p' <<<"$line")
    ratio=$(awk -v s="$sent" -v f="$film" 'BEGIN { printf "%.3f", s / f }')
    echo "2. bytes at $ranks ranks: the tile exchange sent $sent bytes for a film of $film: ${ratio}x;" \
         "the photon join sent $joins more ($(awk -v s="$sent" -v j="$joins" -v f="$film" 'BEGIN { printf "%.2f", (s + j) / f }')x with it)"
    echo "target mpi_bytes_per_film_${ranks}ranks $ratio"
done

# ---- 3. Startup ----------------------------------------------------------------------------
# Beside rt, an MPI program that only starts and ends (MPI_Init, MPI_Finalize): what mpirun
# and Open MPI cost before rt does anything.
printf '#include <mpi.h>\nint main(int c, char** v) { MPI_Init(&c, &v); MPI_Finalize(); }\n' >"$tmp/empty.cpp"
mpicxx -O2 "$tmp/empty.cpp" -o "$tmp/empty" || echo "mpi bench: mpicxx failed; no empty-program baseline"
tiny=(--quiet --preview --size 16x16 "$root/scenes/showcase.lua")
for f in start0 start1 start4 empty1 empty4; do : >"$tmp/$f.txt"; done
for ((i = 0; i < runs; i++)); do
    wall "$rt" "${tiny[@]}" --threads 1 --output "$tmp/t0.png" >>"$tmp/start0.txt"
    wall "${mpi[@]}" -np 1 "$rt" "${tiny[@]}" --threads 1 --output "$tmp/t1.png" >>"$tmp/start1.txt"
    wall "${mpi[@]}" -np 4 "$rt" "${tiny[@]}" --threads 1 --output "$tmp/t4.png" >>"$tmp/start4.txt"
    [ -x "$tmp/empty" ] && wall "${mpi[@]}" -np 1 "$tmp/empty" >>"$tmp/empty1.txt"
    [ -x "$tmp/empty" ] && wall "${mpi[@]}" -np 4 "$tmp/empty" >>"$tmp/empty4.txt"
done
s0=$(median <"$tmp/start0.txt")
s1=$(median <"$tmp/start1.txt")
s4=$(median <"$tmp/start4.txt")
startup=$(awk -v a="$s1" -v b="$s4" 'BEGIN { printf "%.3f", b / a }')
echo
echo "3. startup (16x16 showcase, wall): rt alone ${s0} s, mpirun 1 rank ${s1} s, 4 ranks ${s4} s: ${startup}x"
if [ -s "$tmp/empty1.txt" ]; then
    e1=$(median <"$tmp/empty1.txt")
    e4=$(median <"$tmp/empty4.txt")
    echo "   an empty MPI program: 1 rank ${e1} s, 4 ranks ${e4} s: $(awk -v a="$e1" -v b="$e4" 'BEGIN { printf "%.3f", b / a }')x;" \
         "rt's own part: 1 rank $(awk -v a="$s1" -v b="$e1" 'BEGIN { printf "%.3f", a - b }') s, 4 ranks $(awk -v a="$s4" -v b="$e4" 'BEGIN { printf "%.3f", a - b }') s"
fi
echo "target mpi_startup_4_over_1 $startup"

# ---- 4. Balance ----------------------------------------------------------------------------
echo
for lease in dynamic static; do
    : >"$tmp/spread.txt"
    for ((i = 0; i < runs; i++)); do
        "${mpi[@]}" -np 4 "$rt" --quiet --stats --threads 1 --spp 16 --mpi-lease $lease \
            --output "$tmp/h.png" "$root/tests/perf/mpi/half_glass.lua" 2>"$tmp/h.txt"
        busy=$(sed -n 's/.*busy cpu s per rank//p' "$tmp/h.txt")
        spread=$(awk '{ for (i = 1; i <= NF; i++) m += $i; m /= NF
                        for (i = 1; i <= NF; i++) { d = ($i > m ? $i - m : m - $i) / m; if (d > w) w = d }
                        printf "%.3f", w }' <<<"$busy")
        echo "$spread" >>"$tmp/spread.txt"
        echo "4. $lease leases, run $((i + 1)): busy CPU s per rank$busy; spread $spread"
    done
    spread=$(median <"$tmp/spread.txt")
    echo "4. $lease leases: median spread $spread"
    echo "target mpi_balance_spread_$lease $spread"
done
