#!/usr/bin/env bash
# run_golden.sh: render one scene and compare it with its golden image (or update the golden).
#
# usage: run_golden.sh RT_BINARY SCENE.lua GOLDEN_DIR OUT_DIR [--update]
#                      [--statistical] [--update-stats=N]
#                      [--report-name=LABEL] [rt args...]
#
#   NAME      the scene's file name without .lua
#   settings  GOLDEN_DIR/NAME.txt gives size, seed and args (see image_compare.h); with --update
#             a missing file is created with the default thresholds
#   render    RT_BINARY --quiet --features=all --size WxH --seed S --output OUT_DIR/NAME.png
#             <args from NAME.txt> <rt args...> SCENE, run from the repository root (the parent
#             of GOLDEN_DIR), so SCENE and the paths inside it are relative to the repository
#   compare   RT_BINARY --compare against GOLDEN_DIR/NAME.png (src/app/compare.cpp); its
#             report goes to OUT_DIR
#   update    with --update, the render is copied to GOLDEN_DIR/NAME.png instead
#   statistical  with --statistical and a GOLDEN_DIR/NAME.stats, a render that is not the
#             golden's bits passes when its block means are statistically the reference's
#             (a Monte Carlo chapter solved with other random numbers; block_stats.h); make
#             check and make grade use it, raybook's own make test does not
#   stats     with --update-stats=N, render seeds 1..N and write GOLDEN_DIR/NAME.stats
#   label     --report-name=LABEL (default NAME) names the render, the report files and the
#             verdict line, so two tests of one scene (say two chapter binaries) can run in
#             parallel without overwriting each other's files
#
# Prints one line. Exit status: 0 pass (or updated), 1 fail (or unreadable input), 2 usage or
# missing thresholds.
set -euo pipefail

usage() {
    echo "usage: run_golden.sh RT_BINARY SCENE.lua GOLDEN_DIR OUT_DIR [--update]" \
        "[--report-name=LABEL] [rt args...]" >&2
    exit 2
}

# An absolute path for $1, resolved from the caller's directory (the file need not exist)
absolute() {
    case "$1" in
        /*) printf '%s\n' "$1" ;;
        *) printf '%s\n' "$PWD/$1" ;;
    esac
}

# Parse the arguments; --update and --report-name may appear anywhere after the four positional
# ones; everything else goes to rt
[[ $# -ge 4 ]] || usage
rt=$(absolute "$1")
scene=$2
golden_dir=$(absolute "$3")
out_dir=$(absolute "$4")
shift 4
update=0
label=
statistical=0
stats_renders=0
rt_extra=()
for arg in "$@"; do
    case "$arg" in
        --update) update=1 ;;
        --report-name=*) label=${arg#--report-name=} ;;
        --statistical) statistical=1 ;;
        --update-stats=*) stats_renders=${arg#--update-stats=} ;;
        *) rt_extra+=("$arg") ;;
    esac
done
name=$(basename "$scene" .lua)
label=${label:-$name}
repo_root=$(dirname "$golden_dir")
thresholds=$golden_dir/$name.txt
golden_png=$golden_dir/$name.png
render_png=$out_dir/$label.png

# SCENE is relative to the repository root; accept a path relative to the caller's directory
# too, when only that one exists
if [[ $scene != /* && ! -e $repo_root/$scene && -e $scene ]]; then
    scene=$(absolute "$scene")
fi

# Find the thresholds file; when updating, a missing one is created (after a good render)
create_thresholds=0
thresholds_source=$thresholds
if [[ ! -f $thresholds ]]; then
    if [[ $update -eq 0 ]]; then
        echo "$label: FAIL: no thresholds file $thresholds; run make golden-update"
        exit 2
    fi
    create_thresholds=1
    thresholds_source=/dev/null # render with the defaults below
fi

# Read size, seed and args (the C++ parser of rt --compare validates the whole file)
size=192x144
seed=1
args_line=
while IFS= read -r line || [[ -n $line ]]; do
    line=${line%%#*} # drop the comment
    read -r key value <<<"$line" || true
    case "$key" in
        size) size=$value ;;
        seed) seed=$value ;;
        args) args_line=$value ;;
    esac
done <"$thresholds_source"
read -r -a file_args <<<"$args_line" || true

# Render from the repository root; remove the old render so a silent failure cannot pass
mkdir -p "$out_dir"
rm -f "$render_png"
stderr_file=$(mktemp)
trap 'rm -f "$stderr_file"' EXIT
status=0
(
    cd "$repo_root"
    "$rt" --quiet --features=all --size "$size" --seed "$seed" --output "$render_png" \
        ${file_args[@]+"${file_args[@]}"} ${rt_extra[@]+"${rt_extra[@]}"} "$scene"
) 2>"$stderr_file" >/dev/null || status=$?
if [[ $status -ne 0 ]]; then
    echo "$label: FAIL: render failed (exit $status)"
    cat "$stderr_file"
    exit 1
fi
if [[ ! -f $render_png ]]; then
    echo "$label: FAIL: render exited 0 but wrote no image $render_png"
    cat "$stderr_file"
    exit 1
fi

# --update-stats=N: the reference statistics of a Monte Carlo golden, from N renders with seeds
# 1 to N (rb_blockstats, in the build's tests folder); --statistical checks use them
if [[ $stats_renders -gt 0 ]]; then
    renders=()
    for ((s = 1; s <= stats_renders; s++)); do
        (
            cd "$repo_root"
            "$rt" --quiet --features=all --size "$size" --seed "$s" --output "$out_dir/$label-seed$s.png" \
                ${file_args[@]+"${file_args[@]}"} ${rt_extra[@]+"${rt_extra[@]}"} "$scene"
        ) >/dev/null
        renders+=("$out_dir/$label-seed$s.png")
    done
    "$(dirname "$rt")/tests/rb_blockstats" "$golden_dir/$name.stats" "${renders[@]}"
    rm -f "${renders[@]}"
    echo "$name: block statistics of $stats_renders renders written to $golden_dir/$name.stats"
    exit 0
fi

# Update the golden image (and create its thresholds file), or compare with it
if [[ $update -eq 1 ]]; then
    mkdir -p "$golden_dir"
    if [[ $create_thresholds -eq 1 ]]; then
        cat >"$thresholds" <<'EOF'
# Golden-image settings and thresholds (read by tests/golden/run_golden.sh and rt --compare).
# About one 8-bit level (1/255 = 0.00392), for a deterministic render: loosen them only where
# a Monte Carlo estimate needs it, and say why here.
size 192x144
seed 1
rmse 0.001
pixel_tol 0.004
max_fraction 0.0005
EOF
    fi
    cp "$render_png" "$golden_png.tmp.$$"
    mv "$golden_png.tmp.$$" "$golden_png"
    if [[ $create_thresholds -eq 1 ]]; then
        echo "$name: golden updated (created $name.txt with the default thresholds)"
    else
        echo "$name: golden updated"
    fi
    exit 0
fi
stats_args=()
if [[ $statistical -eq 1 && -f $golden_dir/$name.stats ]]; then
    stats_args=(--stats "$golden_dir/$name.stats")
fi
status=0
"$rt" --compare "$golden_png" "$render_png" --thresholds "$thresholds" \
    --name "$label" --report-dir "$out_dir" ${stats_args[@]+"${stats_args[@]}"} || status=$?
exit "$status"
