#!/usr/bin/env bash
# No silent surprises: each scene in tests/scenes/warnings/ renders (exit code 0, the image is
# written) and prints the warnings its header asks for, on stderr, as lines that start with
# "rt: warning:" and name the scene's gr.render line (the line marked "--!").
#   -- expect-warning: TEXT    a warning line must contain TEXT (may repeat)
#   -- expect-no-warning       no warning at all
#   -- rt-args: ARGS           extra command-line arguments
#   -- rt-no-output-override   let the scene choose its output name (no --output)
#
# Usage: bash tests/scenes/warnings.sh RT_BINARY OUT_DIR
# Prints one line per case and a final "N passed, M failed"; exits 1 on any failure.
set -u

HERE=$(cd "$(dirname "$0")" && pwd)

# shellcheck source=../check_helpers.sh
source "$(dirname "$0")/../check_helpers.sh"
rt_and_out_dir "$@"


for scene in "$HERE"/warnings/*.lua; do
    name=$(basename "$scene" .lua)
    work="$OUT/$name"
    rm -rf "$work"
    mkdir -p "$work"
    read -r -a args <<<"$(header "$scene" rt-args | head -n 1)"
    image=out.png
    if grep -q '^-- rt-no-output-override' "$scene"; then
        image=$(sed -n "s/.*gr.render([^']*'\([^']*\)'.*/\1/p" "$scene" | head -n 1)
    else
        args+=(--output out.png)
    fi
    (cd "$work" && timeout 60 "$RT" --quiet "${args[@]}" "$scene") >"$work.stdout" 2>"$work.stderr"
    rc=$?
    problems=""
    [ $rc -eq 0 ] || problems+=" exit code $rc: $(head -c 300 "$work.stderr");"
    [ -s "$work/$image" ] || problems+=" no image $image was written;"
    warnings=$(grep '^rt: warning: ' "$work.stderr")
    line=$(grep -n -- '--!' "$scene" | head -n 1 | cut -d: -f1)
    if grep -q '^-- expect-no-warning' "$scene"; then
        [ -z "$warnings" ] || problems+=" unexpected warning: $warnings;"
    else
        [ -n "$warnings" ] || problems+=" no warning;"
        if [ -n "$line" ] && [ -n "$warnings" ] && ! grep -q -- "$(basename "$scene"):$line:" <<<"$warnings"; then
            problems+=" the warning does not name line $line: $warnings;"
        fi
        while IFS= read -r text; do
            [ -z "$text" ] && continue
            grep -qF -- "$text" <<<"$warnings" || problems+=" no warning says '$text' (got: $warnings);"
        done < <(header "$scene" expect-warning)
    fi
    if [ -n "$problems" ]; then
        fail "$name" "${problems%;}"
    else
        ok "$name"
    fi
done

finish
