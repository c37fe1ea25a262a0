#!/usr/bin/python3
"""Plays ur_robot_driver under a namespace (vrrw_evaluation's test_demo_real.py, vrrw_demos' replay_real.test):
its trajectory action (takes a goal, ends at its last point, succeeds) and joint_states (unprefixed names, all
zero at first); every goal it received is appended to a JSON-lines file.

  driver_stand_in.py NS GOALS.jsonl
"""
import json
import sys
import threading

import actionlib
import rospy
from control_msgs.msg import FollowJointTrajectoryAction, FollowJointTrajectoryResult
from sensor_msgs.msg import JointState

JOINTS = ['shoulder_pan_joint', 'shoulder_lift_joint', 'elbow_joint', 'wrist_1_joint', 'wrist_2_joint', 'wrist_3_joint']


def main():
    rospy.init_node('stand_in_driver')
    namespace, record = rospy.myargv(sys.argv)[1].rstrip('/'), rospy.myargv(sys.argv)[2]
    state = JointState(name=JOINTS, position=[0.0] * len(JOINTS))
    lock = threading.Lock()

    def execute(goal):
        points = goal.trajectory.points
        with lock:  # there at once, and said so (a real arm's joint_states show it there when it reports)
            for k, name in enumerate(goal.trajectory.joint_names):
                if name in JOINTS:
                    state.position[JOINTS.index(name)] = points[-1].positions[k]
            state.header.stamp = rospy.Time.now()
            publisher.publish(state)
        with open(record, 'a') as f:
            f.write(json.dumps({'joint_names': list(goal.trajectory.joint_names), 'points': len(points),
                                'first': list(points[0].positions), 'last': list(points[-1].positions),
                                'seconds': points[-1].time_from_start.to_sec() - points[0].time_from_start.to_sec()})
                    + '\n')
        server.set_succeeded(FollowJointTrajectoryResult(error_string='stand-in executed'))

    publisher = rospy.Publisher(namespace + '/joint_states', JointState, queue_size=10)
    server = actionlib.SimpleActionServer(namespace + '/scaled_pos_joint_traj_controller/follow_joint_trajectory',
                                          FollowJointTrajectoryAction, execute, auto_start=False)
    server.start()
    rate = rospy.Rate(50)
    while not rospy.is_shutdown():
        with lock:
            state.header.stamp = rospy.Time.now()
            publisher.publish(state)
        rate.sleep()


if __name__ == '__main__':
    main()
