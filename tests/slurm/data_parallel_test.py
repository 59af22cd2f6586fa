#!/usr/bin/env python3
"""scripts/slurm/data_parallel.sh: one Slurm job that runs render data-parallel over N ranks.

  data_parallel_test.py cli REPO RENDER PROXY_GEN DATA_DIR SCENES_DIR WORK_DIR PROXY_CACHE
      the sbatch script of --dry-run (resources; the command it runs, executed with a stand-in
      srun to check every argument's quoting), bad arguments refused with one line and exit 2,
      and a --local run of 2 ranks equal to the single-process exact render (R, G, B)
  data_parallel_test.py cluster REPO RENDER PROXY_GEN DATA_DIR SCENES_DIR WORK_DIR PROXY_CACHE
      a real single-node Slurm (local_cluster.sh): sbatch's refusal is one line, a 2-rank render
      submitted with --wait equals the single-process exact render bit for bit (R, G, B) and says
      2 ranks, a failing job's exit status is data_parallel.sh's; exits 77 (skipped) only when
      Slurm cannot start here. The cluster is stopped at the end, also on failure.
  PROXY_CACHE: the folder of the test scene's proxies (tests/mpi's, made by its make_proxies).
"""
import importlib.util
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

from cluster_support import (SKIP, TestFailure, check, clean_up, slurm_env,  # noqa: E402
                             start_cluster, stop_checked)

mode, repo, render, proxy_gen, data_dir, scenes_dir, work, proxy_cache = sys.argv[1:9]
spec = importlib.util.spec_from_file_location(
    "mpi_support", os.path.join(repo, "tests", "mpi", "mpi_support.py"))
mpi_support = importlib.util.module_from_spec(spec)
spec.loader.exec_module(mpi_support)

SCRIPT = os.path.join(repo, "scripts", "slurm", "data_parallel.sh")
SPP, SEED = "8", "5"


def dp(*argv, env=None, cwd=None, timeout=300):
    t0 = time.monotonic()
    r = subprocess.run([SCRIPT, *argv], capture_output=True, text=True, env=env, cwd=cwd,
                       timeout=timeout)
    r.seconds = time.monotonic() - t0
    return r


def one_error_line(r, code, what, needle=""):
    lines = r.stderr.strip().splitlines()
    check(r.returncode == code, f"{what}: exit {r.returncode}, expected {code}; stderr "
          f"{r.stderr!r}")
    check(len(lines) == 1 and lines[0].startswith("data_parallel.sh: error: "),
          f"{what}: expected one error line, got {r.stderr!r}")
    check(needle in lines[0], f"{what}: the error line does not mention {needle!r}: {lines[0]}")


def single_render(scene):
    """The single-process exact render the data-parallel ones must equal."""
    out = os.path.join(work, "single.exr")
    mpi_support.run([render, scene, "--estimator", "exact", "--spp", SPP, "--seed", SEED, "-o",
                     out, "--quiet", "--threads", "2"], env=os.environ)
    return out


def check_render(single, out, summary_path, ranks, threads, what):
    same, text = mpi_support.rgb_equal(single, out, work)
    check(same, f"{what}: R, G, B differ from the single-process exact render\n{text}")
    with open(summary_path) as f:
        s = json.load(f)
    check(s["ranks"] == ranks and len(s["per_rank"]) == ranks,
          f"{what}: the summary says {s['ranks']} ranks, expected {ranks}")
    check(s["threads"] == threads, f"{what}: {s['threads']} threads per rank, expected {threads}")
    check(s["estimator"] == "exact", f"{what}: estimator {s['estimator']}")


def bin_dir_with(names, folder):
    """A folder of links to the named programs of PATH only (a PATH without sbatch)."""
    os.makedirs(folder)
    for name in names:
        os.symlink(shutil.which(name), os.path.join(folder, name))
    return folder


# ---- cli -------------------------------------------------------------------------------------

