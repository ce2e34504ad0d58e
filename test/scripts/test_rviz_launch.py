#!/usr/bin/env python3
"""The rviz:=true launch args (issue 17), checked without a display: roslaunch's own config
loader reads nao_arm_exploration.launch and nao_arm_sim.launch with rviz:=false and rviz:=true;
only with true do robot_state_publisher (on the suite's URDF, as robot_description) and rviz (with
the committed config) appear, and the config parses as YAML and names the displays and topics
the view needs. lightworld_experiment.launch likewise: rviz:=true adds rviz on the LightWorld
config and turns the env node's rendering (~render) on; off by default. And every node those
launches start with rviz:=true resolves to an executable, as roslaunch resolves it: rviz and
robot_state_publisher come from ./rl's apt packages, so the set-up commands are enough.

Run with the workspace sourced: /usr/bin/python3 test/scripts/test_rviz_launch.py [--xunit FILE]
(`./rl test` registers it with catkin_run_tests_target).
"""
import os
import sys
import unittest

import roslaunch.config
import roslib.packages
import rospkg
import yaml

SUITE = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
EXPLORATION = os.path.join(SUITE, "launch", "launch", "nao_arm_exploration.launch")
NAO = rospkg.RosPack().get_path("nao_interface")
SIM = os.path.join(NAO, "launch", "nao_arm_sim.launch")
CONFIG = os.path.join(NAO, "rviz", "nao_arm.rviz")
URDF = os.path.join(NAO, "urdf", "nao_upper_body.urdf")
LIGHTWORLD = os.path.join(SUITE, "launch", "launch", "lightworld_experiment.launch")
LIGHTWORLD_CONFIG = os.path.join(rospkg.RosPack().get_path("rl_env"), "rviz", "lightworld.rviz")


def load(launch_file, *args):
    return roslaunch.config.load_config_default([(launch_file, list(args))], None)


def nodes_by_package(config):
    return {n.package: n for n in config.nodes}


def displays(config_file):
    with open(config_file) as f:
        doc = yaml.safe_load(f)
    return doc["Visualization Manager"]["Displays"], doc["Visualization Manager"]


class RvizArg(unittest.TestCase):
    def check_launch(self, launch_file, *extra):
        off = nodes_by_package(load(launch_file, "rviz:=false", *extra))
        self.assertNotIn("rviz", off)
        self.assertNotIn("robot_state_publisher", off)
        self.assertEqual(set(nodes_by_package(load(launch_file, *extra))), set(off),
                         "rviz must default to false")
        config = load(launch_file, "rviz:=true", *extra)
        on = nodes_by_package(config)
        self.assertEqual(set(on) - set(off), {"rviz", "robot_state_publisher"})
        self.assertEqual(on["robot_state_publisher"].type, "robot_state_publisher")
        self.assertEqual(on["rviz"].type, "rviz")
        # rviz opens the committed config.
        args = on["rviz"].args.split()
        self.assertIn("-d", args)
        self.assertEqual(os.path.realpath(args[args.index("-d") + 1]), os.path.realpath(CONFIG))
        # robot_state_publisher gets the suite's URDF.
        description = config.params.get("/robot_description")
        self.assertIsNotNone(description, "no /robot_description parameter")
        with open(URDF) as f:
            self.assertEqual(description.value, f.read())
        return on

    def test_exploration_launch(self):
        self.check_launch(EXPLORATION)
        # With a real robot's driver too (no simulator).
        on = self.check_launch(EXPLORATION, "sim:=false")
        self.assertNotIn("nao_arm_sim", {n.type for n in on.values()})

    def test_sim_launch(self):
        self.check_launch(SIM)

    def test_lightworld_launch(self):
        def render(config):
            return config.params["/env/render"].value

        default = load(LIGHTWORLD)
        off = load(LIGHTWORLD, "rviz:=false")
        self.assertEqual(set(nodes_by_package(default)), set(nodes_by_package(off)),
                         "rviz must default to false")
        self.assertNotIn("rviz", nodes_by_package(off))
        self.assertIs(render(default), False)
        on_config = load(LIGHTWORLD, "rviz:=true")
        on = nodes_by_package(on_config)
        self.assertEqual(set(on) - set(nodes_by_package(off)), {"rviz"})
        self.assertIs(render(on_config), True)
        self.assertEqual(on["rl_env"].type, "env")
        args = on["rviz"].args.split()
        self.assertEqual(os.path.realpath(args[args.index("-d") + 1]),
                         os.path.realpath(LIGHTWORLD_CONFIG))


class RvizConfig(unittest.TestCase):
    def test_config_names_the_displays_and_topics(self):
        shown, manager = displays(CONFIG)
        by_class = {}
        for d in shown:
            by_class.setdefault(d["Class"], []).append(d)
            self.assertTrue(d.get("Enabled"), d["Name"])
        self.assertEqual(by_class["rviz/RobotModel"][0]["Robot Description"], "robot_description")
        self.assertIn("rviz/TF", by_class)
        images = {d["Image Topic"] for d in by_class["rviz/Image"]}
        self.assertEqual(images, {"/naoqi_driver/camera/front/image_raw",
                                  "/nao_arm_bridge/pink_mask"})
        self.assertEqual(by_class["rviz/MarkerArray"][0]["Marker Topic"], "/nao_arm_bridge/markers")
        # The fixed frame is the URDF's root link.
        self.assertEqual(manager["Global Options"]["Fixed Frame"], "torso")
        with open(URDF) as f:
            self.assertIn('<link name="torso">', f.read())

    def test_lightworld_config_shows_the_rendered_grid(self):
        shown, manager = displays(LIGHTWORLD_CONFIG)
        self.assertEqual([(d["Class"], d["Image Topic"], d["Enabled"]) for d in shown],
                         [("rviz/Image", "/rl_env/image", True)])
        # The env node's image frame (rl_env/render), so rviz reports no missing frame.
        self.assertEqual(manager["Global Options"]["Fixed Frame"], "rl_env")


class RvizInstalled(unittest.TestCase):
    def test_every_rviz_node_resolves_to_an_executable(self):
        for launch_file in (EXPLORATION, SIM, LIGHTWORLD):
            for node in load(launch_file, "rviz:=true").nodes:
                with self.subTest(launch=os.path.basename(launch_file), node=node.type):
                    found = roslib.packages.find_node(node.package, node.type)
                    self.assertTrue(found, "%s/%s is not installed" % (node.package, node.type))
                    self.assertTrue(os.access(found[0], os.X_OK), found[0])


if __name__ == "__main__":
    argv = sys.argv[1:]
    if "--xunit" in argv:
        i = argv.index("--xunit")
        path = argv[i + 1]
        import rosunit
        suite = unittest.TestSuite(unittest.defaultTestLoader.loadTestsFromTestCase(c)
                                   for c in (RvizArg, RvizConfig, RvizInstalled))
        result = rosunit.create_xml_runner("rl_texplore_tests", "test_rviz_launch",
                                           results_file=path).run(suite)
        sys.exit(0 if result.wasSuccessful() else 1)
    unittest.main()
