#!/usr/bin/env python3
"""The Slurm backend on a one-node cluster of this machine (tools/slurm_local.sh).

Starts the cluster, submits a small sweep with the runner's --slurm (2 agents x 2 trials x 50
steps, one array task per trial), waits for the merge jobs, compares every per-trial file
with the same sweep run locally (--jobs 2), resubmits after deleting one task's folder (only
that task runs again), checks the option rules and reproduce.py's arrays (dry run), then
stops the cluster. If the cluster does not start the test fails with the daemons' log lines.

Run: /usr/bin/python3 rl_experiment/test/test_slurm.py EXPERIMENT_BINARY [--xunit FILE]
(root: the cluster's daemons run as root). `./rl test` runs it.
"""
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
SCRIPTS = os.path.join(ROOT, "rl_experiment", "scripts")
CLUSTER = os.path.join(ROOT, "tools", "slurm_local.sh")
sys.path.insert(0, SCRIPTS)
sys.path.insert(0, HERE)
import slurm_sweep  # noqa: E402

EXPERIMENT = None  # set by main()
STATE = None       # the cluster's state folder, private to this test
# The columns of trial-NNN.csv and trials.csv that depend on the machine's load.
TIMING = {"seconds", "steps_per_second", "peak_rss_mb"}
AGENTS = {
    "vanir": ["--agent", "texplore", "--v", "1", "--n", "3", "--rollouts", "20", "--lambda", "1"],
    "qlearner": ["--agent", "qlearner"],
}
COMMON = ["--env", "lightworld", "--steps", "50", "--trials", "2", "--seed", "11",
          "--eval-every", "25", "--eval-samples", "200"]


def env():
    e = dict(os.environ)
    e["PATH"] = "/usr/sbin:/usr/bin:/sbin:/bin:" + e.get("PATH", "")
    e["RL_SLURM_DIR"] = STATE
    e["SLURM_CONF"] = os.path.join(STATE, "slurm.conf")
    return e


def run(cmd, check=True):
    res = subprocess.run(cmd, capture_output=True, text=True, env=env())
    if check and res.returncode != 0:
        raise AssertionError("%s exited %d:\n%s%s" % (" ".join(cmd), res.returncode, res.stdout,
                                                      res.stderr))
    return res


def job_ids(stdout):
    m = re.search(r"submitted: array job (\S+) \(\d+ tasks\), merge job (\S+)", stdout)
    if not m:
        raise AssertionError("no job ids in:\n" + stdout)
    return [i for i in m.groups() if i != "none"]


def wait_for(ids, timeout=600):
    t0 = time.time()
    while time.time() - t0 < timeout:
        out = run(["squeue", "-h", "-o", "%i %T", "-j", ",".join(ids)], check=False).stdout
        if not out.strip():
            return time.time() - t0
        time.sleep(1)
    raise AssertionError("jobs %s still queued after %d s:\n%s" % (ids, timeout, out))


def completed_states(ids):
    """{job id: state} from the job-completion log (sacct -c: no accounting database here)."""
    out = run(["sacct", "-c", "-n", "-P", "-o", "JobID,State"], check=False).stdout
    states = {}
    for line in out.splitlines():
        parts = line.split("|")
        if len(parts) == 2:
            states[parts[0].strip()] = parts[1].strip()
    return {i: states.get(i, "missing") for i in ids}


