#!/usr/bin/env python3
"""The cockpit driven as rviz drives it (cockpit.test): the handles of ~cue_control sit at the cue ball; a feedback
message that turns the aim, moves the tip or pulls the speed handle brings a new prediction, drawn on
~trajectory_markers, whose strike follows the stroke (the direction of the cue, the sign of the spin and of the
squirt for side spin, a speed that scales the ball's as the model's linear contact laws say); a burst of drags gives a
few predictions, the last of the last drag; a ball clicked with "Publish Point" is planned; ~animation plays the
shots and ~animate replays them at a slow motion, refusing bad requests with their code.
"""
import math
import sys
import threading
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import PointStamped
from visualization_msgs.msg import InteractiveMarkerFeedback, InteractiveMarkerInit, InteractiveMarkerUpdate, MarkerArray

from billiard_shot_planner.msg import Ball, ErrorCode, PathSample, ShotPrediction, TableState
from billiard_shot_planner.srv import Animate, AnimateRequest, GetConfiguration

NODE = "/shot_predictor/"
RADIUS = 0.028575  # config/default.yaml ball/radius
SPEED_SCALE = 0.1  # config/default.yaml cockpit/speed_scale, m per m/s
CUE = (0.2, 0.1)  # the cue ball and ball "one" on the diagonal through the (+x, +y) corner pocket
ONE = (0.8, 0.4)


def ball(ball_id, xy):
    b = Ball()
    b.id = ball_id
    b.position.x, b.position.y = xy
    return b


def yaw_quaternion(pose, yaw):
    pose.orientation.z, pose.orientation.w = math.sin(0.5 * yaw), math.cos(0.5 * yaw)


class Recorder:
    """The messages of a topic with their arrival times."""

    def __init__(self, topic, kind):
        self.lock = threading.Lock()
        self.messages = []
        self.subscriber = rospy.Subscriber(topic, kind, self.received, queue_size=100)

    def received(self, message):
        with self.lock:
            self.messages.append((time.monotonic(), message))

    def count(self):
        with self.lock:
            return len(self.messages)

    def since(self, index):
        with self.lock:
            return [m for _, m in self.messages[index:]]

    def arrived_after(self, moment):
        """The messages that arrived after the monotonic time `moment`."""
        with self.lock:
            return [m for arrival, m in self.messages if arrival > moment]

    def last_arrival(self):
        with self.lock:
            return self.messages[-1][0] if self.messages else 0.0


