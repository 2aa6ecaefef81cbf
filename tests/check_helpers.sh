# Shared by the shell test scripts (source it): one line per check, a closing count, and the
# header comments that steer a scene.
passed=0
failed=0

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
