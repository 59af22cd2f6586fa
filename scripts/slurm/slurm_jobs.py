"""Talking to Slurm, for submit.py and data_parallel.py: sbatch options, job submission, job
states from scontrol, and the error that ends either script with one line and an exit code."""
import re
import subprocess
import time

# Job states after which a job never runs again (squeue/scontrol names).
TERMINAL_STATES = {"COMPLETED", "FAILED", "CANCELLED", "TIMEOUT", "NODE_FAIL", "OUT_OF_MEMORY",
                   "PREEMPTED", "BOOT_FAIL", "DEADLINE", "SPECIAL_EXIT", "REVOKED"}
# --wait asks slurmctld every 0.5 s at first, then less and less often, at most every 30 s:
# quick for short tests, gentle on a shared controller during long studies.
POLL_FIRST_SECONDS = 0.5
POLL_GROWTH = 1.2
POLL_MAX_SECONDS = 30.0


class Failure(Exception):
    """One error line, "<file>: <what>; <why> (<what to do>)", and the exit code to end with."""

    def __init__(self, file, message, code):
        super().__init__(f"{file}: {message}")
        self.code = code


def bad_input(file, message):
    return Failure(file, message, 2)


def sbatch_options(pairs):
    """sbatch options "--NAME=VALUE" for the (NAME, VALUE) pairs whose VALUE is set, in order."""
    return [f"--{name}={value}" for name, value in pairs if value]


def array_ranges(ids):
    """[0,1,2,5,7,8] -> "0-2,5,7-8" (sbatch --array syntax)."""
    out = []
    start = prev = None
    for k in sorted(ids):
        if prev is not None and k == prev + 1:
            prev = k
            continue
        if start is not None:
            out.append(str(start) if start == prev else f"{start}-{prev}")
        start = prev = k
    if start is not None:
        out.append(str(start) if start == prev else f"{start}-{prev}")
    return ",".join(out)


def run_slurm(argv, what):
    try:
        r = subprocess.run(argv, capture_output=True, text=True, timeout=60)
    except FileNotFoundError:
        raise Failure(argv[0], f"cannot {what}; the Slurm command is not installed (run on a "
                      "Slurm login node, or start scripts/slurm/local_cluster.sh)", 1)
    except subprocess.TimeoutExpired:
        raise Failure(argv[0], f"cannot {what}; no answer in 60 s (check that slurmctld runs: "
                      "sinfo)", 1)
    return r


def sbatch(argv, what):
    r = run_slurm(argv, what)
    first = (r.stderr.strip().splitlines() or [f"exit status {r.returncode}"])[-1]
    if r.returncode != 0:
        raise Failure("sbatch", f"cannot {what}; {first} (fix the sbatch options or the "
                      "cluster)", 1)
    m = re.match(r"\s*(\d+)", r.stdout)
    if not m:
        raise Failure("sbatch", f"cannot {what}; no job id in its output {r.stdout.strip()!r} "
                      "(check the sbatch version)", 1)
    return m.group(1)


def job_records(job):
    """scontrol's records of a job (one per array task), or None once slurmctld forgot it.
    Other scontrol errors (a busy controller) are retried for up to a minute."""
    for attempt in range(60):
        r = run_slurm(["scontrol", "show", "job", "-o", job], "ask for the job's state")
        if r.returncode == 0:
            return [dict(f.split("=", 1) for f in line.split() if "=" in f)
                    for line in r.stdout.splitlines() if line.strip()]
        if "Invalid job id" in r.stderr:
            return None
        time.sleep(1)
    raise Failure("scontrol", f"cannot ask for job {job}'s state; "
                  f"{(r.stderr.strip().splitlines() or ['no answer'])[-1]} (check that slurmctld "
                  "runs: sinfo; the jobs keep running)", 1)


def exit_status(record):
    code = record.get("ExitCode", "0:0").split(":")[0]
    return int(code) if code.isdigit() else 1


def active_jobs(jobs):
    """Those of jobs with a record (an array task) still pending or running."""
    return [job for job in jobs
            if any(r.get("JobState") not in TERMINAL_STATES for r in job_records(job) or [])]
