#!/usr/bin/env bash
# raybook's BVH against Embree, counted instead of timed (issue 41): each ray kind (coherent,
# incoherent, shadow) traced by one side at a time (raybook, Embree default mode, Embree robust
# mode) under valgrind, on the same mesh and the same rays. Prints the table of chapter 3's
# "Where the cycles go" and writes it to BUILD_DIR/bench/bvh_callgrind.md.
#
# usage: tests/perf/bvh_callgrind.sh BUILD_DIR [file.obj]
#   file.obj     default: bunny_L2.obj in $RB_SHARED/assets (RB_SHARED: ../shared beside the
#                repository), the mesh of bvh_vs_embree in make bench
#   RAYS=N       rays per set (default 65536; the coherent set is a sqrt(N) x sqrt(N) camera)
#   CACHEGRIND=0 skip the cachegrind cross-check
#
# How: bvh_vs_embree --profile SIDE KIND builds only that side and traces the set twice. Under
# callgrind (--instr-atstart=no --collect-atstart=no) its client requests leave the load and the
# build uninstrumented, let the first pass warm the simulated caches, and collect the second
# only. cachegrind (valgrind 3.19 has no client requests for it) runs the same command with one
# pass and with two; the difference is one warm pass. Both simulate the same caches, set here to
# this machine's L1 (48 KiB data, 32 KiB instructions) and L2 (1 MiB) as the last level. Node
# visits and triangle tests are raybook's own counts (bvh_vs_embree --counts); Embree's release
# library keeps none. valgrind runs no AVX-512, so Embree runs its AVX2 kernels here, as raybook
# does; natively, Embree picks AVX-512 on a CPU that has it.
set -euo pipefail
build=$(cd "${1:?usage: bvh_callgrind.sh BUILD_DIR [file.obj]}" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
obj=${2:-${RB_SHARED:-$root/../shared}/assets/bunny_L2.obj}
[ -f "$obj" ] || { echo "bvh_callgrind: $obj not found"; exit 1; }
bin=$build/tests/perf/bvh_vs_embree
[ -x "$bin" ] || { echo "bvh_callgrind: $bin not built (it needs Embree 3: apt-get install libembree-dev)"; exit 1; }
command -v valgrind >/dev/null || { echo "bvh_callgrind: valgrind is not installed (apt-get install valgrind)"; exit 1; }
rays=${RAYS:-65536}
caches=(--I1=32768,8,64 --D1=49152,12,64 --LL=1048576,8,64)
tmp=$(mktemp -d /tmp/raybook-callgrind.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$build/bench"
report=$build/bench/bvh_callgrind.md

# The events line of a callgrind or cachegrind output file, as "Ir I1mr D1mr D1mw ILmr DLmr DLmw".
events() {  # file
  awk '$1 == "events:" { for (i = 2; i <= NF; i++) name[i - 1] = $i }
       $1 == "totals:" || $1 == "summary:" && NF > 2 { for (i = 2; i <= NF; i++) v[name[i - 1]] = $i }
       END { print v["Ir"] + 0, v["I1mr"] + 0, v["D1mr"] + 0, v["D1mw"] + 0, v["ILmr"] + 0, v["DLmr"] + 0, v["DLmw"] + 0 }' "$1"
}

# Per ray from "Ir I1mr D1mr D1mw ILmr DLmr DLmw" and the ray count: "instructions L1 LL".
per_ray() {  # n Ir I1mr D1mr D1mw ILmr DLmr DLmw
  awk -v n="$1" -v ir="$2" -v i1="$3" -v d1r="$4" -v d1w="$5" -v il="$6" -v dlr="$7" -v dlw="$8" \
    'BEGIN { printf "%.0f %.2f %.2f\n", ir / n, (i1 + d1r + d1w) / n, (il + dlr + dlw) / n }'
}

profile() {  # tool side kind passes out
  local tool=$1 side=$2 kind=$3 passes=$4 out=$5 log
  if [ "$tool" = callgrind ]; then
    log=$(nice valgrind --tool=callgrind --instr-atstart=no --collect-atstart=no --cache-sim=yes \
            "${caches[@]}" --callgrind-out-file="$out" \
            "$bin" "$obj" --profile "$side" "$kind" --rays "$rays" --passes "$passes" 2>&1) ||
      { echo "$log" >&2; exit 1; }
  else
    log=$(nice valgrind --tool=cachegrind "${caches[@]}" --cachegrind-out-file="$out" \
            "$bin" "$obj" --profile "$side" "$kind" --rays "$rays" --passes "$passes" 2>&1) ||
      { echo "$log" >&2; exit 1; }
  fi
  grep '^profile ' <<<"$log" | tail -1
}

"$bin" "$obj" --counts --rays "$rays" >"$tmp/counts.txt"
declare -A count_of
while read -r _ kind _ nodes _ packs _ exact; do
  count_of[$kind]="$nodes $packs $exact"
done < <(grep '^counts ' "$tmp/counts.txt")

{
  echo "Per ray, $(basename "$obj"), $rays rays a set, one thread, $(valgrind --version);"
  echo "instructions and L1/LL misses from callgrind (second pass only), cachegrind's two-pass"
  echo "difference beside them; raybook's nodes, packs and exact tests from --counts:"
  echo
  echo "| rays | side | instructions | L1 misses | LL misses | cachegrind: instructions, L1, LL | wide nodes | packs of 4 | exact tests |"
  echo "|---|---|---:|---:|---:|---:|---:|---:|---:|"
} | tee "$report"
for kind in coherent incoherent shadow; do
  for side in raybook embree embree-robust; do
    line=$(profile callgrind "$side" "$kind" 2 "$tmp/cg.out")
    n=$(awk '{ for (i = 1; i < NF; i++) if ($i == "rays") print $(i + 1) }' <<<"$line")
    read -r ir l1 ll < <(per_ray "$n" $(events "$tmp/cg.out"))
    cross="-"
    if [ "${CACHEGRIND:-1}" != 0 ]; then
      profile cachegrind "$side" "$kind" 1 "$tmp/c1.out" >/dev/null
      profile cachegrind "$side" "$kind" 2 "$tmp/c2.out" >/dev/null
      read -r -a one < <(events "$tmp/c1.out")
      read -r -a two < <(events "$tmp/c2.out")
      diff=()
      for i in 0 1 2 3 4 5 6; do diff+=($((two[i] - one[i]))); done
      cross=$(per_ray "$n" "${diff[@]}" | awk '{ printf "%s, %s, %s", $1, $2, $3 }')
    fi
    counts="- | - | -"
    [ "$side" = raybook ] && counts=$(awk '{ printf "%s | %s | %s", $1, $2, $3 }' <<<"${count_of[$kind]}")
    name=$side; [ "$side" = raybook ] && name=$(awk '{ print "raybook " $3 }' <<<"$line")
    echo "| $kind | $name | $ir | $l1 | $ll | $cross | $counts |" | tee -a "$report"
  done
done
echo
echo "bvh_callgrind: table saved to $report"
