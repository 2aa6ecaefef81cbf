#!/usr/bin/env bash
# Scenes that would not fit fail early and cleanly. Each case checks exit code 1, a message that
# names the file, the line and the limit, no image or temporary file left behind, and (for
# memory) a peak resident size far below what the scene asked for:
# - --max-memory refuses a 2-million-triangle mesh, an OBJ of 50 million faces streamed through
#   a pipe (it never exists on disk, and rt stops reading after the first million or so), an
#   image too large for the limit, and a script that grows a table;
# - a full disk (a file-size limit, ulimit -f, makes write() fail the way ENOSPC does) and a
#   read-only output folder are clear errors, not a truncated image.
#
# Usage: bash tests/resources.sh RT_BINARY OUT_DIR
# Prints one line per check and a final "N passed, M failed"; exits 1 on any failure.
set -u

# shellcheck source=check_helpers.sh
source "$(dirname "$0")/check_helpers.sh"
rt_and_out_dir "$@"

# A scene around one mesh file, in folder $1, rendering WxH ($3) to out.png.
write_scene() {
    local dir=$1 mesh=$2 size=$3
    cat >"$dir/scene.lua" <<EOF
root = gr.node('root')
local m = gr.mesh('m', '$mesh')
m:set_material(gr.material({0.7, 0.7, 0.7}, {0, 0, 0}, 10))
root:add_child(m)
gr.render(root, 'out.png', ${size%x*}, ${size#*x}, {0, 0, 3}, {0, 0, -1}, {0, 1, 0}, 50,
          {0.3, 0.3, 0.3}, {gr.light({1, 1, 3}, {1, 1, 1}, {1, 0, 0})})
EOF
}

# A flat grid of N×N quads (2N² triangles) as OBJ text.
grid_obj() {
    awk -v n="$1" 'BEGIN {
        for (j = 0; j <= n; j++) for (i = 0; i <= n; i++) printf "v %g %g 0\n", i / n - 0.5, j / n - 0.5
        for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
            a = j * (n + 1) + i + 1
            printf "f %d %d %d\nf %d %d %d\n", a, a + 1, a + n + 2, a, a + n + 2, a + n + 1
        } }'
}

# expect_refusal NAME TEXT MAX_PEAK_KIB: check the run that just ended in $work (exit code in
# $rc, peak RSS in KiB in $work/peak).
expect_refusal() {
    local name=$1 text=$2 maxPeak=$3
    local problems=""
    [ "$rc" -eq 1 ] || problems+=" exit code $rc, expected 1;"
    grep -q -- "$text" "$work/stderr" || problems+=" stderr lacks '$text': $(head -c 300 "$work/stderr");"
    local peak
    peak=$(tail -n 1 "$work/peak" 2>/dev/null)
    # Under the sanitizers (make test-sanitize sets RB_SANITIZE=1) the peak is not checked:
    # AddressSanitizer's shadow memory and its quarantine of freed blocks (256 MiB) add several
    # hundred MiB that rt does not control. The refusals themselves are still checked.
    [ "${RB_SANITIZE:-0}" = 1 ] && maxPeak=""
    if [ -n "$maxPeak" ] && { [ -z "$peak" ] || [ "$peak" -gt "$maxPeak" ]; }; then
        problems+=" peak memory ${peak:-unknown} KiB, expected at most $maxPeak KiB;"
    fi
    leftovers=$(find "$work" -maxdepth 1 \( -name '*.png' -o -name '*.hdr' -o -name '*.tmp*' \) |
        tr '\n' ' ')
    [ -z "$leftovers" ] || problems+=" left behind: $leftovers;"
    if [ -n "$problems" ]; then fail "$name" "${problems%;}"; else ok "$name"; fi
}

# run_rt DIR ARGS...: run rt in DIR under a 60 s timeout, recording its peak RSS.
run_rt() {
    local dir=$1
    shift
    (cd "$dir" && exec /usr/bin/time -o peak -f %M timeout 60 "$RT" --quiet "$@") 2>"$dir/stderr"
    rc=$?
}

echo "== memory: --max-memory"

# A 2-million-triangle grid needs about 600 MiB to load; 64 MiB refuses it while reading.
work="$OUT/mesh-over-limit"
rm -rf "$work" && mkdir -p "$work"
grid_obj 1000 >"$work/grid.obj"
write_scene "$work" grid.obj 32x32
run_rt "$work" --max-memory 64M scene.lua
rm -f "$work/grid.obj"
expect_refusal mesh-over-limit "scene.lua:2: grid.obj:[0-9]*: the mesh read so far (.* triangles, .* vertices) with its BVH needs about .* MiB, but only .* of the memory limit of 64.0 MiB (--max-memory 64M)" 200000

