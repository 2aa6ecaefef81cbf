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
(make test: 3 kills at 64x48; full size: --kills 12 --size 192x128.)
"""
import argparse
import os
import random
import re
import signal
import subprocess
import sys
from pathlib import Path

from mpi_helpers import (MPIRUN, OPTIONS, SHOWCASE, fail, finish, journal_positions, ok,
                         rank_pid, setup, start, wait, when_journal_grows)


def run_and_kill(command, log, journal, victim, growth):
    """Run `command` (an mpirun) with stderr to `log`. With a victim, SIGKILL that rank once
    the journal holds `growth` more tiles than when the run began. Returns (exit code, pid
    killed or None)."""
    job = start(command, log)
    killed = None

    def kill_victim():
        nonlocal killed
        pid = rank_pid(job.pid, victim)
        if pid is None:
            return False
        try:
            os.kill(pid, signal.SIGKILL)
            killed = pid
        except ProcessLookupError:
            pass
        return True

    if victim is not None:
        when_journal_grows(job, journal, growth, kill_victim)
    return wait(job), killed


def check_said(text, victim, pid, held, tiles, must):
    """What is wrong with what the surviving ranks said after rank `victim` (pid `pid`) was
    killed with `held` tiles in the journal: one line naming the rank and what the journal
    holds. It `must` be there once the journal grew (every rank was rendering); a kill during
    start-up may end the others before they could speak. None when nothing is wrong."""
    lines = [line for line in text.splitlines() if " was lost" in line]
    expected = (f"rt: rank {victim} (pid {pid}) was lost, and mpirun ended the job; the journal "
                f"{{}} holds {held} of {tiles} tiles")
    if len(lines) > 1 or (must and not lines):
        return f"{len(lines)} lines about a lost rank: {text.strip()}"
    if lines and not re.match(re.escape(expected).replace(r"\{\}", r"\S+"), lines[0]):
        return f"said: {lines[0]}"
    return None


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
    if not setup(out):
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
            # At most half an even share of what is left per kill still to come: the journal
            # grows by whole leases, and tiles go on arriving until the kill lands, so every
            # kill must leave room for that before the image is done.
            share = (tiles - len(held)) // (2 * (args.kills - kills + 1))
            growth = rng.randint(0, max(0, share))
        log = out / f"run{runs}.txt"
        command = MPIRUN + ["-np", str(ranks), rt] + render + ["--stats", "--output", str(image)]
        if runs > 1:
            command.append("--resume")
        code, killed = run_and_kill(command, log, journal, victim, growth)
        text = log.read_text(errors="replace")
        reused = re.search(r"--resume: reused (\d+) of (\d+) tiles", text)
        # A run killed before rank 0 read the journal says nothing about it; the others must.
        if (held and (reused or not killed)
                and (not reused or int(reused.group(1)) != len(held))):
            fail(f"run {runs}", f"the journal held {len(held)} tiles, rt said: "
                 f"{reused.group(0) if reused else 'nothing about reusing'}")
        if reused:
            carried += int(reused.group(1))
        what = (f"run {runs}: {ranks} ranks, {len(held)} tiles carried over, "
                + (f"rank {victim} killed after {growth} more" if killed else "not killed"))
        if code is None:
            fail(what, "mpirun did not end")
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
            said = check_said(text, victim, killed, len(now), tiles, growth > 0 and ranks > 1)
            if missing:
                fail(what, f"tiles lost: {sorted(missing)}")
            elif said:
                fail(what, said)
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
    return finish()


if __name__ == "__main__":
    sys.exit(main())