def rows_without_timing(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return sorted(({k: v for k, v in r.items() if k not in TIMING} for r in rows),
                  key=lambda r: int(r["trial"]))


def compare_folders(test, local, slurm):
    names = sorted(n for n in os.listdir(local) if n.endswith(".csv") and n != "run.csv")
    test.assertIn("steps-000.csv", names)
    for name in names:
        path = os.path.join(slurm, name)
        test.assertTrue(os.path.exists(path), "the merged folder lacks " + name)
        if name == "trials.csv" or name.startswith("trial-"):
            test.assertEqual(rows_without_timing(os.path.join(local, name)),
                             rows_without_timing(path), name)
        else:
            with open(os.path.join(local, name), "rb") as a, open(path, "rb") as b:
                test.assertEqual(a.read(), b.read(), name + " differs")
    return names


class SlurmSweep(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        res = subprocess.run([CLUSTER, "start"], capture_output=True, text=True, env=env())
        if res.returncode != 0:
            raise AssertionError("the one-node cluster did not start:\n" + res.stdout + res.stderr)
        cls.work = tempfile.mkdtemp(prefix="rl-slurm-test-")
        cls.timings = {}

    @classmethod
    def tearDownClass(cls):
        subprocess.run([CLUSTER, "stop"], capture_output=True, env=env())
        shutil.rmtree(cls.work, ignore_errors=True)

    def submit(self, label, out, extra=()):
        cmd = ([EXPERIMENT] + AGENTS[label] + COMMON
               + ["--label", label, "--slurm", "--trials-per-task", "1", "--out", out]
               + list(extra))
        res = run(cmd)
        return res.stdout

    def test_1_sweep_equals_local_run(self):
        ids, outs = [], {}
        t0 = time.time()
        for label in AGENTS:
            outs[label] = os.path.join(self.work, "slurm", label)
            stdout = self.submit(label, outs[label])
            self.assertIn("2 array tasks, 0 finished already", stdout)
            ids += job_ids(stdout)
        wait_for(ids)
        slurm_seconds = time.time() - t0
        self.assertEqual(set(completed_states(ids).values()), {"COMPLETED"},
                         completed_states(ids))
        t0 = time.time()
        for label in AGENTS:
            local = os.path.join(self.work, "local", label)
            run([EXPERIMENT] + AGENTS[label] + COMMON
                + ["--label", label, "--jobs", "2", "--progress", "off", "--out", local])
            names = compare_folders(self, local, outs[label])
            if label == "vanir":  # the forest's accuracy log (Q-learning has no model)
                self.assertIn("accuracy-001.csv", names)
        print("\nslurm sweep %.1f s (submit to merged), local %.1f s" % (slurm_seconds,
                                                                         time.time() - t0))
        # The merged run.csv records the whole sweep, like a local run's.
        with open(os.path.join(outs["vanir"], "run.csv")) as f:
            run_csv = dict(r[:2] for r in csv.reader(f) if len(r) >= 2)
        self.assertEqual(run_csv["option.trials"], "2")
        self.assertEqual(run_csv["option.first-trial"], "0")
        self.assertIn("--slurm", run_csv["command_line"])

    def test_2_rerun_resumes_and_resubmits_only_the_missing_task(self):
        out = os.path.join(self.work, "slurm", "vanir")
        self.assertTrue(os.path.exists(os.path.join(out, "trials.csv")), "test_1 ran first")
        stdout = self.submit("vanir", out)
        self.assertIn("2 array tasks, 2 finished already", stdout)
        self.assertIn("array job none", stdout)
        wait_for(job_ids(stdout))
        with open(os.path.join(out, "steps-001.csv"), "rb") as f:
            before = f.read()
        shutil.rmtree(os.path.join(out, "slurm", "parts", "trials-001-001"))
        os.remove(os.path.join(out, "steps-001.csv"))
        stdout = self.submit("vanir", out)
        self.assertIn("2 array tasks, 1 finished already", stdout)
        ids = job_ids(stdout)
        wait_for(ids)
        self.assertEqual(set(completed_states(ids).values()), {"COMPLETED"})
        with open(os.path.join(out, "steps-001.csv"), "rb") as f:
            self.assertEqual(f.read(), before)

    def test_3_merge_refuses_parts_of_different_runs(self):
        out = os.path.join(self.work, "mixed")
        for i, seed in enumerate(("11", "12")):
            part = os.path.join(out, "slurm", "parts", "trials-%03d-%03d" % (i, i))
            run([EXPERIMENT, "--agent", "qlearner", "--env", "lightworld", "--steps", "20",
                 "--seed", seed, "--first-trial", str(i), "--trials", "1", "--progress", "off",
                 "--out", part])
        with self.assertRaises(slurm_sweep.SweepError) as e:
            slurm_sweep.merge(out)
        self.assertIn("different configuration", str(e.exception))

    def test_4_option_rules(self):
        res = run([EXPERIMENT, "--env", "lightworld", "--partition", "x", "--out", "/tmp/x"],
                  check=False)
        self.assertEqual(res.returncode, 2)
        self.assertIn("option --partition needs --slurm", res.stderr)
        res = run([EXPERIMENT, "--env", "lightworld", "--slurm"], check=False)
        self.assertEqual(res.returncode, 2)
        self.assertIn("--slurm needs --out", res.stderr)
        res = run([EXPERIMENT, "--env", "lightworld", "--slurm", "--jobs", "2", "--out", "/tmp/x"],
                  check=False)
        self.assertEqual(res.returncode, 2)
        self.assertIn("--jobs does not combine with --slurm", res.stderr)

    def test_5_reproduce_submits_one_array_per_experiment(self):
        out = os.path.join(self.work, "reproduce")
        e = env()
        e["RL_EXPERIMENT"] = EXPERIMENT
        res = subprocess.run(["/usr/bin/python3", os.path.join(SCRIPTS, "reproduce.py"),
                              "lightworld", "--quick", "--trials", "3", "--slurm",
                              "--trials-per-task", "2", "--slurm-dry-run", "--out", out],
                             capture_output=True, text=True, env=e)
        self.assertEqual(res.returncode, 0, res.stdout + res.stderr)
        arrays = re.findall(r"would run: sbatch .*--array (\S+) ", res.stdout)
        self.assertEqual(len(arrays), 3, res.stdout)  # explore-task, combined, ablation
        self.assertEqual(len(arrays[2].split(",")), 4 * 2)  # 4 ablation agents x 2 blocks
        self.assertRegex(res.stdout, r"--dependency afterok:DRYRUN:DRYRUN:DRYRUN")
        with open(os.path.join(out, "slurm", "rl-lightworld-report.sh")) as f:
            report = f.read()
        self.assertIn("--collect", report)
        self.assertNotIn("--slurm", report)


def main(argv):
    global EXPERIMENT, STATE
    xunit = None
    if "--xunit" in argv:
        i = argv.index("--xunit")
        xunit = argv[i + 1]
        argv = argv[:i] + argv[i + 2:]
    if not argv:
        print(__doc__, file=sys.stderr)
        return 2
    EXPERIMENT = os.path.abspath(argv[0])
    STATE = tempfile.mkdtemp(prefix="rl-slurm-state-")
    suite = unittest.defaultTestLoader.loadTestsFromTestCase(SlurmSweep)
    if xunit is None:
        ok = unittest.TextTestRunner(verbosity=2).run(suite).wasSuccessful()
    else:
        from test_stats import _Recorder, write_xunit
        result = unittest.TextTestRunner(resultclass=_Recorder, verbosity=2).run(suite)
        write_xunit(xunit, result, "rl_experiment.test_slurm")
        ok = result.wasSuccessful()
    if ok:
        shutil.rmtree(STATE, ignore_errors=True)
    else:
        print("the cluster's logs: %s/log" % STATE, file=sys.stderr)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