def cli(scene):
    quoted = os.path.join(work, "out dir", "it's $HOME.exr")  # space, quote, $: one argument
    no_slurm = dict(os.environ, PATH=bin_dir_with(["bash", "python3", "dirname"],
                                                  os.path.join(work, "bin-no-slurm")))

    # The script for a 3-rank job, printed without sbatch installed.
    r = dp("--ranks", "3", "--cpus-per-rank", "2", "--mem-per-rank", "2G", "--time", "1:00:00",
           "--partition", "short", "--dry-run", "--", render, scene, "--spp", SPP, "-o", quoted,
           env=no_slurm, cwd=work)
    check(r.returncode == 0 and not r.stderr, f"dry run: exit {r.returncode}: {r.stderr}")
    script = r.stdout
    for line in ("#SBATCH --ntasks=3", "#SBATCH --cpus-per-task=2",
                 "#SBATCH --mem-per-cpu=1024M", "#SBATCH --time=1:00:00",
                 "#SBATCH --partition=short"):
        check(line in script.splitlines(), f"dry run: no line {line!r} in\n{script}")
    check(script.count("srun --mpi=pmix ") == 1, f"dry run: not launched by srun --mpi=pmix:\n"
          f"{script}")

    # Run that script with a stand-in srun that records its arguments: the exact command.
    fake = os.path.join(work, "bin-fake-srun")
    os.makedirs(fake)
    record = os.path.join(work, "srun-argv.json")
    with open(os.path.join(fake, "srun"), "w") as f:
        f.write("#!/usr/bin/env python3\nimport json, os, sys\n"
                "json.dump(sys.argv[1:], open(os.environ['SRUN_RECORD'], 'w'))\nsys.exit(3)\n")
    os.chmod(os.path.join(fake, "srun"), 0o755)
    job = os.path.join(work, "job.sh")
    with open(job, "w") as f:
        f.write(script)
    env = dict(os.environ, PATH=fake + os.pathsep + os.environ["PATH"], SLURM_CPUS_PER_TASK="2",
               SRUN_RECORD=record)
    p = subprocess.run(["bash", job], capture_output=True, text=True, env=env, cwd="/")
    with open(record) as f:
        argv = json.load(f)
    want = ["--mpi=pmix", "--ntasks=3", "--cpus-per-task=2", "--kill-on-bad-exit=1", render,
            "--data-parallel", scene, "--spp", SPP, "-o", quoted, "--threads", "2"]
    check(argv == want, f"the job runs {argv}\nexpected {want}")
    check(p.returncode == 3 and "data_parallel: exit status 3" in p.stdout,
          f"the job script's exit {p.returncode} (srun's was 3): {p.stdout}{p.stderr}")

    # --data-parallel given: not added twice; one CPU: the memory as given; no limits asked.
    r = dp("--ranks", "2", "--mem-per-rank", "3000M", "--dry-run", "--", render,
           "--data-parallel", scene, "-o", "x.exr", env=no_slurm)
    check(r.returncode == 0, f"dry run 2: exit {r.returncode}: {r.stderr}")
    check(r.stdout.count("--data-parallel") == 1, f"--data-parallel twice:\n{r.stdout}")
    check("#SBATCH --mem-per-cpu=3000M" in r.stdout.splitlines() and "--time" not in r.stdout
          and "--partition" not in r.stdout, f"dry run 2:\n{r.stdout}")
    check("#SBATCH --ntasks=2" in r.stdout and "#SBATCH --cpus-per-task=1" in r.stdout,
          f"dry run 2: resources:\n{r.stdout}")
    r = dp("--ranks", "2", "--local", "--dry-run", "--", render, scene, "-o", "x.exr")
    check(r.returncode == 0 and r.stdout.startswith("mpirun ") and
          f"-np 2 {render} --data-parallel {scene} -o x.exr --threads 1" in r.stdout,
          f"--local --dry-run: exit {r.returncode}: {r.stdout}{r.stderr}")

    # Bad arguments: one line, exit 2, nothing written.
    empty = os.path.join(work, "empty")
    os.makedirs(empty)
    target = ["--", render, scene, "-o", "x.exr"]
    bad = [
        ([], "--ranks"),
        (target, "--ranks"),
        (["--ranks", "0"] + target, "--ranks"),
        (["--ranks", "two"] + target, "--ranks"),
        (["--ranks", "2", "--cpus-per-rank", "0"] + target, "--cpus-per-rank"),
        (["--ranks", "2", "--mem-per-rank", "2X"] + target, "--mem-per-rank"),
        (["--ranks", "2", "--time", "soon"] + target, "--time"),
        (["--ranks", "2", "--partition", "a b"] + target, "--partition"),
        (["--ranks", "2", "--bogus"] + target, "--bogus"),
        (["--ranks", "2", render, scene], "no -- before PROGRAM"),
        (["--ranks", "2", "--"], "PROGRAM"),
        (["--ranks", "2", "--", shutil.which("true"), scene], "render or render-compare"),
        (["--ranks", "2", "--", os.path.join(work, "nowhere", "render"), scene], "missing"),
        (["--ranks", "2", "--", render, scene, "--threads", "4"], "--cpus-per-rank"),
        (["--ranks", "2", "--", render, scene, "--threads=4"], "--cpus-per-rank"),
        (["--ranks", "2", "--local", "--wait"] + target, "--wait"),
        (["--ranks", "2", "--local", "--partition", "p"] + target, "--partition"),
    ]
    for argv, needle in bad:
        r = dp(*argv, cwd=empty)
        one_error_line(r, 2, " ".join(argv) or "no arguments", needle)
        check(not r.stdout, f"{argv}: stdout {r.stdout!r}")
    r = dp("--ranks", "2", *target, env=no_slurm, cwd=empty)
    one_error_line(r, 2, "without sbatch", "sbatch")
    check(not os.listdir(empty), f"refused runs wrote {os.listdir(empty)}")
    print(f"ok: dry runs and {len(bad) + 1} refusals")

    # The same job here under mpirun: 2 ranks of 2 threads equal the single-process render.
    single = single_render(scene)
    out = os.path.join(work, "local.exr")
    r = dp("--local", "--ranks", "2", "--cpus-per-rank", "2", "--", render, scene,
           "--forwarding", "proxies", "--spp", SPP, "--seed", SEED, "-o", out, "--json",
           out + ".json", "--quiet")
    check(r.returncode == 0, f"--local run: exit {r.returncode}\n{r.stdout}{r.stderr}")
    print(f"timing: --local run of 2 ranks: {r.seconds:.1f} s")
    check_render(single, out, out + ".json", 2, 2, "--local, 2 ranks x 2 threads")
    print("ok: --local 2-rank exact render equals the single-process render")
    return 0


