#!/usr/bin/env python3
"""bag_to_tracks on a bag written here: a cue ball at rest for three frames, then rolling at 1 m/s along x at
30 Hz, beside a ball that stays put; the strike's time found from the motion, the tracks relative to it, and bad
input refused with exit code 2."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

import rosbag
import rospy
from geometry_msgs.msg import Point

from billiard_shot_planner.msg import Ball, TableState

TOOL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "nodes", "bag_to_tracks")
TOPIC = "/shot_predictor/table_state"
T0 = 100.0  # the bag's clock at the first frame, s
FRAME = 1.0 / 30.0


def cue_x(k):
    """The cue ball's x at frame k: at rest for frames 0–2, then 1 m/s from the strike at frame 2."""
    return max(0.0, (k - 2) * FRAME)


def write_bag(path):
    with rosbag.Bag(path, "w") as bag:
        for k in range(33):
            state = TableState()
            state.header.stamp = rospy.Time.from_sec(T0 + k * FRAME)
            state.header.frame_id = "table"
            state.balls = [Ball(id="cue", position=Point(cue_x(k), 0.1, 0.0)),
                           Ball(id="one", position=Point(0.5, 0.2, 0.0))]
            if k == 10:
                state.balls = state.balls[1:]  # a missed frame of the cue ball
            bag.write(TOPIC, state, state.header.stamp)


def run(*args):
    result = subprocess.run([sys.executable, TOOL] + list(args), capture_output=True, text=True)
    return result.returncode, result.stdout, result.stderr


class BagToTracks(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.bag = os.path.join(self.dir.name, "shot.bag")
        write_bag(self.bag)

    def tearDown(self):
        self.dir.cleanup()

    def test_tracks_start_at_the_strike(self):
        code, out, err = run(self.bag, "--duration", "0.5")
        self.assertEqual(code, 0, err)
        answer = json.loads(out)
        self.assertAlmostEqual(answer["strike_time"], T0 + 2 * FRAME, places=6)
        cue = answer["tracks"]["cue"]
        # Frames 2 to 17 lie within 0.5 s of the strike; frame 10 has no cue ball.
        self.assertEqual(len(cue), 15)
        for t, x, y in cue:
            k = round(t / FRAME) + 2
            self.assertNotEqual(k, 10)
            self.assertAlmostEqual(x, cue_x(k), places=9)
            self.assertAlmostEqual(y, 0.1, places=9)
        self.assertEqual(cue[0][0], 0.0)
        self.assertEqual(len(answer["tracks"]["one"]), 16)

    def test_a_given_strike_time_is_used(self):
        code, out, err = run(self.bag, "--strike-time", str(T0), "--duration", "0.05")
        self.assertEqual(code, 0, err)
        times = [p[0] for p in json.loads(out)["tracks"]["cue"]]
        self.assertEqual(len(times), 2)
        for t, expected in zip(times, [0.0, FRAME]):
            self.assertAlmostEqual(t, expected, places=8)  # stamps hold nanoseconds

    def test_bad_input_exits_2_with_the_reason(self):
        for args, reason in [((os.path.join(self.dir.name, "none.bag"),), "cannot read"),
                             ((self.bag, "--topic", "/other"), "no message"),
                             ((self.bag, "--cue-ball", "seven"), "in no message"),
                             ((self.bag, "--move-threshold", "10"), "never moves"),
                             ((self.bag, "--duration", "-1"), "--duration")]:
            code, _, err = run(*args)
            self.assertEqual(code, 2, args)
            self.assertIn(reason, err, args)


if __name__ == "__main__":
    unittest.main()
