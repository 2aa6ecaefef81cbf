#!/usr/bin/env python3
"""A tile that fails on one rank never gives a wrong image (issue 40).

rt_fault is rt with a fault hook (tests/mpi/CMakeLists.txt; injectFault in
src/mpi/mpi_cluster.cpp): RB_FAULT=rank:R,tile:K,kind:throw|hang makes tile K throw, or never
finish, on rank R. The showcase at 64x48 (12 tiles, leased one at a time to 3 ranks of one
thread: rank 1's first leases are tiles 0-2, rank 2's tiles 3-5, so both faults below are sure
to fire) renders on 3 ranks:
- kind:throw on rank 2: mpirun exits 1, with one line naming the rank, its host and pid, the
  tile and its pixels, the fault, what the journal holds and the command that resumes; no image;
- kind:hang on rank 1, with --tile-timeout 2 (15 under the sanitizers) and --partial: rank 0
  sees the lease overdue and stops the job: exit 1, one line naming the rank, its pid and the
  tile, the journal and the resume command; no image, and the partial image holds exactly the
  journal's tiles;
- kind:hang on rank 0 itself (its first lease is tile 6), with the same --tile-timeout and
  --partial:
  rank 0's watcher sees its own lease overdue and says so in the same words, and the job ends
  as above (exit 1, one line, no image, the partial image holds the journal's tiles);
- after each, --resume without the fault says it reused the journal's tiles and writes the
  bytes of one process's render (rt_fault resumes: its journal names rt's version and commit,
  which rt_fault's own are sure to match even when only one of the two was rebuilt);
- rt itself has no hook: under RB_FAULT it renders the image, the same bytes.
Usage: fault.py RT_BINARY RT_FAULT_BINARY OUT_DIR
"""
import os
import re
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from job_end import check_partial
from mpi_helpers import MPIRUN, OPTIONS, SHOWCASE, fail, finish, journal_positions, ok, setup

SIZE = "64x48"
TILES = 12
RENDER = OPTIONS + ["--size", SIZE]
# A tile's name in rt's message: its position, then first..last column x first..last row.
TILE = r"tile {k} \(pixels (\d+)\.\.(\d+) x (\d+)\.\.(\d+)\)"
LIMIT = 60  # seconds a run may take (each takes a few here)
# --tile-timeout for the hang cases: 2 s, or 15 s under the sanitizers (RB_SANITIZE), where a
# rank's honest tile on a busy machine once took over 2 s, and rank 0 took its own slow tile
# for a hang before the injected one was due. A hang never ends, so either limit catches it.
HANG_LIMIT = 15 if os.environ.get("RB_SANITIZE") == "1" else 2


def run(command, fault=None):
    """Run `command` with RB_FAULT set to `fault` (or unset); (exit code, stderr, seconds). The
    exit code is None when it still ran after LIMIT seconds (a hang not seen): then mpirun gets
    SIGTERM, which ends the job as Ctrl-C does."""
    env = dict(os.environ)
    env.pop("RB_FAULT", None)
    if fault:
        env["RB_FAULT"] = fault
    begin = time.monotonic()
    job = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                           env=env)
    try:
        _, text = job.communicate(timeout=LIMIT)
        code = job.returncode
    except subprocess.TimeoutExpired:
        job.terminate()
        _, text = job.communicate()
        code = None
    return code, text, time.monotonic() - begin


def tile_is_real(match):
    """True when the pixels a message gave are one 16x16 tile of the 64x48 film."""
    x0, x1, y0, y1 = (int(g) for g in match.groups()[-4:])
    return (x0 % 16 == 0 and y0 % 16 == 0 and x1 == x0 + 15 and y1 == y0 + 15 and x1 < 64
            and y1 < 48)


