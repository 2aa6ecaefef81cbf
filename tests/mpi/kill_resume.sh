#!/usr/bin/env bash
# A killed rank loses nothing: the showcase renders on 2 ranks until its journal holds a third
# of the film, then rank KILL (1: a worker, 0: rank 0, which writes the journal) gets SIGKILL.
# Open MPI ends the job; no image may be there, only the journal. --resume on 3 ranks, then on
# 1, must finish the image byte-identical to one process's, render fewer tiles than the image
# has (the journal's were kept), and remove the journal.
# Usage: bash tests/mpi/kill_resume.sh RT_BINARY OUT_DIR KILL
set -u
source "$(dirname "$0")/../check_helpers.sh"
source "$(dirname "$0")/common.sh"
kill=${3:?usage: kill_resume.sh RT_BINARY OUT_DIR KILL}
rt_and_out_dir "$1" "$2"
cd "$OUT" && rm -f ./*.png ./*.journal ./*.txt

W=$((256 / SHRINK)) H=$((160 / SHRINK))
OPTIONS=("${SHOWCASE_OPTIONS[@]}" --light-samples=3 --size ${W}x$H "$SHOWCASE")
TILES=$(((W + 15) / 16 * ((H + 15) / 16)))
reference reference.png "${OPTIONS[@]}" || fail "reference" "rt alone failed"

for resume_ranks in 3 1; do
    image=killed-then-$resume_ranks.png
    size=$(kill_halfway 2 "$kill" $((W * H * 12)) "$image" "${OPTIONS[@]}" --threads 1)
    if [ $? -ne 0 ]; then
        fail "kill rank $kill" "the render ended before the journal reached a third of the film"
        continue
    fi
    if [ -e "$image" ] || [ ! -s "$image.journal" ]; then
        fail "kill rank $kill" "after the kill: image there: $([ -e "$image" ] && echo yes || echo no), journal: $(stat -c %s "$image.journal" 2>/dev/null || echo none)"
        continue
    fi
    ok "rank $kill killed at a journal of $size bytes: no image, the journal kept"
    if ! timeout 300 "${MPIRUN[@]}" -np $resume_ranks "$RT" "${OPTIONS[@]}" --threads 1 --resume \
        --stats --output "$image" 2>"$image.stats.txt"; then
        fail "--resume on $resume_ranks ranks" "mpirun failed: $(grep rt: "$image.stats.txt")"
        continue
    fi
    rendered=$(tiles_rendered "$image.stats.txt")
    if ! cmp -s reference.png "$image"; then
        fail "--resume on $resume_ranks ranks" "$image differs from one process's render"
    elif [ "$rendered" -ge "$TILES" ] || [ "$rendered" -le 0 ]; then
        fail "--resume on $resume_ranks ranks" "rendered $rendered of $TILES tiles: the journal was not used"
    elif [ -e "$image.journal" ]; then
        fail "--resume on $resume_ranks ranks" "the journal is still there after the image"
    else
        ok "--resume on $resume_ranks ranks rendered the other $rendered of $TILES tiles: byte-identical, journal gone"
    fi
done
finish
