#!/usr/bin/env python3
"""rostest: a brought-up scene has every link in tf, the published joint limits, prefixed names
and mimic joints that follow their leader."""
import math
import unittest
import xml.etree.ElementTree as ET

import numpy
import rospy
import rostest
import tf2_ros
import yaml
from sensor_msgs.msg import JointState

TOLERANCE = 1e-6


def rotation(axis, angle):
    axis = numpy.asarray(axis, dtype=float) / numpy.linalg.norm(axis)
    k = numpy.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return numpy.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


def origin_matrix(joint):
    origin = joint.find('origin')
    xyz = [float(v) for v in (origin.get('xyz', '0 0 0') if origin is not None else '0 0 0').split()]
    r, p, y = [float(v) for v in (origin.get('rpy', '0 0 0') if origin is not None else '0 0 0').split()]
    m = numpy.eye(4)
    m[:3, :3] = rotation([0, 0, 1], y) @ rotation([0, 1, 0], p) @ rotation([1, 0, 0], r)
    m[:3, 3] = xyz
    return m


def transform_matrix(t):
    q = t.transform.rotation
    x, y, z, w = q.x, q.y, q.z, q.w
    m = numpy.eye(4)
    m[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                 [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                 [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    m[:3, 3] = [t.transform.translation.x, t.transform.translation.y, t.transform.translation.z]
    return m


class Bringup(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('bringup_check')
        deadline = rospy.Time.now() + rospy.Duration(60)
        while not rospy.has_param('/scene/robots') and rospy.Time.now() < deadline:
            rospy.sleep(0.1)
        cls.urdf = ET.fromstring(rospy.get_param('/robot_description'))
        cls.robots = rospy.get_param('/scene/robots')
        cls.joints = {j.get('name'): j for j in cls.urdf.iter('joint')}
        cls.links = [link.get('name') for link in cls.urdf.iter('link')]
        with open(rospy.get_param('~expectations')) as f:
            cls.expected = yaml.safe_load(f)
        cls.tf = tf2_ros.Buffer()
        cls.listener = tf2_ros.TransformListener(cls.tf)

    def lookup(self, parent, child):
        return self.tf.lookup_transform(parent, child, rospy.Time(0), rospy.Duration(20))

    def robot_joints(self, name):
        return [j for j in self.joints.values() if j.get('name').startswith(name + '_')]

    def test_every_link_is_in_tf(self):
        missing = [link for link in self.links
                   if not self.tf.can_transform('world', link, rospy.Time(0), rospy.Duration(20))]
        self.assertEqual(missing, [], f'{len(missing)} of {len(self.links)} links not in tf')

    def test_every_joint_states_message_holds_every_robot(self):
        # robot_state_publisher keeps one queued message: a robot left out of a message can be starved.
        held = set()
        for name in self.robots:
            held.update(rospy.wait_for_message(f'/{name}/joint_states', JointState, 10).name)
        messages = []
        subscriber = rospy.Subscriber('/joint_states', JointState, messages.append)
        deadline = rospy.Time.now() + rospy.Duration(1.0)
        while rospy.Time.now() < deadline:
            rospy.sleep(0.05)
        subscriber.unregister()
        self.assertGreater(len(messages), 5)
        partial = [sorted(held - set(m.name)) for m in messages if not held <= set(m.name)]
        self.assertEqual(partial, [], f'{len(partial)} of {len(messages)} /joint_states messages lack joints')

    def test_every_robot_name_is_its_own_prefix(self):
        owners = {}
        for name, robot in self.robots.items():
            stack, seen = [robot['base_link']], set()
            while stack:
                link = stack.pop()
                seen.add(link)
                stack += [j.find('child').get('link') for j in self.joints.values()
                          if j.find('parent').get('link') == link]
            for link in seen:
                self.assertTrue(link.startswith(name + '_'), f'{link} of robot {name} lacks the prefix')
                owners[link] = name
        self.assertEqual(sorted(owners), sorted(link for link in self.links if link != 'world'))

    def published_facts(self, robot):
        """The expected facts of a robot's model and of its gripper (Fetch's is part of its model)."""
        parts = [self.expected['robots'][robot['model']]]
        if robot['gripper'] in self.expected['grippers']:
            parts.append(self.expected['grippers'][robot['gripper']])
        return parts

    def test_joint_counts_and_limits_match_the_published_values(self):
        tolerance = self.expected['tolerance']['limit']
        for name, robot in self.robots.items():
            parts = self.published_facts(robot)
            for facts in parts:
                for joint_name, limits in facts['joints'].items():
                    joint = self.joints.get(f'{name}_{joint_name}')
                    self.assertIsNotNone(joint, f'{name}: joint {joint_name} missing')
                    self.assertEqual(joint.get('type'), limits['type'], f'{name}_{joint_name} type')
                    limit = joint.find('limit')
                    for key in ('lower', 'upper', 'velocity', 'effort'):
                        if key in limits:
                            self.assertAlmostEqual(float(limit.get(key)), limits[key], delta=tolerance,
                                                   msg=f'{name}_{joint_name} {key}')
                for joint_name, mimic in facts.get('mimic', {}).items():
                    element = self.joints[f'{name}_{joint_name}'].find('mimic')
                    self.assertEqual(element.get('joint'), f"{name}_{mimic['joint']}")
                    self.assertAlmostEqual(float(element.get('multiplier', 1)), mimic['multiplier'])
            movable = [j for j in self.robot_joints(name) if j.get('type') != 'fixed' and j.find('mimic') is None]
            mimic = [j for j in self.robot_joints(name) if j.find('mimic') is not None]
            self.assertEqual(len(movable), sum(p['counts']['movable'] for p in parts), f'{name}: movable joints')
            self.assertEqual(len(mimic), sum(p['counts']['mimic'] for p in parts), f'{name}: mimic joints')

    def test_mimic_joints_follow_their_leader(self):
        states = {}
        for name in self.robots:
            msg = rospy.wait_for_message(f'/{name}/joint_states', JointState, 10)
            states.update(dict(zip(msg.name, msg.position)))
        checked = 0
        for joint in self.joints.values():
            mimic = joint.find('mimic')
            if mimic is None:
                continue
            leader = states[mimic.get('joint')]
            value = float(mimic.get('multiplier', 1)) * leader + float(mimic.get('offset', 0))
            expected = origin_matrix(joint)
            axis = [float(v) for v in joint.find('axis').get('xyz').split()] if joint.find('axis') is not None \
                else [1, 0, 0]
            motion = numpy.eye(4)
            if joint.get('type') == 'prismatic':
                motion[:3, 3] = numpy.asarray(axis) * value
            else:
                motion[:3, :3] = rotation(axis, value)
            expected = expected @ motion
            actual = transform_matrix(self.lookup(joint.find('parent').get('link'), joint.find('child').get('link')))
            numpy.testing.assert_allclose(actual, expected, atol=TOLERANCE, err_msg=joint.get('name'))
            checked += 1
        self.assertGreater(checked, 0)


if __name__ == '__main__':
    rostest.rosrun('vrrw_bringup', 'bringup_check', Bringup)
