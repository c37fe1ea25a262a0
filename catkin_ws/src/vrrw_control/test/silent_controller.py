#!/usr/bin/python3
"""Stand-in for a controller that takes a FollowJointTrajectory goal and never finishes it (the tests kill it
mid-goal): the arm controller of robot ~robot under /<robot>/arm_controller/follow_joint_trajectory."""
import actionlib
import rospy
from control_msgs.msg import FollowJointTrajectoryAction


def main():
    rospy.init_node('silent_controller')
    robot = rospy.get_param('~robot')
    goals = []

    def on_goal(goal):
        goal.set_accepted()
        goals.append(goal)  # held, never finished

    server = actionlib.ActionServer(f'/{robot}/arm_controller/follow_joint_trajectory', FollowJointTrajectoryAction,
                                    on_goal, auto_start=False)
    server.start()
    rospy.spin()


if __name__ == '__main__':
    main()
