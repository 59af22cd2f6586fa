"""The local single-node Slurm cluster for tests: start, stop, and a watcher that stops it when
the test process is gone (ctest's timeout kills a test without running its finally: clauses)."""
import os
import shlex
import shutil
import subprocess
import sys
import time

SKIP = 77  # ctest's SKIP_RETURN_CODE for the cluster tests


class TestFailure(Exception):
    """A check of a cluster test failed (the test prints it and exits 1)."""


def check(condition, message):
    if not condition:
        raise TestFailure(message)


def cluster(repo, cluster_dir, command):
    """Runs local_cluster.sh --dir CLUSTER_DIR COMMAND (start, stop, status, env)."""
    return subprocess.run([os.path.join(repo, "scripts", "slurm", "local_cluster.sh"), "--dir",
                           cluster_dir, command], capture_output=True, text=True, timeout=90)


def stop_when_gone(repo, cluster_dir):
    """A detached watcher that stops the cluster once this test process is gone."""
    script = (f"while kill -0 {os.getpid()} 2>/dev/null; do sleep 1; done; exec "
              f"{shlex.quote(os.path.join(repo, 'scripts', 'slurm', 'local_cluster.sh'))} "
              f"--dir {shlex.quote(cluster_dir)} stop")
    subprocess.Popen(["bash", "-c", script], start_new_session=True, stdin=subprocess.DEVNULL,
                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def slurm_env(cluster_dir):
    """The environment that points sbatch & co at the cluster."""
    return dict(os.environ, SLURM_CONF=os.path.join(cluster_dir, "slurm.conf"))


def start_cluster(repo, cluster_dir):
    """Starts the cluster, with the watcher that stops it if the test dies. True when it runs;
    False when Slurm cannot run here (the caller exits SKIP); a failed start fails the test."""
    stop_when_gone(repo, cluster_dir)
    t0 = time.monotonic()
    r = cluster(repo, cluster_dir, "start")
    sys.stdout.write(r.stdout)
    if r.returncode == 4:
        print(f"SKIP: Slurm cannot run here: {r.stderr.strip()}")
        return False
    if r.returncode != 0:
        sys.exit(f"FAIL: local_cluster.sh start: exit {r.returncode}: {r.stderr}")
    print(f"timing: cluster start: {time.monotonic() - t0:.1f} s")
    return True


def daemon_pids(cluster_dir):
    """The pids of the cluster's daemons (munged, slurmctld, slurmd) from their pid files."""
    pids = []
    for name in ("munged", "slurmctld", "slurmd"):
        try:
            with open(os.path.join(cluster_dir, "run", f"{name}.pid")) as f:
                pids.append(int(f.read().strip()))
        except (OSError, ValueError):
            pass
    return pids


def alive(pid):
    """True while the process runs (a zombie counts as gone)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split(") ")[1].split()[0] != "Z"
    except (OSError, IndexError):
        return False


def stop_and_wait(repo, cluster_dir, timeout=15):
    """Stops the cluster and waits for its daemons to exit: stop returns once their pid files
    are gone, and slurmctld may take a moment longer (it saves its state) on a loaded machine.
    Returns stop's result, the daemons still alive after `timeout` s, and the seconds waited."""
    pids = daemon_pids(cluster_dir)
    r = cluster(repo, cluster_dir, "stop")
    t0 = time.monotonic()
    while any(alive(p) for p in pids) and time.monotonic() - t0 < timeout:
        time.sleep(0.1)
    return r, [p for p in pids if alive(p)], time.monotonic() - t0


def stop_checked(repo, cluster_dir):
    """A test's last step on the cluster: its three daemons left pid files, stop exits 0 and none
    of them is alive 15 s later (else TestFailure). Returns the seconds waited for them."""
    pids = daemon_pids(cluster_dir)
    check(len(pids) == 3, f"pid files of the three daemons: {pids}")
    r, left, waited = stop_and_wait(repo, cluster_dir)
    check(r.returncode == 0, f"stop: exit {r.returncode}: {r.stderr}")
    check(not left, f"daemons alive 15 s after stop: {left}")
    return waited


def clean_up(repo, cluster_dir, started, folder):
    """A cluster test's finally: stops the cluster if a failure left it running, removes FOLDER."""
    if started:
        cluster(repo, cluster_dir, "stop")
    shutil.rmtree(folder, ignore_errors=True)
