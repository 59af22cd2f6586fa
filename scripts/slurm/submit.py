#!/usr/bin/env python3
"""Runs a plan's work units as a Slurm job array and its merge as a dependent job.

A plan is a folder with plan.json (format in docs/slurm.md): "units" (K), "run_unit" (the argv
of one unit, "{unit}" replaced by its index 0..K-1) and "merge" (the argv that combines them).
Unit K is done when PLAN_DIR/units/K.done exists; the unit command writes it last, after its
outputs are renamed into place, so a done unit is never run again and a half-written one
always is.

Usage: submit.sh PLAN_DIR [--resume] [--wait] [--cpus-per-task N] [--mem M] [--partition P]
                          [--time T] [--max-parallel N] [--sbatch-arg ARG]... [--dry-run]
       submit.sh PLAN_DIR --local [--jobs N] [--resume]   (no Slurm: run the units here)
Exit codes: 0 submitted (with --wait: the merge succeeded), 1 a job failed or sbatch refused,
2 bad plan or arguments, 3 could not write into PLAN_DIR/slurm.
"""
import argparse
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

from slurm_jobs import (POLL_FIRST_SECONDS, POLL_GROWTH, POLL_MAX_SECONDS, TERMINAL_STATES, Failure,
                        active_jobs, array_ranges, bad_input, exit_status, job_records, run_slurm,
                        sbatch, sbatch_options)

PROG = "submit.sh"
MAX_UNITS = 1_000_000
PLAN_VERSION = 1
UNIT = "{unit}"
PLAN_DIR_TOKEN = "{plan_dir}"


# ---- the plan --------------------------------------------------------------------------------

class Plan:
    def __init__(self, folder, units, run_unit, merge, name):
        self.dir = folder
        self.units = units
        self.run_unit = run_unit
        self.merge = merge
        self.name = name

    def done_marker(self, unit):
        return os.path.join(self.dir, "units", f"{unit}.done")

    def missing_units(self):
        return [k for k in range(self.units) if not os.path.exists(self.done_marker(k))]

    @property
    def slurm_dir(self):
        return os.path.join(self.dir, "slurm")


def argv_of(value, key, path):
    if (not isinstance(value, list) or not value or
            not all(isinstance(a, str) and a for a in value)):
        raise bad_input(path, f'"{key}" is not an argv; it must be a non-empty list of non-empty '
                        f'strings (write e.g. ["render-compare", "--merge", "{PLAN_DIR_TOKEN}"])')
    return value


def read_plan(plan_dir):
    if not os.path.isdir(plan_dir):
        raise bad_input(plan_dir, "not a plan folder; it does not exist or is not a folder "
                        "(pass the folder that holds plan.json)")
    folder = os.path.abspath(plan_dir)
    if "%" in folder or "\\" in folder:
        raise bad_input(folder, "unusable plan folder; sbatch reads % and \\ in its log paths "
                        "as patterns (rename or move the folder)")
    path = os.path.join(folder, "plan.json")
    if not os.path.isfile(path):
        raise bad_input(path, "cannot read the plan; the file is missing or not a regular file "
                        "(write the plan first, e.g. render-compare --plan)")
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as e:
        raise bad_input(path, f"cannot read the plan; {e} (rewrite it as JSON, see docs/slurm.md)")
    if not isinstance(data, dict):
        raise bad_input(path, "not a plan; the top level is not a JSON object (see docs/slurm.md)")
    version = data.get("version", PLAN_VERSION)
    if version != PLAN_VERSION:
        raise bad_input(path, f'unsupported "version" {version!r}; this submitter reads version '
                        f"{PLAN_VERSION} (use the submitter of the proxyvis that wrote the plan)")
    units = data.get("units")
    if isinstance(units, bool) or not isinstance(units, int) or not 1 <= units <= MAX_UNITS:
        raise bad_input(path, f'"units" is {units!r}; it must be an integer in [1, {MAX_UNITS}] '
                        "(the number of work units)")
    run_unit = argv_of(data.get("run_unit"), "run_unit", path)
    if not any(UNIT in a for a in run_unit):
        raise bad_input(path, f'"run_unit" never names "{UNIT}"; every unit would do the same '
                        f'work (put "{UNIT}" where the unit index goes)')
    merge = argv_of(data.get("merge"), "merge", path)
    name = data.get("name", "proxyvis")
    if not isinstance(name, str) or not re.fullmatch(r"[A-Za-z0-9_.+-]{1,64}", name):
        raise bad_input(path, f'"name" is {name!r}; a job name is 1-64 letters, digits or _.+- '
                        '(or leave it out)')
    return Plan(folder, units, run_unit, merge, name)


