#!/usr/bin/env bash
# An rt built without MPI renders as before, and --mpi and --resume say how to get MPI: exit
# code 1 and one line naming make mpi.
# Usage: bash tests/mpi/not_built.sh RT_BINARY
set -u
RT=$1
for option in --mpi --resume; do
    message=$("$RT" "$option" "$(dirname "$0")/../../scenes/chapter01-raycast.lua" 2>&1 >/dev/null)
    rc=$?
    if [ $rc -ne 1 ] || [ "$(echo "$message" | wc -l)" -ne 1 ] || [[ $message != *"make mpi"* ]]; then
        echo "FAIL $option: exit $rc: $message"
        exit 1
    fi
    echo "ok   $option: $message"
done
