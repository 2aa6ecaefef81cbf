#!/usr/bin/env python3
"""Ranks that die at random, repeatedly, lose nothing.

The showcase (common.sh's cheap options, one thread a rank) renders under `mpirun -np 3`; a
random rank (rank 0 included) gets SIGKILL at a random moment: once the journal has grown by a
random number of tiles since the run began (0: as soon as the rank's process exists, often
before it has loaded the scene). Then `--resume` on a random number of ranks (1 to 3), killed
again, until KILLS kills have landed; the last resume runs to the end. Checked:

- the image is byte-identical to one process's render, and the journal is gone;
- no tile is lost: after each kill the journal holds every tile it held before the run (the
  tiles carried over are rewritten first, atomically), and the next --resume says it reused
  exactly the tiles the journal holds;
- no finished tile is rendered again: every journal holds each tile once (a carried-over tile
  rendered again would be journaled twice), and the last run renders exactly the tiles the
  journal did not hold (its --stats tile count). Only tiles in flight at a kill, rendered but
  not yet journaled, are rendered again, and those the kills explain.

The randomness comes from one seed, printed first, so a failure replays with --seed.
Usage: chaos.py RT_BINARY OUT_DIR [--kills N] [--size WxH] [--seed S]
(make test: 3 kills at 64x48; full size: --kills 12 --size 128x96.)
"""
import argparse
import os
import random
import re
import shutil
import signal
import struct
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SHOWCASE = ROOT / "scenes" / "showcase.lua"
# common.sh's SHOWCASE_OPTIONS: every chapter's sampling on, but cheap.
OPTIONS = ["--quiet", "--preview", "--aa=jittered", "--light-samples=2", "--glossy-samples=2",
           "--dof-samples=4", "--photon-passes=2", "--photons=20000", "--threads", "1"]
MPIRUN = ["mpirun", "-q", "--oversubscribe"]
TIMEOUT = 120  # seconds one mpirun may take before the test gives up on it

checks = {"passed": 0, "failed": 0}


def ok(what):
    print(f"ok   {what}", flush=True)
    checks["passed"] += 1


def fail(what, why):
    print(f"FAIL {what}: {why}", flush=True)
    checks["failed"] += 1


def journal_positions(path):
    """The tile positions of the whole records of the journal at `path` (journal.h's format:
    a text header ending in an empty line, then TILE, position, float count, floats, checksum),
    in the order written; none when there is no journal."""
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        return []
    end = data.find(b"\n\n")
    if not data.startswith(b"raybook tile journal") or end < 0:
        return []
    positions, at = [], end + 2
    while len(data) - at >= 12 and data[at:at + 4] == b"TILE":
        position, count = struct.unpack_from("<iI", data, at + 4)
        size = 12 + 4 * count + 8
        if len(data) - at < size:
            break
        positions.append(position)
        at += size
    return positions


def rank_pid(mpirun, rank):
    """The pid of rank `rank` of the job started by the process `mpirun`, or None yet."""
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
            ppid = int(stat[stat.rindex(")") + 2:].split()[1])
            if ppid != mpirun:
                continue
            env = (entry / "environ").read_bytes().split(b"\0")
        except (OSError, ValueError):
            continue
        if f"OMPI_COMM_WORLD_RANK={rank}".encode() in env:
            return int(entry.name)
    return None


