#!/usr/bin/env python3
"""Bad options to the suite's nodes with no ROS master to reach: each node prints one
"program: message" line (no doubled prefix) and exits 2 at once, instead of waiting for a
master that no parameter could come from; a good command line still waits for one (roscpp's
behaviour). The nodes are the built ones (`rosrun`, the workspace sourced).

Run with the workspace sourced: /usr/bin/python3 test/scripts/test_node_errors.py [--xunit FILE]
(`./rl test` registers it with catkin_run_tests_target).
"""
import os
import subprocess
import sys
import unittest

# A port no master listens on: the nodes see no master.
NO_MASTER = dict(os.environ, ROS_MASTER_URI="http://localhost:1", ROS_HOSTNAME="localhost")


def run(package, node, *args, timeout=20):
    return subprocess.run(["rosrun", package, node, *args], env=NO_MASTER, timeout=timeout,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


class BadOptionsWithoutMaster(unittest.TestCase):
    def check(self, package, node, program, args, expected):
        done = run(package, node, *args)
        self.assertEqual(done.returncode, 2, done.stderr)
        errors = [line for line in done.stderr.splitlines() if line.startswith(program + ":")]
        self.assertEqual(len(errors), 1, done.stderr)
        self.assertNotIn(program + ": " + program + ":", errors[0])
        self.assertIn(expected, errors[0])

    def test_env_unknown_environment(self):
        self.check("rl_env", "env", "env", ["--env", "nosuch"], "nosuch")

    def test_env_unknown_option(self):
        self.check("rl_env", "env", "env", ["--nosuch", "1"], "unknown option '--nosuch'")

    def test_env_render_without_a_view(self):
        self.check("rl_env", "env", "env", ["--env", "taxi", "--render"],
                   "taxi has no rendered view")

    def test_agent_failed_check(self):
        self.check("rl_agent", "agent", "agent", ["--agent", "nosuch"], "nosuch")

    def test_experiment_node_bad_value(self):
        self.check("rl_experiment", "experiment_node", "experiment_node", ["--steps", "0"],
                   "--steps")

    def test_good_command_line_waits_for_a_master(self):
        with self.assertRaises(subprocess.TimeoutExpired):
            run("rl_env", "env", "--env", "taxi", timeout=3)


if __name__ == "__main__":
    argv = sys.argv[1:]
    if "--xunit" in argv:
        path = argv[argv.index("--xunit") + 1]
        import rosunit
        suite = unittest.defaultTestLoader.loadTestsFromTestCase(BadOptionsWithoutMaster)
        result = rosunit.create_xml_runner("rl_texplore_tests", "test_node_errors",
                                           results_file=path).run(suite)
        sys.exit(0 if result.wasSuccessful() else 1)
    unittest.main()
