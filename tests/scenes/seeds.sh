#!/usr/bin/env bash
# seeds.sh: a smoke test (CTest: seed_scenes_smoke): render each seed scene
# (scenes/seeds/*.lua, one per seed report, each in that seed's own Lua dialect) small, from
# the repository root; fail when any render fails. It does not look at the pictures: the
# golden tests golden-seed.NAME compare each with golden/NAME.png. So each renders as --preview
# (one sample of everything): at full counts seed 000 alone took 12 s, and 45 s under the
# sanitizers, to show what the golden test shows again.
#
# usage: seeds.sh RT_BINARY OUT_DIR
#
# Every scene must exit 0 and write its image. Prints one line per scene and a summary.
set -euo pipefail

if [[ $# -ne 2 ]]; then
    echo "usage: seeds.sh RT_BINARY OUT_DIR" >&2
    exit 2
fi
case "$1" in /*) rt=$1 ;; *) rt=$PWD/$1 ;; esac
case "$2" in /*) out=$2 ;; *) out=$PWD/$2 ;; esac
repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
mkdir -p "$out"

cd "$repo_root"
failed=0
count=0
for scene in scenes/seeds/*.lua; do
    name=$(basename "$scene" .lua)
    image=$out/$name.png
    rm -f "$image"
    count=$((count + 1))
    status=0
    "$rt" --quiet --preview --features=all --size 160x120 --seed 1 --output "$image" "$scene" \
        2>"$out/$name.err" || status=$?
    if [[ $status -ne 0 ]]; then
        echo "$name: FAIL: exit $status"
        sed 's/^/  /' "$out/$name.err"
        failed=$((failed + 1))
    elif [[ ! -s $image ]]; then
        echo "$name: FAIL: exited 0 but wrote no image $image"
        failed=$((failed + 1))
    else
        echo "$name: ok"
    fi
done
if [[ $count -eq 0 ]]; then
    echo "seeds: FAIL: no scenes in scenes/seeds/"
    exit 1
fi
echo "seeds: $((count - failed)) of $count scenes rendered"
[[ $failed -eq 0 ]]
