#!/usr/bin/env python3
"""What the job says when it ends early under mpirun (src/mpi/job_end.h).

The showcase at 256x160 (160 tiles, so that under load the signal lands long before the end;
128x80 under the sanitizers, SHRINK) renders on 3 ranks; once its journal holds a few tiles:
- Ctrl-C to mpirun (SIGINT), with --partial: mpirun exits 1; rank 0 says, once, that mpirun
  stopped the job and how many tiles the journal holds (its whole records), with the command
  that resumes; the partial image holds exactly those tiles;
- SIGTERM to mpirun: the same line, and no partial image without --partial; --resume then says
  it reused that many tiles and finishes the image byte-identical to one process's;
- SIGKILL to rank 2, then to rank 0: one line naming the lost rank and its pid, and what the
  journal holds (rank 0 gone, rank 1 says it);
- --time-limit with --partial: the time limit's line names the journal and its tiles, and the
  partial image holds them; and again on tiles that take minutes, which stop inside the tile,
  leaving no half-done tile in the journal.
Usage: job_end.py RT_BINARY OUT_DIR
"""
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from mpi_helpers import (MPIRUN, OPTIONS, SHOWCASE, SHRINK, fail, finish, journal_positions, ok,
                         rank_pid, setup, start, wait, when_journal_grows)
from png_read import read_png

