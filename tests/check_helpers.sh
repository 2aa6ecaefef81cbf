# Shared by the shell test scripts (source it): one line per check, a closing count, and the
# header comments that steer a scene.
passed=0
failed=0
# The repository these helpers belong to.
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

## The arguments RT_BINARY OUT_DIR that most test scripts take: sets RT and OUT, both absolute
## (OUT is created); exits 2 with the usage line for anything else.
rt_and_out_dir() {
    if [ $# -ne 2 ]; then
        echo "usage: $0 RT_BINARY OUT_DIR" >&2
        exit 2
    fi
    RT=$(realpath "$1")
    OUT=$(mkdir -p "$2" && realpath "$2")
}

## Record a passed check.
ok() { echo "ok   $1"; passed=$((passed + 1)); }
## Record a failed check and why.
fail() { echo "FAIL $1: $2"; failed=$((failed + 1)); }
## The values of a scene's header comments ("-- KEY: value", top comment block only).
header() { sed -n "/^--/!q; s/^-- $2: *//p" "$1"; }
## Print "N passed, M failed" and return non-zero if anything failed.
finish() {
    echo "$passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}
