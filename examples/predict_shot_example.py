#!/usr/bin/env python3
"""Asks the shot predictor what a follow shot does and prints the answer.

The cue is level and points along the table's x axis; its tip touches the cue ball 1 cm above the ball's centre
at 2 m/s. Run it beside the node:

    roslaunch billiard_shot_planner predict_shot.launch
    rosrun billiard_shot_planner predict_shot_example.py [--speed 2.0] [--service /shot_predictor/predict_shot]

Exits 0 when the node answered the shot, 1 when it refused it (the reason is printed), 2 when no node answered.
"""
import argparse
import math
import sys

import rospy
from geometry_msgs.msg import PointStamped, PoseStamped

from billiard_shot_planner.srv import PredictShot, PredictShotRequest

BALL_RADIUS = 0.0286  # m, the node's default ball


def follow_shot(speed):
    """A level cue along +x, its tip 1 cm above the centre of a ball at (-0.6, -0.2) in the table frame."""
    request = PredictShotRequest()
    ball = (-0.6, -0.2)
    request.ball_position = PointStamped()
    request.ball_position.header.frame_id = "table"
    request.ball_position.point.x, request.ball_position.point.y = ball
    request.ball_position.point.z = BALL_RADIUS
    request.cue_pose = PoseStamped()
    request.cue_pose.header.frame_id = "table"
    height = 0.01  # m above the centre: a follow shot
    # The tip sits on the ball's surface: its distance from the centre along -x makes the hit point exact.
    request.cue_pose.pose.position.x = ball[0] - math.sqrt(BALL_RADIUS**2 - height**2)
    request.cue_pose.pose.position.y = ball[1]
    request.cue_pose.pose.position.z = BALL_RADIUS + height
    request.cue_pose.pose.orientation.w = 1.0  # the cue frame's x axis along the table's x axis
    request.cue_speed = speed
    return request


def print_answer(response):
    prediction = response.prediction
    v, w = response.ball_velocity, response.ball_angular_velocity
    print("success: %s" % response.success)
    if not response.success:
        print("message: %s" % response.message)
        return
    print("ball_velocity: %.6f %.6f %.6f" % (v.x, v.y, v.z))
    print("ball_angular_velocity: %.6f %.6f %.6f" % (w.x, w.y, w.z))
    print("states: %s" % " ".join(response.states))
    print("outcome: %s" % prediction.outcome)
    p = prediction.final_position
    print("final_position: %.6f %.6f %.6f" % (p.x, p.y, p.z))
    print("duration: %.6f" % prediction.duration)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--speed", type=float, default=2.0, help="cue speed, m/s (default 2.0)")
    parser.add_argument("--service", default="/shot_predictor/predict_shot", help="the node's service")
    parser.add_argument("--timeout", type=float, default=30.0, help="seconds to wait for the service")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("predict_shot_example", anonymous=True)
    try:
        rospy.wait_for_service(args.service, timeout=args.timeout)
        response = rospy.ServiceProxy(args.service, PredictShot)(follow_shot(args.speed))
    except (rospy.ROSException, rospy.ServiceException) as error:
        print("no answer from %s: %s" % (args.service, error), file=sys.stderr)
        return 2
    print_answer(response)
    return 0 if response.success else 1


if __name__ == "__main__":
    sys.exit(main())