def run_and_kill(command, log, journal, victim, growth):
    """Run `command` (an mpirun) with stderr to `log`. With a victim, SIGKILL that rank once
    the journal holds `growth` more tiles than when the run began. Returns (exit code, killed)."""
    start = len(journal_positions(journal))
    with open(log, "wb") as err:
        job = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=err)
    killed = False
    deadline = time.monotonic() + TIMEOUT
    while victim is not None and job.poll() is None and time.monotonic() < deadline:
        if len(journal_positions(journal)) - start >= growth:
            pid = rank_pid(job.pid, victim)
            if pid is not None:
                try:
                    os.kill(pid, signal.SIGKILL)
                    killed = True
                    break
                except ProcessLookupError:
                    pass
        time.sleep(0.005)
    try:
        return job.wait(timeout=max(1.0, deadline - time.monotonic())), killed
    except subprocess.TimeoutExpired:
        job.kill()
        job.wait()
        return None, killed


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("rt")
    parser.add_argument("out")
    parser.add_argument("--kills", type=int, default=3)
    parser.add_argument("--size", default="64x48")
    parser.add_argument("--seed", type=int, default=None)
    args = parser.parse_args()
    rt = str(Path(args.rt).resolve())
    out = Path(args.out).resolve()
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    if shutil.which("mpirun") is None:
        fail("mpirun", "not found (make mpi installs Open MPI)")
        return 1
    seed = args.seed if args.seed is not None else int.from_bytes(os.urandom(4), "little")
    print(f"chaos: seed {seed}; replay with: python3 {sys.argv[0]} {args.rt} {args.out} "
          f"--kills {args.kills} --size {args.size} --seed {seed}", flush=True)
    rng = random.Random(seed)
    width, height = (int(v) for v in args.size.split("x"))
    tiles = ((width + 15) // 16) * ((height + 15) // 16)
    render = OPTIONS + ["--size", args.size, str(SHOWCASE)]

    reference = out / "reference.png"
    if subprocess.run([rt] + render + ["--output", str(reference)]).returncode != 0:
        fail("reference", "rt alone failed")
        return 1
    image = out / "chaos.png"
    journal = Path(str(image) + ".journal")

    kills, runs, carried, lost, ranks = 0, 0, 0, 0, 3
    held = []  # the journal's tiles before this run
    while runs < args.kills + 10:
        runs += 1
        victim = growth = None
        if kills < args.kills:
            victim = rng.randrange(ranks)
            # At most an even share of what is left per kill still to come, so every kill
            # lands before the image is done.
            share = (tiles - len(held)) // (args.kills - kills + 1)
            growth = rng.randint(0, max(0, share))
        log = out / f"run{runs}.txt"
        command = MPIRUN + ["-np", str(ranks), rt] + render + ["--stats", "--output", str(image)]
        if runs > 1:
            command.append("--resume")
        code, killed = run_and_kill(command, log, journal, victim, growth)
        text = log.read_text(errors="replace")
        reused = re.search(r"--resume: reused (\d+) of (\d+) tiles", text)
        if runs > 1 and held and (not reused or int(reused.group(1)) != len(held)):
            fail(f"run {runs}", f"the journal held {len(held)} tiles, rt said: "
                 f"{reused.group(0) if reused else 'nothing about reusing'}")
        if reused:
            carried += int(reused.group(1))
        what = (f"run {runs}: {ranks} ranks, {len(held)} tiles carried over, "
                + (f"rank {victim} killed after {growth} more" if killed else "not killed"))
        if code is None:
            fail(what, f"mpirun still running after {TIMEOUT} s")
            return 1
        if killed and image.exists():
            # The kill landed after rank 0 wrote the image: done, with one kill fewer.
            if reference.read_bytes() != image.read_bytes():
                fail(what, "the image differs from one process's render")
            else:
                ok(f"{what}: the image was written before the kill landed, byte-identical")
            break
        if killed:
            kills += 1
            now = journal_positions(journal)
            if len(set(now)) != len(now):
                fail(what, f"the journal holds a tile twice: {sorted(now)}")
            missing = set(held) - set(now)
            lost += len(missing)
            if missing:
                fail(what, f"tiles lost: {sorted(missing)}")
            else:
                ok(f"{what}: the journal holds {len(now)} of {tiles}")
            held = now
        elif code != 0 or not image.exists():
            fail(what, f"exit {code}, no image: {text.strip()}")
            return 1
        else:
            rendered = sum(int(n) for n in re.search(r"tiles per rank((?: \d+)+)", text)
                           .group(1).split())
            if rendered != tiles - len(held):
                fail(what, f"rendered {rendered} tiles, expected the {tiles - len(held)} "
                     "the journal did not hold")
            elif reference.read_bytes() != image.read_bytes():
                fail(what, "the image differs from one process's render")
            elif journal.exists():
                fail(what, "the journal is still there after the image")
            else:
                ok(f"{what}: rendered the other {rendered} of {tiles}, byte-identical to one "
                   "process, journal gone")
            break
        ranks = rng.randint(1, 3)
    if kills < args.kills:
        fail("kills", f"only {kills} of {args.kills} landed before the image was done")
    print(f"chaos: seed {seed}: {kills} kills survived in {runs} runs, {carried} tiles carried "
          f"over by --resume, {lost} tiles lost", flush=True)
    print(f"{checks['passed']} passed, {checks['failed']} failed")
    return 1 if checks["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
