#!/usr/bin/python3
"""An independent client: rospy + actionlib + the generated control_msgs Python classes only."""
import unittest

import actionlib
import rospy
import rostest
from control_msgs.msg import (FollowJointTrajectoryAction, FollowJointTrajectoryGoal, FollowJointTrajectoryResult,
                              GripperCommandAction, GripperCommandGoal, JointTolerance)
from sensor_msgs.msg import JointState
from trajectory_msgs.msg import JointTrajectoryPoint

JOINTS = ["ur5e_" + j for j in ("shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                "wrist_1_joint", "wrist_2_joint", "wrist_3_joint")]


class RospyClient(unittest.TestCase):
    def setUp(self):
        self.arm = actionlib.SimpleActionClient("/ur5e/arm_controller/follow_joint_trajectory",
                                                FollowJointTrajectoryAction)
        self.assertTrue(self.arm.wait_for_server(rospy.Duration(15.0)))

    def positions(self):
        state = rospy.wait_for_message("/ur5e/joint_states", JointState, timeout=5.0)
        return dict(zip(state.name, state.position))

    def test_drives_the_arm(self):
        start = self.positions()
        order = list(reversed(JOINTS))  # any joint order is accepted
        target = [start[j] + 0.1 * (k + 1) for k, j in enumerate(order)]
        goal = FollowJointTrajectoryGoal()
        goal.trajectory.joint_names = order
        goal.trajectory.points = [
            JointTrajectoryPoint(positions=[start[j] for j in order], velocities=[0.0] * 6,
                                 time_from_start=rospy.Duration(0.0)),
            JointTrajectoryPoint(positions=target, velocities=[0.0] * 6, time_from_start=rospy.Duration(1.0)),
        ]
        goal.goal_tolerance = [JointTolerance(name=JOINTS[0], position=0.001)]
        goal.goal_time_tolerance = rospy.Duration(0.5)
        self.arm.send_goal(goal)
        self.assertTrue(self.arm.wait_for_result(rospy.Duration(10.0)))
        self.assertEqual(self.arm.get_state(), actionlib.GoalStatus.SUCCEEDED)
        self.assertEqual(self.arm.get_result().error_code, FollowJointTrajectoryResult.SUCCESSFUL)
        rospy.sleep(0.05)
        end = self.positions()
        for j, q in zip(order, target):
            self.assertAlmostEqual(end[j], q, delta=1e-9)

    def test_rejection_carries_code_and_reason(self):
        goal = FollowJointTrajectoryGoal()
        goal.trajectory.joint_names = JOINTS[:5]
        goal.trajectory.points = [JointTrajectoryPoint(positions=[0.0] * 5, time_from_start=rospy.Duration(1.0))]
        self.arm.send_goal(goal)
        self.assertTrue(self.arm.wait_for_result(rospy.Duration(5.0)))
        self.assertEqual(self.arm.get_state(), actionlib.GoalStatus.REJECTED)
        self.assertEqual(self.arm.get_result().error_code, FollowJointTrajectoryResult.INVALID_JOINTS)
        self.assertIn("ur5e_wrist_3_joint", self.arm.get_result().error_string)

    def test_gripper(self):
        gripper = actionlib.SimpleActionClient("/ur5e/gripper_controller/gripper_cmd", GripperCommandAction)
        self.assertTrue(gripper.wait_for_server(rospy.Duration(10.0)))
        goal = GripperCommandGoal()
        goal.command.position = 0.4
        goal.command.max_effort = 10.0
        gripper.send_goal(goal)
        self.assertTrue(gripper.wait_for_result(rospy.Duration(5.0)))
        self.assertEqual(gripper.get_state(), actionlib.GoalStatus.SUCCEEDED)
        self.assertTrue(gripper.get_result().reached_goal)


if __name__ == "__main__":
    rospy.init_node("rospy_client")
    rostest.rosrun("vrrw_control", "rospy_client", RospyClient)
