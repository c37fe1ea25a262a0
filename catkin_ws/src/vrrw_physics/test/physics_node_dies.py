#!/usr/bin/env python3
"""rostest: kill -9 of the physics node leaves the master and the rest of the launch up (physics.launch
does not mark it required)."""
import os
import signal
import time
import unittest
from xmlrpc.client import ServerProxy

import rosgraph
import rosnode
import rospy
import rostest
from sensor_msgs.msg import JointState

CALLER = '/physics_node_dies'


def pid_of(node):
    uri = rosnode.get_api_uri(rosgraph.Master(CALLER), node, skip_cache=True)
    _, _, pid = ServerProxy(uri).getPid(CALLER)
    return pid


def alive(node):
    return rosnode.rosnode_ping(node, max_count=1)


class PhysicsNodeDies(unittest.TestCase):
    def test_the_rest_of_the_launch_stays_up(self):
        rospy.wait_for_message('/ur5e/joint_states', JointState, timeout=60)
        self.assertTrue(alive('/scene'))
        os.kill(pid_of('/physics'), signal.SIGKILL)
        deadline = time.time() + 10
        while alive('/physics') and time.time() < deadline:
            time.sleep(0.2)
        self.assertFalse(alive('/physics'))
        time.sleep(3.0)  # a required node's death would have shut the whole launch down by now
        self.assertTrue(rosgraph.is_master_online())
        self.assertTrue(alive('/scene'))


if __name__ == '__main__':
    rospy.init_node('physics_node_dies', anonymous=True)
    rostest.rosrun('vrrw_physics', 'physics_node_dies', PhysicsNodeDies)