# ---- the job scripts -------------------------------------------------------------------------

def shell_word(arg, plan):
    """arg as one shell word: {plan_dir} replaced now, {unit} by the script's $unit."""
    parts = arg.replace(PLAN_DIR_TOKEN, plan.dir).split(UNIT)
    return '"$unit"'.join(shlex.quote(p) if p else "" for p in parts) or "''"


def command_line(argv, plan):
    return " ".join(shell_word(a, plan) for a in argv)


def unit_script(plan):
    marker = shlex.quote(os.path.join(plan.dir, "units")) + '/"$unit".done'
    return f"""#!/usr/bin/env bash
# Generated by scripts/slurm/submit.py: runs one unit of the plan in {plan.dir}.
# The unit is the array index (or the first argument): a unit already done exits at once, so
# a requeued or repeated task never redoes finished work.
set -u
unit=${{1:-${{SLURM_ARRAY_TASK_ID:?run as an array task or pass the unit index}}}}
cd {shlex.quote(plan.dir)} || exit 1
if [ -e {marker} ]; then
  echo "unit $unit: already done"
  exit 0
fi
echo "unit $unit: started on $(hostname) at $(date -u +%FT%TZ) (job ${{SLURM_JOB_ID:-none}})"
{command_line(plan.run_unit, plan)}
status=$?
if [ $status -ne 0 ]; then
  echo "unit $unit: failed with exit status $status" >&2
  exit $status
fi
if [ ! -e {marker} ]; then
  echo "unit $unit: the command succeeded but wrote no units/$unit.done; counted as failed" >&2
  exit 1
fi
"""


def merge_script(plan):
    return f"""#!/usr/bin/env bash
# Generated by scripts/slurm/submit.py: merges the {plan.units} units of the plan in {plan.dir}
# once every one is done; its exit status is also kept in slurm/merge.exit.
set -u
cd {shlex.quote(plan.dir)} || exit 1
missing=""
for ((k = 0; k < {plan.units}; k++)); do
  [ -e "units/$k.done" ] || missing="$missing $k"
done
if [ -n "$missing" ]; then
  echo "merge: units not done:$missing; not merging" >&2
  status=1
else
  {command_line(plan.merge, plan)}
  status=$?
fi
echo $status > slurm/merge.exit.tmp && mv slurm/merge.exit.tmp slurm/merge.exit
exit $status
"""


def write_atomically(path, text, mode=0o644):
    tmp = f"{path}.tmp{os.getpid()}"
    try:
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(text)
        os.chmod(tmp, mode)
        os.replace(tmp, path)
    except OSError as e:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise Failure(path, f"cannot write; {e.strerror} (make the plan folder writable)", 3)


def write_scripts(plan):
    try:
        os.makedirs(os.path.join(plan.slurm_dir, "logs"), exist_ok=True)
        os.makedirs(os.path.join(plan.dir, "units"), exist_ok=True)
    except OSError as e:
        raise Failure(plan.slurm_dir, f"cannot create; {e.strerror} (make the plan folder "
                      "writable)", 3)
    scripts = (os.path.join(plan.slurm_dir, "run_unit.sh"),
               os.path.join(plan.slurm_dir, "merge.sh"))
    write_atomically(scripts[0], unit_script(plan), 0o755)
    write_atomically(scripts[1], merge_script(plan), 0o755)
    return scripts


# ---- Slurm -----------------------------------------------------------------------------------

def wait_for_merge(plan, job):
    """The merge job's exit status once it ended (1 if it never ran). Says how many units are
    done whenever that changes."""
    delay = POLL_FIRST_SECONDS
    done_before = None
    while True:
        done = plan.units - len(plan.missing_units())
        if done != done_before:
            print(f"{PROG}: {done} of {plan.units} units done", flush=True)
            done_before = done
        records = job_records(job)
        if not records:
            return read_merge_exit(plan)
        record = records[0]
        state = record.get("JobState", "UNKNOWN")
        if state in TERMINAL_STATES:
            status = exit_status(record)
            return status if state == "COMPLETED" or status != 0 else 1
        if state == "PENDING" and record.get("Reason") == "DependencyNeverSatisfied":
            run_slurm(["scancel", job], "cancel the merge job")
            return 1
        time.sleep(delay)
        delay = min(delay * POLL_GROWTH, POLL_MAX_SECONDS)


def read_merge_exit(plan):
    try:
        with open(os.path.join(plan.slurm_dir, "merge.exit")) as f:
            return int(f.read().strip() or 1)
    except (OSError, ValueError):
        return 1


