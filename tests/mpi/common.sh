# Shared by the MPI tests (source it after tests/check_helpers.sh): how to start mpirun on a CI
# machine, the showcase options the tests render with, and how to find and kill a rank.
#
# CI runs as root on 2 cores: Open MPI needs its root switches, and --oversubscribe for more
# ranks than cores; -q keeps mpirun's own banners out of stderr, so rt's lines are all there is.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
MPIRUN=(mpirun -q --oversubscribe)
mpi() { "${MPIRUN[@]}" "$@"; }

command -v mpirun >/dev/null || { echo "FAIL mpirun not found (make mpi installs Open MPI)"; exit 1; }

SHOWCASE=$ROOT/scenes/showcase.lua
# Under the sanitizers (make test-sanitize sets RB_SANITIZE=1) a render is several times slower,
# and what they check is the code each case runs, not how many pixels it runs on: the tests
# that render the showcase again and again divide its width and height by SHRINK.
SHRINK=1
[ "${RB_SANITIZE:-0}" = 1 ] && SHRINK=2
# The showcase with every chapter's sampling on but cheap: --preview's one sample of each, then
# jittered antialiasing, 2x2 area-light and glossy samples, 4 lens samples and two photon passes
# of 20,000 (chapters 1-16 all take part: tone map, photons, CSG, quadrics, textures, bump, ...).
SHOWCASE_OPTIONS=(--quiet --preview --aa=jittered --light-samples=2 --glossy-samples=2
                  --dof-samples=4 --photon-passes=2 --photons=20000)

## reference FILE ARGS...: rt alone, rendering ARGS... into FILE; returns rt's status. The
## image is the same whatever the thread count, so tests that compare against the same render
## may share it: with MPI_REFERENCES set (CTest gives it to kill_worker, kill_rank0 and
## journal_refused, which all render the showcase at 256x160 with three light samples, 14 s
## of a core natively and about 20 s under the sanitizers), the first renders it into that
## folder, keyed by rt's file, the arguments and the scenes folder's files, and the others copy it.
reference() {
    local file=$1 key kept
    shift
    if [ -z "${MPI_REFERENCES:-}" ]; then
        "$RT" "$@" --output "$file"
        return
    fi
    key=$({ stat -L -c '%n %s %Y' "$RT"; printf '%s\n' "$@";
            find "$ROOT/scenes" -type f -printf '%p %s %T@\n' | sort; } | sha1sum | cut -c1-16)
    kept=$MPI_REFERENCES/$key.png
    if [ ! -s "$kept" ]; then
        mkdir -p "$MPI_REFERENCES"
        "$RT" "$@" --output "$kept.$$.png" || return
        mv -f "$kept.$$.png" "$kept"
    fi
    cp "$kept" "$file"
}

## The pids under process PARENT, at any depth.
descendants() {
    local child
    for child in $(pgrep -P "$1"); do
        echo "$child"
        descendants "$child"
    done
}

## The pid of rank RANK among the processes under PARENT (a background mpi), or nothing yet.
rank_pid() {
    local parent=$1 rank=$2 pid
    for pid in $(descendants "$parent"); do
        if tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$rank"; then
            echo "$pid"
            return
        fi
    done
}

## The sum of the "tiles per rank" that rt --stats printed into the file STATS.
tiles_rendered() {
    sed -n 's/.*tiles per rank//p' "$1" | tr ' ' '\n' | awk 'NF { s += $1 } END { print s + 0 }'
}

## Start `mpi -np RANKS RT ARGS... --output IMAGE`, SIGKILL rank KILL once IMAGE's journal
## holds more than a third of a FILM-byte film, and wait for mpirun. Prints the journal's size
## at the kill; returns 1 when the render ended before it could be killed.
kill_halfway() {
    local ranks=$1 kill=$2 film=$3 image=$4
    shift 4
    mpi -np "$ranks" "$RT" "$@" --output "$image" 2>/dev/null &
    local job=$! size=0 pid=""
    while kill -0 "$job" 2>/dev/null; do
        size=$(stat -c %s "$image.journal" 2>/dev/null || echo 0)
        if [ "$size" -gt $((film / 3)) ]; then
            pid=$(rank_pid "$job" "$kill")
            [ -n "$pid" ] && kill -9 "$pid" && break
        fi
        sleep 0.01
    done
    wait "$job" 2>/dev/null
    echo "$size"
    [ -n "$pid" ]
}