# 50 million faces through a named pipe: refused after about a million, long before the end.
work="$OUT/fifty-million-faces"
rm -rf "$work" && mkdir -p "$work"
mkfifo "$work/huge.obj"
write_scene "$work" huge.obj 32x32
awk 'BEGIN { print "v 0 0 0"; print "v 1 0 0"; print "v 0 1 0"
             for (i = 0; i < 50000000; i++) print "f 1 2 3" }' >"$work/huge.obj" 2>/dev/null &
writer=$!
run_rt "$work" --max-memory 256M scene.lua
kill "$writer" 2>/dev/null
wait "$writer" 2>/dev/null
rm -f "$work/huge.obj"
expect_refusal fifty-million-faces "huge.obj:[0-9]*: the mesh read so far (1048576 triangles, 3 vertices)" 300000

# An image of 8000×8000 needs about 1.4 GiB for its film and PNG encoding.
work="$OUT/image-over-limit"
rm -rf "$work" && mkdir -p "$work"
grid_obj 2 >"$work/small.obj"
write_scene "$work" small.obj 8000x8000
run_rt "$work" --max-memory 512M scene.lua
expect_refusal image-over-limit "scene.lua:5: the image of 8000x8000 pixels needs about 1.4 GiB, but only .* of the memory limit of 512 MiB (--max-memory 512M)" 100000

# The same scene renders when the limit allows it (at a size that takes no time).
run_rt "$work" --max-memory 512M --size 64x64 scene.lua
if [ "$rc" -eq 0 ] && [ -s "$work/out.png" ]; then ok image-within-limit; else
    fail image-within-limit "exit code $rc: $(head -c 300 "$work/stderr")"; fi
rm -f "$work/out.png"

# A script's own allocations count against the limit too.
work="$OUT/script-over-limit"
rm -rf "$work" && mkdir -p "$work"
printf 'local t = {}\nfor i = 1, 1e8 do t[i] = {i} end\n' >"$work/scene.lua"
run_rt "$work" --max-memory 64M scene.lua
expect_refusal script-over-limit "scene.lua: the scene script exceeded the memory limit of .* MiB for scripts (.*--max-memory 64M)" 200000