# ---- submission ------------------------------------------------------------------------------

def units_to_run(plan, resume):
    missing = plan.missing_units()
    done = plan.units - len(missing)
    if done and not resume:
        raise bad_input(os.path.join(plan.dir, "units"), f"{done} of {plan.units} units are "
                        "already done; a plan is submitted once (pass --resume to run only the "
                        "missing units, or empty units/ to start over)")
    return missing


def check_not_running(plan):
    """Refuses a second submission while jobs of the previous one are queued or running."""
    path = os.path.join(plan.slurm_dir, "submission.json")
    try:
        with open(path) as f:
            jobs = [str(j) for j in json.load(f).get("jobs", [])]
    except (OSError, ValueError, AttributeError):
        return
    active = active_jobs(jobs)
    if active:
        raise bad_input(path, f"jobs {', '.join(active)} of the last submission are still "
                        "queued or running; submitting again would run units twice (wait for "
                        "them, or scancel them, then pass --resume)")


def resource_options(args):
    return sbatch_options([("cpus-per-task", args.cpus_per_task), ("mem", args.mem),
                           ("partition", args.partition), ("time", args.time)]) + args.sbatch_arg


def submit(plan, args):
    missing = units_to_run(plan, args.resume)
    if not args.dry_run:
        if not shutil.which("sbatch"):
            raise Failure("sbatch", "cannot submit; the Slurm command is not installed (run on "
                          "a Slurm login node, start scripts/slurm/local_cluster.sh, or use "
                          "--local)", 1)
        check_not_running(plan)
    logs = os.path.join(plan.slurm_dir, "logs")
    unit_sh = os.path.join(plan.slurm_dir, "run_unit.sh")
    merge_sh = os.path.join(plan.slurm_dir, "merge.sh")
    common = ["sbatch", "--parsable", f"--chdir={plan.dir}"] + resource_options(args)
    array_cmd = None
    if missing:
        spec = array_ranges(missing)
        if args.max_parallel:
            spec += f"%{args.max_parallel}"
        array_cmd = common + [f"--job-name={plan.name}-units", f"--array={spec}",
                              f"--output={logs}/unit-%a.out", "--open-mode=append", unit_sh]
    merge_cmd = common + [f"--job-name={plan.name}-merge", f"--output={logs}/merge-%j.out"]

    after_units = ["--dependency=afterok:{}", "--kill-on-invalid-dep=yes"] if array_cmd else []

    if args.dry_run:
        if array_cmd:
            print(shlex.join(array_cmd))
        print(shlex.join(merge_cmd + [a.format("<units job>") for a in after_units] + [merge_sh]))
        return 0

    write_scripts(plan)
    try:
        os.unlink(os.path.join(plan.slurm_dir, "merge.exit"))
    except OSError:
        pass
    jobs = []
    if array_cmd:
        array_job = sbatch(array_cmd, f"submit {len(missing)} units")
        jobs.append(array_job)
        noun = "unit" if len(missing) == 1 else "units"
        print(f"{PROG}: {noun} {array_ranges(missing)} ({len(missing)} of {plan.units}): "
              f"job {array_job}", flush=True)
        merge_cmd += [a.format(array_job) for a in after_units]
    else:
        print(f"{PROG}: all {plan.units} units are done; submitting the merge only", flush=True)
    try:
        merge_job = sbatch(merge_cmd + [merge_sh], "submit the merge")
    except Failure:
        # Units without their merge would finish unnoticed: take them back.
        if array_cmd:
            run_slurm(["scancel", jobs[0]], "cancel the units job")
            print(f"{PROG}: cancelled job {jobs[0]}: its merge could not be submitted",
                  flush=True)
        raise
    jobs.append(merge_job)
    after = f" (after job {jobs[0]} succeeds)" if array_cmd else ""
    print(f"{PROG}: merge: job {merge_job}{after}", flush=True)
    write_atomically(os.path.join(plan.slurm_dir, "submission.json"),
                     json.dumps({"jobs": jobs, "units": missing, "time": time.time()}) + "\n")
    if not args.wait:
        return 0
    status = wait_for_merge(plan, merge_job)
    return report_end(plan, status, f"merge job {merge_job}")


