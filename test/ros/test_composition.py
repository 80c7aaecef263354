#!/usr/bin/env python3
"""predict_shot.launch composed into a robot's system (composition.test): the node answers under the name the launch
argument gives it, in the robot's table frame published by the robot's own tf, and the launch file publishes no
world -> table transform of its own."""
import sys
import unittest

import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import PointStamped, PoseStamped

from billiard_shot_planner.msg import ErrorCode
from billiard_shot_planner.srv import PredictShot, PredictShotRequest

RADIUS = 0.0286


class CompositionTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_composition")
        rospy.wait_for_service("/robot_predictor/predict_shot", timeout=30)
        cls.predict = rospy.ServiceProxy("/robot_predictor/predict_shot", PredictShot)
        cls.tf_buffer = tf2_ros.Buffer()
        cls.listener = tf2_ros.TransformListener(cls.tf_buffer)

    def request(self):
        """A level centre hit along +x of the robot's table, cue pose and ball given in that frame."""
        req = PredictShotRequest()
        req.cue_pose = PoseStamped()
        req.cue_pose.header.frame_id = "robot_table"
        req.cue_pose.pose.position.x, req.cue_pose.pose.position.z = -0.4 - 1.5 * RADIUS, RADIUS
        req.cue_pose.pose.orientation.w = 1.0
        req.cue_speed = 1.5
        req.ball_position = PointStamped()
        req.ball_position.header.frame_id = "robot_table"
        req.ball_position.point.x = -0.4
        return req

    def test_the_node_answers_under_its_name_in_the_robots_frame(self):
        answer = self.predict(self.request())
        self.assertTrue(answer.success, answer.message)
        self.assertEqual(answer.error_code.val, ErrorCode.SUCCESS)
        self.assertEqual(answer.prediction.header.frame_id, "robot_table")
        self.assertGreater(answer.ball_velocity.x, 1.0)

    def test_the_launch_file_publishes_no_table_frame_of_its_own(self):
        rospy.sleep(1.0)
        self.assertTrue(self.tf_buffer.can_transform("map", "robot_table", rospy.Time(0), rospy.Duration(5)))
        self.assertFalse(self.tf_buffer.can_transform("world", "table", rospy.Time(0), rospy.Duration(1)))


if __name__ == "__main__":
    rostest.rosrun("billiard_shot_planner", "test_composition", CompositionTest, sys.argv)