def fault_case(name, rt_fault, out, fault, extra, expect):
    """Render on 3 ranks under RB_FAULT=`fault` with `extra` options; check exit 1, one end
    line matching `expect` (a regex; {held} is the journal's tile count), that a real tile is
    named, and that no image was written. Returns (image, journal tiles, stderr) or None."""
    image = out / f"{name}.png"
    code, text, seconds = run(MPIRUN + ["-np", "3", rt_fault] + RENDER + extra +
                              ["--output", str(image), str(SHOWCASE)], fault)
    held = journal_positions(f"{image}.journal")
    lines = [line for line in text.splitlines()
             if line.startswith("rt:") and "wrote the" not in line]
    pattern = expect.format(held=len(held), tiles=TILES)
    said = re.search(pattern, lines[0]) if len(lines) == 1 else None
    if code != 1:
        fail(name, f"mpirun exit {code}, expected 1: {text.strip()}")
    elif not said:
        fail(name, f"expected one line matching {pattern!r}, got: {text.strip()}")
    elif not tile_is_real(said):
        fail(name, f"the pixels named are no tile of the film: {said.group(0)}")
    elif image.exists():
        fail(name, "an image was written")
    else:
        ok(f"{name}: exit 1 in {seconds:.1f} s, one line: {lines[0][:170]}...")
        return image, held, text
    return None


def resume_case(name, rt, image, held, reference):
    """--resume with `rt`, RB_FAULT unset, reuses the journal's tiles and gives the reference's
    bytes."""
    code, text, seconds = run(MPIRUN + ["-np", "3", rt] + RENDER +
                              ["--output", str(image), "--resume", str(SHOWCASE)])
    if code != 0 or f"--resume: reused {len(held)} of {TILES} tiles" not in text:
        fail(f"{name} --resume", f"exit {code}, expected 'reused {len(held)} of {TILES}': {text}")
    elif reference.read_bytes() != image.read_bytes():
        fail(f"{name} --resume", "the image differs from one process's")
    else:
        ok(f"{name} --resume reused the journal's {len(held)} tiles in {seconds:.1f} s: "
           "byte-identical to one process")


def main():
    rt, rt_fault = (str(Path(a).resolve()) for a in sys.argv[1:3])
    out = Path(sys.argv[3]).resolve()
    if not setup(out):
        return 1
    reference = out / "reference.png"
    subprocess.run([rt] + RENDER + ["--output", str(reference), str(SHOWCASE)], check=True)

    # rt has no fault hook: RB_FAULT changes nothing.
    plain = out / "plain.png"
    code, text, _ = run(MPIRUN + ["-np", "3", rt] + RENDER + ["--output", str(plain),
                                                              str(SHOWCASE)],
                        "rank:2,tile:4,kind:throw")
    if code != 0 or reference.read_bytes() != plain.read_bytes():
        fail("rt ignores RB_FAULT", f"exit {code}, or other bytes: {text}")
    else:
        ok("rt ignores RB_FAULT (no hook outside rt_fault): byte-identical to one process")

    resume = (r"the journal \S+ holds {held} of {tiles} tiles, and `mpirun -np 3 .* --resume` "
              r"renders")
    # A tile that throws: the failing rank says so, at the agreement that ends the render.
    thrown = (r"^rt: error: rank 2 \(host \S+, pid \d+\) failed on " + TILE.format(k=4) +
              r": injected fault \(RB_FAULT=rank:2,tile:4,kind:throw\); " + resume)
    if done := fault_case("throw", rt_fault, out, "rank:2,tile:4,kind:throw", [], thrown):
        image, held, _ = done
        if 4 in held:
            fail("throw", f"the failed tile 4 is in the journal: {held}")
        resume_case("throw", rt_fault, image, held, reference)
    # A tile that never finishes: rank 0 stops the job once the lease is HANG_LIMIT s overdue. On a
    # worker, rank 0's main thread sees it; on rank 0 itself, its watcher thread does (the main
    # thread, the one that may call MPI, is the hung one).
    for name, rank, tile, verb in (("hang", 1, 1, "has returned nothing"),
                                   ("hang0", 0, 6, "has finished nothing")):
        hung = (rf"^rt: rank {rank} \(host \S+, pid \d+\) {verb} for over {HANG_LIMIT} s "
                r"\(--tile-timeout\) while rendering " + TILE.format(k=tile) +
                r", so the job stops without writing an image; " + resume)
        if done := fault_case(name, rt_fault, out, f"rank:{rank},tile:{tile},kind:hang",
                              ["--tile-timeout", str(HANG_LIMIT), "--partial"], hung):
            image, held, text = done
            check_partial(name, image, len(held), text, TILES)
            resume_case(name, rt_fault, image, held, reference)
    return finish()


if __name__ == "__main__":
    sys.exit(main())
