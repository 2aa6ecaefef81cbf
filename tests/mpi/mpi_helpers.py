"""Shared by the Python MPI tests (chaos.py, job_end.py): the showcase render they use, one
line per check, how to read a journal and how to find a rank of one's own mpirun."""
import os
import shutil
import struct
import subprocess
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SHOWCASE = ROOT / "scenes" / "showcase.lua"
# common.sh's SHOWCASE_OPTIONS (every chapter's sampling on, but cheap), one thread a rank.
OPTIONS = ["--quiet", "--preview", "--aa=jittered", "--light-samples=2", "--glossy-samples=2",
           "--dof-samples=4", "--photon-passes=2", "--photons=20000", "--threads", "1"]
# CI runs as root on 2 cores; -q keeps Open MPI's banners off stderr.
MPIRUN = ["mpirun", "-q", "--oversubscribe"]
# Under the sanitizers (make test-sanitize sets RB_SANITIZE=1) a render is several times slower,
# and they check the code each case runs, not how many pixels: tests that render the showcase
# again and again divide its width and height by SHRINK (as common.sh does).
SHRINK = 2 if os.environ.get("RB_SANITIZE") == "1" else 1
TIMEOUT = 120  # seconds one mpirun may take before a test gives up on it

checks = {"passed": 0, "failed": 0}


def ok(what):
    print(f"ok   {what}", flush=True)
    checks["passed"] += 1


def fail(what, why):
    print(f"FAIL {what}: {why}", flush=True)
    checks["failed"] += 1


def finish():
    """Print the count; the exit code: 1 if anything failed."""
    print(f"{checks['passed']} passed, {checks['failed']} failed")
    return 1 if checks["failed"] else 0


def setup(out):
    """A fresh OUT folder, Open MPI's root switches; False (with a FAIL) without mpirun."""
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    if shutil.which("mpirun") is None:
        fail("mpirun", "not found (make mpi installs Open MPI)")
        return False
    return True


def journal_positions(path):
    """The tile positions of the whole records of the journal at `path` (journal.h's format:
    a text header ending in an empty line, then TILE, position, float count, floats, checksum),
    in the order written; none when there is no journal."""
    try:
        data = Path(path).read_bytes()
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
    """The pid of rank `rank` of the job started by the process `mpirun` (its child: this
    test's ranks only, never another job's), or None yet."""
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


def start(command, log):
    """Start `command` with stderr into the file `log`."""
    with open(log, "wb") as err:
        return subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=err)


def when_journal_grows(job, journal, growth, act):
    """Once the journal holds `growth` more tiles than now, call act(); False when the job
    ended (or TIMEOUT passed) first."""
    begin = len(journal_positions(journal))
    deadline = time.monotonic() + TIMEOUT
    while job.poll() is None and time.monotonic() < deadline:
        if len(journal_positions(journal)) - begin >= growth and act():
            return True
        time.sleep(0.002)
    return False


def wait(job):
    """The job's exit code, or None when it was still running after TIMEOUT (then killed)."""
    try:
        return job.wait(timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        job.kill()
        job.wait()
        return None