def wait_until(predicate, timeout=20.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(0.05)
    return False


class CockpitTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_cockpit")
        cls.predictions = Recorder(NODE + "prediction", ShotPrediction)
        cls.markers = Recorder(NODE + "trajectory_markers", MarkerArray)
        cls.animation = Recorder(NODE + "animation", MarkerArray)
        cls.updates = Recorder(NODE + "cue_control/update", InteractiveMarkerUpdate)
        cls.full = Recorder(NODE + "cue_control/update_full", InteractiveMarkerInit)
        cls.feedback = rospy.Publisher(NODE + "cue_control/feedback", InteractiveMarkerFeedback, queue_size=100)
        cls.clicked = rospy.Publisher("/clicked_point", PointStamped, queue_size=1)
        cls.table = rospy.Publisher(NODE + "table_state", TableState, queue_size=1, latch=True)
        rospy.wait_for_service(NODE + "animate", timeout=30)
        cls.animate = rospy.ServiceProxy(NODE + "animate", Animate)
        cls.configuration = rospy.ServiceProxy(NODE + "get_configuration", GetConfiguration)
        assert wait_until(lambda: cls.feedback.get_num_connections() > 0), "the cockpit does not listen for feedback"
        state = TableState()
        state.header.frame_id = "table"
        state.balls = [ball("cue", CUE), ball("one", ONE)]
        cls.table.publish(state)

    # --- helpers -------------------------------------------------------------------------------------------------
    def handle_pose(self, name):
        """The latest pose the server gave the handle `name` (full updates and incremental ones)."""
        pose = None
        for update in [m for m in self.full.since(0)] + self.updates.since(0):
            for marker in update.markers:
                if marker.name == name:
                    pose = marker.pose
            for pose_update in getattr(update, "poses", []):  # a full update (InteractiveMarkerInit) has none
                if pose_update.name == name:
                    pose = pose_update.pose
        return pose

    def drag(self, name, pose, event=InteractiveMarkerFeedback.POSE_UPDATE):
        message = InteractiveMarkerFeedback()
        message.header.frame_id = "table"
        message.client_id = "/rviz/test"
        message.marker_name = name
        message.control_name = "test"
        message.event_type = event
        message.pose = pose
        self.feedback.publish(message)

    def aim(self, yaw):
        pose = self.handle_pose("aim")
        pose.position.x, pose.position.y, pose.position.z = CUE[0], CUE[1], RADIUS
        pose.orientation.x = pose.orientation.y = 0.0
        yaw_quaternion(pose, yaw)
        self.drag("aim", pose)

    def tip(self, yaw, a, b):
        """The tip at the hit point (a, b) of a cue heading `yaw` (docs/stroke_conventions.md)."""
        pose = self.handle_pose("tip")
        forward, right = (math.cos(yaw), math.sin(yaw)), (math.sin(yaw), -math.cos(yaw))
        depth = math.sqrt(1.0 - a * a - b * b)
        pose.position.x = CUE[0] + RADIUS * (a * right[0] - depth * forward[0])
        pose.position.y = CUE[1] + RADIUS * (a * right[1] - depth * forward[1])
        pose.position.z = RADIUS * (1.0 + b)
        self.drag("tip", pose)

    def speed(self, yaw, speed):
        """The speed handle `speed` x speed_scale behind a centre hit's tip, on a level cue heading `yaw`."""
        pose = self.handle_pose("speed")
        behind = RADIUS + SPEED_SCALE * speed
        pose.position.x = CUE[0] - behind * math.cos(yaw)
        pose.position.y = CUE[1] - behind * math.sin(yaw)
        pose.position.z = RADIUS
        self.drag("speed", pose)

    def settled_prediction(self, after):
        """The last prediction once none has come for a second (the drags sent before `after` answered)."""
        self.assertTrue(wait_until(lambda: self.predictions.count() > after), "no prediction after the drag")
        self.assertTrue(wait_until(lambda: time.monotonic() - self.predictions.last_arrival() > 1.0))
        return self.predictions.since(0)[-1]

    def drive(self, yaw, a=0.0, b=0.0, speed=2.0):
        """One stroke set through the three handles, and its prediction."""
        before = self.predictions.count()
        self.aim(yaw)
        self.tip(yaw, a, b)
        self.speed(yaw, speed)
        return self.settled_prediction(before)

    # --- tests ---------------------------------------------------------------------------------------------------
    def test_a_the_handles_come_to_the_cue_ball(self):
        self.assertTrue(wait_until(lambda: self.handle_pose("aim") is not None), "no handles on ~cue_control")

        def at_cue_ball():
            pose = self.handle_pose("aim")
            return abs(pose.position.x - CUE[0]) < 1e-6 and abs(pose.position.y - CUE[1]) < 1e-6

        self.assertTrue(wait_until(at_cue_ball, 10.0), "the aim handle did not move to the table's cue ball")
        for name in ("tip", "speed"):
            self.assertIsNotNone(self.handle_pose(name), name)

    def test_b_a_drag_of_the_aim_draws_a_prediction_along_the_new_heading(self):
        markers_before = self.markers.count()
        prediction = self.drive(math.radians(90.0))
        velocity = prediction.ball_velocity
        heading = math.degrees(math.atan2(velocity.y, velocity.x))
        self.assertAlmostEqual(heading, 90.0, delta=0.1)  # a centre hit: the ball goes where the cue points
        self.assertGreater(math.hypot(velocity.x, velocity.y), 1.0)
        drawn = self.markers.since(markers_before)
        self.assertTrue(any(m.ns == "trajectory" for array in drawn for m in array.markers), "no new path drawn")

    def test_c_right_english_spins_the_ball_counter_clockwise_and_squirts_it_left(self):
        prediction = self.drive(0.0, a=0.4)
        self.assertGreater(prediction.ball_angular_velocity.z, 1.0)
        self.assertGreater(prediction.ball_velocity.y, 0.0)  # left of a cue heading +x
        self.assertGreater(prediction.ball_velocity.x, 1.0)

    def test_d_the_speed_handle_scales_the_strike(self):
        # The constant-restitution laws of config/default.yaml have no velocity scale: the strike is linear in the
        # cue's speed but for the ball's weight, whose impulse over the tip's contact (< 2 ms) is below
        # g * 2 ms / 2.5 m/s < 1 % of the ball's momentum.
        slow = self.drive(0.0, speed=2.0).ball_velocity
        fast = self.drive(0.0, speed=3.0).ball_velocity
        self.assertAlmostEqual(fast.x / slow.x, 1.5, delta=0.01)

    def test_e_a_burst_of_drags_gives_few_predictions_the_last_of_the_last_drag(self):
        self.drive(0.0)
        before = self.predictions.count()
        yaws = [math.radians(d) for d in range(0, 46)]
        for yaw in yaws:
            self.aim(yaw)
        prediction = self.settled_prediction(before)
        answered = self.predictions.count() - before
        self.assertLessEqual(answered, 10, "the drags were not throttled")
        velocity = prediction.ball_velocity
        self.assertAlmostEqual(math.degrees(math.atan2(velocity.y, velocity.x)), 45.0, delta=0.1)

    def test_f_a_clicked_ball_is_planned_and_drawn_with_its_spread(self):
        markers_before = self.markers.count()
        point = PointStamped()
        point.header.frame_id = "table"
        point.point.x, point.point.y = ONE[0] + 0.5 * RADIUS, ONE[1]
        self.clicked.publish(point)

        def plan_drawn():
            return any(m.ns == "plan_spread" for a in self.markers.since(markers_before) for m in a.markers)

        self.assertTrue(wait_until(plan_drawn, 60.0), "no plan drawn for the clicked ball")

    def test_g_the_animation_moves_the_balls_along_the_path(self):
        prediction = self.drive(0.0, speed=2.0)
        # The drive's own animation (cockpit/animate) may still be playing: only frames that arrive after the answer
        # belong to the replay, and the first of them is skipped in case it was on its way before the replay began.
        answer = self.animate(AnimateRequest(slow_motion=2.0))
        answered = time.monotonic()
        self.assertTrue(answer.success, answer.message)
        self.assertEqual(answer.error_code.val, ErrorCode.SUCCESS)
        # The length of the shot from the message: its longest path, a pocketed ball's fall (0.25 s) besides.
        length = max(b.path[-1].time + (0.25 if b.outcome == "pocketed" else 0.0) for b in prediction.balls)
        self.assertAlmostEqual(answer.duration, 2.0 * length, delta=1e-9)
        self.assertTrue(wait_until(lambda: len(self.animation.arrived_after(answered)) > 10, 10.0), "no animation")
        positions = []
        for frame in self.animation.arrived_after(answered)[1:]:
            for marker in frame.markers:
                if marker.ns == "animation" and prediction.balls[marker.id].id == "cue":
                    positions.append(marker.pose.position.x)
        self.assertGreater(positions[-1], positions[0] + 0.05, "the cue ball did not move along +x")

    def test_h_bad_requests_are_refused_with_their_code(self):
        answer = self.animate(AnimateRequest(slow_motion=-1.0))
        self.assertFalse(answer.success)
        self.assertEqual(answer.error_code.val, ErrorCode.INVALID_ARGUMENT)
        self.assertIn("slow_motion", answer.message)
        backwards = ShotPrediction()
        backwards.header.frame_id = "table"
        backwards.balls = [self.predictions.since(0)[-1].balls[0]]
        backwards.balls[0].path = [PathSample(time=1.0), PathSample(time=0.5)]
        answer = self.animate(AnimateRequest(slow_motion=1.0, prediction=backwards))
        self.assertFalse(answer.success)
        self.assertIn("prediction.balls[0].path", answer.message)
        # Clicks on empty cloth and in a frame tf does not know, a drag of NaNs: the node goes on answering.
        for frame, x in (("table", -1.0), ("nowhere", 0.0)):
            point = PointStamped()
            point.header.frame_id = frame
            point.point.x = x
            self.clicked.publish(point)
        pose = self.handle_pose("aim")
        pose.orientation.w = float("nan")
        self.drag("aim", pose)
        rospy.sleep(1.0)
        self.assertTrue(self.configuration().success)
        velocity = self.drive(0.0).ball_velocity
        self.assertAlmostEqual(math.degrees(math.atan2(velocity.y, velocity.x)), 0.0, delta=0.1)


if __name__ == "__main__":
    rostest.rosrun("billiard_shot_planner", "cockpit", CockpitTest, sys.argv)
