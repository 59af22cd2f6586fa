"""mpirun with the flags this machine needs (as root, oversubscribed, in a container)."""
import os


def mpirun_cmd(ranks):
    # --oversubscribe: more ranks than cores; --bind-to none: a rank's TBB threads may use any
    # core. Root is allowed because CI and the sessions run as root.
    return ["mpirun", "-q", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none",
            "-np", str(ranks)]


def mpi_env():
    env = dict(os.environ)
    env.update({
        "OMPI_ALLOW_RUN_AS_ROOT": "1",
        "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
        # Containers forbid the cross-memory attach Open MPI's shared-memory transport tries
        # first; without this every message prints a warning.
        "OMPI_MCA_btl_vader_single_copy_mechanism": "none",
        # A rank waiting for a message spins on its core unless oversubscribed; ctest runs other
        # tests beside this one, so it yields instead (a 2-rank render: 0.3 s less CPU of 1.2).
        "OMPI_MCA_mpi_yield_when_idle": "1",
    })
    return env