WIDTH, HEIGHT = 256 // SHRINK, 160 // SHRINK
SIZE = f"{WIDTH}x{HEIGHT}"
TILES = (WIDTH // 16) * (HEIGHT // 16)


def lit_tiles(path):
    """The 16x16 tiles of the PNG at `path` with any colour (a partial image's rendered ones)."""
    width, height, _, rows = read_png(str(path))
    return sum(1 for ty in range(0, height, 16) for tx in range(0, width, 16)
               if any(rows[y][3 * tx:3 * min(tx + 16, width)].strip(b"\0")
                      for y in range(ty, min(ty + 16, height))))


def stop_case(name, rt, out, extra, act, expect_code, expect_line):
    """Render on 3 ranks with `extra` options, call act(job) once the journal holds 3 tiles,
    and check the exit code and that stderr's only end line matches `expect_line` (a regex
    where {held} is the journal's tile count and {pid} what act returned). Returns the image,
    the journal's tile count and stderr, or None."""
    image = out / f"{name}.png"
    journal = Path(f"{image}.journal")
    log = out / f"{name}.txt"
    job = start(MPIRUN + ["-np", "3", rt] + OPTIONS + ["--size", SIZE, "--output", str(image)]
                + extra + [str(SHOWCASE)], log)
    acted = {}
    if not when_journal_grows(job, journal, 3, lambda: acted.setdefault("pid", act(job))):
        wait(job)
        fail(name, "the render ended before the journal held 3 tiles")
        return None
    code = wait(job)
    text = log.read_text(errors="replace")
    held = len(journal_positions(journal))
    lines = [line for line in text.splitlines()
             if line.startswith("rt:") and "wrote the" not in line]
    pattern = expect_line.format(held=held, tiles=TILES, pid=acted["pid"])
    if code != expect_code:
        fail(name, f"mpirun exit {code}, expected {expect_code}: {text.strip()}")
    elif len(lines) != 1 or not re.search(pattern, lines[0]):
        fail(name, f"expected one line matching {pattern!r}, got: {text.strip()}")
    elif image.exists():
        fail(name, "an image was written")
    else:
        ok(f"{name}: exit {code}, one line: {lines[0][:150]}...")
        return image, held, text
    return None


def check_partial(name, image, held, text, tiles=TILES):
    """The partial image beside `image` holds the `held` tiles (of `tiles`) of the journal."""
    partial = image.with_suffix(".partial.png")
    said = re.search(r"wrote the (\d+) of (\d+) tiles rendered so far to (\S+)", text)
    if not said or int(said.group(1)) != held or said.group(3) != str(partial):
        fail(f"{name} --partial", f"expected 'wrote the {held} of {tiles} tiles ...': {text}")
    elif (lit := lit_tiles(partial)) != held:
        fail(f"{name} --partial", f"{lit} tiles have colour, the journal holds {held}")
    else:
        ok(f"{name} --partial: {partial.name} holds the journal's {held} of {tiles} tiles")


def main():
    rt, out = str(Path(sys.argv[1]).resolve()), Path(sys.argv[2]).resolve()
    if not setup(out):
        return 1
    to_mpirun = lambda sig: lambda job: os.kill(job.pid, sig) or job.pid

    def kill_rank(rank):
        def act(job):
            pid = rank_pid(job.pid, rank)
            if pid:
                os.kill(pid, signal.SIGKILL)
            return pid
        return act

    stopped = (r"^rt: stopped by mpirun \(Ctrl-C or SIGTERM\); the journal \S+ holds {held} of "
               r"{tiles} tiles, and `mpirun -np 3 .* --resume` renders the rest")
    # Ctrl-C reaches mpirun, which sends SIGTERM to every rank (and SIGKILL a second later).
    if done := stop_case("ctrl-c", rt, out, ["--partial"], to_mpirun(signal.SIGINT), 1, stopped):
        check_partial("ctrl-c", *done)
    if done := stop_case("sigterm", rt, out, [], to_mpirun(signal.SIGTERM), 1, stopped):
        image, held, _ = done
        if image.with_suffix(".partial.png").exists():
            fail("sigterm", "a partial image was written without --partial")
        reference = out / "reference.png"
        subprocess.run([rt] + OPTIONS + ["--size", SIZE, "--output", str(reference),
                                         str(SHOWCASE)], check=True)
        resumed = subprocess.run(MPIRUN + ["-np", "2", rt] + OPTIONS +
                                 ["--size", SIZE, "--output", str(image), "--resume",
                                  str(SHOWCASE)], stderr=subprocess.PIPE, text=True)
        if f"--resume: reused {held} of {TILES} tiles" not in resumed.stderr:
            fail("sigterm --resume", f"expected 'reused {held} of {TILES}': {resumed.stderr}")
        elif reference.read_bytes() != image.read_bytes():
            fail("sigterm --resume", "the image differs from one process's")
        else:
            ok(f"sigterm --resume reused the journal's {held} tiles: byte-identical")
    lost = (r"^rt: rank {rank} \(pid {pid}\) was lost, and mpirun ended the job; the journal \S+ "
            r"holds {held} of {tiles} tiles, and `mpirun -np 3 .* --resume` renders the rest")
    for rank in (2, 0):
        # Killed by this test, the rank's exit is mpirun's: 137 (128 + SIGKILL).
        stop_case(f"rank-{rank}-lost", rt, out, [], kill_rank(rank), 137,
                  lost.replace("{rank}", str(rank)))
    # --time-limit: every rank finishes its leases, then rank 0 says what the journal holds.
    # 512 x 384 (768 tiles) takes about 7 s on 2 ranks, well past the limit; at 256 x 192 the
    # render took 1.9 s once the ground plane left the top-level tree, and finished first.
    image = out / "time-limit.png"
    limited = subprocess.run(MPIRUN + ["-np", "2", rt] + OPTIONS +
                             ["--size", "512x384", "--time-limit", "2", "--partial",
                              "--output", str(image), str(SHOWCASE)],
                             stderr=subprocess.PIPE, text=True)
    held = len(journal_positions(f"{image}.journal"))
    if limited.returncode != 124 or not re.search(
            rf"^rt: stopped after the time limit of 2 s \(--time-limit\), without writing an "
            rf"image; the journal \S+ holds {held} of 768 tiles", limited.stderr, re.M):
        fail("time limit", f"exit {limited.returncode}: {limited.stderr}")
    else:
        ok(f"time limit: exit 124, the journal's {held} of 768 tiles named")
        check_partial("time limit", image, held, limited.stderr, 768)
    # --time-limit inside a tile: six tiles of 65,536 samples a pixel under 64 lights take
    # minutes each, and every rank gives up its tile after the pixel it is on (PixelStop), so
    # the job stops within seconds, and no half-done tile reaches the journal or the partial
    # image. Before the pixels asked, each rank finished its tile first.
    scene = out / "one-slow-tile.lua"
    scene.write_text(SLOW_TILES)
    image = out / "time-limit-in-a-tile.png"
    started = time.monotonic()
    limited = subprocess.run(MPIRUN + ["-np", "3", rt, "--quiet", "--threads", "1",
                                       "--time-limit", "1", "--partial", "--spp", "65536",
                              "--output", str(image), str(scene)],
                             stderr=subprocess.PIPE, text=True, timeout=600)
    took = time.monotonic() - started
    held = len(journal_positions(f"{image}.journal"))
    if limited.returncode != 124 or took > 30 or held != 0 or not re.search(
            r"^rt: stopped after the time limit of 1 s \(--time-limit\), without writing an "
            r"image; the journal \S+ holds 0 of 6 tiles", limited.stderr, re.M):
        fail("time limit in a tile",
             f"exit {limited.returncode} after {took:.0f} s, {held} tiles journaled: "
             f"{limited.stderr}")
    else:
        ok(f"time limit in a tile: exit 124 after {took:.1f} s, no half-done tile journaled")
        check_partial("time limit in a tile", image, 0, limited.stderr, 6)
    return finish()


# Six 16x16 tiles whose pixels take ~0.1 s each at --spp 65536 (a sphere around the camera, 64
# lights).
SLOW_TILES = """local root = gr.node('root')
local s = gr.sphere('s')
s:scale(100, 100, 100)
s:set_material(gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 10))
root:add_child(s)
local lights = {}
for i = 1, 64 do lights[i] = gr.light({0, 0, i}, {0.01, 0.01, 0.01}, {1, 0, 0}) end
gr.render(root, 'slow.png', 48, 32, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, {0.5, 0.5, 0.5}, lights)
"""


if __name__ == "__main__":
    sys.exit(main())