# An 8192×8192 texture, an 8-bit PNG of under 1 MiB (a checker of 64-texel squares): its
# decoded size is checked against the limit, from the header, before anything is decoded; and
# within the limit its texels are kept as the file's sRGB bytes, 3 per texel (float texels
# alone took 12, and the load peaked at 965 MiB). Decoding adds stb's inflated rows (3 bytes a
# texel more) and a few MiB: 8 bytes a texel (512 MiB) is a bound the 8-bit store meets (it
# measured 389 MiB) and float texels cannot.
work="$OUT/texture-over-limit"
rm -rf "$work" && mkdir -p "$work/textures"  # the texture beside, not among, the outputs
python3 - "$work/textures/big.png" <<'PY'
import struct, sys, zlib
n = 8192
rows = [bytes([0]) + (b'\xc8\x32\x32' * 64 + b'\x32\x32\xc8' * 64) * (n // 128),
        bytes([0]) + (b'\x32\x32\xc8' * 64 + b'\xc8\x32\x32' * 64) * (n // 128)]
data = zlib.compress(b''.join(rows[(y // 64) % 2] for y in range(n)), 9)
chunk = lambda t, d: struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d))
header = struct.pack('>IIBBBBB', n, n, 8, 2, 0, 0, 0)
open(sys.argv[1], 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', header) +
                              chunk(b'IDAT', data) + chunk(b'IEND', b''))
PY
cat >"$work/scene.lua" <<'EOF'
root = gr.node('root')
local m = gr.material({1, 1, 1}, {0, 0, 0}, 1)
m:set_texture('kd', 'textures/big.png')
local s = gr.sphere('s')
s:set_material(m)
root:add_child(s)
gr.render(root, 'out.png', 32, 24, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.3, 0.3, 0.3},
          {gr.light({5, 5, 5}, {1, 1, 1}, {1, 0, 0})})
EOF
if "$RT" --list-features | grep -q texture; then
    run_rt "$work" --max-memory 512M scene.lua
    expect_refusal texture-over-limit "scene.lua:3: material:set_texture: textures/big.png: the 8192x8192 texture image needs about 1.0 GiB, but only .* of the memory limit of 512 MiB (--max-memory 512M)" 100000
    run_rt "$work" --max-memory 2G scene.lua
    peak=$(tail -n 1 "$work/peak" 2>/dev/null)
    if [ "$rc" -ne 0 ] || [ ! -s "$work/out.png" ]; then
        fail texture-within-limit "exit code $rc: $(head -c 300 "$work/stderr")"
    elif [ "${RB_SANITIZE:-0}" != 1 ] && [ "${peak:-999999999}" -gt 524288 ]; then
        fail texture-within-limit "peak memory ${peak:-unknown} KiB, expected at most 524288 KiB (8 bytes a texel)"
    else
        ok "texture-within-limit (peak ${peak:-unchecked} KiB)"
    fi
    rm -f "$work/out.png" "$work/textures/big.png"
fi

# A size rt cannot read.
work="$OUT/bad-size"
rm -rf "$work" && mkdir -p "$work"
run_rt "$work" --max-memory 12Q scene.lua
expect_refusal bad-size "--max-memory: expected a size of at least 1M, such as 512M or 4G" ""

echo "== output: a full disk and a read-only folder"

# With a 1 KiB file-size limit the PNG (about 3.7 KiB) cannot be written.
work="$OUT/full-disk"
rm -rf "$work" && mkdir -p "$work"
grid_obj 20 >"$work/small.obj"
write_scene "$work" small.obj 256x256
(ulimit -f 1 && run_rt "$work" scene.lua && exit "$rc")
rc=$?
expect_refusal full-disk "scene.lua:5: out.png: cannot write the PNG file (File too large)" ""

# Chapter 12's Radiance HDR output goes through the same atomic writer (the RGBE film is far
# over 1 KiB too).
if "$RT" --list-features | grep -q tone_map; then
    (ulimit -f 1 && run_rt "$work" --output out.hdr scene.lua && exit "$rc")
    rc=$?
    expect_refusal full-disk-hdr \
        "scene.lua:5: out.hdr: cannot write the Radiance HDR file (File too large)" ""
    # The local tone map's buffers (73 B per pixel) count against the budget before the render:
    # 2000 x 2000 pixels fit in 200M as a plain image (96 MB) but not with them (388 MB).
    run_rt "$work" --max-memory 200M --size 2000x2000 --tone-map=local scene.lua
    expect_refusal tone-map-memory "2000x2000 pixels and its tone map needs about" 100000
fi

# A real full disk, where the machine allows it: a 16 KiB tmpfs, filled to within 1 KiB and
# mounted as the output folder in a private mount namespace (unshare -m, which needs root or user
# namespaces). What is left on it is listed before the namespace, and the tmpfs, go away.
work="$OUT/no-space"
rm -rf "$work" && mkdir -p "$work/disk"
grid_obj 20 >"$work/small.obj"
write_scene "$work" small.obj 256x256
sed -i "s#'out.png'#'disk/out.png'#" "$work/scene.lua"
if unshare -m sh -c "mount -t tmpfs -o size=16k tmpfs '$work/disk'" 2>/dev/null; then
    (cd "$work" && exec unshare -m bash -c '
        mount -t tmpfs -o size=16k tmpfs disk || exit 99
        dd if=/dev/zero of=disk/filler bs=1k count=15 2>/dev/null
        /usr/bin/time -o peak -f %M "$0" --quiet scene.lua
        rc=$?
        ls -A disk >listing
        exit $rc' "$RT") 2>"$work/stderr"
    rc=$?
    expect_refusal no-space "scene.lua:5: disk/out.png: cannot write the PNG file (No space left on device)" ""
    [ "$(cat "$work/listing")" = filler ] && ok no-space-disk-left-as-it-was ||
        fail no-space-disk-left-as-it-was "the disk held: $(tr '\n' ' ' <"$work/listing")"
else
    echo "skip no-space: this machine cannot mount a tmpfs in a private mount namespace"
fi

# A folder nobody may write to. Root may write anywhere, so as root rt runs as user nobody
# (setpriv), from a copy of the binary in a folder nobody can read.
work="$OUT/read-only"
rm -rf "$work" && mkdir -p "$work/ro"
cp "$RT" "$work/rt"
grid_obj 2 >"$work/small.obj"
write_scene "$work" small.obj 16x16
sed -i "s#'out.png'#'ro/out.png'#" "$work/scene.lua"
chmod 755 "$work" && chmod 644 "$work"/*.obj "$work/scene.lua" && chmod 555 "$work/ro"
if [ "$(id -u)" = 0 ]; then
    as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups)
else
    as_user=()
fi
chmod 777 "$work"  # the unprivileged rt writes its stderr and peak files here
(cd "$work" && exec /usr/bin/time -o peak -f %M "${as_user[@]}" ./rt --quiet scene.lua) 2>"$work/stderr"
rc=$?
expect_refusal read-only "scene.lua:5: ro/out.png: cannot write the PNG file (Permission denied)" ""
[ -z "$(ls -A "$work/ro")" ] && ok read-only-folder-left-empty ||
    fail read-only-folder-left-empty "found: $(ls -A "$work/ro")"

finish
