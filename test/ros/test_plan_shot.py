#!/usr/bin/env python3
"""The planner's ROS interface with an actionlib client: ~plan_shot plans a straight-in pot that ~predict_shot,
asked independently with the plan's own cue pose and speed, predicts to drop; feedback comes while it plans; a
preempted goal ends preempted with the best plan so far; every bad goal is rejected with the reason; the service
~plan_shot_now answers the same goals.
"""
import sys
import time
import unittest

import actionlib
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus

from billiard_shot_planner.msg import Ball, ErrorCode, PlanShotAction, PlanShotGoal
from billiard_shot_planner.srv import PlanShotNow, PredictShot, PredictShotRequest

NODE = "/shot_predictor/"
RADIUS = 0.0286
TOP_RIGHT = "top_right"  # the (+x, +y) corner pocket


def ball(ball_id, x, y):
    b = Ball()
    b.id = ball_id
    b.position.x, b.position.y = x, y
    return b


def straight_in_goal():
    """The cue ball and ball "one" on the diagonal through the top-right corner pocket."""
    goal = PlanShotGoal()
    goal.table.header.frame_id = "table"
    goal.table.balls = [ball("cue", 0.2, 0.1), ball("one", 0.8, 0.4)]
    goal.target = "one"
    goal.budget = 3.0
    goal.seed = 3
    return goal


def long_goal():
    """The straight-in shot with a hundred thousand rollouts per shot: a plan that takes far longer than the test."""
    goal = straight_in_goal()
    goal.budget = 30.0
    goal.override_names = ["planning/rollouts"]
    goal.override_values = [100000]
    return goal


class PlanShotTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_plan_shot")
        cls.client = actionlib.SimpleActionClient(NODE + "plan_shot", PlanShotAction)
        assert cls.client.wait_for_server(rospy.Duration(30)), "no ~plan_shot action server"
        rospy.wait_for_service(NODE + "plan_shot_now", timeout=30)
        cls.plan_now = rospy.ServiceProxy(NODE + "plan_shot_now", PlanShotNow)
        cls.predict = rospy.ServiceProxy(NODE + "predict_shot", PredictShot)

    def run_goal(self, goal, timeout=60.0):
        feedback = []
        self.client.send_goal(goal, feedback_cb=feedback.append)
        self.assertTrue(self.client.wait_for_result(rospy.Duration(timeout)), "no result in time")
        return self.client.get_state(), self.client.get_result(), feedback

    def test_a_straight_in_plan_pots_when_predicted(self):
        state, result, feedback = self.run_goal(straight_in_goal())
        self.assertEqual(state, GoalStatus.SUCCEEDED, result.message)
        self.assertTrue(result.success and result.found, result.explanation)
        self.assertEqual(result.error_code.val, ErrorCode.SUCCESS)
        # Stamped when planned: the plan's cue pose and its prediction alike.
        self.assertFalse(result.plan.cue_pose.header.stamp.is_zero())
        self.assertEqual(result.prediction.header.stamp, result.plan.cue_pose.header.stamp)
        self.assertEqual(result.plan.target, "one")
        self.assertEqual(result.plan.pocket, TOP_RIGHT)
        self.assertTrue(result.plan.confidence_low <= result.plan.success_probability <= result.plan.confidence_high)
        self.assertGreater(len(feedback), 0)
        # The plan replayed through ~predict_shot, which knows nothing of the planner.
        request = PredictShotRequest()
        request.cue_pose = result.plan.cue_pose
        request.cue_speed = result.plan.cue_speed
        request.table = straight_in_goal().table
        answer = self.predict(request)
        self.assertTrue(answer.success, answer.message)
        outcomes = {b.id: b for b in answer.prediction.balls}
        self.assertEqual(outcomes["one"].outcome, "pocketed")
        self.assertEqual(outcomes["one"].pocket, TOP_RIGHT)
        self.assertNotEqual(outcomes["cue"].outcome, "pocketed")

    def test_a_preempted_goal_ends_with_the_best_plan_so_far(self):
        self.client.send_goal(long_goal())
        time.sleep(1.5)
        start = time.time()
        self.client.cancel_goal()
        self.assertTrue(self.client.wait_for_result(rospy.Duration(20)), "no result after the cancel")
        self.assertLess(time.time() - start, 20.0)
        self.assertEqual(self.client.get_state(), GoalStatus.PREEMPTED)
        result = self.client.get_result()
        self.assertTrue(result.success and result.found, result.message)
        self.assertEqual(result.plan.target, "one")
        self.assertGreater(result.plan.rollouts, 0)

    def test_bad_goals_are_rejected_with_the_reason(self):
        cases = []
        goal = straight_in_goal()
        goal.target = "seven"
        cases.append((goal, "target"))
        goal = straight_in_goal()
        goal.table.balls = []
        cases.append((goal, "table"))
        goal = straight_in_goal()
        goal.override_names = ["planning/limits/min_speed", "planning/limits/max_speed"]
        goal.override_values = [5.0, 2.0]
        cases.append((goal, "planning/limits"))
        goal = straight_in_goal()
        goal.pocket = "pocket9"
        cases.append((goal, "pocket"))
        goal = straight_in_goal()
        goal.override_names = ["planning/noise/phi"]
        goal.override_values = [-1.0]
        cases.append((goal, "planning/noise/phi"))
        goal = straight_in_goal()
        goal.table.balls[1].position.x = float("nan")
        cases.append((goal, "table.balls[1].position"))
        for goal, field in cases:
            state, result, _ = self.run_goal(goal)
            self.assertEqual(state, GoalStatus.REJECTED, field)
            self.assertFalse(result.success)
            self.assertEqual(result.error_code.val, ErrorCode.INVALID_ARGUMENT, field)
            self.assertIn(field, result.message)

    def test_a_moving_table_is_refused_with_its_code_and_a_trackers_noise_is_not(self):
        """A plan starts from a table at rest: a ball rolling at 0.3 m/s ends it with BALLS_MOVING, a ball whose
        tracked speed is below ~planning/rest_speed (0.01 m/s) is at rest."""
        goal = straight_in_goal()
        goal.table.balls[1].velocity.y = 0.3
        state, result, _ = self.run_goal(goal)
        self.assertEqual(state, GoalStatus.REJECTED, result.message)
        self.assertEqual(result.error_code.val, ErrorCode.BALLS_MOVING, result.message)
        self.assertIn("rest_speed", result.message)
        goal.table.balls[1].velocity.y = 0.003
        goal.table.balls[0].angular_velocity.z = 0.1  # rad/s: 0.003 m/s at the ball's radius
        answer = self.plan_now(goal).result
        self.assertTrue(answer.success and answer.found, answer.message)

    def test_a_goal_that_pots_nothing_is_aborted_with_the_closest_attempt(self):
        """The straight-in shot with the cue limited to 0.1 m/s: the object ball leaves at most at about 0.13 m/s
        and rolls at most v^2 / (2 mu_r g) = 0.09 m against the 0.53 m to the pocket, so nothing pots. The action
        ends aborted with NO_SHOT_FOUND, and the result still explains why."""
        goal = straight_in_goal()
        goal.budget = 1.0
        goal.override_names = ["planning/limits/min_speed", "planning/limits/max_speed"]
        goal.override_values = [0.05, 0.1]
        state, result, _ = self.run_goal(goal)
        self.assertEqual(state, GoalStatus.ABORTED, result.message)
        self.assertFalse(result.success or result.found)
        self.assertEqual(result.error_code.val, ErrorCode.NO_SHOT_FOUND)
        self.assertTrue(result.explanation)

    def test_the_service_answers_the_same_goals(self):
        answer = self.plan_now(straight_in_goal()).result
        self.assertTrue(answer.success and answer.found, answer.message)
        self.assertEqual(answer.plan.target, "one")
        goal = straight_in_goal()
        goal.target = "seven"
        answer = self.plan_now(goal).result
        self.assertFalse(answer.success)
        self.assertIn("target", answer.message)


if __name__ == "__main__":
    rostest.rosrun("billiard_shot_planner", "test_plan_shot", PlanShotTest, sys.argv)
