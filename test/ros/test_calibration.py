#!/usr/bin/env python3
"""Calibration through the node, as a robot with a camera would use it. Two shots are drawn by ~predict_shot with
a rolling friction of 0.015 (the node's own is 0.01) and published on ~table_state as a camera would see them (every
third path sample, 1 mm noise): one recorded before its sightings arrive, from the latest TableState before the
strike; one recorded after them, with its table in the request. ~fit_calibration finds the rolling friction within
3 sigma, from every sighting; bad requests are refused by name; ~clear_shots forgets the shots.
"""
import random
import sys
import unittest

import rospy
import rostest
from std_srvs.srv import Trigger

from billiard_shot_planner.msg import Ball, TableState
from billiard_shot_planner.srv import (FitCalibration, FitCalibrationRequest, PredictShot, PredictShotRequest,
                                       RecordShot, RecordShotRequest)

NODE = "/shot_predictor/"
RADIUS = 0.0286
TRUE_ROLLING_FRICTION = 0.015
NOISE = 0.001  # m


def table_state(stamp, positions):
    table = TableState()
    table.header.frame_id = "table"
    table.header.stamp = stamp
    for ball_id, (x, y) in positions.items():
        ball = Ball()
        ball.id = ball_id
        ball.position.x, ball.position.y = x, y
        table.balls.append(ball)
    return table


def level_cue(x, y):
    """A level cue along +x, its tip 1 mm behind the ball at (x, y) and a third of a radius above its centre."""
    request = RecordShotRequest()
    request.cue_pose.header.frame_id = "table"
    request.cue_pose.pose.position.x = x - RADIUS - 0.001
    request.cue_pose.pose.position.y = y
    request.cue_pose.pose.position.z = RADIUS * 4.0 / 3.0
    request.cue_pose.pose.orientation.w = 1.0
    request.cue_speed = 0.8
    return request


class CalibrationTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_calibration")
        for name in ("predict_shot", "record_shot", "fit_calibration", "clear_shots"):
            rospy.wait_for_service(NODE + name, timeout=30)
        cls.predict = rospy.ServiceProxy(NODE + "predict_shot", PredictShot)
        cls.record = rospy.ServiceProxy(NODE + "record_shot", RecordShot)
        cls.fit = rospy.ServiceProxy(NODE + "fit_calibration", FitCalibration)
        cls.clear = rospy.ServiceProxy(NODE + "clear_shots", Trigger)
        cls.camera = rospy.Publisher(NODE + "table_state", TableState, queue_size=1000)
        deadline = rospy.Time.now() + rospy.Duration(10)
        while cls.camera.get_num_connections() == 0 and rospy.Time.now() < deadline:
            rospy.sleep(0.05)
        cls.rng = random.Random(5)

    def truth_path(self, shot, x, y):
        """The cue ball's path from (x, y) as the true constants make it: [(t, x, y)]."""
        request = PredictShotRequest()
        request.cue_pose, request.cue_speed = shot.cue_pose, shot.cue_speed
        request.table = table_state(rospy.Time(0), {"cue": (x, y)})
        request.override_names = ["motion/rolling_friction"]
        request.override_values = [TRUE_ROLLING_FRICTION]
        answer = self.predict(request)
        self.assertTrue(answer.success, answer.message)
        return [(s.time, s.position.x, s.position.y) for s in answer.prediction.trajectory[::3]]

    def publish_sightings(self, strike, path):
        for t, x, y in path:
            seen = (x + self.rng.gauss(0.0, NOISE), y + self.rng.gauss(0.0, NOISE))
            self.camera.publish(table_state(strike + rospy.Duration(t), {"cue": seen}))
            rospy.sleep(0.004)
        return len(path)

    def test_a_recorded_shots_fit_back_to_the_constant_that_drew_them(self):
        self.assertTrue(self.clear().success)
        clock = rospy.Time.now()
        # Recorded before its sightings: its table is the latest TableState stamped before the strike.
        first = level_cue(-0.8, 0.2)
        self.camera.publish(table_state(clock, {"cue": (-0.8, 0.2)}))
        rospy.sleep(0.3)
        first.strike_time = clock + rospy.Duration(0.1)
        answer = self.record(first)
        self.assertTrue(answer.success, answer.message)
        self.assertEqual((answer.shot_index, answer.shots_recorded), (0, 1))
        sightings = self.publish_sightings(first.strike_time, self.truth_path(first, -0.8, 0.2))
        # Recorded after its sightings, with its table in the request.
        second = level_cue(-0.3, -0.25)
        second.strike_time = clock + rospy.Duration(30.0)
        sightings += self.publish_sightings(second.strike_time, self.truth_path(second, -0.3, -0.25))
        rospy.sleep(0.5)
        second.table = table_state(rospy.Time(0), {"cue": (-0.3, -0.25)})
        answer = self.record(second)
        self.assertTrue(answer.success, answer.message)
        self.assertEqual(answer.shots_recorded, 2)

        request = FitCalibrationRequest()
        request.fit = ["motion/rolling_friction"]
        request.position_noise = NOISE
        fitted = self.fit(request)
        self.assertTrue(fitted.success, fitted.message)
        print("fitted rolling friction %.6f +- %.6f from %d sightings, residuals %s m"
              % (fitted.values[0], fitted.sigmas[0], sightings, fitted.residuals))
        self.assertEqual(fitted.shots, 2)
        self.assertEqual(fitted.observations, 2 * sightings, "every sighting is a track point")
        self.assertEqual(fitted.names, ["motion/rolling_friction"])
        self.assertTrue(fitted.identifiable[0])
        self.assertLess(fitted.sigmas[0], 0.0005)
        self.assertLess(abs(fitted.values[0] - TRUE_ROLLING_FRICTION), 3.0 * fitted.sigmas[0])
        self.assertEqual(len(fitted.residuals), 2)
        self.assertLess(max(fitted.residuals), 3.0 * NOISE)
        self.assertIn("rolling_friction", fitted.overlay_yaml)

    def test_b_bad_requests_are_refused_by_name(self):
        request = FitCalibrationRequest()
        cases = [([], "fit"), (["motion/no_such_thing"], "fit[0]")]
        for names, field in cases:
            request.fit = names
            answer = self.fit(request)
            self.assertFalse(answer.success)
            self.assertIn(field, answer.message)
        request.fit = ["motion/rolling_friction"]
        request.budget = -1.0
        answer = self.fit(request)
        self.assertFalse(answer.success)
        self.assertIn("budget", answer.message)

        shot = level_cue(0.0, 0.0)
        shot.table = table_state(rospy.Time(0), {"one": (0.5, 0.0)})
        answer = self.record(shot)
        self.assertFalse(answer.success)
        self.assertIn("table.balls", answer.message)
        shot = level_cue(0.0, 0.0)
        shot.table = table_state(rospy.Time(0), {"cue": (0.0, 0.0)})
        shot.cue_speed = 0.0
        answer = self.record(shot)
        self.assertFalse(answer.success)
        self.assertIn("cue_speed", answer.message)
        shot = level_cue(0.0, 0.0)
        shot.table = table_state(rospy.Time(0), {"cue": (0.0, 0.5)})  # the cue misses its ball
        answer = self.record(shot)
        self.assertFalse(answer.success)

    def test_c_cleared_shots_are_gone(self):
        answer = self.clear()
        self.assertTrue(answer.success, answer.message)
        request = FitCalibrationRequest()
        request.fit = ["motion/rolling_friction"]
        answer = self.fit(request)
        self.assertFalse(answer.success)
        self.assertIn("shots", answer.message)


if __name__ == "__main__":
    rostest.rosrun("billiard_shot_planner", "calibration", CalibrationTest, sys.argv)
