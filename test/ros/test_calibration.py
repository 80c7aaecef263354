#!/usr/bin/env python3
"""Calibration through the node, as a robot with a camera would use it. Two shots are drawn by ~predict_shot with
a rolling friction of 0.015 (the node's own is 0.01) and published on ~table_state as a camera would see them (every
third path sample, 1 mm noise): one recorded before its sightings arrive, from the latest TableState before the
strike; one recorded after them, with its table in the request. The action ~fit_calibration finds the rolling
friction within 3 sigma, from every sighting, reporting its iterations as feedback; cancelled, a fit ends preempted
with the best fit so far; ~fit_calibration_now answers the same goal; bad goals are refused by name; ~clear_shots
forgets the shots; sightings in a frame tf learns of only later wait for it and count.
"""
import random
import sys
import unittest

import actionlib
import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import TransformStamped
from actionlib_msgs.msg import GoalStatus
from std_srvs.srv import Trigger

from billiard_shot_planner.msg import (Ball, ErrorCode, FitCalibrationAction, FitCalibrationGoal, TableState)
from billiard_shot_planner.srv import (FitCalibrationNow, PredictShot, PredictShotRequest, RecordShot,
                                       RecordShotRequest)

NODE = "/shot_predictor/"
RADIUS = 0.0286
TRUE_ROLLING_FRICTION = 0.015
NOISE = 0.001  # m


def table_state(stamp, positions, frame="table"):
    table = TableState()
    table.header.frame_id = frame
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
        for name in ("predict_shot", "record_shot", "fit_calibration_now", "clear_shots"):
            rospy.wait_for_service(NODE + name, timeout=30)
        cls.predict = rospy.ServiceProxy(NODE + "predict_shot", PredictShot)
        cls.record = rospy.ServiceProxy(NODE + "record_shot", RecordShot)
        fit_now = rospy.ServiceProxy(NODE + "fit_calibration_now", FitCalibrationNow)
        cls.fit = staticmethod(lambda goal: fit_now(goal).result)
        cls.fit_action = actionlib.SimpleActionClient(NODE + "fit_calibration", FitCalibrationAction)
        assert cls.fit_action.wait_for_server(rospy.Duration(30)), "no ~fit_calibration action server"
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

        request = FitCalibrationGoal()
        request.fit = ["motion/rolling_friction"]
        request.position_noise = NOISE
        feedback = []
        self.fit_action.send_goal(request, feedback_cb=feedback.append)
        self.assertTrue(self.fit_action.wait_for_result(rospy.Duration(120)), "no result in time")
        self.assertEqual(self.fit_action.get_state(), GoalStatus.SUCCEEDED)
        fitted = self.fit_action.get_result()
        self.assertTrue(fitted.success, fitted.message)
        self.assertTrue(feedback, "no feedback while fitting")
        self.assertGreaterEqual(feedback[-1].local_fits, 1)
        self.assertGreaterEqual(feedback[-1].chi2, fitted.chi2 * (1.0 - 1e-9))  # the fit only goes down
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
        again = self.fit(request)  # the service: the same goal, the same deterministic fit
        self.assertTrue(again.success, again.message)
        self.assertAlmostEqual(again.values[0], fitted.values[0], delta=1e-3 * fitted.sigmas[0])

    def test_b_a_cancelled_fit_ends_preempted_with_the_best_fit_so_far(self):
        """Three constants with a noise of 1 micrometre, which no fit explains: the search goes on over many
        starting points for up to 600 s. Cancelled after its first feedback, it ends preempted within seconds, its
        result the best point so far (not converged)."""
        request = FitCalibrationGoal()
        request.fit = ["motion/rolling_friction", "motion/sliding_friction", "motion/spinning_friction"]
        request.position_noise = 1e-6
        request.starts = 1000
        request.budget = 600.0
        feedback = []
        self.fit_action.send_goal(request, feedback_cb=feedback.append)
        deadline = rospy.Time.now() + rospy.Duration(60)
        while not feedback and rospy.Time.now() < deadline:
            rospy.sleep(0.01)
        self.assertTrue(feedback, "no feedback within 60 s")
        cancelled = rospy.Time.now()
        self.fit_action.cancel_goal()
        self.assertTrue(self.fit_action.wait_for_result(rospy.Duration(30)), "not stopped within 30 s")
        print("stopped %.2f s after the cancel" % (rospy.Time.now() - cancelled).to_sec())
        self.assertEqual(self.fit_action.get_state(), GoalStatus.PREEMPTED)
        result = self.fit_action.get_result()
        self.assertTrue(result.success, result.message)
        self.assertFalse(result.converged)
        self.assertIn("stopped on request", result.message)
        self.assertEqual(len(result.values), 3)

    def test_c_bad_requests_are_refused_by_name(self):
        request = FitCalibrationGoal()
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
        self.assertEqual(answer.error_code.val, ErrorCode.INVALID_ARGUMENT)
        self.fit_action.send_goal(request)
        self.assertTrue(self.fit_action.wait_for_result(rospy.Duration(30)))
        self.assertEqual(self.fit_action.get_state(), GoalStatus.REJECTED)
        self.assertIn("budget", self.fit_action.get_result().message)

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

    def test_d_cleared_shots_are_gone(self):
        answer = self.clear()
        self.assertTrue(answer.success, answer.message)
        request = FitCalibrationGoal()
        request.fit = ["motion/rolling_friction"]
        answer = self.fit(request)
        self.assertFalse(answer.success)
        self.assertIn("shots", answer.message)


    def test_e_sightings_wait_until_tf_can_place_them(self):
        """Sightings from a camera frame tf does not know yet are held back, not dropped: once its transform comes
        (here the identity), every one is a track point."""
        self.assertTrue(self.clear().success)
        shot = level_cue(-0.5, 0.1)
        shot.strike_time = rospy.Time.now() + rospy.Duration(100.0)
        shot.table = table_state(rospy.Time(0), {"cue": (-0.5, 0.1)})
        answer = self.record(shot)
        self.assertTrue(answer.success, answer.message)
        path = self.truth_path(shot, -0.5, 0.1)[:30]
        for t, x, y in path:
            self.camera.publish(table_state(shot.strike_time + rospy.Duration(t), {"cue": (x, y)}, "late_camera"))
            rospy.sleep(0.004)
        rospy.sleep(0.5)
        identity = TransformStamped()
        identity.header.stamp = rospy.Time.now()
        identity.header.frame_id = "table"
        identity.child_frame_id = "late_camera"
        identity.transform.rotation.w = 1.0
        broadcaster = tf2_ros.StaticTransformBroadcaster()
        broadcaster.sendTransform(identity)
        request = FitCalibrationGoal()
        request.fit = ["motion/rolling_friction"]
        request.position_noise = NOISE
        deadline = rospy.Time.now() + rospy.Duration(10.0)
        fitted = self.fit(request)
        while fitted.observations < 2 * len(path) and rospy.Time.now() < deadline:
            rospy.sleep(0.2)
            fitted = self.fit(request)
        self.assertTrue(fitted.success, fitted.message)
        self.assertEqual(fitted.observations, 2 * len(path), "every held sighting is a track point")

if __name__ == "__main__":
    rostest.rosrun("billiard_shot_planner", "calibration", CalibrationTest, sys.argv)
