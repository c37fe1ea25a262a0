#!/usr/bin/env python3
"""rostest: plan with /ur5e/plan, execute on /ur5e/arm_controller/follow_joint_trajectory, and
check that the arm arrives and every state along the way was collision-free."""
import unittest

import actionlib
import rospy
import rostest
from control_msgs.msg import FollowJointTrajectoryAction, FollowJointTrajectoryGoal, FollowJointTrajectoryResult
from sensor_msgs.msg import JointState
from vrrw_common.services import PersistentServices
from vrrw_msgs.srv import CheckState, Plan

GOALS = [[0.9, -1.2, 1.4, -1.8, -1.57, 0.3], [-0.6, -1.9, 2.0, -1.6, -1.2, -0.5], [0.0, -1.57, 1.57, -1.57, -1.57, 0.0]]


class PlanAndExecute(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('workspace_check')
        services = PersistentServices(wait_seconds=60)
        cls.plan = staticmethod(lambda **request: services.call('/ur5e/plan', Plan, **request))
        cls.check = staticmethod(lambda **request: services.call('/ur5e/check_state', CheckState, **request))
        cls.arm = actionlib.SimpleActionClient('/ur5e/arm_controller/follow_joint_trajectory',
                                               FollowJointTrajectoryAction)
        assert cls.arm.wait_for_server(rospy.Duration(60))
        cls.joints = rospy.get_param('/scene/robots/ur5e/arm_joints')
        cls.collision_free_samples = 0

    def state(self):
        msg = rospy.wait_for_message('/ur5e/joint_states', JointState, 5)
        return [msg.position[msg.name.index(j)] for j in self.joints]

    def test_planned_motions_execute_and_arrive(self):
        for goal in GOALS:
            request = JointState(name=self.joints, position=goal)
            response = self.plan(goal_joints=request, seed=1, time_limit=2.0)
            self.assertEqual(response.error_code, 0, response.message)
            points = response.trajectory.points
            self.assertGreater(len(points), 1)
            for point in points[::max(1, len(points) // 20)]:
                verdict = self.check(joint_state=JointState(name=response.trajectory.joint_names,
                                                            position=point.positions))
                self.assertTrue(verdict.valid, f'{verdict.link_a} - {verdict.link_b}: {verdict.message}')
            self.arm.send_goal(FollowJointTrajectoryGoal(trajectory=response.trajectory))
            duration = points[-1].time_from_start.to_sec()
            self.assertTrue(self.arm.wait_for_result(rospy.Duration(duration + 10)))
            self.assertEqual(self.arm.get_result().error_code, FollowJointTrajectoryResult.SUCCESSFUL)
            rospy.sleep(0.1)
            for actual, wanted in zip(self.state(), goal):
                self.assertAlmostEqual(actual, wanted, delta=1e-6)


if __name__ == '__main__':
    rostest.rosrun('vrrw_bringup', 'workspace_check', PlanAndExecute)
