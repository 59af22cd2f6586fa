#!/usr/bin/env python3
"""scripts/slurm/local_cluster.sh's refusals, which need no Slurm: bad usage (exit 2, one error
line), a folder munged could not serve its socket from (exit 1 before anything starts), and
status/stop of a folder without a cluster.

  local_cluster_cli_test.py REPO_ROOT
"""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

REPO = None


def cluster(*argv, env=None):
    return subprocess.run([os.path.join(REPO, "scripts", "slurm", "local_cluster.sh")] +
                          list(argv), capture_output=True, text=True, timeout=60,
                          env={**os.environ, **(env or {})})


class LocalClusterCliTest(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.mkdtemp(prefix="proxyvis-cluster-cli-")
        os.chmod(self.work, 0o755)
        self.dir = os.path.join(self.work, "cluster")

    def tearDown(self):
        shutil.rmtree(self.work, ignore_errors=True)

    def assert_one_error(self, r, code):
        lines = r.stderr.strip().splitlines()
        self.assertEqual(r.returncode, code, r.stderr)
        self.assertEqual(len(lines), 1, r.stderr)
        self.assertTrue(lines[0].startswith("local_cluster.sh: error: "), lines[0])
        return lines[0]

    def test_bad_usage_is_refused(self):
        for argv, env in (([], None), (["--dir", self.dir], None),
                          (["--dir", self.dir, "start", "stop"], None),
                          (["--dir", self.dir, "restart"], None), (["--dir"], None),
                          (["--dir", self.dir, "start"], {"PROXYVIS_SLURM_START_TIMEOUT": "5s"}),
                          (["--dir", self.dir, "start"], {"PROXYVIS_SLURM_START_TIMEOUT": "0"})):
            with self.subTest(argv=argv, env=env):
                self.assert_one_error(cluster(*argv, env=env), 2)
                self.assertFalse(os.path.exists(self.dir), "a refused start created its folder")

    def test_parent_folder_munged_cannot_use_is_refused_before_starting(self):
        private = os.path.join(self.work, "private")
        os.makedirs(private, mode=0o700)
        os.chmod(private, 0o700)
        target = os.path.join(private, "cluster")
        line = self.assert_one_error(cluster("--dir", target, "start"), 1)
        self.assertIn(f"the parent folder {private} is not searchable by all", line)
        self.assertFalse(os.path.exists(target), "started although munged would refuse")

    def test_status_and_stop_without_a_cluster(self):
        r = cluster("--dir", self.dir, "status")
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("no cluster in", r.stdout)
        r = cluster("--dir", self.dir, "stop")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stderr, "")

    def test_help_is_the_header_comment(self):
        r = cluster("--help")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(r.stdout.startswith("A real single-node Slurm cluster"), r.stdout)
        self.assertIn("tests skip on 4.", r.stdout)
        self.assertNotIn("set -e", r.stdout)

    def test_env_names_the_config_of_the_folder(self):
        r = cluster("--dir", self.dir + "/", "env")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout, f"export SLURM_CONF={self.dir}/slurm.conf\n")


if __name__ == "__main__":
    REPO = sys.argv.pop(1)
    unittest.main(verbosity=2)
