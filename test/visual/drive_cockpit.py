#!/usr/bin/env python3
"""Drives rviz's cockpit as a person would, for the visual test and the documentation's screenshots: puts a table on
~table_state, then turns the cue's aim handle to point along +y and pulls the speed handle to 1.4 m/s (feedback
messages on ~cue_control/feedback, as rviz sends when a handle is let go) and waits for the prediction it asks for; with --click, clicks ball "one" (as rviz's
Publish Point) and waits for its plan to be drawn; with --animate, replays the last prediction slowed down (a
screenshot then catches the balls on their way).

Usage: drive_cockpit.py [--click] [--animate SLOW_MOTION]. Exit 0 once done, 1 when the node did not answer.
"""
import argparse
import math
import sys
import time

import rospy
from geometry_msgs.msg import PointStamped
from visualization_msgs.msg import InteractiveMarkerFeedback, InteractiveMarkerUpdate, MarkerArray

from billiard_shot_planner.msg import Ball, ShotPrediction, TableState
from billiard_shot_planner.srv import Animate, AnimateRequest

NODE = "/shot_predictor/"
RADIUS = 0.028575
SPEED_SCALE = 0.1  # config/default.yaml cockpit/speed_scale: m per m/s
CUE_SPEED = 1.4  # m/s
BALLS = {"cue": (-0.6, -0.3), "one": (0.3, 0.2), "two": (0.7, -0.45), "three": (-0.15, 0.45)}


def wait_for(predicate, timeout):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline and not rospy.is_shutdown():
        if predicate():
            return True
        time.sleep(0.05)
    return False


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--click", action="store_true")
    parser.add_argument("--animate", type=float, default=0.0)
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("drive_cockpit")
    seen = {"aim": None, "prediction": None, "plan": False}

    def update(message):
        for marker in message.markers:
            if marker.name == "aim":
                seen["aim"] = marker.pose

    def predicted(message):
        seen["prediction"] = message

    def drawn(message):
        seen["plan"] = seen["plan"] or any(m.ns == "plan_spread" for m in message.markers)

    rospy.Subscriber(NODE + "cue_control/update_full", InteractiveMarkerUpdate, update)
    rospy.Subscriber(NODE + "cue_control/update", InteractiveMarkerUpdate, update)
    rospy.Subscriber(NODE + "prediction", ShotPrediction, predicted)
    rospy.Subscriber(NODE + "trajectory_markers", MarkerArray, drawn)
    feedback = rospy.Publisher(NODE + "cue_control/feedback", InteractiveMarkerFeedback, queue_size=10)
    clicked = rospy.Publisher("/clicked_point", PointStamped, queue_size=1)
    table = rospy.Publisher(NODE + "table_state", TableState, queue_size=1, latch=True)
    state = TableState()
    state.header.frame_id = "table"
    for name, (x, y) in BALLS.items():
        ball = Ball(id=name)
        ball.position.x, ball.position.y = x, y
        state.balls.append(ball)
    table.publish(state)

    def aim_at_cue_ball():
        pose = seen["aim"]
        return pose is not None and abs(pose.position.x - BALLS["cue"][0]) < 1e-6
    if not wait_for(aim_at_cue_ball, 20.0) or not wait_for(lambda: feedback.get_num_connections() > 0, 10.0):
        print("the cockpit's handles did not come to the cue ball")
        return 1

    drag = InteractiveMarkerFeedback(client_id="/rviz/drive_cockpit", marker_name="aim", control_name="turn")
    drag.header.frame_id = "table"
    drag.event_type = InteractiveMarkerFeedback.MOUSE_UP
    drag.pose = seen["aim"]
    drag.pose.orientation.x = drag.pose.orientation.y = 0.0
    drag.pose.orientation.z = drag.pose.orientation.w = math.sqrt(0.5)  # the cue along +y
    feedback.publish(drag)
    # The speed handle pulled to 1.4 m/s: a centre hit that slides, then rolls (both of the path's colours).
    pull = InteractiveMarkerFeedback(client_id="/rviz/drive_cockpit", marker_name="speed", control_name="pull")
    pull.header.frame_id = "table"
    pull.event_type = InteractiveMarkerFeedback.MOUSE_UP
    pull.pose = drag.pose
    pull.pose.position.y = BALLS["cue"][1] - RADIUS - SPEED_SCALE * CUE_SPEED
    feedback.publish(pull)

    def along_y():
        v = seen["prediction"].ball_velocity if seen["prediction"] else None
        return v is not None and 0.5 < v.y < 2.5 and abs(v.x) < 1e-3 * v.y
    if not wait_for(along_y, 20.0):
        print("no prediction along +y after the drag")
        return 1
    print("cockpit driven: the cue turned to +y, pulled to %.1f m/s and its prediction drawn" % CUE_SPEED)

    if args.click:
        point = PointStamped()
        point.header.frame_id = "table"
        point.point.x, point.point.y = BALLS["one"]
        clicked.publish(point)
        if not wait_for(lambda: seen["plan"], 60.0):
            print("no plan drawn for the clicked ball")
            return 1
        print("cockpit driven: ball 'one' clicked and its plan drawn")
    if args.animate > 0.0:
        rospy.wait_for_service(NODE + "animate", timeout=10)
        answer = rospy.ServiceProxy(NODE + "animate", Animate)(AnimateRequest(slow_motion=args.animate))
        if not answer.success:
            print("animate: " + answer.message)
            return 1
        print("cockpit driven: the shot animated for %.1f s" % answer.duration)
    return 0


if __name__ == "__main__":
    sys.exit(main())
