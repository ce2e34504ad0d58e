#!/usr/bin/env python3
"""Run by experiment_node_resume.test: kill the experiment node mid-run, resume it, and check
that the finished trial was kept as it was and the others ran once."""
import csv
import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

import rospy
import rostest


def node(out, *extra):
    return subprocess.Popen(["rosrun", "rl_experiment", "experiment_node", "__name:=experiment",
                             "--steps", "40", "--trials", "3", "--seed", "5", "--out", out] +
                            list(extra), stdout=subprocess.PIPE, stderr=subprocess.STDOUT)


class Resume(unittest.TestCase):
    def test_killed_run_resumes(self):
        base = tempfile.mkdtemp(prefix="rl_resume_")
        out = os.path.join(base, "run")
        first = node(out)
        summary0 = os.path.join(out, "trial-000.csv")
        deadline = time.time() + 60
        while not os.path.exists(summary0) and time.time() < deadline:
            time.sleep(0.05)
        self.assertTrue(os.path.exists(summary0), "trial 0 did not finish within 60 s")
        first.send_signal(signal.SIGKILL)
        first.wait()
        with open(summary0, "rb") as f:
            kept = f.read()
        done_before = sorted(n for n in os.listdir(out) if n.startswith("trial-"))
        self.assertLess(len(done_before), 3, "the run finished before the kill")

        second = node(out, "--resume")
        text, _ = second.communicate(timeout=120)
        text = text.decode(errors="replace")
        self.assertEqual(second.returncode, 0, text)
        self.assertIn("resuming: %d trial(s) already finished" % len(done_before), text)
        with open(summary0, "rb") as f:
            self.assertEqual(f.read(), kept, "the finished trial was rewritten")
        with open(os.path.join(out, "trials.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual([int(r["trial"]) for r in rows], [0, 1, 2])
        self.assertTrue(all(int(r["steps"]) == 40 for r in rows))
        # A different configuration is refused rather than mixed into the folder.
        third = subprocess.run(["rosrun", "rl_experiment", "experiment_node",
                                "__name:=experiment", "--steps", "41", "--trials", "3", "--seed",
                                "5", "--out", out, "--resume"], capture_output=True, timeout=60)
        self.assertNotEqual(third.returncode, 0)
        self.assertIn(b"different configuration", third.stdout + third.stderr)
        shutil.rmtree(base)


if __name__ == "__main__":
    rospy.init_node("check_resume")
    rostest.rosrun("rl_texplore_tests", "resume", Resume)
