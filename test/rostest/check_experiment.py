#!/usr/bin/env python3
"""Checks a running experiment launch file (lightworld_experiment.launch,
nao_arm_exploration.launch): waits until the experiment node reports that it finished, then
asserts that the run folder holds the expected logs and that actions and rewards flowed
(rl_agent/rl_action, rl_agent/rl_reward_breakdown). Parameters: ~out, ~steps, ~trials,
~num_actions (the environment's), ~seed (the run seed), ~timeout (seconds), ~bag (with
record:=true: the recording, whose recorder must be subscribed to ~recorded topics)."""
import csv
import struct
import os
import unittest

import rosgraph.masterapi
import rospy
import rostest
from rl_msgs.msg import RLAction, RLRewardBreakdown
from std_msgs.msg import String


class Experiment(unittest.TestCase):
    def setUp(self):
        self.progress = []
        self.actions = []
        self.breakdowns = []
        rospy.Subscriber("rl_experiment/progress", String, lambda m: self.progress.append(m.data))
        rospy.Subscriber("rl_agent/rl_action", RLAction, lambda m: self.actions.append(m.action))
        rospy.Subscriber("rl_agent/rl_reward_breakdown", RLRewardBreakdown,
                         lambda m: self.breakdowns.append(m))

    def test_logs_and_flow(self):
        out = rospy.get_param("~out")
        steps = int(rospy.get_param("~steps"))
        trials = int(rospy.get_param("~trials"))
        num_actions = int(rospy.get_param("~num_actions"))
        deadline = rospy.Time.now() + rospy.Duration(float(rospy.get_param("~timeout", 100)))
        while not rospy.is_shutdown() and rospy.Time.now() < deadline:
            if any(p.startswith("finished") for p in self.progress):
                break
            rospy.sleep(0.2)
        finished = [p for p in self.progress if p.startswith("finished")]
        self.assertTrue(finished, "no 'finished' on rl_experiment/progress; got %s" %
                        self.progress[-5:])
        self.assertEqual(finished[-1], "finished: %d/%d trials" % (trials, trials))
        for t in range(trials):
            with open(os.path.join(out, "steps-%03d.csv" % t)) as f:
                rows = list(csv.DictReader(f))
            self.assertEqual(len(rows), steps, "steps-%03d.csv" % t)
            self.assertEqual([int(r["step"]) for r in rows], list(range(steps)))
            actions = {int(r["action"]) for r in rows}
            self.assertTrue(actions <= set(range(num_actions)), actions)
            self.assertGreater(len(actions), 1, "the agent always took the same action")
            # TEXPLORE-VANIR reports its novelty reward for the steps.
            self.assertTrue(any(r["novelty"] not in ("", "0") for r in rows))
        with open(os.path.join(out, "trials.csv")) as f:
            summary = list(csv.DictReader(f))
        self.assertEqual([int(r["trial"]) for r in summary], list(range(trials)))
        self.assertTrue(all(int(r["steps"]) == steps for r in summary))
        with open(os.path.join(out, "run.csv")) as f:
            run = {r["name"]: r["value"] for r in csv.DictReader(f)}
        self.assertIn("suite_version", run)
        self.assertEqual(run["run_seed"], str(rospy.get_param("~seed")))
        # Actions and rewards went over the topics while we listened.
        self.assertGreater(len(self.actions), 0)
        self.assertGreater(len(self.breakdowns), 0)
        self.assertTrue(all(0 <= a < num_actions for a in self.actions))
        # record:=true: a rosbag recorder subscribed to the rl topics, writing the bag (still
        # ".active" while the launch runs).
        bag = rospy.get_param("~bag", "")
        if bag:
            state = rosgraph.masterapi.Master("/check_experiment").getSystemState()
            subscribers = {topic: nodes for topic, nodes in state[1]}
            for topic in rospy.get_param("~recorded").split():
                self.assertIn("/record", subscribers.get(topic, []),
                              "%s is not recorded: %s" % (topic, subscribers.get(topic)))
            self.assertTrue(os.path.exists(bag) or os.path.exists(bag + ".active"),
                            "no bag at %s" % bag)
        # The launch file's agent journal: a header, then the original's record layout with
        # one record per step the agent learned from (a trial's first state teaches nothing).
        journal = rospy.get_param("~journal", "")
        if journal:
            with open(journal, "rb") as f:
                data = f.read()
            self.assertTrue(data.startswith(b"RL_EXPERIENCE_JOURNAL 1\n"), data[:40])
            body = data[data.index(b"\nend\n") + 5:]
            nfeats = struct.unpack("=i", body[:4])[0]
            record = 2 * nfeats * 4 + 4 + 4 + 1
            self.assertEqual((len(body) - 4) % record, 0, "a partial record")
            self.assertGreaterEqual((len(body) - 4) // record, trials * (steps - 1))


if __name__ == "__main__":
    rospy.init_node("check_experiment")
    rostest.rosrun("rl_texplore_tests", "experiment", Experiment)
