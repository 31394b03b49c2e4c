#!/usr/bin/python3
"""Every file in test/ros/config/invalid/ makes yarn_tearing_node exit non-zero at start with a
message on stderr that names the offending parameter (the file's `# expect: <text>` line).

Each config is uploaded to its own namespace /invalid_<file>, and the node binary is run
directly with __name:=invalid_<file> so that it reads it as its private parameters."""
import glob
import os
import re
import unittest

import rosparam
import roslib.packages
import rospy
import rostest
from yarn_rostest_support import run_under_names

NODE_TIMEOUT = 20.0  # [s]


def expected_text(path):
    with open(path) as stream:
        match = re.search(r"^# expect: (.+)$", stream.read(), re.MULTILINE)
    if match is None:
        raise ValueError("%s has no '# expect: <text>' line" % path)
    return match.group(1).strip()


class InvalidConfigTest(unittest.TestCase):
    def test_invalid_configs_exit_non_zero_naming_the_parameter(self):
        rospy.init_node("invalid_config_test")
        node_binary = roslib.packages.find_node("yarn_tearing", "yarn_tearing_node")[0]
        materials = rosparam.load_file(rospy.get_param("~materials"))[0][0]
        files = sorted(glob.glob(os.path.join(rospy.get_param("~config_dir"), "*.yaml")))
        self.assertGreater(len(files), 5)
        cases = [os.path.splitext(os.path.basename(path))[0] for path in files]
        names = ["invalid_" + case for case in cases]
        for path, name in zip(files, names):
            rosparam.upload_params("/" + name, materials)
            for params, namespace in rosparam.load_file(path):
                rosparam.upload_params("/" + name, params)

        results = run_under_names(node_binary, names, NODE_TIMEOUT)
        for path, case, name, result in zip(files, cases, names, results):
            with self.subTest(case=case):
                self.assertNotEqual(result.returncode, 0, "%s: the node did not fail" % case)
                expect = expected_text(path)
                self.assertIn(expect, result.stderr,
                              "%s: stderr does not name '%s':\n%s" % (case, expect, result.stderr))
                self.assertRegex(result.stderr, r"(invalid|missing) parameter /%s/" % name)


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "invalid_config", InvalidConfigTest)
