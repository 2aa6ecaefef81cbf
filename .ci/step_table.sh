# CI's step times (issue 40: so that growth is visible), sourced by .ci/run.
#   step_took NAME SECONDS   record a step (and say how long it took, as .ci/run always did)
#   step_stages LOG          record the stages make test names in LOG ("make test: X took N s")
#   step_table TOTAL         print every recorded step and the total, one row each
step_names=()
step_seconds=()

step_record() {
    step_names+=("$1")
    step_seconds+=("$2")
}

step_took() {
    step_record "$1" "$2"
    echo "$1 took $2 s"
}

step_stages() {
    local line
    while IFS= read -r line; do
        [[ $line =~ ^make\ test:\ (.*)\ took\ ([0-9]+)\ s$ ]] &&
            step_record "  ${BASH_REMATCH[1]}" "${BASH_REMATCH[2]}"
    done <"$1"
}

step_table() {
    local i
    printf '\n%-56s %8s %7s\n' "CI step" "seconds" "minutes"
    for i in "${!step_names[@]}"; do
        printf '%-56s %8d %7.1f\n' "${step_names[i]}" "${step_seconds[i]}" \
            "$(awk "BEGIN { print ${step_seconds[i]} / 60 }")"
    done
    printf '%-56s %8d %7.1f\n' "total" "$1" "$(awk "BEGIN { print $1 / 60 }")"
}
