#!/usr/bin/python3
"""~cases (200) seeded mutations of a valid parameter file (infinities, 1e308, 1e-300, wrong
types, huge strings, missing and unknown keys, yarns and fabrics past the budget) are each loaded by
check_config, which validates exactly as yarn_tearing_node does and then simulates up to 1 s.
Each must exit 0 (valid, and the simulation stayed finite) or 1 with a message naming a parameter
of its namespace; never 3 (valid but non-finite) and never a signal."""
import copy
import random
import unittest

import rosparam
import roslib.packages
import rospy
import rostest
from yarn_rostest_support import run_under_names

SEED = 10
CASES = 200     # unless ~cases says
TIMEOUT = 30.0  # [s] per case
HUGE = 100000   # [characters]

VALUES = [float("nan"), float("inf"), -float("inf"), 1.0e308, -1.0e308, 1.0e300, 1.0e-300,
          1.0e-200, 5.0e-324, 0.0, -0.0, -1.0, 0, 1, -1, 2 ** 31 - 1, -2 ** 31, 100001, 1.0e7,
          "x", "1e8", "x" * HUGE, True, [], [0.0], [1.0e308, 0.0, 0.0],
          [float("inf"), 0.0, 0.0], [0.0, 0.0, 0.0], {}, {"a": 1}, None]


def paths(tree, prefix=()):
    """Every key path in a YAML tree (dict keys and list indices)."""
    items = tree.items() if isinstance(tree, dict) else enumerate(tree) \
        if isinstance(tree, list) else []
    for key, value in items:
        yield prefix + (key,)
        yield from paths(value, prefix + (key,))


def mutate(config, rng):
    """1-3 mutations: a value replaced (from VALUES or scaled by 10^k), a key deleted or added."""
    config = copy.deepcopy(config)
    for _ in range(rng.randint(1, 3)):
        path = rng.choice(list(paths(config)))
        parent = config
        for key in path[:-1]:
            parent = parent[key]
        key = path[-1]
        action = rng.random()
        if action < 0.1 and isinstance(parent, dict):
            del parent[key]
        elif action < 0.15 and isinstance(parent, dict):
            parent["unknown_%d" % rng.randint(0, 99)] = 1.0
        elif action < 0.45 and isinstance(parent[key], (int, float)) and \
                not isinstance(parent[key], bool):
            parent[key] = float(parent[key] or 1.0) * 10.0 ** rng.randint(-300, 300)
        elif action < 0.5 and isinstance(parent[key], list) and \
                isinstance(config.get("yarns"), list) and config["yarns"] and \
                isinstance(config["yarns"][0], dict):
            count, vertices = rng.choice([(11, 100000), (3, 2000)])  # past / within budget
            config["yarns"] = [dict(config["yarns"][0], name="y%d" % i, num_vertices=vertices)
                               for i in range(count)]
        elif action < 0.5 and isinstance(config.get("fabrics"), list) and config["fabrics"] and \
                isinstance(config["fabrics"][0], dict):
            ends, picks = rng.choice([(577, 576), (257, 256), (16, 12)])  # past / within budget
            config["fabrics"][0] = dict(config["fabrics"][0], ends=ends, picks=picks)
        else:
            value = rng.choice(VALUES)
            if value is None:
                continue
            parent[key] = copy.deepcopy(value)
    return config


class ParameterFuzzTest(unittest.TestCase):
    def test_mutated_files_exit_0_or_1_naming_a_parameter(self):
        rospy.init_node("parameter_fuzz_test")
        checker = roslib.packages.find_node("yarn_tearing", "check_config")[0]
        materials = rosparam.load_file(rospy.get_param("~materials"))[0][0]
        valid = rosparam.load_file(rospy.get_param("~config"))[0][0]
        rng = random.Random(SEED)
        cases = rospy.get_param("~cases", CASES)
        outcomes = {0: 0, 1: 0}
        uploaded = []  # (case, name, config), in the seeded order
        for case in range(cases):
            name = "fuzz_%d" % case
            config = mutate(valid, rng)
            try:
                rosparam.upload_params("/" + name, materials)
                rosparam.upload_params("/" + name, config)
            except Exception:  # a value XML-RPC cannot carry: nothing to check
                continue
            uploaded.append((case, name, config))

        results = run_under_names(checker, [name for _, name, _ in uploaded], TIMEOUT)
        for (case, name, config), result in zip(uploaded, results):
            with self.subTest(case=case, config=str(config)[:2000]):
                self.assertIn(result.returncode, (0, 1), result.stderr[-2000:])
                if result.returncode == 1:
                    self.assertRegex(result.stderr, r"(invalid|missing) parameter /%s/" % name)
                outcomes[result.returncode] = outcomes.get(result.returncode, 0) + 1
            rosparam.delete_param("/" + name)
        rospy.loginfo("parameter fuzz: %d valid, %d refused", outcomes[0], outcomes[1])
        self.assertGreater(outcomes[0], 10, "too few mutations left the file valid")
        self.assertGreater(outcomes[1], cases // 2, "too few mutations were refused")


if __name__ == "__main__":
    rostest.rosrun("yarn_tearing", "parameter_fuzz", ParameterFuzzTest)