def report_end(plan, status, what):
    if status == 0:
        print(f"{PROG}: {what} succeeded: {plan.units} units merged", flush=True)
        return 0
    missing = plan.missing_units()
    logs = os.path.join(plan.slurm_dir, "logs")
    if missing:
        shown = ", ".join(str(k) for k in missing[:10]) + (", ..." if len(missing) > 10 else "")
        noun = "unit" if len(missing) == 1 else "units"
        why = (f"{noun} {shown} did not finish, so the merge did not run (see "
               f"{logs}/unit-{missing[0]}.out, fix the cause, then submit again with --resume)")
    else:
        why = (f"every unit is done but the merge failed with exit status {status} (see its log "
               f"in {logs}; then submit again with --resume)")
    raise Failure(plan.dir, f"{what} did not succeed; {why}", status if status > 0 else 1)


def run_locally(plan, args):
    """The same scripts without Slurm: missing units in parallel here, then the merge."""
    missing = units_to_run(plan, args.resume)
    unit_sh, merge_sh = write_scripts(plan)
    logs = os.path.join(plan.slurm_dir, "logs")

    def run(k):
        with open(os.path.join(logs, f"unit-{k}.out"), "a") as log:
            return subprocess.run([unit_sh, str(k)], stdout=log, stderr=subprocess.STDOUT,
                                  cwd=plan.dir).returncode

    with ThreadPoolExecutor(max_workers=args.jobs or os.cpu_count() or 1) as pool:
        list(pool.map(run, missing))
    print(f"{PROG}: ran units {array_ranges(missing) or 'none'} here", flush=True)
    if plan.missing_units():
        return report_end(plan, 1, "the local run")
    with open(os.path.join(logs, "merge-local.out"), "w") as log:
        status = subprocess.run([merge_sh], stdout=log, stderr=subprocess.STDOUT,
                                cwd=plan.dir).returncode
    return report_end(plan, status, "the local merge")


# ---- command line ----------------------------------------------------------------------------

class Parser(argparse.ArgumentParser):
    def error(self, message):
        raise bad_input("arguments", f"{message}; not a valid command line (see {PROG} --help)")


def integer_in(lo, hi):
    def parse(text):
        if not re.fullmatch(r"[0-9]+", text) or not lo <= int(text) <= hi:
            raise argparse.ArgumentTypeError(f"'{text}' is not an integer in [{lo}, {hi}]")
        return int(text)
    return parse


def memory(text):
    if not re.fullmatch(r"[1-9][0-9]*[KMGT]?", text):
        raise argparse.ArgumentTypeError(f"'{text}' is not a memory size like 4000M or 16G")
    return text


def parse_args(argv):
    p = Parser(prog=PROG, description=__doc__.split("\n\n")[0],
               formatter_class=argparse.RawDescriptionHelpFormatter,
               epilog="The plan format and fault handling: docs/slurm.md.")
    p.add_argument("plan_dir", metavar="PLAN_DIR", help="the folder holding plan.json")
    p.add_argument("--resume", action="store_true",
                   help="run only the units whose units/K.done is missing, then the merge")
    p.add_argument("--wait", action="store_true",
                   help="wait for the merge job and exit with its status")
    p.add_argument("--cpus-per-task", type=integer_in(1, 4096), metavar="N")
    p.add_argument("--mem", type=memory, metavar="M", help="memory per job, e.g. 16G")
    p.add_argument("--partition", metavar="P")
    p.add_argument("--time", metavar="T", help="time limit per job, e.g. 2:00:00")
    p.add_argument("--max-parallel", type=integer_in(1, 100000), metavar="N",
                   help="at most N units run at once (--array=...%%N)")
    p.add_argument("--sbatch-arg", action="append", default=[], metavar="ARG",
                   help="one more sbatch option for both jobs, e.g. --sbatch-arg=--account=x")
    p.add_argument("--dry-run", action="store_true",
                   help="print the sbatch commands, submit nothing, write nothing")
    p.add_argument("--local", action="store_true",
                   help="no Slurm: run the missing units on this machine, then the merge")
    p.add_argument("--jobs", type=integer_in(1, 4096), metavar="N",
                   help="with --local: units at once (default: the number of CPUs)")
    return p.parse_args(argv)


def main(argv):
    try:
        args = parse_args(argv)
        if args.local and (args.dry_run or args.wait):
            raise bad_input("arguments", "--local runs everything here and waits; --dry-run and "
                            "--wait are for Slurm (leave them out)")
        plan = read_plan(args.plan_dir)
        return run_locally(plan, args) if args.local else submit(plan, args)
    except Failure as e:
        print(f"{PROG}: error: {e}", file=sys.stderr)
        return e.code
    except KeyboardInterrupt:
        print(f"{PROG}: error: interrupted; jobs already submitted keep running (squeue)",
              file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