# ---- cluster ---------------------------------------------------------------------------------

def on_cluster(scene):
    single = single_render(scene)
    # munged serves its socket only below folders anyone can search: a fresh folder in /tmp.
    tmp = tempfile.mkdtemp(prefix="proxyvis-slurm-dp-")
    os.chmod(tmp, 0o755)
    cluster_dir = os.path.join(tmp, "cluster")
    started = False
    try:
        if not start_cluster(repo, cluster_dir):
            return SKIP
        started = True
        env = slurm_env(cluster_dir)
        jobs = os.path.join(work, "jobs")  # the jobs' folder: their logs land here
        os.makedirs(jobs)

        # sbatch refuses: one line with its reason, nothing runs.
        r = dp("--ranks", "2", "--partition", "nosuch", "--", render, scene, "-o",
               os.path.join(jobs, "refused.exr"), env=env, cwd=jobs)
        one_error_line(r, 1, "unknown partition", "sbatch: cannot submit the job; ")
        check("partition" in r.stderr, f"sbatch's reason is missing: {r.stderr}")

        out = os.path.join(jobs, "cluster.exr")
        r = dp("--ranks", "2", "--wait", "--", render, scene, "--forwarding", "proxies",
               "--spp", SPP, "--seed", SEED, "-o", out, "--json", out + ".json", "--quiet",
               env=env, cwd=jobs)
        sys.stdout.write(r.stdout)
        m = re.search(r"job (\d+): render over 2 ranks", r.stdout)
        log = os.path.join(jobs, f"slurm-{m.group(1)}.out") if m else None
        log_text = open(log).read() if log and os.path.exists(log) else "(no log)"
        check(r.returncode == 0 and not r.stderr,
              f"2-rank job: exit {r.returncode}: {r.stderr}\nits log:\n{log_text}")
        print(f"timing: 2-rank render job, submit to end (--wait): {r.seconds:.1f} s")
        check("data_parallel: exit status 0" in log_text, f"the job's log:\n{log_text}")
        check_render(single, out, out + ".json", 2, 1, "cluster, 2 ranks x 1 thread")
        print("ok: the 2-rank job's exact render equals the single-process render")

        # A job whose program fails: its exit status is data_parallel.sh's.
        r = dp("--ranks", "2", "--wait", "--", render, os.path.join(work, "nosuch.json"), "-o",
               os.path.join(jobs, "failed.exr"), env=env, cwd=jobs)
        one_error_line(r, 2, "failing job", "FAILED with exit status 2")
        print(f"timing: failing job (--wait): {r.seconds:.1f} s")
        print("ok: a failed job's exit status 2 is passed on")

        waited = stop_checked(repo, cluster_dir)
        started = False
        print(f"timing: daemons gone {waited:.1f} s after stop returned")
        return 0
    finally:
        clean_up(repo, cluster_dir, started, tmp)


def main():
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    t0 = time.monotonic()
    scene = mpi_support.make_unique_scene(os.path.join(work, "scene"), data_dir, scenes_dir,
                                          proxy_gen, proxy_cache=proxy_cache)
    print(f"timing: test scene: {time.monotonic() - t0:.1f} s")
    try:
        code = cli(scene) if mode == "cli" else on_cluster(scene)
    except (TestFailure, subprocess.TimeoutExpired) as e:
        print(f"FAIL: {e}")
        return 1
    if code == 0:
        print("PASS")
    return code or 0


if __name__ == "__main__":
    sys.exit(main())
