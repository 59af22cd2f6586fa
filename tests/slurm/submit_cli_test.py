#!/usr/bin/env python3
"""scripts/slurm/submit.sh without a cluster: the sbatch commands it would run (--dry-run), the
plans and arguments it refuses (exit 2, one error line naming the file, nothing written), a
missing sbatch, and the done-marker rule of the generated unit script (--local).

  submit_cli_test.py REPO_ROOT
"""
import contextlib
import io
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

REPO = None


def submit(*argv, env=None):
    """submit.sh as a program (its wrapper, the generated scripts, PATH lookups)."""
    return subprocess.run([os.path.join(REPO, "scripts", "slurm", "submit.sh")] + list(argv),
                          capture_output=True, text=True, timeout=60, env=env)


def submit_here(*argv):
    """submit.py's main() in this process: the same checks without a Python start each."""
    sys.path.insert(0, os.path.join(REPO, "scripts", "slurm"))
    import submit as submitter
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = submitter.main(list(argv))
    return subprocess.CompletedProcess(argv, code, out.getvalue(), err.getvalue())


def tree(folder):
    return sorted(os.path.relpath(os.path.join(d, f), folder)
                  for d, _, files in os.walk(folder) for f in files + ["/"])


class SubmitTest(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.mkdtemp(prefix="proxyvis-submit-test-")
        self.plan = os.path.join(self.work, "plan")
        os.makedirs(os.path.join(self.plan, "units"))

    def tearDown(self):
        shutil.rmtree(self.work, ignore_errors=True)

    def write_plan(self, plan=None, text=None, **keys):
        data = {"units": 10, "run_unit": ["prog", "--run-unit", "{plan_dir}", "{unit}"],
                "merge": ["prog", "--merge", "{plan_dir}"]}
        data.update(keys)
        with open(os.path.join(self.plan, "plan.json"), "w") as f:
            f.write(text if text is not None else json.dumps(plan or data))

    def mark_done(self, *units):
        for k in units:
            open(os.path.join(self.plan, "units", f"{k}.done"), "w").close()

    def assert_refused(self, r, code, names):
        lines = r.stderr.strip().splitlines()
        self.assertEqual(r.returncode, code, r.stderr)
        self.assertEqual(len(lines), 1, r.stderr)
        self.assertTrue(lines[0].startswith(f"submit.sh: error: {names}"), lines[0])
        self.assertFalse(os.path.exists(os.path.join(self.plan, "slurm")), "wrote into the plan")

    def test_dry_run_submits_all_units_then_the_merge(self):
        self.write_plan()
        before = tree(self.plan)
        r = submit(self.plan, "--dry-run")
        self.assertEqual(r.returncode, 0, r.stderr)
        array, merge = r.stdout.strip().splitlines()
        self.assertIn(" --array=0-9 ", array)
        self.assertIn(f" --chdir={self.plan} ", array)
        self.assertIn(f" --output={self.plan}/slurm/logs/unit-%a.out ", array)
        self.assertTrue(array.endswith(f"{self.plan}/slurm/run_unit.sh"), array)
        self.assertIn(" '--dependency=afterok:<units job>' --kill-on-invalid-dep=yes ", merge)
        self.assertTrue(merge.endswith(f"{self.plan}/slurm/merge.sh"), merge)
        self.assertEqual(tree(self.plan), before, "--dry-run wrote files")

    def test_resume_submits_only_missing_units_with_resources(self):
        self.write_plan()
        self.mark_done(0, 1, 2, 5, 9)
        r = submit_here(self.plan, "--dry-run", "--resume", "--cpus-per-task", "2", "--mem", "4G",
                   "--partition", "gpu", "--time", "1:00:00", "--max-parallel", "3",
                   "--sbatch-arg=--account=proj")
        self.assertEqual(r.returncode, 0, r.stderr)
        array, merge = r.stdout.strip().splitlines()
        self.assertIn(" --array=3-4,6-8%3 ", array)
        for line in (array, merge):
            for opt in ("--cpus-per-task=2", "--mem=4G", "--partition=gpu", "--time=1:00:00",
                        "--account=proj"):
                self.assertIn(f" {opt} ", line)

    def test_resume_with_every_unit_done_submits_the_merge_alone(self):
        self.write_plan()
        self.mark_done(*range(10))
        r = submit_here(self.plan, "--dry-run", "--resume")
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = r.stdout.strip().splitlines()
        self.assertEqual(len(lines), 1, r.stdout)
        self.assertNotIn("--dependency", lines[0])
        self.assertTrue(lines[0].endswith("merge.sh"), lines[0])

    def test_done_units_without_resume_are_refused(self):
        self.write_plan()
        self.mark_done(4)
        r = submit_here(self.plan, "--dry-run")
        self.assert_refused(r, 2, os.path.join(self.plan, "units"))
        self.assertIn("1 of 10 units are already done", r.stderr)
        self.assertIn("--resume", r.stderr)

    def test_bad_plans_are_refused(self):
        path = os.path.join(self.plan, "plan.json")
        run_unit = ["p", "{unit}"]
        cases = {
            "not json": dict(text="{units: 3"),
            "not an object": dict(text="[1, 2]"),
            "no units": dict(plan={"run_unit": run_unit, "merge": ["m"]}),
            "zero units": dict(units=0),
            "too many units": dict(units=1_000_001),
            "units as text": dict(units="8"),
            "units as bool": dict(units=True),
            "units fractional": dict(units=2.5),
            "run_unit without {unit}": dict(run_unit=["p", "--run-unit", "x"]),
            "run_unit a string": dict(run_unit="p {unit}"),
            "run_unit empty arg": dict(run_unit=["p", "", "{unit}"]),
            "merge empty": dict(merge=[]),
            "merge not strings": dict(merge=["m", 3]),
            "newer version": dict(version=2),
            "bad name": dict(name="a b"),
        }
        for what, plan in cases.items():
            with self.subTest(what):
                self.write_plan(**plan)
                self.assert_refused(submit_here(self.plan, "--dry-run"), 2, path)
        # --local reads the plan the same way.
        self.write_plan(text="{units: 3")
        self.assert_refused(submit(self.plan, "--local"), 2, path)

    def test_missing_plan_and_folder_are_refused(self):
        self.assert_refused(submit_here(self.plan), 2, os.path.join(self.plan, "plan.json"))
        missing = os.path.join(self.work, "nowhere")
        self.assert_refused(submit_here(missing), 2, missing)

    def test_plan_folder_with_a_percent_sign_is_refused(self):
        # sbatch would expand %a, %j... in the log paths under it.
        folder = os.path.join(self.work, "100%a")
        os.makedirs(folder)
        with open(os.path.join(folder, "plan.json"), "w") as f:
            json.dump({"units": 1, "run_unit": ["p", "{unit}"], "merge": ["m"]}, f)
        r = submit_here(folder, "--dry-run")
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertEqual(r.stdout, "")
        self.assertTrue(r.stderr.startswith(f"submit.sh: error: {folder}: unusable plan folder"),
                        r.stderr)

    def test_bad_arguments_are_refused(self):
        self.write_plan()
        for argv in (["--cpus-per-task", "0"], ["--cpus-per-task", "2x"], ["--mem", "4X"],
                     ["--mem", "-1G"], ["--max-parallel", "0"], ["--frobnicate"],
                     ["--local", "--wait"], []):
            with self.subTest(argv):
                args = argv if argv == [] else [self.plan] + argv
                self.assert_refused(submit_here(*args), 2, "arguments")

    def test_missing_sbatch_is_one_error_and_writes_nothing(self):
        self.write_plan()
        bin_dir = os.path.join(self.work, "bin")
        os.makedirs(bin_dir)
        for tool in ("bash", "python3", "dirname"):
            os.symlink(shutil.which(tool), os.path.join(bin_dir, tool))
        r = submit(self.plan, env={**os.environ, "PATH": bin_dir})
        self.assert_refused(r, 1, "sbatch: ")

    def test_unit_that_writes_no_done_marker_counts_as_failed(self):
        # The command succeeds but never writes units/K.done: the merge must not run.
        self.write_plan(units=2, run_unit=["true", "{unit}"],
                        merge=["touch", "{plan_dir}/merged"])
        r = submit(self.plan, "--local", "--jobs", "2")
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("units 0, 1 did not finish", r.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.plan, "merged")))
        with open(os.path.join(self.plan, "slurm", "logs", "unit-1.out")) as f:
            log = f.read()
        self.assertIn("wrote no units/1.done", log)


if __name__ == "__main__":
    REPO = sys.argv.pop(1)
    unittest.main(verbosity=2)
